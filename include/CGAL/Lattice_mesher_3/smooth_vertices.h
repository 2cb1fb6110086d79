// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_SMOOTH_VERTICES_H
#define CGAL_LATTICE_MESHER_3_SMOOTH_VERTICES_H

#include <CGAL/Lattice_mesher_3/Lattice_3.h>
#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>
#include <CGAL/Lattice_mesher_3/internal/stage_parameters.h>

#include <CGAL/enum.h>
#include <CGAL/Kernel/global_functions_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <iostream>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

namespace internal {

// Settings of smooth_vertices().
struct Smoothing_options
{
  /// Vertices of tetrahedra whose smallest dihedral angle (isotropic space, degrees) is below
  /// this, lattice tetrahedra (`lattice`) excepted, are moved; the others stay where the
  /// optimization put them.
  double select_angle = 55.;
  /// Moves lower the sum over a star of (target_angle - smallest angle)^2 over its tetrahedra
  /// below the target (70: about the regular tetrahedron's 70.5, so that every tetrahedron is
  /// pulled up) ...
  double target_angle = 70.;
  /// ... plus worst_weight x (worst_angle - smallest angle)^2 below worst_angle: with the
  /// first term alone, moves trade the worst tetrahedra for the mean (fig9 FCC: 356 tetrahedra
  /// below 40 degrees, 267 with it) ...
  double worst_angle = 50.;
  double worst_weight = 4.;
  /// ... plus the square of (target_radius_ratio - radius ratio) x radius_ratio_weight (degrees
  /// per unit) below that target, since angles alone leave tetrahedra with short edges ...
  double target_radius_ratio = 0.9;
  double radius_ratio_weight = 50.;
  /// ... and never lower the star's smallest angle below this (or its current value if lower),
  /// nor add a tetrahedron below it to the star (unless the star has one below half of it).
  double floor_angle = 40.;
  /// The lattice the vertices follow and its cube edge l*. A tetrahedron whose six edges
  /// (isotropic space) all lie within lattice_tolerance x l* of a lattice vector (a one-ring
  /// offset or the sum of two) and whose smallest angle is at least the floor is a lattice
  /// tetrahedron, and is not selected. Besides the lattice's own, these are the half pyramids
  /// between a wall on a lattice plane and the first layer (BCC: 45 degrees), the best there:
  /// moving their apex pushed the layer off the lattice (fig8 BCC: mean epsilon 2.57 -> 3.63).
  /// Without them (no one-ring, or l* = 0) every tetrahedron below select_angle is selected.
  Lattice_3 lattice;
  double edge_length = 0.;
  double lattice_tolerance = 0.1;
  int max_passes = 3;
  int threads = 1;
  /// One flag per vertex, or empty: then the first pass searches only the vertices that share a
  /// tetrahedron with a flagged one (those around the moves of an earlier smoothing).
  std::vector<bool> around;
};

template <typename NamedParameters>
Smoothing_options smoothing_options(const NamedParameters& np)
{
  Smoothing_options o;
  read_lattice_to_keep(o, np, "smooth_vertices");
  read_parameter(np, internal_np::selection_angle, o.select_angle);
  read_parameter(np, internal_np::target_angle, o.target_angle);
  read_parameter(np, internal_np::worst_angle, o.worst_angle);
  read_parameter(np, internal_np::worst_weight, o.worst_weight);
  read_parameter(np, internal_np::target_radius_ratio, o.target_radius_ratio);
  read_parameter(np, internal_np::radius_ratio_weight, o.radius_ratio_weight);
  read_parameter(np, internal_np::floor_angle, o.floor_angle);
  read_parameter(np, internal_np::lattice_tolerance, o.lattice_tolerance);
  read_parameter(np, internal_np::around_vertices, o.around);
  read_parameter(np, internal_np::number_of_passes, o.max_passes);
  read_parameter(np, internal_np::number_of_threads, o.threads);
  for(double x : { o.worst_weight, o.radius_ratio_weight, o.lattice_tolerance })
    if(!(x >= 0.) || !std::isfinite(x))
      throw std::invalid_argument("smooth_vertices(): worst_weight(), radius_ratio_weight() and lattice_tolerance() must be at least 0 and finite");
  if(o.max_passes < 0 || o.threads < 1)
    throw std::invalid_argument("smooth_vertices(): number_of_passes() must be at least 0 and number_of_threads() at least 1");
  return o;
}

} // namespace internal

