// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_OPTIMIZE_PARTICLES_H
#define CGAL_LATTICE_MESHER_3_OPTIMIZE_PARTICLES_H

#include <CGAL/Lattice_mesher_3/Gaussian_hole_kernel_3.h>
#include <CGAL/Lattice_mesher_3/Lattice_3.h>
#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/internal/particle_neighbors.h>
#include <CGAL/Lattice_mesher_3/internal/stage_parameters.h>

#include <Eigen/Core>
#include <LBFGS.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/// What a round did.
struct Optimization_result
{
  int iterations = 0;     ///< number of L-BFGS iterations
  int restarts = 0;       ///< line-search failures recovered by restarting L-BFGS
  double energy = 0.;     ///< total GHK energy over interacting pairs, at the end
  double gradient_rms = 0.; ///< root mean square over the movable particles of the energy gradient, at the end
};

namespace internal {

// Settings of one optimization round (Alg. 1 of the paper); the defaults are the paper's.
struct Optimization_options
{
  double edge_length = 0.;          ///< l*, in the isotropic space
  double neighbor_radius = 1.3;     ///< R / l*: pairs closer than this (isotropic) interact
  double gradient_tolerance = 1e-2; ///< EpsG on the RMS particle gradient, in units of 1/l*
  int max_iterations = 13;          ///< MaxIts; 0 = until converged (at most `iteration_cap`)
  int iteration_cap = 1000;         ///< bound on a round without MaxIts, so that it always ends
  /// A round without MaxIts also ends, once its RMS gradient is within 10 x `gradient_tolerance`,
  /// when its last 50 iterations lowered the energy by less than this fraction: what is left
  /// then is a slow drift of the whole lattice, not its local order (knot1 BCC, 20k: 750 more
  /// iterations, to the cap, for 0.27 % of the energy took 47 of the 109 s, and left 386
  /// tetrahedra below 40 degrees instead of 343).
  double stall_tolerance = 3e-4;
  double boundary_distance = 0.3;   ///< particles this close (x l*) to the boundary / an edge snap to it
  /// false: a free particle that leaves the domain or comes that close to its boundary is put
  /// back inside at `boundary_distance` and stays free (a fixed number of boundary particles, as
  /// in Particle2013, whose hole-less kernel would otherwise push the interior onto the boundary)
  bool free_particles_join_boundary = true;
  int threads = 1;
};


// The settings of optimize_particles(), delete_particles(), insert_particles(),
// insert_feature_particles() and grow_particles() from their named parameters.
template <typename NamedParameters>
Optimization_options optimization_options(const NamedParameters& np, const char* stage)
{
  Optimization_options o;
  o.edge_length = required_edge_length(np, stage);
  read_parameter(np, internal_np::neighbor_radius_ratio, o.neighbor_radius);
  read_parameter(np, internal_np::gradient_tolerance, o.gradient_tolerance);
  read_parameter(np, internal_np::number_of_iterations, o.max_iterations);
  read_parameter(np, internal_np::maximum_number_of_iterations, o.iteration_cap);
  read_parameter(np, internal_np::stall_tolerance, o.stall_tolerance);
  read_parameter(np, internal_np::boundary_distance_ratio, o.boundary_distance);
  read_parameter(np, internal_np::free_particles_join_boundary, o.free_particles_join_boundary);
  read_parameter(np, internal_np::number_of_threads, o.threads);
  auto require = [&](bool ok, const char* what) {
    if(!ok) throw std::invalid_argument(std::string(stage) + "(): the named parameter " + what);
  };
  require(o.neighbor_radius > 0. && std::isfinite(o.neighbor_radius), "neighbor_radius_ratio() must be positive and finite");
  require(o.gradient_tolerance > 0. && std::isfinite(o.gradient_tolerance), "gradient_tolerance() must be positive and finite");
  require(o.max_iterations >= 0, "number_of_iterations() must be at least 0");
  require(o.iteration_cap >= 1, "maximum_number_of_iterations() must be at least 1");
  require(o.stall_tolerance >= 0., "stall_tolerance() must be at least 0");
  require(o.boundary_distance >= 0. && o.boundary_distance < 1., "boundary_distance_ratio() must be in [0, 1)");
  require(o.threads >= 1, "number_of_threads() must be at least 1");
  return o;
}


// The total GHK energy of a particle set, over a frozen neighbour graph, as a function of the
// variables U: particle i is at X0_i + M_i U_i (units of l*), with M_i = P_i T_i. T_i, the frame
// at the start, makes U isotropic: under a stretched field the physical Hessian is B^T H B,
// conditioned like the square of the stretch (6400 for fig8), while in U it is about H, so
// L-BFGS converges as for T = I. P_i keeps the motion on the constraint: 0 for a fixed
// particle, the edge tangent for a sharp-edge one, the tangent plane for a boundary one. Work
// buffers are allocated once: the evaluation itself allocates nothing.
class Particle_energy_3
{
public:
  Particle_energy_3(const Neighbor_graph& graph, const Gaussian_hole_kernel_3& kernel,
                    const std::vector<Vec3>& origin, const std::vector<Mat3>& maps, int threads)
    : graph_(graph), kernel_(kernel), origin_(origin), maps_(maps), threads_(threads),
      x_(origin.size())
  {
    const std::size_t np = graph.pairs.size();
    pair_energy_.resize(np, default_init);
    pair_gradient_.resize(np, default_init);
    pair_shared_.resize(graph.map_slopes.empty() ? 0 : np, default_init);
#pragma omp parallel for num_threads(threads) schedule(static)
    for(std::ptrdiff_t p = 0; p < std::ptrdiff_t(pair_shared_.size()); ++p) pair_shared_[p].setZero();   // pairs without slope
  }

