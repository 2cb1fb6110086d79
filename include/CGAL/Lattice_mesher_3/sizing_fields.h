// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_SIZING_FIELDS_H
#define CGAL_LATTICE_MESHER_3_SIZING_FIELDS_H

#include <CGAL/Lattice_mesher_traits_3.h>
#include <CGAL/Lattice_mesher_3/internal/particle_neighbors.h>
#include <CGAL/Bbox_3.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <memory>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3Sizing

A sizing field given by samples: at each sample point p_s the mesh edge may be at most h_s, and
the size grows away from the samples with a slope of at most `grading`:

  h(x) = min_s (h_s + grading |x - p_s|),

the largest function below every sample whose gradient is at most `grading` (a Lipschitz
envelope), so that a lattice can follow it. Evaluations use a grid whose nodes each keep the
sample that wins there (found by a Dijkstra search from the samples); a query takes the
exact minimum over the samples of its cell's eight nodes and those in its cell: never below
the envelope, above it by a few percent where a sample wins around itself but at no node near
it (300 random samples of sizes 0.05 to 1.5 in a 10 x 10 x 3 box: 1 % of the points, by at
most 6 %). Samples at or above `max_size` are
dropped and the field is at most `max_size` (unbounded when it is infinite).

Used for the size that follows the shape (`size_samples()`) and for sizes the user
gives at points (a Medit `.sol` of sizes at the vertices of a mesh): one mechanism for both.
Queries are `const` and thread-safe.

\tparam K a CGAL kernel
*/
template <typename K>
class Graded_sizing_field_3
{
public:
  typedef typename K::Point_3 Point_3; ///< the point type
  typedef std::pair<Point_3, double> Sample; ///< a sample: a point and the largest edge length there

  /// the constant field `max_size`
  explicit Graded_sizing_field_3(double max_size = std::numeric_limits<double>::infinity())
    : m_max(max_size), m_grading(1.), m_grid(std::make_shared<const Grid>())
  {}

  /// builds the envelope of `samples`. `cell` is the grid spacing (default: the median sample
  /// size, coarser if the samples' box would need more than 2^22 nodes). Throws
  /// `std::invalid_argument` if `grading` is not positive and finite, if `max_size` is not
  /// positive, or if a sample's size is not positive or its point not finite.
  template <typename SampleRange>
  Graded_sizing_field_3(const SampleRange& samples, double grading, double max_size, double cell = 0.)
    : m_max(max_size), m_grading(grading)
  {
    std::shared_ptr<Grid> grid = std::make_shared<Grid>();
    if(!(grading > 0.) || !std::isfinite(grading))
      throw std::invalid_argument("Graded_sizing_field_3: the grading must be positive and finite");
    if(!(max_size > 0.))
      throw std::invalid_argument("Graded_sizing_field_3: the largest size must be positive");
    for(const Sample& s : samples) {
      const double x = CGAL::to_double(s.first.x()), y = CGAL::to_double(s.first.y()), z = CGAL::to_double(s.first.z());
      if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
        throw std::invalid_argument("Graded_sizing_field_3: a sample point is not finite");
      if(!(s.second > 0.))
        throw std::invalid_argument("Graded_sizing_field_3: the size " + std::to_string(s.second) + " of a sample is not positive");
      if(s.second < max_size) grid->samples.push_back({ { x, y, z }, s.second });
    }
    if(!grid->samples.empty()) build(*grid, cell);
    m_grid = grid;
  }

  /// h(x), at most `max_size()`
  double operator()(const Point_3& p) const
  {
    const Grid& g = *m_grid;
    if(g.samples.empty()) return m_max;
    const std::array<double, 3> x = { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) };
    std::array<int, 3> c;
    for(int a = 0; a < 3; ++a) {
      const double f = std::floor((x[a] - g.origin[a]) / g.cell);
      if(!(f >= 0.) || f > double(g.n[a] - 2)) return far_value(x);   // off the grid (or NaN)
      c[a] = int(f);
    }
    double h = m_max;
    for(int k = 0; k < 8; ++k) {
      const std::int32_t s = g.winner[g.node(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1))];
      if(s >= 0) h = (std::min)(h, value(g.samples[std::size_t(s)], x));
    }
    const std::size_t cell = g.node(c[0], c[1], c[2]);
    for(std::int32_t k = g.cell_start[cell]; k < g.cell_start[cell + 1]; ++k)
      h = (std::min)(h, value(g.samples[std::size_t(g.cell_samples[std::size_t(k)])], x));
    return h;
  }

  /// the largest size: the field never exceeds it (infinite: unbounded)
  double max_size() const { return m_max; }
  /// the largest slope of the field, in size per unit length
  double grading() const { return m_grading; }
  /// the smallest sample size (`max_size()` without samples)
  double min_size() const
  {
    double h = m_max;
    for(const Size_sample& s : m_grid->samples) h = (std::min)(h, s.size);
    return h;
  }
  /// number of samples kept (those whose size is below `max_size()`)
  std::size_t number_of_samples() const { return m_grid->samples.size(); }