namespace internal {

// The 6 axis and 8 diagonal directions a free vertex tries.
inline std::vector<Eigen::Vector3d> axis_and_diagonal_directions()
{
  std::vector<Eigen::Vector3d> directions;
  for(int a = 0; a < 6; ++a) { directions.emplace_back(Eigen::Vector3d::Zero()); directions.back()[a / 2] = (a % 2) ? -1. : 1.; }
  for(int d = 0; d < 8; ++d)
    directions.push_back(Eigen::Vector3d((d & 1) ? -1. : 1., (d & 2) ? -1. : 1., (d & 4) ? -1. : 1.) / std::sqrt(3.));
  return directions;
}

// Pattern search from x: steps of the given fractions of `unit` along each direction, each step
// size repeated while it improves (at most 4 times). `attempt(y, x)` tries the point y; if it
// takes it, it sets x to where the vertex went and returns true.
template <typename Attempt>
void pattern_search(Eigen::Vector3d x, const std::vector<Eigen::Vector3d>& directions, double unit, Attempt attempt,
                    std::initializer_list<double> steps = { .3, .1, .03 })
{
  for(double step : steps)
    for(int repeat = 0, improved = 1; improved && repeat < 4; ++repeat) {
      improved = 0;
      for(const Eigen::Vector3d& d : directions)
        if(attempt(Eigen::Vector3d(x + step * unit * d), x)) improved = 1;
    }
}

// Descent from x along minus the gradient of `penalty`, by forward differences of 1% of `unit`
// along the vectors of `basis` (the directions the vertex may move in), with steps of 10%, 3% and
// 1% of `unit` tried in turn; at most 4 times, and no further once no step is taken. `attempt`
// as in pattern_search(); `current()` is the penalty where the vertex is. Returns x's last place.
template <typename Penalty, typename Current, typename Attempt>
Eigen::Vector3d gradient_descent(Eigen::Vector3d x, const std::vector<Eigen::Vector3d>& basis, const Eigen::Matrix3d& b,
                                 double unit, Penalty penalty, Current current, Attempt attempt)
{
  const double h = .01 * unit;
  for(int iteration = 0; iteration < 4; ++iteration) {
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    for(const Eigen::Vector3d& e : basis) {
      const double p = penalty(Eigen::Vector3d(x + h * e));
      if(!std::isfinite(p)) return x;   // an inverted tetrahedron within h: no gradient
      d -= (p - current()) / h * e;
    }
    const double length = (b * d).norm();   // isotropic
    if(!(length > 0.)) return x;
    d /= length;
    bool moved = false;
    for(double step : { .1, .03, .01 })
      if(attempt(Eigen::Vector3d(x + step * unit * d), x)) { moved = true; break; }
    if(!moved) return x;
  }
  return x;
}

} // namespace internal