  // positions (units of l*) of the variables U
  Vec3 position(const Eigen::VectorXd& U, std::ptrdiff_t i) const
  { return origin_[i] + maps_[i] * U.segment<3>(3 * i); }

  double operator()(const Eigen::VectorXd& U, Eigen::VectorXd& G)
  {
    const auto& slopes = graph_.map_slopes;
    const std::ptrdiff_t np = std::ptrdiff_t(graph_.pairs.size());
    const std::ptrdiff_t n = std::ptrdiff_t(graph_.number_of_particles());
#pragma omp parallel num_threads(threads_)
    {
#pragma omp for schedule(static)
      for(std::ptrdiff_t i = 0; i < n; ++i) x_[i] = position(U, i);
      // (pairs with a slope cost more, and gather where the size changes)
#pragma omp for schedule(dynamic, 2048)
      for(std::ptrdiff_t p = 0; p < np; ++p) {
        const int i = graph_.pairs[p][0], j = graph_.pairs[p][1];
        const Vec3 d = x_[i] - x_[j];
        // B = B_ij + sum_a S_a (m - m_ij)_a, m the midpoint (just B_ij without slopes)
        Mat3 B = graph_.pair_map[p];
        std::array<Mat3, 3> S;
        const bool sloped = !slopes.empty() && graph_.sloped_pairs[p];
        if(sloped) {
          const Vec3 shift = .5 * ((x_[i] - origin_[i]) + (x_[j] - origin_[j]));
          for(int a = 0; a < 3; ++a) {
            S[a] = .5 * (slopes[i][a] + slopes[j][a]);
            B += shift[a] * S[a];
          }
        }
        Vec3 f;
        pair_energy_[p] = kernel_.energy_and_force(B * d, f);
        pair_gradient_[p] = -(B.transpose() * f);   // dE_ij/dX_i, and minus dE_ij/dX_j ...
        // ... but for the share of B's motion they have in common: half of g . S_a d, g = -f
        if(sloped) for(int a = 0; a < 3; ++a) pair_shared_[p][a] = -.5 * f.dot(S[a] * d);
      }
#pragma omp for schedule(static)
      for(std::ptrdiff_t i = 0; i < n; ++i) {
        Vec3 g = Vec3::Zero();
        for(int e = graph_.offsets[i]; e < graph_.offsets[i + 1]; ++e) {
          const int p = graph_.pair_of[e];
          if(graph_.pairs[p][0] == i) g += pair_gradient_[p];
          else g -= pair_gradient_[p];
          if(!slopes.empty()) g += pair_shared_[p];
        }
        G.segment<3>(3 * i) = maps_[i].transpose() * g;
      }
    }
    // serial sum: the same energy for any number of threads
    double e = 0.;
    for(double pe : pair_energy_) e += pe;
    if(e < best_energy_) { best_energy_ = e; best_U_ = U; }
    return e;
  }

