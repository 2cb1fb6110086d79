// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_INSERT_DELETE_PARTICLES_H
#define CGAL_LATTICE_MESHER_3_INSERT_DELETE_PARTICLES_H

#include <CGAL/Lattice_mesher_3/Gaussian_hole_kernel_3.h>
#include <CGAL/Lattice_mesher_3/Lattice_3.h>
#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/optimize_particles.h>
#include <CGAL/Lattice_mesher_3/internal/particle_neighbors.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

namespace internal {

// see delete_particles()
template <typename Domain, typename FrameField, typename Point_3>
std::size_t delete_particles(Particle_set_3<Point_3>& ps, const Domain& /*domain*/, const FrameField& field,
                             const Lattice_3& lattice, const Optimization_options& o)
{
  typedef typename Domain::Geom_traits K;
  using internal::Vec3;
  const std::size_t n = ps.size();
  if(n < 2) return 0;
  const double lc = lattice.closest_distance * o.edge_length;
  const double radius = o.neighbor_radius * o.edge_length;
  const std::vector<Vec3> x = internal::to_vectors(ps.points);
  const internal::Particle_frames frames = internal::compute_particle_frames<K>(x, field, o.threads);
  const internal::Neighbor_graph graph = internal::build_neighbor_graph<K>(x, frames, field, radius, o.threads);

  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ps.kinds[a] > ps.kinds[b]; });

  // each particle's neighbours by ascending isotropic distance, sorted by all threads: the
  // deletions, one after the other, only skip those already deleted
  struct Neighbor { double distance; int index; };   // (uninitialized: written by all threads)
  internal::Unzeroed_vector<Neighbor> nearest;
  nearest.resize(graph.neighbor.size(), internal::default_init);
#pragma omp parallel for num_threads(o.threads) schedule(static)
  for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(n); ++i) {
    for(int e = graph.offsets[i]; e < graph.offsets[i + 1]; ++e) {
      const int j = graph.neighbor[e];
      nearest[e] = { (graph.pair_map[graph.pair_of[e]] * (x[i] - x[j])).norm(), j };
    }
    std::sort(nearest.begin() + graph.offsets[i], nearest.begin() + graph.offsets[i + 1],
              [](const Neighbor& a, const Neighbor& b) { return a.distance < b.distance || (a.distance == b.distance && a.index < b.index); });
  }

  static const int counts[5] = { 1, 2, 4, 6, 8 };
  static const double factors[5] = { 0.5, 0.75, 0.85, 0.9, 0.95 };
  std::vector<char> alive(n, 1);
  std::vector<double> d;
  std::size_t deleted = 0;
  for(std::size_t i : order) {
    if(ps.kinds[i] == Particle_kind::FIXED) continue;
    d.clear();
    for(int e = graph.offsets[i]; e < graph.offsets[i + 1] && d.size() < 8; ++e)
      if(alive[nearest[e].index]) d.push_back(nearest[e].distance);
    if(d.size() < 8) d.resize(8, radius);   // (the neighbours are within the radius)
    double sum = 0.;
    int k = 0;
    for(int r = 0; r < 5; ++r) {
      for(; k < counts[r]; ++k) sum += d[k];
      if(sum / counts[r] < factors[r] * lc) { alive[i] = 0; ++deleted; break; }
    }
  }
  if(deleted > 0) {
    Particle_set_3<Point_3> kept;
    for(std::size_t i = 0; i < n; ++i)
      if(alive[i]) kept.push_back(ps.points[i], ps.kinds[i], ps.feature[i]);
    ps = std::move(kept);
  }
  return deleted;
}