private:
  struct Size_sample
  {
    std::array<double, 3> point;
    double size;
  };

  // shared between copies: the field is copied into frame fields and callables
  struct Grid
  {
    std::vector<Size_sample> samples;
    double cell = 0.;
    std::array<double, 3> origin = { 0., 0., 0. };
    std::array<int, 3> n = { 0, 0, 0 };
    std::vector<std::int32_t> winner;   // the sample that wins at each node, or -1
    // the samples in each cell (CSR): one may win around itself but at none of its cell's nodes
    std::vector<std::int32_t> cell_start, cell_samples;

    std::size_t node(int i, int j, int k) const
    { return (std::size_t(i) * std::size_t(n[1]) + std::size_t(j)) * std::size_t(n[2]) + std::size_t(k); }
  };

  double value(const Size_sample& s, const std::array<double, 3>& x) const
  {
    const double d = std::sqrt(CGAL::square(x[0] - s.point[0]) + CGAL::square(x[1] - s.point[1])
                               + CGAL::square(x[2] - s.point[2]));
    return s.size + m_grading * d;
  }

  // beyond the grid every sample is farther than (max - size) / grading, unless unbounded
  double far_value(const std::array<double, 3>& x) const
  {
    if(std::isfinite(m_max)) return m_max;
    double h = std::numeric_limits<double>::infinity();
    for(const Size_sample& s : m_grid->samples) h = (std::min)(h, value(s, x));
    return h;
  }

  void build(Grid& g, double cell) const
  {
    // the box of the samples, grown by their reach: (max - size) / grading
    std::array<double, 3> lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    std::vector<double> sizes;
    for(const Size_sample& s : g.samples) {
      const double reach = std::isfinite(m_max) ? (m_max - s.size) / m_grading : 0.;
      for(int a = 0; a < 3; ++a) {
        lo[a] = (std::min)(lo[a], s.point[a] - reach);
        hi[a] = (std::max)(hi[a], s.point[a] + reach);
      }
      sizes.push_back(s.size);
    }
    std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
    if(!(cell > 0.)) cell = sizes[sizes.size() / 2];
    const double volume = (hi[0] - lo[0] + 2. * cell) * (hi[1] - lo[1] + 2. * cell) * (hi[2] - lo[2] + 2. * cell);
    cell = (std::max)(cell, std::cbrt(volume / double(1 << 22)));
    g.cell = cell;
    for(int a = 0; a < 3; ++a) {
      g.origin[a] = lo[a] - cell;
      g.n[a] = int(std::ceil((hi[a] - lo[a]) / cell)) + 3;
    }
    const std::size_t nodes = std::size_t(g.n[0]) * std::size_t(g.n[1]) * std::size_t(g.n[2]);
    g.winner.assign(nodes, -1);
    // cells are indexed as their lowest node
    std::vector<std::size_t> cell_of(g.samples.size());
    g.cell_start.assign(nodes + 1, 0);
    for(std::size_t s = 0; s < g.samples.size(); ++s) {
      std::array<int, 3> c;
      for(int a = 0; a < 3; ++a) c[a] = int(std::floor((g.samples[s].point[a] - g.origin[a]) / g.cell));
      cell_of[s] = g.node(c[0], c[1], c[2]);
      ++g.cell_start[cell_of[s] + 1];
    }
    for(std::size_t q = 0; q < nodes; ++q) g.cell_start[q + 1] += g.cell_start[q];
    g.cell_samples.resize(g.samples.size());
    {
      std::vector<std::int32_t> fill(g.cell_start.begin(), g.cell_start.end() - 1);
      for(std::size_t s = 0; s < g.samples.size(); ++s) g.cell_samples[std::size_t(fill[cell_of[s]]++)] = std::int32_t(s);
    }
    std::vector<float> best(nodes, std::numeric_limits<float>::infinity());

    // Dijkstra over the nodes: each node takes the sample of the neighbour that reached it
    // and keeps it while no other sample gives it a smaller value
    typedef std::pair<double, std::size_t> Entry;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
    auto offer = [&](int i, int j, int k, std::int32_t s) {
      if(i < 0 || j < 0 || k < 0 || i >= g.n[0] || j >= g.n[1] || k >= g.n[2]) return;
      const std::array<double, 3> x = { g.origin[0] + i * g.cell, g.origin[1] + j * g.cell, g.origin[2] + k * g.cell };
      const double v = value(g.samples[std::size_t(s)], x);
      const std::size_t q = g.node(i, j, k);
      if(v >= m_max || !(float(v) < best[q])) return;
      best[q] = float(v);
      g.winner[q] = s;
      queue.push(Entry(v, q));
    };
    for(std::size_t s = 0; s < g.samples.size(); ++s) {
      std::array<int, 3> c;
      for(int a = 0; a < 3; ++a) c[a] = int(std::floor((g.samples[s].point[a] - g.origin[a]) / g.cell));
      for(int k = 0; k < 8; ++k) offer(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1), std::int32_t(s));
    }
    while(!queue.empty()) {
      const Entry e = queue.top();
      queue.pop();
      if(float(e.first) > best[e.second]) continue;   // superseded
      const std::int32_t s = g.winner[e.second];
      const int i = int(e.second / (std::size_t(g.n[1]) * std::size_t(g.n[2])));
      const int j = int((e.second / std::size_t(g.n[2])) % std::size_t(g.n[1]));
      const int k = int(e.second % std::size_t(g.n[2]));
      for(int di = -1; di <= 1; ++di)
        for(int dj = -1; dj <= 1; ++dj)
          for(int dk = -1; dk <= 1; ++dk)
            if(di != 0 || dj != 0 || dk != 0) offer(i + di, j + dj, k + dk, s);
    }
    drop_dominated(g);
  }

  // A cell's sample that one of the cell's node winners w dominates at the sample's own point is
  // dominated everywhere (h_w + G |x - p_w| <= h_w + G |p_s - p_w| + G |x - p_s| <= h_s + G |x -
  // p_s|), and w answers the cell's queries: it leaves the cell's list (samples written densely
  // along chords, as the shape's are, are mostly such: pinion, 780,000 of them).
  void drop_dominated(Grid& g) const
  {
    std::vector<std::int32_t> start(g.cell_start.size(), 0), kept;
    kept.reserve(g.cell_samples.size());
    for(std::size_t q = 0; q + 1 < g.cell_start.size(); ++q) {
      if(g.cell_start[q] < g.cell_start[q + 1]) {
        const int i = int(q / (std::size_t(g.n[1]) * std::size_t(g.n[2])));
        const int j = int((q / std::size_t(g.n[2])) % std::size_t(g.n[1]));
        const int k = int(q % std::size_t(g.n[2]));
        for(std::int32_t m = g.cell_start[q]; m < g.cell_start[q + 1]; ++m) {
          const std::int32_t s = g.cell_samples[std::size_t(m)];
          const Size_sample& own = g.samples[std::size_t(s)];
          bool dominated = false;
          for(int c = 0; c < 8 && !dominated; ++c) {
            const std::int32_t w = g.winner[g.node(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1))];
            dominated = w >= 0 && w != s && value(g.samples[std::size_t(w)], own.point) <= own.size;
          }
          if(!dominated) kept.push_back(s);
        }
      }
      start[q + 1] = std::int32_t(kept.size());
    }
    g.cell_start.swap(start);
    g.cell_samples.swap(kept);
  }

  double m_max, m_grading;
  std::shared_ptr<const Grid> m_grid;
};

