// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_INTERNAL_PARTICLE_NEIGHBORS_H
#define CGAL_LATTICE_MESHER_3_INTERNAL_PARTICLE_NEIGHBORS_H

#include <CGAL/Lattice_mesher_3/frame_fields.h>

#include <boost/container/vector.hpp>
#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {
namespace internal {

typedef Eigen::Vector3d Vec3;
typedef Eigen::Matrix3d Mat3;

template <typename Point_3>
std::vector<Vec3> to_vectors(const std::vector<Point_3>& points)
{
  std::vector<Vec3> x(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) x[i] = to_eigen(points[i]);
  return x;
}

// A fixed array of points answering range and nearest-point queries by index: a uniform grid of
// cells 1.5 times the mean spacing over the bounding box, the points sorted by cell. Particles
// fill their domain, so a query's few cells hold about the points it asks for; it answers the
// range queries of the insertion, deletion and neighbour graphs in less time than a k-d tree.
template <typename K>
class Point_search_3
{
  typedef typename K::Point_3 Point_3;

public:
  explicit Point_search_3(const std::vector<Point_3>& points) : Point_search_3(to_vectors(points)) {}

  explicit Point_search_3(const std::vector<Vec3>& x)
  {
    const std::size_t n = x.size();
    if(n == 0) return;
    Vec3 hi = x[0];
    lo_ = x[0];
    for(const Vec3& p : x) { lo_ = lo_.cwiseMin(p); hi = hi.cwiseMax(p); }
    const Vec3 span = (hi - lo_).cwiseMax(1e-300);
    cell_ = (std::max)(1.5 * std::cbrt(span.prod() / double(n)), span.maxCoeff() / 1024.);
    for(;;) {   // at most 4 n + 64 cells, for points about on a plane or a line
      for(int a = 0; a < 3; ++a) dims_[a] = long(span[a] / cell_) + 1;
      if(double(dims_[0]) * double(dims_[1]) * double(dims_[2]) <= 4. * double(n) + 64.) break;
      cell_ *= 1.25;
    }
    std::vector<std::size_t> key(n);
    start_.assign(std::size_t(dims_[0] * dims_[1] * dims_[2]) + 1, 0);
    for(std::size_t i = 0; i < n; ++i) { key[i] = index(coord(x[i])); ++start_[key[i] + 1]; }
    for(std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    order_.resize(n);
    for(std::size_t i = 0; i < n; ++i) order_[fill[key[i]]++] = i;
    sorted_.resize(n);
    for(std::size_t k = 0; k < n; ++k) sorted_[k] = x[order_[k]];
  }

  /// appends the indices of the points within Euclidean distance `radius` of `c`
  void in_sphere(const Point_3& c, double radius, std::vector<std::size_t>& out) const
  {
    const Vec3 q = to_eigen(c);
    scan(coord(q - Vec3::Constant(radius)), coord(q + Vec3::Constant(radius)), [&](std::size_t k) {
      if((sorted_[k] - q).squaredNorm() <= radius * radius) out.push_back(order_[k]);
    });
  }

  /// appends the indices of the points in the axis-aligned box `c` +- `half` or in the ball of
  /// radius `radius` around `c`, whichever is smaller (the box under a stretched frame, the
  /// ball, 5 times smaller than its box, under a rotation)
  void in_box_or_sphere(const Vec3& c, const Vec3& half, double radius, std::vector<std::size_t>& out) const
  {
    if(8. * half[0] * half[1] * half[2] > 4.19 * radius * radius * radius)
      return in_sphere(Point_3(c[0], c[1], c[2]), radius, out);
    scan(coord(c - half), coord(c + half), [&](std::size_t k) {
      if(((sorted_[k] - c).cwiseAbs() - half).maxCoeff() <= 0.) out.push_back(order_[k]);
    });
  }

  /// index of the nearest point (the lowest index among equally near ones), and its squared
  /// distance: the cells ring by ring around the query's, until the next ring is farther
  std::pair<std::size_t, double> nearest(const Point_3& c) const
  {
    const Vec3 q = to_eigen(c);
    const std::array<long, 3> o = coord(q);
    std::pair<std::size_t, double> best((std::numeric_limits<std::size_t>::max)(), HUGE_VAL);
    auto visit = [&](std::size_t k) {
      const double d = (sorted_[k] - q).squaredNorm();
      if(d < best.second || (d == best.second && order_[k] < best.first)) best = { order_[k], d };
    };
    const long rings = (std::max)({ dims_[0], dims_[1], dims_[2] });
    for(long r = 0; r <= rings; ++r) {
      // the ring's two faces normal to x, then to y within them, then to z within both
      for(long side : { -r, r }) {
        scan({ o[0] + side, o[1] - r, o[2] - r }, { o[0] + side, o[1] + r, o[2] + r }, visit);
        if(r > 0) {
          scan({ o[0] - r + 1, o[1] + side, o[2] - r }, { o[0] + r - 1, o[1] + side, o[2] + r }, visit);
          scan({ o[0] - r + 1, o[1] - r + 1, o[2] + side }, { o[0] + r - 1, o[1] + r - 1, o[2] + side }, visit);
        }
        if(r == 0) break;
      }
      // points beyond this ring are at least r cells away (from the query clamped to the grid)
      if(best.second <= double(r) * cell_ * double(r) * cell_) break;
    }
    return best;
  }

  std::size_t size() const { return sorted_.size(); }

private:
  std::array<long, 3> coord(const Vec3& p) const
  {
    std::array<long, 3> c;
    for(int a = 0; a < 3; ++a) {
      const double t = std::floor((p[a] - lo_[a]) / cell_);
      c[a] = t < 0. ? 0L : t >= double(dims_[a]) ? dims_[a] - 1 : long(t);
    }
    return c;
  }
  std::size_t index(const std::array<long, 3>& c) const { return std::size_t((c[0] * dims_[1] + c[1]) * dims_[2] + c[2]); }

  // calls f on the sorted positions of the points in the cells a..b (clipped to the grid)
  template <typename F>
  void scan(std::array<long, 3> a, std::array<long, 3> b, F f) const
  {
    if(sorted_.empty()) return;
    for(int i = 0; i < 3; ++i) { a[i] = (std::max)(a[i], 0L); b[i] = (std::min)(b[i], dims_[i] - 1); if(a[i] > b[i]) return; }
    for(long i = a[0]; i <= b[0]; ++i)
      for(long j = a[1]; j <= b[1]; ++j)
        for(std::size_t k = start_[index({ i, j, a[2] })], end = start_[index({ i, j, b[2] }) + 1]; k < end; ++k) f(k);
  }

  std::vector<Vec3> sorted_;          // the points, by cell
  std::vector<std::size_t> order_;    // their indices
  std::vector<std::size_t> start_;    // the first position of each cell, and the end
  Vec3 lo_ = Vec3::Zero();
  double cell_ = 1.;
  long dims_[3] = { 1, 1, 1 };
};

// Half-widths of the axis-aligned box around the isotropic ball of radius r under the frame T
// (the ball maps to an ellipsoid whose extent along axis a is r |row a of T|), widened by
// `slack` for a field that varies within the ball. Under a stretched field the Euclidean ball
// covering the largest stretch holds many times the particles it needs (80 times at fig8's peak).
inline Vec3 reach_box(const Mat3& t, double r, double slack = 1.5)
{
  return slack * r * Vec3(t.row(0).norm(), t.row(1).norm(), t.row(2).norm());
}

// The search region of an isotropic ball of radius r at a particle with frame t: its box, or
// the Euclidean ball covering r under the largest stretch of the field (x1.1), the smaller.
template <typename K>
void search_isotropic_ball(const Point_search_3<K>& search, const Vec3& c, const Mat3& t, double r,
                           double max_stretch, std::vector<std::size_t>& out)
{
  search.in_box_or_sphere(c, reach_box(t, r), 1.1 * max_stretch * r, out);
}

// Frames of the particles: T_i, B_i = T_i^-1, and the largest stretch of any T_i.
struct Particle_frames
{
  std::vector<Mat3> T, B;
  double max_stretch = 1.;
};

template <typename K, typename FrameField>
Particle_frames compute_particle_frames(const std::vector<Vec3>& x, const FrameField& field, int threads)
{
  typedef typename K::Point_3 Point_3;
  Particle_frames f;
  const std::ptrdiff_t n = std::ptrdiff_t(x.size());
  f.T.resize(n);
  f.B.resize(n);
  std::vector<double> stretch(n, 0.);
  bool failed = false;
  std::string what;
#pragma omp parallel for num_threads(threads) schedule(static)
  for(std::ptrdiff_t i = 0; i < n; ++i) {
    try {
      const Point_3 p(x[i][0], x[i][1], x[i][2]);
      f.T[i] = field.frame(p);
      f.B[i] = isotropic_map(f.T[i], p);
      stretch[i] = max_stretch(f.T[i]);
    } catch(const std::exception& e) {
#pragma omp critical(lattice_mesher_3_frames)
      { if(!failed) { failed = true; what = e.what(); } }
    }
  }
  if(failed) throw std::domain_error(what);
  if(n > 0) f.max_stretch = *std::max_element(stretch.begin(), stretch.end());
  return f;
}

// An array whose resize() leaves new elements default-initialized (not zeroed, which would be
// done by one thread): those of the neighbour graphs and the energy are filled by all threads.
template <typename T>
using Unzeroed_vector = boost::container::vector<T>;
using boost::container::default_init;

// The neighbours of every particle within an isotropic radius, as a symmetric CSR graph, and
// its half as a list of pairs (i < j) with the isotropic map B of the pair's midpoint. B is
// frozen when the graph is built: the energy of an optimization round is then a smooth function
// of the positions, with the exact gradient that the line search needs.
struct Neighbor_graph
{
  // CSR: neighbours of i are entries [offsets[i], offsets[i+1]), by ascending pair index; entry
  // e is particle neighbor[e], through pair pair_of[e].
  std::vector<int> offsets;
  Unzeroed_vector<int> neighbor, pair_of;
  Unzeroed_vector<std::array<int, 2> > pairs;
  Unzeroed_vector<Mat3> pair_map;
  // dB/dx_a (a = 0, 1, 2) at each particle, in the units of the positions: a pair's map is then
  // B_ij + sum_a S_a (m - m_ij)_a, S the mean of its particles' slopes and m its moving midpoint
  // (`estimate_map_slopes()`); empty: B frozen.
  Unzeroed_vector<std::array<Mat3, 3> > map_slopes;
  // per pair, with map_slopes: whether one of its particles has a slope (where the field is the
  // same around both, B_ij stays as it is)
  Unzeroed_vector<char> sloped_pairs;