// Candidates p_i + T(p_i) l O_k for the given offsets O_k (unit cube) and the particles i from
// `first_source` on, projected on the boundary when outside, minus those within 0.1 l of a
// particle or of an earlier candidate; accepted in ascending GHK energy while no particle
// (accepted ones included) is closer than min_distance.
template <typename Domain, typename FrameField, typename Point_3>
std::size_t insert_candidates(Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                              const Lattice_3& lattice, const std::vector<Eigen::Vector3d>& offsets,
                              double min_distance, const Optimization_options& o, std::size_t first_source = 0)
{
  typedef typename Domain::Geom_traits K;
  using internal::Vec3;
  using internal::Mat3;
  const std::size_t n = ps.size();
  if(n == 0) return 0;
  const double l = o.edge_length;
  const double coincidence = 0.1 * l;
  const double snap = o.boundary_distance * l;
  const bool has_features = domain.number_of_curves() > 0;
  const Gaussian_hole_kernel_3 kernel(lattice);

  const std::vector<Vec3> x = internal::to_vectors(ps.points);
  const internal::Particle_frames frames = internal::compute_particle_frames<K>(x, field, o.threads);
  const internal::Point_search_3<K> search(x);
  const double reach = 1.1 * frames.max_stretch;   // Euclidean radius per unit isotropic radius (grids)

  // only the candidates that may be accepted are kept (a few percent), each with its index
  struct Candidate { std::size_t index; Point_3 p; Particle_kind kind; int feature; double energy; Mat3 B; };
  const std::size_t m = offsets.size();
  const std::size_t sources = n - (std::min)(first_source, n);
  std::vector<Candidate> cand;
  const double block = (std::max)(min_distance, coincidence);
  double offset_radius = 0.;
  for(const Eigen::Vector3d& off : offsets) offset_radius = (std::max)(offset_radius, off.norm());
  // A bound of each particle's distance to the boundary: a candidate closer to its particle
  // than that is inside without an inside test (the ball around an inside point up to the
  // surface is inside).
  std::vector<double> clearance(n, 0.);
#pragma omp parallel for num_threads(o.threads) schedule(static)
  for(std::ptrdiff_t i = std::ptrdiff_t(n - sources); i < std::ptrdiff_t(n); ++i)
    if(ps.kinds[i] == Particle_kind::FREE) clearance[i] = domain.inside_distance_bound(ps.points[i]);
  bool failed = false;
  std::string what;
#pragma omp parallel num_threads(o.threads)
  {
    std::vector<std::size_t> near, around;
    std::vector<Candidate> kept;
    std::ptrdiff_t around_of = -1;
    // a source's candidates inside cost little, on the boundary their projections: chunks of
    // whole sources, taken as threads free up
#pragma omp for schedule(dynamic, 32 * (std::max)(int(m), 1))
    for(std::ptrdiff_t c = 0; c < std::ptrdiff_t(sources * m); ++c) {
      Candidate cd;
      cd.index = std::size_t(c);
      try {
        const std::size_t i = n - sources + std::size_t(c) / m, k = std::size_t(c) % m;
        // the lattice offset in the frame at the candidate's midpoint with i: under a varying
        // field, i's own frame would put the candidates on its side of a gradient too far apart
        Vec3 q = x[i] + l * (frames.T[i] * offsets[k]);
        const Vec3 mid = .5 * (x[i] + q);
        q = x[i] + l * (field.frame(Point_3(mid[0], mid[1], mid[2])) * offsets[k]);
        // Most candidates fall on a particle (the lattice around i is already there): drop them
        // with i's neighbours, one search per particle, before any per-candidate search.
        if(around_of != std::ptrdiff_t(i)) {
          around.clear();
          internal::search_isotropic_ball(search, x[i], frames.T[i], offset_radius * l + block, frames.max_stretch, around);
          around_of = std::ptrdiff_t(i);
        }
        // inside without a test when within the clearance of i or of a particle occupying it
        bool occupied = false, inside = (q - x[i]).norm() < clearance[i];
        for(std::size_t j : around)
          if((frames.B[i] * (q - x[j])).norm() < block) {
            occupied = true;
            inside = inside || (q - x[j]).norm() < clearance[j];
            if(inside) break;
          }
        Point_3 p(q[0], q[1], q[2]);
        inside = inside || domain.is_inside(p);
        if(occupied && inside) continue;
        cd.kind = Particle_kind::FREE;
        cd.feature = -1;
        if(!inside) {
          p = domain.project_on_surface(p).point;
          cd.kind = Particle_kind::BOUNDARY;
          if(has_features) {
            const auto f = domain.project_on_features(p);
            const Mat3 Bp = internal::isotropic_map(field.frame(p), p);
            if(f.index >= 0 && (Bp * (internal::to_eigen(p) - internal::to_eigen(f.point))).norm() <= snap) {
              p = f.point;
              cd.kind = Particle_kind::SHARP_EDGE;
              cd.feature = f.index;
            }
          }
          q = internal::to_eigen(p);
        }
        cd.p = p;
        const Mat3 T = field.frame(p);
        cd.B = internal::isotropic_map(T, p);
        // a candidate that can never be accepted is dropped before its energy is computed; most
        // that were projected on the boundary fall on a neighbour of i: no search for them
        bool blocked = false;
        for(std::size_t j : around) if((cd.B * (q - x[j])).norm() < block) { blocked = true; break; }
        if(blocked) continue;
        near.clear();
        internal::search_isotropic_ball(search, q, T, (std::max)(min_distance, kernel.support_radius() * l),
                                        frames.max_stretch, near);
        double e = 0.;
        for(std::size_t j : near) {
          const Vec3 v = cd.B * (q - x[j]);
          if(v.norm() < block) { blocked = true; break; }
          e += kernel.energy(v / l);
        }
        cd.energy = e;
        if(!blocked) kept.push_back(cd);
      } catch(const std::exception& ex) {
#pragma omp critical(lattice_mesher_3_insert)
        { if(!failed) { failed = true; what = ex.what(); } }
      }
    }
#pragma omp critical(lattice_mesher_3_insert)
    cand.insert(cand.end(), kept.begin(), kept.end());
  }
  if(failed) throw std::domain_error(what);
  std::sort(cand.begin(), cand.end(), [](const Candidate& a, const Candidate& b) { return a.index < b.index; });

  // Coincident candidates: keep the first of each 0.1 l* cluster (deterministic order).
  internal::Hash_grid_3 seen(coincidence * reach);
  std::vector<std::size_t> order;
  for(std::size_t c = 0; c < cand.size(); ++c) {
    const Vec3 q = internal::to_eigen(cand[c].p);
    bool dup = false;
    seen.for_each_near(q, [&](const Vec3& r, int) { if((cand[c].B * (q - r)).norm() < coincidence) dup = true; });
    if(dup) continue;
    seen.insert(q, int(c));
    order.push_back(c);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cand[a].energy < cand[b].energy; });

  internal::Hash_grid_3 accepted(min_distance * reach);
  std::size_t inserted = 0;
  for(std::size_t c : order) {
    const Vec3 q = internal::to_eigen(cand[c].p);
    bool blocked = false;
    accepted.for_each_near(q, [&](const Vec3& r, int) { if((cand[c].B * (q - r)).norm() < min_distance) blocked = true; });
    if(blocked) continue;
    accepted.insert(q, int(c));
    ps.push_back(cand[c].p, cand[c].kind, cand[c].feature);
    ++inserted;
  }
  return inserted;
}