/*!
\ingroup PkgLatticeMesher3Sizing

The local thickness of the domain and the gap in front of it at a point of its surface (see
`thickness_samples()`); -1 where the march found none within its reach.
*/
template <typename K>
struct Thickness_sample_3
{
  typename K::Point_3 point;    ///< on the surface
  typename K::Vector_3 normal;  ///< the unit outward normal there
  double thickness = -1.;       ///< along the inward normal, to where the domain is left
  double gap = -1.;             ///< along the outward normal, to where the domain is met again
};

/*!
\ingroup PkgLatticeMesher3Sizing

Measures the domain at the points of `domain.sample_surface(spacing)`: the thickness, marching
from each point along the inward normal until the domain is left, and the gap in front of it,
marching along the outward normal until the domain is met again; no farther than `reach` and
`gap_reach`, in steps of `step`, the crossing then located to 1/64 of a step. A part thinner than a step (or
a point near an edge sharper than a right angle, whose inward normal leaves at once) measures a
step. Points closer than `step / 2` to a feature curve are skipped: their normal is either
face's, along which the march may run in the plane of the other face. `threads` OpenMP
threads share the points.

\tparam MeshDomain a model of `LatticeMeshDomain_3`
*/
template <typename MeshDomain>
std::vector<Thickness_sample_3<typename MeshDomain::Geom_traits> >
thickness_samples(const MeshDomain& domain, double spacing, double step, double reach, double gap_reach,
                  int threads = 1)
{
  typedef typename MeshDomain::Geom_traits K;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  if(!(spacing > 0.) || !(step > 0.) || !(reach > 0.) || !(gap_reach > 0.))
    throw std::invalid_argument("thickness_samples(): the spacing, the step and the reaches must be positive");
  std::vector<Point_3> points;
  domain.sample_surface(spacing, std::back_inserter(points));
  std::vector<Thickness_sample_3<K> > result(points.size());
  std::vector<char> skipped(points.size(), 0);
  // the distance along `direction` from `p` at which is_inside() first differs from `inside`
  auto march = [&](const Point_3& p, const Vector_3& direction, bool inside) {
    const double reach_here = inside ? reach : gap_reach;
    double t = .5 * step;
    for(; t <= reach_here; t += step)
      if(domain.is_inside(p + t * direction) != inside) break;
    if(t > reach_here) return -1.;
    double a = (std::max)(0., t - step), b = t;
    for(int it = 0; it < 6; ++it) {
      const double m = .5 * (a + b);
      (domain.is_inside(p + m * direction) != inside ? b : a) = m;
    }
    return (std::max)(b, step);
  };
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64)
  for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(points.size()); ++i) {
    Thickness_sample_3<K>& r = result[std::size_t(i)];
    if(domain.number_of_curves() > 0 && domain.project_on_features(points[std::size_t(i)]).squared_distance < .25 * step * step) {
      skipped[std::size_t(i)] = 1;
      continue;
    }
    const auto s = domain.project_on_surface(points[std::size_t(i)]);
    r.point = s.point;
    r.normal = s.direction;
    r.thickness = march(s.point, -s.direction, true);
    r.gap = march(s.point, s.direction, false);
  }
  std::size_t kept = 0;
  for(std::size_t i = 0; i < result.size(); ++i)
    if(!skipped[i] && (result[i].thickness >= 0. || result[i].gap >= 0.)) result[kept++] = result[i];
  result.resize(kept);
  return result;
}

