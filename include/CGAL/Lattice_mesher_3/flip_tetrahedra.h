// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_FLIP_TETRAHEDRA_H
#define CGAL_LATTICE_MESHER_3_FLIP_TETRAHEDRA_H

#include <CGAL/Lattice_mesher_3/Lattice_3.h>
#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>
#include <CGAL/Lattice_mesher_3/internal/stage_parameters.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/enum.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

namespace internal {

// Settings of flip_tetrahedra().
struct Flip_options
{
  /// The lattice whose tetrahedra the mapped tetrahedra should match, and its cube edge l*.
  /// Without them (no one-ring, or l* = 0) only the smallest angle is raised.
  Lattice_3 lattice;
  double edge_length = 0.;
  /// Tetrahedra whose shape energy is below this are taken as lattice tetrahedra and not tried.
  double shape_tolerance = 0.05;
  /// Shape-matching flips may not take the smallest angle of the tetrahedra they replace below
  /// this (or below its current value if that is lower).
  double floor_angle = 40.;
  /// Then only faces and edges of tetrahedra whose smallest dihedral angle (isotropic space,
  /// degrees) is below this are tried for a higher smallest angle.
  double target_angle = 50.;
  /// A tetrahedron below floor_angle may also 2-2 flip one of its boundary edges whose two
  /// boundary faces lie in one plane (the sine of the angle between their normals below this):
  /// the surface stays, only its triangulation changes, and the cap tetrahedra of a thin boundary
  /// triangle, which no interior flip or move improves, go (fig9 FCC: smallest angle 17.9 -> 25.5
  /// degrees, 451 -> 276 tetrahedra below 40). 0: boundary faces are only flipped to remove
  /// inverted tetrahedra (within 1 degree of one plane).
  double boundary_flatness = 1e-6;
  int max_passes = 8;
  /// Edges with more incident tetrahedra than this are not removed (the ring's triangulations grow
  /// as the Catalan numbers; past 7 a removal almost never improves the worst tetrahedron).
  int max_ring_size = 7;
  /// One flag per vertex, or empty: then only the tetrahedra with a vertex that shares a
  /// tetrahedron with a flagged one are tried, the others once a flip changes a tetrahedron
  /// around them (an earlier flipping left them as they are, and only the flagged vertices moved).
  std::vector<bool> around;
  /// OpenMP threads that look for the flips of consecutive candidates at once; the flips are
  /// made in the candidates' order, so they are those of one thread.
  int threads = 1;
};

template <typename NamedParameters>
Flip_options flip_options(const NamedParameters& np)
{
  Flip_options o;
  read_lattice_to_keep(o, np, "flip_tetrahedra");
  read_parameter(np, internal_np::shape_tolerance, o.shape_tolerance);
  read_parameter(np, internal_np::floor_angle, o.floor_angle);
  read_parameter(np, internal_np::target_angle, o.target_angle);
  read_parameter(np, internal_np::boundary_flatness, o.boundary_flatness);
  read_parameter(np, internal_np::number_of_passes, o.max_passes);
  read_parameter(np, internal_np::maximum_ring_size, o.max_ring_size);
  read_parameter(np, internal_np::around_vertices, o.around);
  read_parameter(np, internal_np::number_of_threads, o.threads);
  if(o.threads < 1) throw std::invalid_argument("flip_tetrahedra(): number_of_threads() must be at least 1");
  if(!(o.shape_tolerance >= 0.) || !(o.boundary_flatness >= 0.))
    throw std::invalid_argument("flip_tetrahedra(): shape_tolerance() and boundary_flatness() must be at least 0");
  if(o.max_passes < 0 || o.max_ring_size < 3)
    throw std::invalid_argument("flip_tetrahedra(): number_of_passes() must be at least 0 and maximum_ring_size() at least 3");
  return o;
}

} // namespace internal

/// What `flip_tetrahedra()` did.
struct Flip_result
{
  /// number of 2-3 flips
  std::size_t flips23 = 0, flips32 = 0, edge_removals = 0;   ///< number of edge removals (rings of 4 and more tetrahedra)
  /*! \var flips32
      \brief number of 3-2 flips */
  std::size_t boundary_flips = 0;   ///< 2-2 flips of flat boundary faces, only to remove inverted tetrahedra
  std::size_t total() const { return flips23 + flips32 + edge_removals + boundary_flips; } ///< the total number of flips and edge removals
};