// see insert_particles()
template <typename Domain, typename FrameField, typename Point_3>
std::size_t insert_particles(Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                             const Lattice_3& lattice, const Optimization_options& o)
{
  return internal::insert_candidates(ps, domain, field, lattice, lattice.one_ring,
                                     0.75 * lattice.closest_distance * o.edge_length, o);
}

// see insert_feature_particles()
template <typename Domain, typename FrameField, typename Point_3>
std::size_t insert_feature_particles(Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                                     const Lattice_3& lattice, const Optimization_options& o)
{
  typedef typename Domain::Geom_traits K;
  using internal::Vec3;
  using internal::Mat3;
  const std::size_t n = ps.size();
  if(n == 0 || domain.number_of_curves() == 0) return 0;
  const double l = o.edge_length, lc = lattice.closest_distance * l;
  const std::vector<Vec3> x = internal::to_vectors(ps.points);
  const internal::Particle_frames frames = internal::compute_particle_frames<K>(x, field, o.threads);
  const internal::Point_search_3<K> search(x);
  internal::Hash_grid_3 accepted(0.75 * lc * 1.1 * frames.max_stretch);
  std::vector<std::size_t> near;
  std::size_t inserted = 0;
  for(std::size_t i = 0; i < n; ++i) {
    if(ps.kinds[i] != Particle_kind::SHARP_EDGE) continue;
    const std::size_t curve = std::size_t(ps.feature[i]);
    const Vec3 d = internal::to_eigen(domain.project_on_curve(ps.points[i], curve).direction);
    const double step = l / (frames.B[i] * d).norm();
    for(double sign : { -1., 1. }) {
      const Vec3 q0 = x[i] + sign * step * d;
      const Point_3 p = domain.project_on_curve(Point_3(q0[0], q0[1], q0[2]), curve).point;
      const Vec3 q = internal::to_eigen(p);
      const Mat3 b = internal::isotropic_map(field.frame(p), p);
      near.clear();
      internal::search_isotropic_ball(search, q, b.inverse(), 0.75 * lc, frames.max_stretch, near);
      bool blocked = false;
      for(std::size_t j : near) {
        const double dist = (b * (q - x[j])).norm();
        blocked = blocked || dist < 0.5 * lc ||
                  (dist < 0.75 * lc && (ps.kinds[j] == Particle_kind::SHARP_EDGE || ps.kinds[j] == Particle_kind::FIXED));
      }
      accepted.for_each_near(q, [&](const Vec3& r, int) { blocked = blocked || (b * (q - r)).norm() < 0.75 * lc; });
      if(blocked) continue;
      accepted.insert(q, int(i));
      ps.push_back(p, Particle_kind::SHARP_EDGE, int(curve));
      ++inserted;
    }
  }
  return inserted;
}