/*!
\ingroup PkgLatticeMesher3Sizing

Writes the sizes that the measures of `thickness_samples()` ask for: `cells_across` lattice
cells across each part (its thickness divided by `cells_across`), written at the surface point
and every half size along the chord up to its middle, so that the size holds across the part
and not only at its surface; and one cell across each gap (the gap itself). Sizes at or above
`max_size` are not written.
\returns the output iterator, past the `std::pair<Point_3, double>` written
*/
template <typename K, typename OutputIterator>
OutputIterator size_samples(const std::vector<Thickness_sample_3<K> >& measures, double cells_across,
                            double max_size, OutputIterator out)
{
  if(!(cells_across > 0.))
    throw std::invalid_argument("size_samples(): the number of cells across must be positive");
  for(const Thickness_sample_3<K>& m : measures) {
    double h = std::numeric_limits<double>::infinity();
    if(m.thickness >= 0.) h = m.thickness / cells_across;
    if(m.gap >= 0.) h = (std::min)(h, m.gap);
    if(!(h < max_size)) continue;
    *out++ = std::make_pair(m.point, h);
    if(m.thickness >= 0.)
      for(double t = .5 * h; t <= .5 * m.thickness; t += .5 * h) *out++ = std::make_pair(m.point - t * m.normal, h);
  }
  return out;
}