  double best_energy() const { return best_energy_; }
  const Eigen::VectorXd& best_point() const { return best_U_; }

private:
  const Neighbor_graph& graph_;
  const Gaussian_hole_kernel_3& kernel_;
  const std::vector<Vec3>& origin_;
  const std::vector<Mat3>& maps_;
  int threads_;
  std::vector<Vec3> x_;
  Unzeroed_vector<double> pair_energy_;
  Unzeroed_vector<Vec3> pair_gradient_, pair_shared_;
  double best_energy_ = std::numeric_limits<double>::infinity();
  Eigen::VectorXd best_U_;
};

// The maps M_i = P_i T_i of Particle_energy_3: P_i projects on the constraint of particle i
// (its edge tangent, its tangent plane; 0 if fixed).
template <typename Domain, typename Point_3>
std::vector<Mat3> motion_maps(const Particle_set_3<Point_3>& ps, const Domain& domain, const Particle_frames& frames,
                              int threads)
{
  std::vector<Mat3> m(ps.size());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 256)
  for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(ps.size()); ++i) {
    Mat3 p = Mat3::Identity();
    switch(ps.kinds[i]) {
      case Particle_kind::FIXED: p.setZero(); break;
      case Particle_kind::SHARP_EDGE: {
        const Vec3 d = to_eigen(domain.project_on_curve(ps.points[i], std::size_t(ps.feature[i])).direction);
        p = d * d.transpose();
        break;
      }
      case Particle_kind::BOUNDARY: {
        const Vec3 d = to_eigen(domain.project_on_surface(ps.points[i]).direction);
        p -= d * d.transpose();
        break;
      }
      case Particle_kind::FREE: break;
    }
    m[i] = p * frames.T[i];
  }
  return m;
}

// Alg. 1, lines 14-21: see snap_particles_to_boundary().
template <typename Domain, typename FrameField, typename Point_3>
std::size_t snap_particles_to_boundary(Particle_set_3<Point_3>& ps, const Domain& domain,
                                       const FrameField& field, const Optimization_options& o)
{

  const double threshold = o.boundary_distance * o.edge_length;
  const bool has_features = domain.number_of_curves() > 0;
  std::size_t changed = 0;
#pragma omp parallel for num_threads(o.threads) schedule(dynamic, 256) reduction(+:changed)
  for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(ps.size()); ++i) {
    Point_3& p = ps.points[i];
    Particle_kind& kind = ps.kinds[i];
    if(kind == Particle_kind::FIXED) continue;
    if(kind == Particle_kind::SHARP_EDGE) { p = domain.project_on_curve(p, std::size_t(ps.feature[i])).point; continue; }
    const Eigen::Matrix3d T = field.frame(p), B = isotropic_map(T, p);
    // a free particle deep inside by the domain's cheap bound (|B d| >= |d| / |T|) stays
    if(kind == Particle_kind::FREE && domain.inside_distance_bound(p) > threshold * T.norm()) continue;
    const auto s = domain.project_on_surface(p);
    if(kind == Particle_kind::FREE) {
      auto clearance = [&](const Point_3& q, const decltype(s)& sq) {   // isotropic; -1 outside
        return domain.is_inside(q) ? (B * (to_eigen(q) - to_eigen(sq.point))).norm() : -1.;
      };
      if(clearance(p, s) > threshold) continue;
      if(!o.free_particles_join_boundary) {
        // back inside along the inward normal; next to an edge or a corner that may land on
        // the next face, whose normal the next step follows
        auto t = s;
        for(int step = 0; step < 3 && (step == 0 || clearance(p, t) < 0.999 * threshold); ++step) {
          const Vec3 n = to_eigen(t.direction);
          const Vec3 q = to_eigen(t.point) - n * (threshold / (std::max)((B * n).norm(), 1e-300));
          p = Point_3(q[0], q[1], q[2]);
          t = domain.project_on_surface(p);
        }
        continue;
      }
      kind = Particle_kind::BOUNDARY;
      ++changed;
    }
    p = s.point;
    if(has_features) {
      const auto c = domain.project_on_features(p);
      if(c.index >= 0 && (B * (to_eigen(p) - to_eigen(c.point))).norm() <= threshold) {
        p = c.point;
        kind = Particle_kind::SHARP_EDGE;
        ps.feature[i] = c.index;
        ++changed;
      }
    }
  }
  return changed;
}