  std::size_t number_of_particles() const { return offsets.empty() ? 0 : offsets.size() - 1; }
};

// The pairs into `g` in the order of the particles that found them (`kept`, with their maps,
// consumed), copied by all threads, each freeing the lists it copied.
inline void copy_pairs(std::vector<std::vector<std::pair<int, Mat3> > >& kept, Neighbor_graph& g, int threads)
{
  const std::size_t n = kept.size();
  std::vector<std::size_t> first(n + 1, 0);
  for(std::size_t i = 0; i < n; ++i) first[i + 1] = first[i] + kept[i].size();
  g.pairs.resize(first[n], default_init);
  g.pair_map.resize(first[n], default_init);
#pragma omp parallel for num_threads(threads) schedule(static)
  for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(n); ++i) {
    for(std::size_t k = 0; k < kept[i].size(); ++k) {
      const int j = kept[i][k].first;
      g.pairs[first[i] + k] = { (std::min)(int(i), j), (std::max)(int(i), j) };
      g.pair_map[first[i] + k] = kept[i][k].second;
    }
    std::vector<std::pair<int, Mat3> >().swap(kept[i]);
  }
}

// The CSR lists of g's pairs among n particles, by all threads: each pair takes the next slot of
// its two particles (atomically), then each list is sorted by pair index, the order of one thread.
inline void make_adjacency(Neighbor_graph& g, std::size_t n, int threads)
{
  std::vector<int> fill(n, 0);
  g.offsets.assign(n + 1, 0);
  const std::ptrdiff_t np = std::ptrdiff_t(g.pairs.size());
#pragma omp parallel for num_threads(threads) schedule(static)
  for(std::ptrdiff_t p = 0; p < np; ++p)
    for(int i : g.pairs[p]) {
#pragma omp atomic
      ++fill[i];
    }
  for(std::size_t i = 0; i < n; ++i) g.offsets[i + 1] = g.offsets[i] + fill[i];
  std::copy(g.offsets.begin(), g.offsets.end() - 1, fill.begin());
  g.neighbor.resize(std::size_t(g.offsets[n]), default_init);
  g.pair_of.resize(std::size_t(g.offsets[n]), default_init);
#pragma omp parallel for num_threads(threads) schedule(static)
  for(std::ptrdiff_t p = 0; p < np; ++p)
    for(int k = 0; k < 2; ++k) {
      const int i = g.pairs[p][k];
      int slot;
#pragma omp atomic capture
      slot = fill[i]++;
      g.neighbor[slot] = g.pairs[p][1 - k];
      g.pair_of[slot] = int(p);
    }
#pragma omp parallel num_threads(threads)
  {
    std::vector<std::pair<int, int> > list;   // (pair, neighbour)
#pragma omp for schedule(static)
    for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(n); ++i) {
      list.clear();
      for(int e = g.offsets[i]; e < g.offsets[i + 1]; ++e) list.emplace_back(g.pair_of[e], g.neighbor[e]);
      std::sort(list.begin(), list.end());
      for(int e = g.offsets[i], k = 0; e < g.offsets[i + 1]; ++e, ++k) { g.pair_of[e] = list[k].first; g.neighbor[e] = list[k].second; }
    }
  }
}