/*!
\ingroup PkgLatticeMesher3Sizing

Writes one cell across each gap between two feature curves (the narrow face between two sharp
edges, two curves meeting at an acute angle): at points of the curves about `spacing` apart (the
surface samples within `spacing / 2` of a curve, projected onto it), the distance d to the nearest
point of each other curve closer than `reach`, where the segment between them makes at least 60
degrees with the tangents of both curves (so that curves meeting at a corner at 60 degrees or
more do not count near it). The size d is written at both ends and every d / 2 between them.
Only a face between the curves counts (the segment's midpoint within d / 4 of the surface): two
curves facing each other across the volume or a gap are the business of `thickness_samples()`.
Curves whose points span less than `reach` do not count: a crease shorter than the edge (the
noise of a scanned surface, classified as sharp) gets no particle between its ends.
`threads` OpenMP threads share the points.

These sizes are not part of the size that `CGAL::lattice_mesh_3()` builds by default (the manual's
Design chapter, "Every Surface of libcgal-demo", gives why); a `Graded_sizing_field_3` of them goes
to it as the named parameter `size_field`.
\returns the output iterator, past the `std::pair<Point_3, double>` written

\tparam MeshDomain a model of `LatticeMeshDomain_3`
*/
template <typename MeshDomain, typename OutputIterator>
OutputIterator feature_gap_size_samples(const MeshDomain& domain, double spacing, double reach, OutputIterator out,
                                        int threads = 1)
{
  typedef typename MeshDomain::Geom_traits K;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  if(!(spacing > 0.) || !(reach > 0.))
    throw std::invalid_argument("feature_gap_size_samples(): the spacing and the reach must be positive");
  const std::size_t curves = domain.number_of_curves();
  if(curves < 2) return out;
  std::vector<Point_3> surface;
  domain.sample_surface(spacing, std::back_inserter(surface));
  struct Curve_point { Point_3 point; Vector_3 tangent; std::size_t curve; };
  std::vector<Curve_point> points;
  for(const Point_3& p : surface) {
    const auto c = domain.project_on_features(p);
    if(c.index >= 0 && c.squared_distance < .25 * spacing * spacing) points.push_back({ c.point, c.direction, std::size_t(c.index) });
  }
  std::vector<Bbox_3> extent(curves);
  for(const Curve_point& a : points) extent[a.curve] += a.point.bbox();
  auto short_curve = [&](std::size_t curve) {
    const Bbox_3& b = extent[curve];
    const double dx = b.xmax() - b.xmin(), dy = b.ymax() - b.ymin(), dz = b.zmax() - b.zmin();
    return b.xmax() < b.xmin() || dx * dx + dy * dy + dz * dz < reach * reach;
  };
  points.erase(std::remove_if(points.begin(), points.end(), [&](const Curve_point& a) { return short_curve(a.curve); }), points.end());
  std::vector<Point_3> located;
  for(const Curve_point& a : points) located.push_back(a.point);
  const internal::Point_search_3<K> search(located);
  std::vector<std::vector<std::pair<Point_3, double> > > written(points.size());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64)
  for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(points.size()); ++i) {
    const Curve_point& a = points[std::size_t(i)];
    std::vector<std::size_t> within;
    search.in_sphere(a.point, reach, within);
    std::set<std::size_t> near;   // the other curves within reach
    for(std::size_t j : within) if(points[j].curve != a.curve) near.insert(points[j].curve);
    for(std::size_t other : near) {
      const auto q = domain.project_on_curve(a.point, other);
      const double d = std::sqrt(q.squared_distance);
      if(!(d > 0.) || !(d < reach)) continue;
      const Vector_3 u = (q.point - a.point) / d;
      if(std::abs(u * a.tangent) > .5 || std::abs(u * q.direction) > .5) continue;   // within 60 degrees of a tangent
      // a face between them (its chord's midpoint on the surface), not a part or a gap across the volume
      if(domain.project_on_surface(a.point + .5 * (q.point - a.point)).squared_distance > .0625 * d * d) continue;
      for(double t = 0.; t < d + .25 * d; t += .5 * d)
        written[std::size_t(i)].emplace_back(a.point + (std::min)(t, d) * u, d);
    }
  }
  for(const auto& w : written)
    for(const auto& sample : w) *out++ = sample;
  return out;
}