// see grow_particles()
template <typename Domain, typename FrameField, typename Point_3>
std::size_t grow_particles(Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                           const Lattice_3& lattice, const Optimization_options& o)
{
  // only the particles of the last shell have free one-ring positions: they are the sources
  const double min_distance = 0.75 * lattice.closest_distance * o.edge_length;
  std::size_t total = 0, front = 0;
  for(;;) {
    const std::size_t before = ps.size();
    const std::size_t inserted = internal::insert_candidates(ps, domain, field, lattice, lattice.one_ring, min_distance, o, front);
    if(inserted == 0) break;
    total += inserted;
    front = before;
    internal::optimize_particles_round(ps, domain, field, lattice, o);
  }
  return total;
}
} // namespace internal

/*!
\ingroup PkgLatticeMesher3InsertionDeletion

Mesh-free particle deletion (Alg. 2): with D the ascending isotropic distances from a particle
to its neighbours and l_c = l_closest, the particle is deleted if D[0] < 0.5 l_c, or the mean of
D[0..1] < 0.75 l_c, of D[0..3] < 0.85 l_c, of D[0..5] < 0.9 l_c, or of D[0..7] < 0.95 l_c.
Decisions are sequential against the particles that remain, so of a too-close pair only one goes;
the least constrained go first (free, then boundary, then sharp-edge); fixed particles stay.
Distances beyond the search radius count as that radius. Returns the number deleted.

\tparam Domain a model of `LatticeMeshDomain_3`
\tparam FrameField a model of `FrameField_3`

The named parameters are those of `optimize_particles()`, with its defaults; deletion reads
`edge_length` (required), `lattice`, `neighbor_radius_ratio` and `number_of_threads`.

\throws std::invalid_argument naming the named parameter that is missing or out of range
*/
template <typename Domain, typename FrameField, typename Point_3,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t delete_particles(Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                             const NamedParameters& np = parameters::default_values())
{
  return internal::delete_particles(ps, domain, field, internal::stage_lattice(np), internal::optimization_options(np, "delete_particles"));
}

/*!
\ingroup PkgLatticeMesher3InsertionDeletion

Mesh-free particle insertion (Alg. 2): the candidates are the one-ring positions
p_i + T(p_i) l* O_k of every particle; a candidate outside the domain is projected on the
boundary (and on a sharp edge if it lands within `boundary_distance_ratio` x l* of one). Candidates
within 0.1 l* of a particle or of an earlier candidate are dropped, the rest are sorted by the
GHK energy a particle would have there, and accepted greedily when their nearest particle,
accepted candidates included, is at least 0.75 l_closest away (all distances isotropic).
Returns the number inserted.

\tparam Domain a model of `LatticeMeshDomain_3`
\tparam FrameField a model of `FrameField_3`

The named parameters are those of `optimize_particles()`, with its defaults; insertion reads
`edge_length` (required), `lattice`, `sigma_ratio` (the candidates are ranked by the kernel's
energy), `neighbor_radius_ratio`, `boundary_distance_ratio` and `number_of_threads`.

\throws std::invalid_argument naming the named parameter that is missing or out of range
*/
template <typename Domain, typename FrameField, typename Point_3,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t insert_particles(Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                             const NamedParameters& np = parameters::default_values())
{
  return internal::insert_particles(ps, domain, field, internal::stage_lattice(np), internal::optimization_options(np, "insert_particles"));
}