/*!
\ingroup PkgLatticeMesher3Flips
Shape energy of a tetrahedron given in the isotropic space: the sum over its six edges of
min_k |e / l - O_k|^2, the squared distance of the edge, in lattice units, to the closest
one-ring offset. It is 0 exactly for the tetrahedra of the lattice's Delaunay tetrahedralization
(BCC: all; FCC: the regular ones and the quarters of the octahedra), whose edges are one-ring offsets.
*/
inline double lattice_shape_energy(const std::array<Eigen::Vector3d, 4>& p, const Lattice_3& lattice, double l)
{
  double e = 0.;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
      e += internal::squared_distance_to_closest((p[j] - p[i]) / l, lattice.one_ring);
  return e;
}

namespace internal {

// What a flip is judged by: the smallest dihedral angle of a tetrahedron (isotropic space, B at
// its centroid) and, when a lattice is given, its shape energy.
struct Flip_measure { double angle, shape; };

// A tetrahedral mesh under flips: the tetrahedra around a face or an edge are those of the first
// vertex's incidence list that hold the others (a star has about 24), in the order of creation.
// Lists per vertex instead of hash maps of faces and edges: building those took a third of the
// flips' time (fandisk, 93k tetrahedra, 3 calls: 1 s of 3.6 s).
// Two criteria: SHAPE lowers the sum of the shape energies (the connectivity follows the field)
// without taking the smallest angle below the floor; ANGLE raises the smallest angle.
template <typename Point_3, typename FrameField>
class Flip_mesh
{
public:
  enum Criterion { SHAPE, ANGLE };
  // tetrahedra around an edge (about 5 in a lattice mesh) or replaced by a flip, kept inline
  typedef boost::container::small_vector<int, 8> Tet_list;

  Flip_mesh(Tetrahedral_mesh_3<Point_3>& mesh, const FrameField& field, const Flip_options& o)
    : mesh_(mesh), field_(field), o_(o), changed_(mesh.points.size(), 0), incident_(mesh.points.size())
  {
    for(const std::array<int, 4>& t : mesh.tets) add(t, unmeasured());
    if(!o.around.empty()) around_ = vertices_around(mesh.tets, o.around);
  }

  // A flip that look() found and make() makes: the tetrahedra it replaces and those it creates,
  // measured, and the edges whose removal failed before it was found. SKIP: the tetrahedron is
  // not to be tried; NONE: no flip.
  struct Flip_plan
  {
    enum Kind { SKIP, NONE, FLIP23, EDGE_REMOVAL, BOUNDARY_FLIP } kind = SKIP;
    Tet_list old;
    std::vector<std::array<int, 4> > created;
    std::vector<Flip_measure> measures;
    boost::container::small_vector<std::uint64_t, 6> failed;   // at most t's six edges: no allocation
  };

  // A given tetrahedron is measured when first looked at (with `around`, most are not); while
  // threads look at once, it is measured but not stored. An inverted one (only given ones: flips
  // create none, so measure() need not look) measures -1 degree and a huge shape energy: both
  // criteria take any flip that removes it.
  Flip_measure measured(int t) const
  {
    if(!std::isnan(measure_[t].angle)) return measure_[t];
    const Flip_measure m = measure_now(t);
    if(!looking_in_parallel_) measure_[t] = m;
    return m;
  }
  Flip_measure measure_now(int t) const
  {
    const std::array<int, 4>& v = tets_[t];
    return orientation(v[0], v[1], v[2], v[3]) == CGAL::POSITIVE ? measure(v) : Flip_measure{ -1., 1e6 };
  }
  static Flip_measure unmeasured() { return { std::nan(""), 0. }; }

  // either orientation: the angles are unsigned (edge removal measures its b side reversed)
  Flip_measure measure(const std::array<int, 4>& t) const
  {
    const std::array<Eigen::Vector3d, 4> p = isotropic_tetrahedron(
        field_, std::array<Point_3, 4>{ mesh_.points[t[0]], mesh_.points[t[1]], mesh_.points[t[2]], mesh_.points[t[3]] });
    return { smallest_dihedral_angle(p[0], p[1], p[2], p[3]),
             has_shape() ? lattice_shape_energy(p, o_.lattice, o_.edge_length) : 0. };
  }
  bool has_shape() const { return !o_.lattice.one_ring.empty() && o_.edge_length > 0.; }

  CGAL::Orientation orientation(int a, int b, int c, int d) const
  { return CGAL::orientation(mesh_.points[a], mesh_.points[b], mesh_.points[c], mesh_.points[d]); }

  // (a, b, c, d) reordered to be positive, or false if flat
  bool positive(std::array<int, 4>& t) const
  {
    const CGAL::Orientation o = orientation(t[0], t[1], t[2], t[3]);
    if(o == CGAL::COPLANAR) return false;
    if(o == CGAL::NEGATIVE) std::swap(t[0], t[1]);
    return true;
  }