/*!
\ingroup PkgLatticeMesher3Sizing

How far the surface leaves its tangent plane around a point of it (see `deviation_samples()`):
the largest distance to the surface of the points at distances L, L/2, L/4 and L/8 from it in
eight directions of the tangent plane; -1 at a scale that reaches a feature curve.
*/
template <typename K>
struct Deviation_sample_3
{
  static constexpr int scales = 4;  ///< number of scales at which the deviation is measured
  typename K::Point_3 point;        ///< on the surface
  double largest_scale = 0.;        ///< L
  std::array<double, scales> deviation{}; ///< at L, L/2, L/4, L/8

  /// the scale of `deviation[k]`: L / 2^k
  double scale(int k) const { return std::ldexp(largest_scale, -k); }
};

/*!
\ingroup PkgLatticeMesher3Sizing

Measures the surface's deviation from its tangent plane at the points of
`domain.sample_surface(spacing)`, at the scales `largest_scale` / 2^k (`Deviation_sample_3`):
the chord error that boundary facets of those sizes would make there. A scale that comes within
a tenth of it of a feature curve is not measured (the crease is meshed along the curve, and the
deviation across it is no chord error); points closer than `spacing / 4` to a curve are skipped.
`threads` OpenMP threads share the points.

\tparam MeshDomain a model of `LatticeMeshDomain_3`
*/
template <typename MeshDomain>
std::vector<Deviation_sample_3<typename MeshDomain::Geom_traits> >
deviation_samples(const MeshDomain& domain, double spacing, double largest_scale, int threads = 1)
{
  typedef typename MeshDomain::Geom_traits K;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  typedef Deviation_sample_3<K> Sample;
  if(!(spacing > 0.) || !(largest_scale > 0.))
    throw std::invalid_argument("deviation_samples(): the spacing and the largest scale must be positive");
  std::vector<Point_3> points;
  domain.sample_surface(spacing, std::back_inserter(points));
  std::vector<Sample> result(points.size());
  std::vector<char> kept(points.size(), 0);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64)
  for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(points.size()); ++i) {
    const double to_curve = domain.number_of_curves() > 0
        ? std::sqrt(domain.project_on_features(points[std::size_t(i)]).squared_distance) : HUGE_VAL;
    if(to_curve < .25 * spacing) continue;
    const auto s = domain.project_on_surface(points[std::size_t(i)]);
    const Vector_3 n = s.direction;
    // two unit tangents
    const Vector_3 a = std::abs(CGAL::to_double(n.x())) < .6 ? Vector_3(1, 0, 0) : Vector_3(0, 1, 0);
    const auto cross = K().construct_cross_product_vector_3_object();
    Vector_3 t1 = cross(n, a);
    t1 = t1 / std::sqrt(CGAL::to_double(t1.squared_length()));
    const Vector_3 t2 = cross(n, t1);
    Sample& r = result[std::size_t(i)];
    r.point = s.point;
    r.largest_scale = largest_scale;
    for(int k = 0; k < Sample::scales; ++k) {
      const double l = r.scale(k);
      r.deviation[std::size_t(k)] = -1.;
      if(1.1 * l > to_curve) continue;
      double d = 0.;
      for(int j = 0; j < 8; ++j) {
        const double angle = j * (CGAL_PI / 4.);
        const Point_3 q = s.point + l * (std::cos(angle) * t1 + std::sin(angle) * t2);
        d = (std::max)(d, std::sqrt(domain.project_on_surface(q).squared_distance));
      }
      r.deviation[std::size_t(k)] = d;
      kept[std::size_t(i)] = 1;
    }
  }
  std::size_t count = 0;
  for(std::size_t i = 0; i < result.size(); ++i)
    if(kept[i]) result[count++] = result[i];
  result.resize(count);
  return result;
}