template <typename K, typename FrameField>
Neighbor_graph build_neighbor_graph(const std::vector<Vec3>& x, const Particle_frames& frames,
                                    const FrameField& field, double iso_radius, int threads)
{
  typedef typename K::Point_3 Point_3;
  const std::size_t n = x.size();
  const Point_search_3<K> search(x);

  // Each particle finds candidates in the search region of its isotropic ball; a pair is kept
  // if either finds the other and |B_ij v| <= iso_radius, its B evaluated once, by the smaller
  // particle that found it.
  std::vector<std::vector<int> > candidates(n);
#pragma omp parallel num_threads(threads)
  {
    std::vector<std::size_t> found;
#pragma omp for schedule(dynamic, 256)
    for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(n); ++i) {
      found.clear();
      search_isotropic_ball(search, x[i], frames.T[i], iso_radius, frames.max_stretch, found);
      for(std::size_t j : found) if(j != std::size_t(i)) candidates[i].push_back(int(j));
      std::sort(candidates[i].begin(), candidates[i].end());
    }
  }
  std::vector<std::vector<std::pair<int, Mat3> > > kept(n);   // (j, B_ij), evaluated by i
  bool failed = false;
  std::string what;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 256)
  for(std::ptrdiff_t ii = 0; ii < std::ptrdiff_t(n); ++ii) {
    const int i = int(ii);
    try {
      for(int j : candidates[i]) {
        if(j < i && std::binary_search(candidates[j].begin(), candidates[j].end(), i)) continue;
        const Vec3 v = x[i] - x[j];
        const Point_3 m(0.5 * (x[i][0] + x[j][0]), 0.5 * (x[i][1] + x[j][1]), 0.5 * (x[i][2] + x[j][2]));
        const Mat3 b = isotropic_map(field.frame(m), m);
        if((b * v).squaredNorm() <= iso_radius * iso_radius) kept[i].emplace_back(j, b);
      }
    } catch(const std::exception& e) {
#pragma omp critical(lattice_mesher_3_neighbors)
      { if(!failed) { failed = true; what = e.what(); } }
    }
  }
  if(failed) throw std::domain_error(what);

  Neighbor_graph g;
  copy_pairs(kept, g, threads);
  make_adjacency(g, n, threads);
  return g;
}