  // whether `created` (reordered to be positive) would be better than `old` by the criterion;
  // if so, the plan to replace them
  bool evaluate(const Tet_list& old, std::vector<std::array<int, 4> >& created, Criterion c, Flip_plan& plan) const
  {
    double before = 180., after = 180., shape_before = 0., shape_after = 0.;
    for(int t : old) { before = (std::min)(before, measured(t).angle); shape_before += measured(t).shape; }
    const double floor = c == ANGLE ? before + 1e-9 : (std::min)(before, o_.floor_angle);
    std::vector<Flip_measure> m(created.size());
    for(std::size_t k = 0; k < created.size(); ++k) {
      if(!positive(created[k])) return false;
      m[k] = measure(created[k]);
      after = (std::min)(after, m[k].angle);
      shape_after += m[k].shape;
      if(after < floor || (c == ANGLE && after <= floor)) return false;
      if(c == SHAPE && shape_after >= shape_before - 1e-9) return false;
    }
    plan.old = old;
    plan.created = std::move(created);
    plan.measures = std::move(m);
    return true;
  }

  // Whether a flip around t can succeed depends only on the tetrahedra sharing a vertex with t
  // (those around its edges and faces): t need not be tried again until one of them changes.
  bool worth_trying(int t) const
  {
    const std::array<int, 4>& v = tets_[t];
    return tried_[t] < (std::max)({ changed_[v[0]], changed_[v[1]], changed_[v[2]], changed_[v[3]] });
  }
  void mark_tried(int t) { tried_[t] = clock_; }
  // a new criterion: every tetrahedron is worth trying again, or, with `around`, only those
  // with a vertex around a flagged one or changed by a flip (a tetrahedron that holds a vertex and
  // a flagged one either was given or was made by a flip), and the others once a flip changes a
  // tetrahedron around them
  void forget_tries()
  {
    std::fill(tried_.begin(), tried_.end(), -1);
    failed_removals_.clear();
    if(around_.empty()) return;
    for(std::size_t t = 0; t < tets_.size(); ++t)
      if(alive_[t] && std::none_of(tets_[t].begin(), tets_[t].end(), [&](int v) { return around_[v] != 0 || changed_[v] > 0; }))
        tried_[t] = clock_;
  }

  // 2-3 flip of the face (a, b, c) shared by two tetrahedra
  bool flip23(const std::array<int, 3>& f, Criterion c, Flip_plan& plan) const
  {
    const Tet_list around = tets_around(f[0], f[1], f[2]);
    if(around.size() != 2) return false;
    const int t0 = around[0], t1 = around[1];
    const int p = apex(t0, f), q = apex(t1, f);
    std::vector<std::array<int, 4> > created = { { f[0], f[1], p, q }, { f[1], f[2], p, q }, { f[2], f[0], p, q } };
    // the segment pq must cross the triangle: the three new tetrahedra have the same orientation
    const CGAL::Orientation o = orientation(f[0], f[1], p, q);
    if(o == CGAL::COPLANAR || orientation(f[1], f[2], p, q) != o || orientation(f[2], f[0], p, q) != o) return false;
    return evaluate({ t0, t1 }, created, c, plan);
  }