namespace internal {

// see smooth_vertices()
template <typename Point_3, typename Domain, typename FrameField>
std::size_t smooth_vertices(Tetrahedral_mesh_3<Point_3>& mesh, const Domain& domain, const FrameField& field,
                            const Smoothing_options& o)
{
  if(mesh.vertex_kinds.size() != mesh.points.size())
    throw std::invalid_argument("smooth_vertices(): the mesh needs one particle kind per vertex");
  std::vector<std::vector<int> > star(mesh.points.size());
  for(std::size_t t = 0; t < mesh.tets.size(); ++t)
    for(int v : mesh.tets[t]) star[v].push_back(int(t));

  // B of each tetrahedron at its centroid, frozen for a pass: the moves are small against the
  // scale on which the field varies, and the field is not evaluated in the inner loop
  std::vector<Eigen::Matrix3d> maps(mesh.tets.size());
  const std::vector<Eigen::Vector3d> lattice_vectors =   // in units of l*
      o.edge_length > 0. ? internal::lattice_vectors(o.lattice.one_ring) : std::vector<Eigen::Vector3d>();
  const double tolerance2 = CGAL::square(o.lattice_tolerance);
  auto selected_tet = [&](std::size_t t) {
    std::array<Eigen::Vector3d, 4> p;
    for(int i = 0; i < 4; ++i) p[i] = maps[t] * internal::to_eigen(mesh.points[mesh.tets[t][i]]);
    const double angle = smallest_dihedral_angle(p[0], p[1], p[2], p[3]);
    if(angle >= o.select_angle) return false;
    if(angle < o.floor_angle || lattice_vectors.empty()) return true;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if(internal::squared_distance_to_closest((p[j] - p[i]) / o.edge_length, lattice_vectors) >= tolerance2)
          return true;
    return false;   // a lattice tetrahedron
  };
  // The star of v, its other vertices mapped once per search: only v moves during it.
  struct Star_tet { std::size_t t; int k; std::array<Point_3, 4> p; std::array<Eigen::Vector3d, 4> mapped; double penalty; };
  auto gather_star = [&](int v, std::vector<Star_tet>& out) {
    out.clear();
    for(int t : star[v]) {
      Star_tet s;
      s.t = std::size_t(t);
      for(int i = 0; i < 4; ++i) {
        const int w = mesh.tets[t][i];
        if(w == v) s.k = i;
        s.p[i] = mesh.points[w];
        s.mapped[i] = maps[t] * internal::to_eigen(mesh.points[w]);
      }
      out.push_back(s);
    }
  };
  // The star of v with v at `at`, scored by the sum over its tetrahedra of (target - angle)^2
  // for smallest angles below the target: a worst angle raised by a few degrees at the price of
  // good tetrahedra falling towards it costs more than it gains (max-min smoothing made more
  // tetrahedra below 40 degrees than it fixed). `worst` is the star's smallest angle, `below`
  // its number of tetrahedra below the floor.
  // `bound`: a candidate whose penalty exceeds it cannot win, and is abandoned early.
  // The orientation tests come last: most candidates lose on the penalty first, and an
  // inverted tetrahedron rejects the candidate whatever its penalty.
  struct Score { double penalty, worst; int below; };
  const Score lost{ HUGE_VAL, -1., 0 };
  auto star_quality = [&](std::vector<Star_tet>& st, const Point_3& at, double bound) {
    Score s{ 0., 180., 0 };
    for(Star_tet& e : st) {
      e.mapped[e.k] = maps[e.t] * internal::to_eigen(at);
      const std::array<Eigen::Vector3d, 4> n = internal::face_area_vectors(e.mapped[0], e.mapped[1], e.mapped[2], e.mapped[3]);
      const double angle = internal::smallest_angle_of_faces(n);
      s.worst = (std::min)(s.worst, angle);
      s.below += angle < o.floor_angle;
      e.penalty = CGAL::square((std::max)(0., o.target_angle - angle))
                + o.worst_weight * CGAL::square((std::max)(0., o.worst_angle - angle));
      // the radius ratio's term only adds: a candidate already lost is not measured further
      if(s.penalty + e.penalty > bound) return lost;
      const double rho = internal::radius_ratio_of_faces(n, e.mapped[1] - e.mapped[0], e.mapped[2] - e.mapped[0], e.mapped[3] - e.mapped[0],
                                                         internal::shortest_squared_edge(e.mapped[0], e.mapped[1], e.mapped[2], e.mapped[3]));
      e.penalty += CGAL::square(o.radius_ratio_weight * (std::max)(0., o.target_radius_ratio - rho));
      s.penalty += e.penalty;
      if(s.penalty > bound) return lost;
    }
    for(Star_tet& e : st) {
      e.p[e.k] = at;
      if(CGAL::orientation(e.p[0], e.p[1], e.p[2], e.p[3]) != CGAL::POSITIVE) return lost;
    }
    return s;
  };
  // After a full evaluation, the worst tetrahedra first: a candidate that does not win
  // usually loses on them, and is abandoned after a few.
  auto worst_first = [](std::vector<Star_tet>& st) {
    std::stable_sort(st.begin(), st.end(), [](const Star_tet& a, const Star_tet& b) { return a.penalty > b.penalty; });
  };
  // A move must lower the penalty, and may not lower the star's worst angle below the floor nor
  // take another tetrahedron below it: where one tetrahedron of the star is below the floor, the
  // rule on the worst alone lets its neighbours fall to it (elephant 10k: 215 -> 173 below 40).
  // A star with a sliver (below half the floor) may take others below the floor to raise it
  // (couplingdown at 3,000 vertices: smallest angle 7.8 with the count's rule there, 21.3 without).
  auto better = [&](const Score& c, const Score& best) {
    return c.penalty < best.penalty - 1e-6 && c.worst >= (std::min)(best.worst, o.floor_angle)
        && (c.below <= best.below || best.worst < .5 * o.floor_angle);
  };
  auto constrain = [&](int v, const Point_3& p) {
    switch(mesh.vertex_kinds[v]) {
      case Particle_kind::BOUNDARY: return domain.project_on_surface(p).point;
      case Particle_kind::SHARP_EDGE: return domain.project_on_features(p).point;
      default: return p;
    }
  };

  // pattern search for vertex v; returns the number of accepted moves
  auto move_vertex = [&](int v) -> std::size_t {
    const Eigen::Vector3d x = internal::to_eigen(mesh.points[v]);
    // Steps are measured in the isotropic space (the frozen B of a tetrahedron of the star):
    // under a strong stretch (fig9's radial 20, fig8's 80) a Euclidean step fit for the long
    // edges would jump across the short ones.
    const Eigen::Matrix3d& b = maps[star[v].front()];
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    double mean_edge = 0.;   // isotropic
    int count = 0;
    for(int t : star[v])
      for(int w : mesh.tets[t])
        if(w != v) { const Eigen::Vector3d y = internal::to_eigen(mesh.points[w]); centroid += y; mean_edge += (b * (y - x)).norm(); ++count; }
    centroid /= count;
    mean_edge /= count;
    // Free vertices try the 6 axis and 8 diagonal directions; a boundary vertex only the 8 of
    // its tangent plane and a sharp-edge vertex the 2 of its curve (the others are projected
    // back to about where they started), each besides the direction to the star's centroid.
    std::vector<Eigen::Vector3d> directions, basis;   // basis: of the space the vertex moves in
    auto add_centroid_direction = [&](const Eigen::Vector3d& d) { if((b * d).norm() > 1e-3 * mean_edge) directions.push_back(d.normalized()); };
    switch(mesh.vertex_kinds[v]) {
      case Particle_kind::BOUNDARY: {
        const Eigen::Vector3d n = internal::to_eigen(domain.project_on_surface(mesh.points[v]).direction).normalized();
        if(!n.allFinite()) break;
        const Eigen::Vector3d a = n.unitOrthogonal(), b = n.cross(a);
        for(int k = 0; k < 8; ++k)
          directions.push_back(std::cos(k * CGAL_PI / 4.) * a + std::sin(k * CGAL_PI / 4.) * b);
        basis = { a, b };
        add_centroid_direction(centroid - x - n.dot(centroid - x) * n);
        break;
      }
      case Particle_kind::SHARP_EDGE: {
        const Eigen::Vector3d t = internal::to_eigen(domain.project_on_features(mesh.points[v]).direction).normalized();
        if(!t.allFinite()) break;
        directions.push_back(t);
        directions.push_back(-t);
        basis = { t };
        add_centroid_direction(t.dot(centroid - x) * t);
        break;
      }
      default: break;
    }
    if(directions.empty()) {
      directions = internal::axis_and_diagonal_directions();
      add_centroid_direction(centroid - x);
      basis = { Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ() };
    }
    // each direction scaled to unit isotropic length (exactly as it is when B = I)
    for(Eigen::Vector3d& d : directions) d *= d.norm() / (b * d).norm();
    for(Eigen::Vector3d& d : basis) d *= d.norm() / (b * d).norm();
    std::vector<Star_tet> st;
    gather_star(v, st);
    Score best = star_quality(st, mesh.points[v], HUGE_VAL);
    worst_first(st);
    std::size_t accepted = 0;
    auto attempt = [&](const Eigen::Vector3d& y, Eigen::Vector3d& at) {
      Point_3 candidate(y[0], y[1], y[2]);
      // a boundary vertex's candidate is first scored where it is, in the tangent plane: most
      // lose there by far, and only those within a tenth of the best pay for their projection
      // onto the surface (the tangent plane alone, with no margin, lowers the smallest angle of
      // 46 of the 94 closed surfaces of libcgal-demo at 3,000 vertices)
      if(mesh.vertex_kinds[v] == Particle_kind::BOUNDARY && !(star_quality(st, candidate, 1.1 * best.penalty).penalty < 1.1 * best.penalty))
        return false;
      candidate = constrain(v, candidate);
      const Score q = star_quality(st, candidate, best.penalty);
      if(!better(q, best)) return false;
      best = q; mesh.points[v] = candidate; ++accepted; worst_first(st);
      at = internal::to_eigen(candidate);
      return true;
    };
    // A star with a tetrahedron below the floor may need a jump: the pattern search from its
    // largest step. The others descend along the penalty's gradient (most of the smoothing's
    // moves are 3% steps of such stars, which the pattern search pays 15 tries each for), then
    // try the finest pattern step, since the penalty's kinks (a smallest angle changing edge)
    // stop a descent short. (Design chapter: a quarter less time, the same quality.)
    if(best.worst < o.floor_angle || basis.empty()) {
      internal::pattern_search(x, directions, mean_edge, attempt);
      return accepted;
    }
    auto penalty = [&](const Eigen::Vector3d& y) { return star_quality(st, Point_3(y[0], y[1], y[2]), HUGE_VAL).penalty; };
    const Eigen::Vector3d descended =
      internal::gradient_descent(x, basis, b, mean_edge, penalty, [&] { return best.penalty; }, attempt);
    internal::pattern_search(descended, directions, mean_edge, attempt, { .03 });
    return accepted;
  };

  std::size_t moves = 0;
  // A vertex whose star did not change since its last search would only search again: after the
  // first pass, only the vertices sharing a tetrahedron with a moved one are candidates.
  // around_vertices() stands for the moves of an earlier pass.
  std::vector<char> active(mesh.points.size(), 1), moved(mesh.points.size(), 0);
  auto activate_around_moved = [&] {
    active = internal::vertices_around(mesh.tets, moved);
    std::fill(moved.begin(), moved.end(), 0);
  };
  if(!o.around.empty()) {
    if(o.around.size() != mesh.points.size())
      throw std::invalid_argument("smooth_vertices(): around_vertices() needs one flag per vertex");
    std::copy(o.around.begin(), o.around.end(), moved.begin());
    activate_around_moved();
  }
  for(int pass = 0; pass < o.max_passes; ++pass) {
    std::vector<char> selected_tets(mesh.tets.size());
    internal::parallel_for_rethrow(mesh.tets.size(), [&](std::size_t t) {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for(int v : mesh.tets[t]) c += .25 * internal::to_eigen(mesh.points[v]);
      maps[t] = internal::isotropic_map_at<Point_3>(field, c);
      selected_tets[t] = selected_tet(t);
    }, o.threads);
    std::vector<char> selected(mesh.points.size(), 0);
    for(std::size_t t = 0; t < mesh.tets.size(); ++t)
      if(selected_tets[t])
        for(int v : mesh.tets[t]) selected[v] = active[v] && mesh.vertex_kinds[v] != Particle_kind::FIXED;
    // Greedy colouring: vertices of one colour share no tetrahedron, so their stars are moved in
    // parallel with the same result for any number of threads.
    std::vector<int> colour(mesh.points.size(), -1);
    std::vector<std::vector<int> > classes;
    std::vector<char> taken;
    for(std::size_t v = 0; v < mesh.points.size(); ++v) {
      if(!selected[v]) continue;
      taken.assign(classes.size() + 1, 0);
      for(int t : star[v]) for(int w : mesh.tets[t]) if(colour[w] >= 0) taken[colour[w]] = 1;
      const int c = int(std::find(taken.begin(), taken.end(), 0) - taken.begin());
      if(c == int(classes.size())) classes.emplace_back();
      colour[v] = c;
      classes[c].push_back(int(v));
    }
    std::size_t pass_moves = 0;
    for(const std::vector<int>& members : classes) {
#pragma omp parallel for num_threads(o.threads) schedule(dynamic, 16) reduction(+:pass_moves)
      for(std::ptrdiff_t k = 0; k < std::ptrdiff_t(members.size()); ++k) {
        const std::size_t accepted = move_vertex(members[k]);
        moved[members[k]] = accepted > 0;
        pass_moves += accepted;
      }
    }
    activate_around_moved();
    moves += pass_moves;
#ifdef CGAL_LATTICE_MESHER_3_VERBOSE
    std::cerr << "  smoothing pass " << pass << ": " << std::count(selected.begin(), selected.end(), 1)
              << " vertices selected, " << pass_moves << " moves\n";
#endif
    if(pass_moves == 0) break;
  }
  return moves;
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Flips

Moves the vertices of the worst tetrahedra to lower the shortfall of their star's smallest
dihedral angles (measured in the isotropic space of `field`) below a target. A vertex whose star
has a tetrahedron below `floor_angle` moves by a pattern search with steps of 30%, 10% and 3% of
the star's mean edge length (lengths in the isotropic space of a tetrahedron of the star) over
the direction to the star's centroid and the axis and diagonal directions: for free vertices the
6 axes and 8 diagonals, for boundary vertices the 8 directions of the tangent plane (the surface
normal comes from `project_on_surface()`), for sharp-edge vertices the 2 of the curve's tangent.
The others descend along the shortfall's gradient (forward differences of 1% in the space they
move in; steps of 10%, 3% and 1%; at most 4 times), then take the pattern search's 3% steps.
The worst tetrahedra are those below `selection_angle` that are not lattice tetrahedra
(`edge_length`). Boundary vertices stay on the
surface and sharp-edge vertices on the feature curves (each candidate is projected back; a
boundary vertex's candidate only if it scores within a tenth of the best in the tangent plane,
where most lose by far), fixed
vertices (corners) do not move. After the first pass, only vertices sharing a
tetrahedron with a vertex moved in the previous pass are searched again. A move is kept only if no tetrahedron of the star
is inverted (exact orientation tests), the shortfall falls, the star's smallest angle does not
fall below the floor and no other tetrahedron of the star falls below it (unless the star has one
below half the floor), so the boundary stays on the surface and the mesh stays valid. Needs
`mesh.vertex_kinds`.

\tparam Domain a model of `LatticeMeshDomain_3`
\tparam FrameField a model of `FrameField_3`

\cgalNamedParamsBegin
  \cgalParamNBegin{selection_angle}
    \cgalParamDescription{vertices of tetrahedra whose smallest dihedral angle (isotropic space, degrees) is below this, lattice tetrahedra excepted, are moved; the others stay where the optimization put them}
    \cgalParamType{double}
    \cgalParamDefault{55}
  \cgalParamNEnd
  \cgalParamNBegin{target_angle}
    \cgalParamDescription{moves lower the sum over a star of (target_angle - smallest angle)^2 over its tetrahedra below it (about the regular tetrahedron's 70.5, so that every tetrahedron is pulled up) ...}
    \cgalParamType{double}
    \cgalParamDefault{70}
  \cgalParamNEnd
  \cgalParamNBegin{worst_angle}
    \cgalParamDescription{... plus `worst_weight` x (worst_angle - smallest angle)^2 below this, so that moves do not trade the worst tetrahedra for the mean ...}
    \cgalParamType{double}
    \cgalParamDefault{50}
  \cgalParamNEnd
  \cgalParamNBegin{worst_weight}
    \cgalParamDescription{see `worst_angle`}
    \cgalParamType{double}
    \cgalParamDefault{4}
  \cgalParamNEnd
  \cgalParamNBegin{target_radius_ratio}
    \cgalParamDescription{... plus the square of (target_radius_ratio - radius ratio) x `radius_ratio_weight` below this, since angles alone leave tetrahedra with short edges ...}
    \cgalParamType{double}
    \cgalParamDefault{0.9}
  \cgalParamNEnd
  \cgalParamNBegin{radius_ratio_weight}
    \cgalParamDescription{degrees per unit of radius ratio, see `target_radius_ratio`}
    \cgalParamType{double}
    \cgalParamDefault{50}
  \cgalParamNEnd
  \cgalParamNBegin{floor_angle}
    \cgalParamDescription{... and never lower the star's smallest angle below this (or its current value if lower), nor add a tetrahedron below it to the star (unless the star has one below half of it)}
    \cgalParamType{double}
    \cgalParamDefault{40}
  \cgalParamNEnd
  \cgalParamNBegin{around_vertices}
    \cgalParamDescription{one flag per vertex of `mesh`: the first pass searches only the vertices that share a tetrahedron with a flagged one (for instance those an earlier smoothing moved)}
    \cgalParamType{`std::vector<bool>`}
    \cgalParamDefault{empty: every vertex}
  \cgalParamNEnd
  \cgalParamNBegin{edge_length}
    \cgalParamDescription{l*: with it, a tetrahedron whose six edges (isotropic space) all lie within `lattice_tolerance` x l* of a vector of `lattice` (a one-ring offset or the sum of two) and whose smallest angle is at least `floor_angle` is a lattice tetrahedron, and is not selected (not for `Lattice_type::GAUSSIAN`, which forms no lattice)}
    \cgalParamType{double}
    \cgalParamDefault{0: every tetrahedron below `selection_angle` is selected}
  \cgalParamNEnd
  \cgalParamNBegin{lattice}
    \cgalParamDescription{the lattice the vertices follow}
    \cgalParamType{`Lattice_type`}
    \cgalParamDefault{`Lattice_type::BCC`}
  \cgalParamNEnd
  \cgalParamNBegin{lattice_tolerance}
    \cgalParamDescription{see `edge_length`}
    \cgalParamType{double}
    \cgalParamDefault{0.1}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_passes}
    \cgalParamDescription{passes; after the first, only vertices sharing a tetrahedron with a vertex moved in the previous pass are searched again}
    \cgalParamType{int}
    \cgalParamDefault{3}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{OpenMP threads}
    \cgalParamType{int}
    \cgalParamDefault{1}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of moves
\throws std::invalid_argument without a particle kind per vertex, or for a named parameter out of range
*/
template <typename Point_3, typename Domain, typename FrameField,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t smooth_vertices(Tetrahedral_mesh_3<Point_3>& mesh, const Domain& domain, const FrameField& field,
                            const NamedParameters& np = parameters::default_values())
{
  return internal::smooth_vertices(mesh, domain, field, internal::smoothing_options(np));
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_SMOOTH_VERTICES_H