// The slopes of B at the particles (Neighbor_graph::map_slopes), for positions x and maps B
// at them. A frozen B_ij makes the round's minimum a strained lattice where the field varies:
// the force on a particle is the sum of B_ij^T f_ij, which weighs its pairs on the side where B is
// larger more (fig8 FCC: lattice spacing along x off by 7.6 % RMS, edges 1 degree off the
// lattice). B moving with the midpoint makes a pair's isotropic vector that of the isotropic
// coordinates up to second order in its length, so that the minimum is the lattice there.
// Least squares of B_j - B_i = sum_a S_a (x_j - x_i)_a over each particle's neighbours: no field
// evaluation, and a discrete field's steps are smoothed over the neighbour distance. Neighbours
// whose B differs by more than half (a cross field's frame permutation, a discontinuity) are left
// out, and so is a fit whose neighbours span no volume. Left empty where B is the same everywhere.
inline void estimate_map_slopes(Neighbor_graph& g, const std::vector<Vec3>& x, const std::vector<Mat3>& B, int threads)
{
  const std::ptrdiff_t n = std::ptrdiff_t(g.number_of_particles());
  bool varies = false;
  for(const std::array<int, 2>& p : g.pairs) varies = varies || B[p[0]] != B[p[1]];
  g.map_slopes.clear();
  if(!varies) return;
  g.map_slopes.resize(std::size_t(n), default_init);
  std::vector<char> sloped(n, 0);
#pragma omp parallel for num_threads(threads) schedule(static)
  for(std::ptrdiff_t i = 0; i < n; ++i) {
    Mat3 a = Mat3::Zero();
    Eigen::Matrix<double, 3, 9> r = Eigen::Matrix<double, 3, 9>::Zero();
    const double jump = .5 * B[i].norm();
    for(int e = g.offsets[i]; e < g.offsets[i + 1]; ++e) {
      const int j = g.neighbor[e];
      const Mat3 db = B[j] - B[i];
      if(db.norm() > jump) continue;
      const Vec3 d = x[j] - x[i];
      a += d * d.transpose();
      r += d * Eigen::Map<const Eigen::Matrix<double, 1, 9> >(db.data());
    }
    std::array<Mat3, 3>& s = g.map_slopes[i];
    for(Mat3& m : s) m.setZero();
    const double scale = a.trace() / 3.;
    if(!(scale > 0.) || !(a.determinant() > 1e-6 * scale * scale * scale)) continue;
    const Eigen::Matrix<double, 3, 9> slope = a.ldlt().solve(r);
    for(int k = 0; k < 3; ++k) s[k] = Eigen::Map<const Mat3>(slope.row(k).eval().data());
    sloped[i] = !slope.isZero(0.);
  }
  g.sloped_pairs.resize(g.pairs.size(), default_init);
#pragma omp parallel for num_threads(threads) schedule(static)
  for(std::ptrdiff_t p = 0; p < std::ptrdiff_t(g.pairs.size()); ++p) g.sloped_pairs[p] = sloped[g.pairs[p][0]] || sloped[g.pairs[p][1]];
}