  // removal of the interior edge (a, b): its ring of n vertices is triangulated (the best of
  // all triangulations by dynamic programming: the highest smallest angle, or the lowest shape
  // energy), each triangle joined to a and to b. n = 3 is the 3-2 flip, n = 4 the 4-4 flip.
  int remove_edge(int a, int b, int max_ring, Criterion c, Flip_plan& plan) const
  {
    // A removal depends only on the tetrahedra around the edge: once it failed, it fails again
    // until a flip changes a tetrahedron around a or b (each edge is tried from the several
    // candidates around it; fandisk at 18,000 vertices: flips 1.0 s instead of 1.3 s).
    const std::uint64_t key = (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
    const auto failed = failed_removals_.find(key);
    if(failed != failed_removals_.end() && changed_[a] <= failed->second && changed_[b] <= failed->second) return 0;
    const int removed = remove_edge_now(a, b, max_ring, c, plan);
    if(removed == 0) plan.failed.push_back(key);
    return removed;
  }

private:
  int remove_edge_now(int a, int b, int max_ring, Criterion c, Flip_plan& plan) const
  {
    const Tet_list around = tets_around(a, b);
    const int n = int(around.size());
    if(n < 3 || n > max_ring) return 0;
    std::vector<int> ring;
    if(!order_ring(a, b, around, ring)) return 0;   // a boundary edge: its ring is open
    // orient the ring counterclockwise seen from a: then every triangle (i < k < j) of a valid
    // triangulation has a on its positive and b on its negative side (see pair_quality)
    if(orientation(a, b, ring[0], ring[1]) == CGAL::POSITIVE) std::reverse(ring.begin(), ring.end());
    std::vector<std::array<int, 4> > created;
    if(!triangulate_ring(a, b, ring, c, created)) return 0;
    return evaluate(around, created, c, plan) ? n : 0;
  }

public:
  // 2-2 flip of a boundary edge (a, c) whose two boundary faces (a, c, b) and (c, a, e) lie in
  // one plane (the sine of the angle of their normals below `flatness`): (b, e) replaces it on the
  // boundary, and the open ring b .. e around (a, c), closed by (b, e), is triangulated as in
  // remove_edge(), for the highest smallest angle. For inverted tetrahedra (a cell flat in the
  // embedding of tetrahedralize_particles(), within 1 degree: a sliver triangle on a flat boundary
  // face, folded over, is the one thing interior flips cannot undo), and for the worst ones on a
  // planar part of the boundary (`boundary_flatness`).
  int flip_boundary_edge(int a, int c, int max_ring, double flatness, Flip_plan& plan) const
  {
    const Tet_list around = tets_around(a, c);
    const int n = int(around.size()) + 1;
    if(n < 3 || n > max_ring) return 0;
    std::vector<int> ring;
    if(!order_open_ring(a, c, around, ring)) return 0;
    const Eigen::Vector3d pa = to_eigen(mesh_.points[a]), pc = to_eigen(mesh_.points[c]);
    const Eigen::Vector3d n0 = (pc - pa).cross(to_eigen(mesh_.points[ring.front()]) - pa).normalized();
    const Eigen::Vector3d n1 = (to_eigen(mesh_.points[ring.back()]) - pa).cross(pc - pa).normalized();
    if(!(n0.cross(n1).norm() < flatness)) return 0;   // (folded over, b and e are on one side of ac)
    for(int pass = 0; pass < 2; ++pass, std::reverse(ring.begin(), ring.end())) {
      std::vector<std::array<int, 4> > created;
      if(triangulate_ring(a, c, ring, ANGLE, created) && evaluate(around, created, ANGLE, plan)) return n;
    }
    return 0;
  }

private:
  // the best triangulation of the polygon `ring` (closed by its last and first vertex), each
  // triangle joined to a and to b, by dynamic programming: the highest smallest angle, or the
  // lowest shape energy; false if none is valid
  bool triangulate_ring(int a, int b, const std::vector<int>& ring, Criterion c,
                        std::vector<std::array<int, 4> >& created) const
  {
    const int n = int(ring.size());
    // best[i][j]: the best score triangulating ring[i..j] (ANGLE: the smallest angle, SHAPE:
    // minus the shape energy, both maximized; -inf: no valid triangulation); choice[i][j] the apex
    const double none = -HUGE_VAL;
    std::vector<std::vector<double> > best(n, std::vector<double>(n, c == ANGLE ? 180. : 0.));
    std::vector<std::vector<int> > choice(n, std::vector<int>(n, -1));
    for(int len = 2; len < n; ++len)
      for(int i = 0; i + len < n; ++i) {
        const int j = i + len;
        best[i][j] = none;
        for(int k = i + 1; k < j; ++k) {
          if(best[i][k] == none || best[k][j] == none) continue;
          Flip_measure m;
          if(!pair_measure(ring[i], ring[k], ring[j], a, b, m)) continue;
          const double q = c == ANGLE ? (std::min)((std::min)(best[i][k], best[k][j]), m.angle)
                                      : best[i][k] + best[k][j] - m.shape;
          if(q > best[i][j]) { best[i][j] = q; choice[i][j] = k; }
        }
      }
    if(best[0][n - 1] == none) return false;
    collect(ring, choice, 0, n - 1, a, b, created);
    return true;
  }

public:
  // What a try of t finds, the mesh unchanged: the first edge of t whose removal succeeds, else
  // the first face whose 2-3 flip does, else, for an inverted t or one below the floor in the
  // angle pass, the first boundary edge whose 2-2 flip does.
  Flip_plan look(int t, Criterion c) const
  {
    const double folded_flatness = 0.0175;   // an inverted tetrahedron's boundary faces: within 1 degree of one plane
    Flip_plan plan;
    if(!alive(t) || !worth_trying(t) || !candidate(t, c)) return plan;
    const std::array<int, 4> v = tets_[t];
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if(remove_edge(v[i], v[j], o_.max_ring_size, c, plan) > 0) { plan.kind = Flip_plan::EDGE_REMOVAL; return plan; }
    for(int i = 0; i < 4; ++i)
      if(flip23({ v[(i + 1) % 4], v[(i + 2) % 4], v[(i + 3) % 4] }, c, plan)) { plan.kind = Flip_plan::FLIP23; return plan; }
    // how flat two boundary faces must be for t to flip their edge (0: not at all)
    const double flatness = inverted(t) ? folded_flatness
                          : c == ANGLE && angle(t) < o_.floor_angle ? o_.boundary_flatness : 0.;
    for(int i = 0; i < 4 && flatness > 0.; ++i)
      for(int j = i + 1; j < 4; ++j)
        if(flip_boundary_edge(v[i], v[j], o_.max_ring_size, flatness, plan) > 0) { plan.kind = Flip_plan::BOUNDARY_FLIP; return plan; }
    plan.kind = Flip_plan::NONE;
    return plan;
  }

  // Makes what look() found for t, and counts it in `result`.
  void make(int t, Flip_plan& plan, Flip_result& result)
  {
    if(plan.kind == Flip_plan::SKIP) return;
    for(std::uint64_t key : plan.failed) failed_removals_[key] = clock_;
    if(plan.kind == Flip_plan::NONE) { mark_tried(t); return; }
    for(int old : plan.old) remove(old);
    ++clock_;
    for(std::size_t k = 0; k < plan.created.size(); ++k) {
      add(plan.created[k], plan.measures[k]);
      for(int v : plan.created[k]) changed_[v] = clock_;
    }
    switch(plan.kind) {
      case Flip_plan::FLIP23: ++result.flips23; break;
      case Flip_plan::EDGE_REMOVAL: ++(plan.old.size() == 3 ? result.flips32 : result.edge_removals); break;
      default: ++result.boundary_flips; boundary_changed_ = true;
    }
  }

  // Tries the tetrahedra of `list` in its order. With several threads, they look at a batch at
  // once and the flips are made in order; a tetrahedron with a vertex that a flip of its batch
  // changed is looked at again (a try depends on the tetrahedra around t alone, and a flip marks
  // every vertex of the tetrahedra it replaces), so the flips are those of one thread. A batch
  // holds the tetrahedra worth trying of a stretch of the list: the others (after a smoothing,
  // most of the mesh) are neither measured nor handed to the threads, and one that a flip of
  // the batch makes worth trying is looked at in order, as changed.
  void try_all(const std::vector<int>& list, Criterion c, Flip_result& result)
  {
    // larger batches collide more (bunny at 60,000 vertices, two threads: the flips take 2.3 s
    // with 64 candidates a thread, 2.6 s with 512)
    const std::size_t batch = o_.threads > 1 ? 64 * std::size_t(o_.threads) : 1;
    std::vector<Flip_plan> plans;
    std::vector<std::size_t> looked;   // positions in `list` of the batch
    for(std::size_t first = 0, end = 0; first < list.size(); first = end) {
      looked.clear();
      for(; end < list.size() && looked.size() < batch; ++end)
        if(alive(list[end]) && worth_trying(list[end])) looked.push_back(end);
      const long start = clock_;
      plans.assign(looked.size(), Flip_plan());
      if(o_.threads > 1) {
        // each thread stores the measure of its own tetrahedra, not of the others
        looking_in_parallel_ = true;
        try {
          parallel_for_rethrow(looked.size(), [&](std::size_t k) {
            const int t = list[looked[k]];
            if(std::isnan(measure_[t].angle)) measure_[t] = measure_now(t);
            plans[k] = look(t, c);
          }, o_.threads, 2);   // in pairs: most looks end at once, an edge removal's takes long
        } catch(...) { looking_in_parallel_ = false; throw; }
        looking_in_parallel_ = false;
      }
      // on one thread the batch is looked at here; the others of the stretch are skipped unless
      // a flip before them changed a vertex of theirs
      for(std::size_t k = first, next = 0; k < end; ++k) {
        const int t = list[k];
        const std::array<int, 4>& v = tets_[t];
        const bool batched = next < looked.size() && looked[next] == k;
        Flip_plan unlooked;   // SKIP
        Flip_plan& plan = batched ? plans[next++] : unlooked;
        if((batched && o_.threads == 1) || std::any_of(v.begin(), v.end(), [&](int u) { return changed_[u] > start; }))
          plan = look(t, c);
        make(t, plan, result);
      }
    }
  }

  // writes the current tetrahedra back to the mesh, and its boundary faces if they changed
  void commit()
  {
    mesh_.tets.clear();
    for(std::size_t t = 0; t < tets_.size(); ++t)
      if(alive_[t]) mesh_.tets.push_back(tets_[t]);
    if(!boundary_changed_) return;
    // 2-2 flips keep the boundary's vertices: only faces of three of them are looked up (of
    // any three, for a mesh given without its boundary faces)
    std::vector<char> on_boundary(mesh_.points.size(), char(mesh_.boundary_faces.empty()));
    for(const std::array<int, 3>& f : mesh_.boundary_faces) for(int v : f) on_boundary[std::size_t(v)] = 1;
    mesh_.boundary_faces.clear();
    for(std::size_t t = 0; t < tets_.size(); ++t) {
      if(!alive_[t]) continue;
      for(int i = 0; i < 4; ++i) {
        std::array<int, 3> face{ tets_[t][(i + 1) % 4], tets_[t][(i + 2) % 4], tets_[t][(i + 3) % 4] };
        if(!on_boundary[std::size_t(face[0])] || !on_boundary[std::size_t(face[1])] || !on_boundary[std::size_t(face[2])]) continue;
        if(tets_around(face[0], face[1], face[2]).size() != 1) continue;
        // outward: the tetrahedron's own fourth vertex on the negative side
        if(orientation(face[0], face[1], face[2], tets_[t][i]) != CGAL::NEGATIVE) std::swap(face[0], face[1]);
        mesh_.boundary_faces.push_back(face);
      }
    }
    std::sort(mesh_.boundary_faces.begin(), mesh_.boundary_faces.end());
  }

  // the tetrahedra to try: below the angle (ANGLE) or above the shape tolerance (SHAPE)
  bool candidate(int t, Criterion c) const
  {
    return c == ANGLE ? measured(t).angle < o_.target_angle : measured(t).shape > o_.shape_tolerance;
  }
  // those that may be: the candidates and the tetrahedra not measured yet
  std::vector<int> candidates(Criterion c) const
  {
    std::vector<int> out;
    for(std::size_t t = 0; t < tets_.size(); ++t)
      if(alive_[t] && (std::isnan(measure_[t].angle) || candidate(int(t), c)))
        out.push_back(int(t));
    return out;
  }
  bool alive(int t) const { return alive_[t] != 0; }
  bool inverted(int t) const { return measured(t).angle < 0.; }
  double angle(int t) const { return measured(t).angle; }   // smallest dihedral, isotropic

private:
  // the tetrahedra holding the vertices a, b and, if c >= 0, c
  Tet_list tets_around(int a, int b, int c = -1) const
  {
    Tet_list out;
    for(int t : incident_[a]) {
      const std::array<int, 4>& v = tets_[t];
      if(std::find(v.begin(), v.end(), b) != v.end() && (c < 0 || std::find(v.begin(), v.end(), c) != v.end()))
        out.push_back(t);
    }
    return out;
  }

  int apex(int t, const std::array<int, 3>& f) const
  {
    for(int v : tets_[t]) if(v != f[0] && v != f[1] && v != f[2]) return v;
    return -1;
  }

  // both tetrahedra (ring triangle + a, + b): false if a or b is on the wrong side, else their
  // smaller angle and summed shape energy. Opposite sides are not enough: a triangle folded
  // against the ring's orientation would give tetrahedra overlapping the rest of the mesh.
  bool pair_measure(int i, int j, int k, int a, int b, Flip_measure& m) const
  {
    if(orientation(i, j, k, a) != CGAL::POSITIVE || orientation(i, j, k, b) != CGAL::NEGATIVE) return false;
    const Flip_measure ma = measure({ i, j, k, a }), mb = measure({ i, j, k, b });
    m = { (std::min)(ma.angle, mb.angle), ma.shape + mb.shape };
    return true;
  }

  void collect(const std::vector<int>& ring, const std::vector<std::vector<int> >& choice, int i, int j,
               int a, int b, std::vector<std::array<int, 4> >& out) const
  {
    if(j - i < 2) return;
    const int k = choice[i][j];
    out.push_back({ ring[i], ring[k], ring[j], a });
    out.push_back({ ring[i], ring[k], ring[j], b });
    collect(ring, choice, i, k, a, b, out);
    collect(ring, choice, k, j, a, b, out);
  }

  // the vertices around the boundary edge ab from the apex of one boundary face to that of the
  // other; false if ab is not a boundary edge of two boundary faces
  bool order_open_ring(int a, int b, const Tet_list& around, std::vector<int>& ring) const
  {
    std::unordered_map<int, std::vector<int> > link;
    for(int t : around) {
      std::array<int, 2> l{ -1, -1 };
      int k = 0;
      for(int v : tets_[t]) if(v != a && v != b) l[k++] = v;
      link[l[0]].push_back(l[1]);
      link[l[1]].push_back(l[0]);
    }
    int start = -1, ends = 0;
    for(const auto& e : link) {
      if(e.second.size() > 2) return false;
      if(e.second.size() == 1) { ++ends; if(start < 0 || e.first < start) start = e.first; }
    }
    if(ends != 2) return false;
    ring.assign(1, start);
    int previous = -1, current = start;
    while(ring.size() <= around.size()) {
      const std::vector<int>& next = link[current];
      const int v = next[0] != previous ? next[0] : (next.size() > 1 ? next[1] : -1);
      if(v < 0) break;
      previous = current; current = v;
      ring.push_back(v);
    }
    return ring.size() == around.size() + 1 && link[ring.back()].size() == 1;
  }

  // the vertices around edge ab in cyclic order; false if the tetrahedra do not close a ring
  bool order_ring(int a, int b, const Tet_list& around, std::vector<int>& ring) const
  {
    std::vector<std::array<int, 2> > links;
    for(int t : around) {
      std::array<int, 2> l{ -1, -1 };
      int k = 0;
      for(int v : tets_[t]) if(v != a && v != b) l[k++] = v;
      links.push_back(l);
    }
    ring.assign(1, links[0][0]);
    int next = links[0][1];
    std::vector<char> used(links.size(), 0);
    used[0] = 1;
    for(std::size_t step = 1; step < links.size(); ++step) {
      ring.push_back(next);
      bool found = false;
      for(std::size_t e = 0; e < links.size() && !found; ++e) {
        if(used[e]) continue;
        if(links[e][0] == next) { next = links[e][1]; used[e] = 1; found = true; }
        else if(links[e][1] == next) { next = links[e][0]; used[e] = 1; found = true; }
      }
      if(!found) return false;
    }
    return next == ring[0];
  }

  void add(const std::array<int, 4>& t, const Flip_measure& m)
  {
    const int id = int(tets_.size());
    tets_.push_back(t);
    measure_.push_back(m);
    alive_.push_back(1);
    tried_.push_back(-1);
    for(int v : t) incident_[v].push_back(id);
  }

  void remove(int id)
  {
    alive_[id] = 0;
    for(int v : tets_[id]) {
      std::vector<int>& l = incident_[v];
      l.erase(std::find(l.begin(), l.end(), id));   // keeps the order of creation
    }
  }

  Tetrahedral_mesh_3<Point_3>& mesh_;
  const FrameField& field_;
  const Flip_options& o_;
  std::vector<std::array<int, 4> > tets_;
  mutable std::vector<Flip_measure> measure_;
  std::vector<char> alive_;
  // flips done so far; per vertex the flip that last changed its tetrahedra; per tetrahedron the
  // clock of its last unsuccessful try (-1: none)
  long clock_ = 0;
  std::vector<long> changed_, tried_;
  // per edge (a, b), as remove_edge() was asked, the clock of its last unsuccessful removal
  std::unordered_map<std::uint64_t, long> failed_removals_;
  std::vector<char> around_;   // with Flip_options::around: the vertices around the flagged ones
  std::vector<std::vector<int> > incident_;   // per vertex, its live tetrahedra
  bool boundary_changed_ = false;
  bool looking_in_parallel_ = false;   // measured() does not store
};

} // namespace internal

namespace internal {

// see flip_tetrahedra()
template <typename Point_3, typename FrameField>
Flip_result flip_tetrahedra(Tetrahedral_mesh_3<Point_3>& mesh, const FrameField& field,
                            const Flip_options& o)
{
  typedef internal::Flip_mesh<Point_3, FrameField> Flip_mesh;
  if(!o.around.empty() && o.around.size() != mesh.points.size())
    throw std::invalid_argument("flip_tetrahedra(): around_vertices() needs one flag per vertex");
  Flip_mesh fm(mesh, field, o);
  Flip_result result;
  auto run = [&](typename Flip_mesh::Criterion c) {
    for(int pass = 0; pass < o.max_passes; ++pass) {
      const std::size_t before = result.total();
      fm.try_all(fm.candidates(c), c, result);
      if(result.total() == before) break;
    }
  };
  if(fm.has_shape()) { fm.forget_tries(); run(Flip_mesh::SHAPE); }
  fm.forget_tries();
  run(Flip_mesh::ANGLE);
  fm.commit();
  return result;
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Flips

Improves the connectivity of a tetrahedral mesh by topological flips: 2-3 flips of interior faces
and removals of interior edges (3-2 and 4-4 flips, and the general edge removal with the best
triangulation of the edge's ring), measured in the isotropic space of `field` (B at each
tetrahedron's centroid). When `edge_length` is given, flips first lower the
sum of the shape energies (`lattice_shape_energy()`) of the tetrahedra they replace, so that each
mapped tetrahedron approaches a lattice tetrahedron: a Delaunay tetrahedralization ignores the
field, this makes the connectivity follow it. Such a flip may not take the smallest angle below
`floor_angle`. Then faces and edges of tetrahedra below `target_angle` are flipped when that
raises the smallest dihedral angle of the tetrahedra replaced. Flips never create an inverted
tetrahedron (exact orientation tests) and keep the boundary surface: interior flips leave
boundary faces and edges alone; a boundary edge is flipped (2-2, with its two boundary faces)
only where these lie in one plane, for a tetrahedron below `floor_angle` in the angle pass
(`boundary_flatness`) and for an inverted one, which then changes `boundary_faces`. Inverted
or flat tetrahedra in the input (the mesh as a complex is otherwise valid) count as the worst of
all, so that flips remove them where they can, there also by 2-2 flips of two boundary faces
within 1 degree of one plane; `target_angle(0)` does only that.

\tparam FrameField a model of `FrameField_3`

\cgalNamedParamsBegin
  \cgalParamNBegin{edge_length}
    \cgalParamDescription{l*: with it, flips first make the mapped tetrahedra approach those of `lattice` at this cube edge (not for `Lattice_type::GAUSSIAN`, which forms no lattice)}
    \cgalParamType{double}
    \cgalParamDefault{0: no lattice, only the smallest angle is raised}
  \cgalParamNEnd
  \cgalParamNBegin{lattice}
    \cgalParamDescription{the lattice whose tetrahedra the mapped tetrahedra should match}
    \cgalParamType{`Lattice_type`}
    \cgalParamDefault{`Lattice_type::BCC`}
  \cgalParamNEnd
  \cgalParamNBegin{shape_tolerance}
    \cgalParamDescription{tetrahedra whose shape energy is below this are taken as lattice tetrahedra and not tried}
    \cgalParamType{double}
    \cgalParamDefault{0.05}
  \cgalParamNEnd
  \cgalParamNBegin{floor_angle}
    \cgalParamDescription{shape-matching flips may not take the smallest angle of the tetrahedra they replace below this (or below its current value if that is lower); degrees}
    \cgalParamType{double}
    \cgalParamDefault{40}
  \cgalParamNEnd
  \cgalParamNBegin{target_angle}
    \cgalParamDescription{then faces and edges of tetrahedra whose smallest dihedral angle is below this are tried for a higher smallest angle; 0 only removes inverted tetrahedra}
    \cgalParamType{double}
    \cgalParamDefault{50}
  \cgalParamNEnd
  \cgalParamNBegin{boundary_flatness}
    \cgalParamDescription{a tetrahedron below `floor_angle` may 2-2 flip one of its boundary edges whose two boundary faces lie in one plane, the sine of the angle between their normals below this; 0: boundary faces are flipped only to remove inverted tetrahedra}
    \cgalParamType{double}
    \cgalParamDefault{1e-6}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_passes}
    \cgalParamDescription{passes over the candidates of each criterion}
    \cgalParamType{int}
    \cgalParamDefault{8}
  \cgalParamNEnd
  \cgalParamNBegin{around_vertices}
    \cgalParamDescription{one flag per vertex of `mesh`: only the tetrahedra with a vertex that shares a tetrahedron with a flagged one are tried, and the others once a flip changes a tetrahedron around them (after an earlier `flip_tetrahedra()` with the same parameters, when only the flagged vertices have moved since: the others would fail again)}
    \cgalParamType{`std::vector<bool>`}
    \cgalParamDefault{empty: every tetrahedron}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{OpenMP threads that look for the flips of consecutive candidates at once; the flips are made in the candidates' order, so they are the same for any number of threads}
    \cgalParamType{int}
    \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_ring_size}
    \cgalParamDescription{edges with more incident tetrahedra than this are not removed (the ring's triangulations grow as the Catalan numbers)}
    \cgalParamType{int}
    \cgalParamDefault{7}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument naming the named parameter that is out of range
*/
template <typename Point_3, typename FrameField,
          typename NamedParameters = parameters::Default_named_parameters>
Flip_result flip_tetrahedra(Tetrahedral_mesh_3<Point_3>& mesh, const FrameField& field,
                            const NamedParameters& np = parameters::default_values())
{
  return internal::flip_tetrahedra(mesh, field, internal::flip_options(np));
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_FLIP_TETRAHEDRA_H