/*!
\ingroup PkgLatticeMesher3InsertionDeletion

Coarse-to-fine refinement: the insertion of `insert_particles()` at the new (finer) edge length
l* = `edge_length`, every particle p adding its one-ring p + T(p) l* O_k. From a lattice of edge
2 l*, these are the points of the lattice of edge l*. The paper adds p +- l* T(p) t_m along the
frame axes instead, which gives only the simple cubic part of the finer lattice (half of BCC's
points, a quarter of FCC's), the rest being inserted only after another round at l* (fandisk
BCC, 18,000 vertices: 5,358 then, 731 now). Returns the number added.

\tparam Domain a model of `LatticeMeshDomain_3`
\tparam FrameField a model of `FrameField_3`

The named parameters are those of `insert_particles()`.

\throws std::invalid_argument naming the named parameter that is missing or out of range
*/
template <typename Domain, typename FrameField, typename Point_3,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t refine_particles(Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                             const NamedParameters& np = parameters::default_values())
{
  return internal::insert_particles(ps, domain, field, internal::stage_lattice(np), internal::optimization_options(np, "refine_particles"));
}

/*!
\ingroup PkgLatticeMesher3InsertionDeletion

Fills gaps along the sharp curves: for every sharp-edge particle, the points one l* away
(isotropic) along its curve, both ways, projected on the curve, become sharp-edge particles
unless a sharp-edge or fixed particle lies within 0.75 l_c of them, or any particle within 0.5 l_c.
Where the lattice is offset by half a cell from a curve, the face particles beside it stand
0.6 l_c from its points: the one-ring insertion, blocked at 0.75 l_c, leaves the curve bare over
several cells, and the tetrahedralization cuts the corner (fig9 BCC: a notch 0.66 long). The
next deletion then removes the crowded face particles. Returns the number inserted.

\tparam Domain a model of `LatticeMeshDomain_3`
\tparam FrameField a model of `FrameField_3`

The named parameters are those of `optimize_particles()`, with its defaults; this stage reads
`edge_length` (required), `lattice` and `number_of_threads`.

\throws std::invalid_argument naming the named parameter that is missing or out of range
*/
template <typename Domain, typename FrameField, typename Point_3,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t insert_feature_particles(Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                                     const NamedParameters& np = parameters::default_values())
{
  return internal::insert_feature_particles(ps, domain, field, internal::stage_lattice(np), internal::optimization_options(np, "insert_feature_particles"));
}

/*!
\ingroup PkgLatticeMesher3InsertionDeletion

Grows a particle set by rounds of `insert_particles()`, each followed by an optimization round of
`number_of_iterations` L-BFGS iterations (`optimize_particles()`), until a round inserts
nothing. From a single particle this lays one lattice grain that follows the field shell after
shell; particles placed at random instead nucleate many grains, whose offsets mismatch where
they meet (under fig8's field, 5 lattice cells across: grain boundaries all along the faces).
Returns the number inserted.

\tparam Domain a model of `LatticeMeshDomain_3`
\tparam FrameField a model of `FrameField_3`

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{L-BFGS iterations after each insertion}
    \cgalParamType{int}
    \cgalParamDefault{5}
  \cgalParamNEnd
\cgalNamedParamsEnd
The other named parameters are those of `optimize_particles()`, for the insertions and the rounds.

\throws std::invalid_argument naming the named parameter that is missing or out of range
*/
template <typename Domain, typename FrameField, typename Point_3,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t grow_particles(Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                           const NamedParameters& np = parameters::default_values())
{
  internal::Optimization_options o = internal::optimization_options(np, "grow_particles");
  o.max_iterations = parameters::choose_parameter(parameters::get_parameter(np, internal_np::number_of_iterations), 5);
  return internal::grow_particles(ps, domain, field, internal::stage_lattice(np), o);
}


} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INSERT_DELETE_PARTICLES_H