/*!
\ingroup PkgLatticeMesher3Sizing

Writes the sizes at which boundary facets stay within `tolerance` of the surface, from the
measures of `deviation_samples()`: h is the largest measured scale at which the deviation d of
the surface from its tangent plane is at most `tolerance`, grown towards the next larger scale
as d grows between the two (d ~ h^a, a in [1, 2]: a crease, a curvature); below every measured
scale, as a curvature. On a sphere of radius R, d(h) = h^2 / 2R, three times what an
equilateral facet of edge h leaves between its circumcentre and the sphere; the boundary
facets of a lattice, less regular and larger than h, leave 2.5 times that (unit sphere, h =
0.17: 0.0126 where h^2 / 6R is 0.005), hence d itself as the bound. Nothing is written where
the largest measured scale is within the
tolerance. Sizes at or above `max_size` are not written.
\returns the output iterator, past the `std::pair<Point_3, double>` written
*/
template <typename K, typename OutputIterator>
OutputIterator tolerance_size_samples(const std::vector<Deviation_sample_3<K> >& measures, double tolerance,
                                      double max_size, OutputIterator out)
{
  typedef Deviation_sample_3<K> Sample;
  if(!(tolerance > 0.))
    throw std::invalid_argument("tolerance_size_samples(): the tolerance must be positive");
  const double most = tolerance;
  for(const Sample& m : measures) {
    auto d = [&](int k) { return m.deviation[std::size_t(k)]; };
    int k = 0;
    while(k < Sample::scales && d(k) < 0.) ++k;   // the scales that reach a curve
    // within the tolerance at the largest measured scale: no evidence for a smaller size
    if(k == Sample::scales || d(k) <= most) continue;
    while(k + 1 < Sample::scales && d(k + 1) > most) ++k;   // k: the smallest scale beyond it
    double h;
    if(k + 1 == Sample::scales) h = m.scale(k) * std::sqrt(most / d(k));
    else {
      const double a = (std::min)(2., (std::max)(1., std::log2(d(k) / (std::max)(d(k + 1), 1e-300))));
      h = (std::min)(m.scale(k + 1) * std::pow(most / (std::max)(d(k + 1), 1e-300), 1. / a), m.scale(k));
    }
    if(h < max_size) *out++ = std::make_pair(m.point, h);
  }
  return out;
}

/*!
\ingroup PkgLatticeMesher3Sizing

A frame field scaled by a sizing field: T(p) = s(p) T0(p), with s(p) = min(1, h(p) / (l |T0(p)|))
and |T0(p)| the length of the longest column of the frame (its largest stretch when the columns
are orthogonal). Where the size h(p)
is smaller than the lattice edge l of `field`, the lattice cube shrinks to h(p), keeping its
directions and proportions; elsewhere the field is `field`. The mesher then works with l as the
edge length in the isotropic space: everything it measures there (insertion, deletion,
quality) follows h.

\tparam FrameField a model of `FrameField_3`
\tparam Sizing a callable `double(const Point_3&)` returning the largest edge length at a point
\cgalModels `FrameField_3`
*/
template <typename FrameField, typename Sizing>
class Sized_frame_field_3
{
public:
  typedef typename FrameField::Point_3 Point_3;   ///< the point type
  typedef typename FrameField::Matrix_3 Matrix_3; ///< the frame type, a 3x3 matrix

  /// `min_size`: the size is never taken below it
  Sized_frame_field_3(const FrameField& field, const Sizing& sizing, double edge_length, double min_size = 0.)
    : m_field(field), m_sizing(sizing), m_length(edge_length), m_min(min_size)
  {
    if(!(edge_length > 0.) || !std::isfinite(edge_length))
      throw std::invalid_argument("Sized_frame_field_3: the edge length must be positive and finite");
    if(!(min_size >= 0.))
      throw std::invalid_argument("Sized_frame_field_3: the smallest size must not be negative");
  }

  /// the frame T(p) = s(p) T0(p), whose columns are the lattice cube edges at p
  Matrix_3 frame(const Point_3& p) const
  {
    const Matrix_3 t = m_field.frame(p);
    // the longest column: the largest stretch of an orthogonal frame, without an SVD per call
    const double stretch = t.colwise().norm().maxCoeff();
    const double s = (std::max)(m_sizing(p), m_min) / (m_length * stretch);
    return s < 1. ? Matrix_3(s * t) : t;
  }

  /// the lattice edge length l, in the isotropic space of `field()`
  double edge_length() const { return m_length; }
  /// the unscaled frame field T0
  const FrameField& field() const { return m_field; }
  /// the sizing field h
  const Sizing& sizing() const { return m_sizing; }

private:
  FrameField m_field;
  Sizing m_sizing;
  double m_length, m_min;
};

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_SIZING_FIELDS_H