// Uniform hash grid for a growing point set (the insertion's accepted candidates), where a
// k-d tree would have to be rebuilt after every insertion.
class Hash_grid_3
{
public:
  explicit Hash_grid_3(double cell) : cell_(cell) {}
  void insert(const Vec3& p, int id) { cells_[key(cell_of(p))].push_back({p, id}); }
  // calls f(point, id) for every stored point within the 27 cells around p
  template <typename F> void for_each_near(const Vec3& p, F f) const
  {
    const std::array<long, 3> c = cell_of(p);
    for(long dx = -1; dx <= 1; ++dx) for(long dy = -1; dy <= 1; ++dy) for(long dz = -1; dz <= 1; ++dz) {
      auto it = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
      if(it == cells_.end()) continue;
      for(const auto& e : it->second) f(e.first, e.second);
    }
  }

private:
  std::array<long, 3> cell_of(const Vec3& p) const
  { return { long(std::floor(p[0] / cell_)), long(std::floor(p[1] / cell_)), long(std::floor(p[2] / cell_)) }; }
  static long long key(const std::array<long, 3>& c)
  { return (static_cast<long long>(c[0]) * 73856093LL) ^ (static_cast<long long>(c[1]) * 19349663LL) ^ (static_cast<long long>(c[2]) * 83492791LL); }
  double cell_;
  std::unordered_map<long long, std::vector<std::pair<Vec3, int> > > cells_;
};

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_PARTICLE_NEIGHBORS_H