// One round of Alg. 1: see optimize_particles().
template <typename Domain, typename FrameField, typename Point_3>
Optimization_result optimize_particles_round(Particle_set_3<Point_3>& ps, const Domain& domain,
                                             const FrameField& field, const Lattice_3& lattice,
                                             const Optimization_options& o)
{
  typedef typename Domain::Geom_traits K;

  if(!(o.edge_length > 0.) || !std::isfinite(o.edge_length))
    throw std::invalid_argument("optimize_particles_round(): the edge length must be positive and finite");

  Optimization_result result;
  const Gaussian_hole_kernel_3 kernel(lattice);
  const std::size_t n = ps.size();
  if(n < 2) return result;

  const int chunk = 50;
  int remaining = o.max_iterations > 0 ? o.max_iterations : o.iteration_cap;
  std::size_t movable = 0;
  for(Particle_kind k : ps.kinds) movable += (k != Particle_kind::FIXED);
  const double tolerance = o.gradient_tolerance * std::sqrt(double((std::max)(movable, std::size_t(1))));

  // Each rebuild freezes B anew: under a varying field the energy of a chunk is not the one of
  // the previous, and the rebuilt graphs' minima may drift (fig8 FCC: 1,000 iterations with the
  // energy rising). Chunks stop, keeping the better positions, once one no longer lowers it
  // (by `stall_tolerance`).
  std::vector<Point_3> previous_points;
  double previous_energy = std::numeric_limits<double>::infinity();
  while(remaining > 0) {
    std::vector<Vec3> x = to_vectors(ps.points);
    const Particle_frames frames = compute_particle_frames<K>(x, field, o.threads);
    Neighbor_graph graph =
      build_neighbor_graph<K>(x, frames, field, o.neighbor_radius * o.edge_length, o.threads);
    const std::vector<Mat3> maps = motion_maps(ps, domain, frames, o.threads);
    for(Vec3& p : x) p /= o.edge_length;
    estimate_map_slopes(graph, x, frames.B, o.threads);
    Particle_energy_3 energy(graph, kernel, x, maps, o.threads);
    Eigen::VectorXd X = Eigen::VectorXd::Zero(3 * n);   // the variables U, from the start

    LBFGSpp::LBFGSParam<double> param;
    param.epsilon = tolerance;
    param.epsilon_rel = 0.;
    param.max_iterations = (std::min)(remaining, o.max_iterations > 0 ? o.max_iterations : chunk);
    param.linesearch = LBFGSpp::LBFGS_LINESEARCH_BACKTRACKING_STRONG_WOLFE;
    param.max_linesearch = 40;
    bool converged = false;
    for(int attempt = 0; attempt < 3 && param.max_iterations > 0; ++attempt) {
      LBFGSpp::LBFGSSolver<double, LBFGSpp::LineSearchNocedalWright> solver(param);
      double fx = 0.;
      try {
        const int its = solver.minimize(energy, X, fx);
        result.iterations += its;
        remaining -= its;
        converged = its < param.max_iterations;
        break;
      } catch(const std::exception&) {
        // line search stalled (flat or noisy energy): restart from the best point seen
        ++result.restarts;
        X = energy.best_point();
        result.iterations += 1;
        remaining -= 1;
        param.max_iterations = (std::min)(param.max_iterations, remaining);
      }
    }
    if(!X.allFinite()) { X = energy.best_point(); converged = true; }
    if(energy.best_point().size() == X.size() && energy.best_energy() < std::numeric_limits<double>::infinity()) {
      Eigen::VectorXd G(3 * n);
      const double e_end = energy(X, G);
      if(energy.best_energy() < e_end) { X = energy.best_point(); }
      result.energy = (std::min)(e_end, energy.best_energy());
      result.gradient_rms = G.norm() / std::sqrt(double((std::max)(movable, std::size_t(1))));
    }
    for(std::size_t i = 0; i < n; ++i) {
      const Vec3 p = energy.position(X, std::ptrdiff_t(i)) * o.edge_length;
      ps.points[i] = Point_3(p[0], p[1], p[2]);
    }
#ifdef CGAL_LATTICE_MESHER_3_VERBOSE
    std::cerr << "  chunk: " << result.iterations << " its, E " << result.energy << ", rms gradient " << result.gradient_rms
              << ", restarts " << result.restarts << (converged ? " (converged)" : "") << "\n";
#endif
    if(converged || o.max_iterations > 0) break;
    if(result.energy > previous_energy) { ps.points = previous_points; result.energy = previous_energy; break; }
    if(result.gradient_rms < 10. * o.gradient_tolerance &&
       result.energy > previous_energy - o.stall_tolerance * std::abs(previous_energy)) break;
    previous_points = ps.points;
    previous_energy = result.energy;
  }
  internal::snap_particles_to_boundary(ps, domain, field, o);
  return result;
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Optimizer

Snaps particles to their constraints, as each optimization round ends (Alg. 1, lines 14-21): a
free particle outside the domain, or inside within `boundary_distance_ratio` x l* of the
boundary (measured in the isotropic space of the field), is projected on the boundary and
becomes a boundary particle (or, without `free_particles_join_boundary`, is put back inside at
that distance along the inward normal); a boundary particle that close to a sharp edge is
projected on it and becomes a sharp-edge particle. Boundary and sharp-edge particles, which slid
along tangent planes and lines, are put back on their surface and curve.

\tparam Domain a model of `LatticeMeshDomain_3`
\tparam FrameField a model of `FrameField_3`

\cgalNamedParamsBegin
  \cgalParamNBegin{edge_length}
    \cgalParamDescription{l*, the lattice cube edge in the isotropic space of the field}
    \cgalParamType{double}
    \cgalParamExtra{required}
  \cgalParamNEnd
  \cgalParamNBegin{boundary_distance_ratio}
    \cgalParamDescription{particles closer than this times l* to the boundary, or to a sharp edge, snap to it}
    \cgalParamType{double, in [0, 1)}
    \cgalParamDefault{0.3}
  \cgalParamNEnd
  \cgalParamNBegin{free_particles_join_boundary}
    \cgalParamDescription{whether a free particle that leaves the domain or comes that close to its
      boundary becomes a boundary particle; `false` puts it back inside and keeps the number of
      boundary particles (Particle2013, whose hole-less kernel would push the interior onto the boundary)}
    \cgalParamType{bool}
    \cgalParamDefault{true}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of particles that changed kind
\throws std::invalid_argument naming the named parameter that is missing or out of range
*/
template <typename Domain, typename FrameField, typename Point_3,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t snap_particles_to_boundary(Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                                       const NamedParameters& np = parameters::default_values())
{
  return internal::snap_particles_to_boundary(ps, domain, field,
                                              internal::optimization_options(np, "snap_particles_to_boundary"));
}

/*!
\ingroup PkgLatticeMesher3Optimizer

One optimization round (Alg. 1): minimizes the GHK energy of the particles with L-BFGS (LBFGS++)
over the pairs within `neighbor_radius_ratio` x l* in the isotropic space. Each pair's map is B
at its midpoint, to first order during the round (B((p_i + p_j)/2) at the start, and the slope
of B estimated from the particles' maps), so that L-BFGS sees a smooth energy and its exact
gradient, and its minimum is the lattice of the isotropic coordinates where the field varies.
Stops when the RMS gradient (in units of 1/l*) is below `gradient_tolerance`, or after
`number_of_iterations`; without an iteration limit the neighbour graph is rebuilt every 50
iterations so that pairs coming into range are not missed. A line-search failure restarts
L-BFGS from the best point seen. Ends with `snap_particles_to_boundary()`.
`Lattice_particle_mesher_3` calls it with these defaults, except that the closing round of the
finest level runs to `final_gradient_tolerance` without an iteration limit.

\tparam Domain a model of `LatticeMeshDomain_3`
\tparam FrameField a model of `FrameField_3`

\cgalNamedParamsBegin
  \cgalParamNBegin{edge_length}
    \cgalParamDescription{l*, the lattice cube edge in the isotropic space of the field}
    \cgalParamType{double}
    \cgalParamExtra{required}
  \cgalParamNEnd
  \cgalParamNBegin{lattice}
    \cgalParamDescription{the lattice whose one-ring the kernel's holes sit at}
    \cgalParamType{`Lattice_type`}
    \cgalParamDefault{`Lattice_type::BCC`}
  \cgalParamNEnd
  \cgalParamNBegin{sigma_ratio}
    \cgalParamDescription{sigma / l_closest of the kernel}
    \cgalParamType{double}
    \cgalParamDefault{0.3}
  \cgalParamNEnd
  \cgalParamNBegin{neighbor_radius_ratio}
    \cgalParamDescription{R / l*: pairs closer than R in the isotropic space interact}
    \cgalParamType{double}
    \cgalParamDefault{1.3}
  \cgalParamNEnd
  \cgalParamNBegin{gradient_tolerance}
    \cgalParamDescription{EpsG on the RMS particle gradient, in units of 1/l*}
    \cgalParamType{double}
    \cgalParamDefault{0.01}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{MaxIts; 0 runs until converged (at most `maximum_number_of_iterations`)}
    \cgalParamType{int}
    \cgalParamDefault{13}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_number_of_iterations}
    \cgalParamDescription{the bound on a round without MaxIts, so that it always ends}
    \cgalParamType{int}
    \cgalParamDefault{1000}
  \cgalParamNEnd
  \cgalParamNBegin{stall_tolerance}
    \cgalParamDescription{a round without MaxIts also ends, once its RMS gradient is within 10 times
      `gradient_tolerance`, when its last 50 iterations lowered the energy by less than this fraction:
      what is left then is a slow drift of the whole lattice, not its local order}
    \cgalParamType{double}
    \cgalParamDefault{3e-4}
  \cgalParamNEnd
  \cgalParamNBegin{boundary_distance_ratio}
    \cgalParamDescription{as for `snap_particles_to_boundary()`}
    \cgalParamDefault{0.3}
  \cgalParamNEnd
  \cgalParamNBegin{free_particles_join_boundary}
    \cgalParamDescription{as for `snap_particles_to_boundary()`}
    \cgalParamDefault{true}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{OpenMP threads}
    \cgalParamType{int}
    \cgalParamDefault{1}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument naming the named parameter that is missing or out of range
*/
template <typename Domain, typename FrameField, typename Point_3,
          typename NamedParameters = parameters::Default_named_parameters>
Optimization_result optimize_particles(Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                                       const NamedParameters& np = parameters::default_values())
{
  return internal::optimize_particles_round(ps, domain, field, internal::stage_lattice(np),
                                            internal::optimization_options(np, "optimize_particles"));
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_OPTIMIZE_PARTICLES_H
