// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_COLLAPSE_EDGES_H
#define CGAL_LATTICE_MESHER_3_COLLAPSE_EDGES_H

#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>
#include <CGAL/Lattice_mesher_3/smooth_vertices.h>
#include <CGAL/Lattice_mesher_3/internal/stage_parameters.h>

#include <CGAL/Kernel/global_functions_3.h>
#include <CGAL/enum.h>
#include <CGAL/number_type_config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

namespace internal {

// Settings of collapse_edges().
struct Collapse_options
{
  /// The edges of tetrahedra whose smallest dihedral angle (isotropic space, degrees) is below
  /// this are tried.
  double floor_angle = 40.;
  /// Boundary vertices of tetrahedra below this angle are contracted too, into a neighbour on
  /// the boundary; 0 keeps every boundary vertex.
  double boundary_angle = 0.;
  /// ... if no boundary face around the vertex turns by more than this (degrees), so that the
  /// boundary keeps its shape.
  double boundary_turn = 30.;
  /// ... and a vertex on a sharp edge or at a corner too, into a neighbour on the boundary at
  /// most this fraction of the tetrahedron's longest edge away: features closer together than
  /// the lattice can resolve (those of a coarse or noisy surface) give up a vertex.
  double short_edge_ratio = 0.25;
};

template <typename NamedParameters>
Collapse_options collapse_options(const NamedParameters& np)
{
  Collapse_options o;
  read_parameter(np, internal_np::floor_angle, o.floor_angle);
  read_parameter(np, internal_np::boundary_angle, o.boundary_angle);
  read_parameter(np, internal_np::boundary_turn_angle, o.boundary_turn);
  read_parameter(np, internal_np::short_edge_ratio, o.short_edge_ratio);
  if(!(o.boundary_angle >= 0.) || !(o.boundary_turn >= 0.) || !(o.short_edge_ratio >= 0.))
    throw std::invalid_argument("collapse_edges(): boundary_angle(), boundary_turn_angle() and short_edge_ratio() must be at least 0");
  return o;
}

} // namespace internal

namespace internal {

// The link of vertex v in a tetrahedral mesh whose boundary is closed by a vertex at infinity
// (-1): the faces opposite v in its tetrahedra, and for each boundary face at v its opposite
// edge joined to -1; with all their edges and vertices.
struct Vertex_link
{
  std::set<std::array<int, 3> > triangles;
  std::set<std::array<int, 2> > edges;
  std::set<int> vertices;

  void add(std::array<int, 3> f)
  {
    std::sort(f.begin(), f.end());
    triangles.insert(f);
    edges.insert({ f[0], f[1] }); edges.insert({ f[0], f[2] }); edges.insert({ f[1], f[2] });
    vertices.insert(f.begin(), f.end());
  }
};

// The link condition for contracting the edge (a, b) (Dey, Edelsbrunner, Guha and Nekhayev,
// "Topology preserving edge contraction", 1999): the links of a and b meet in the link of the
// edge only, so that the contracted mesh is a manifold (with boundary) of the same topology.
template <typename Tets, typename Faces>
bool link_condition(int a, int b, const std::vector<int>& star_a, const std::vector<int>& star_b,
                    const std::vector<int>& faces_a, const std::vector<int>& faces_b,
                    const Tets& tets, const Faces& faces)
{
  auto link = [&](int v, const std::vector<int>& star, const std::vector<int>& around) {
    Vertex_link l;
    for(int s : star) {
      std::array<int, 3> f; int k = 0;
      for(int u : tets[s]) if(u != v) f[k++] = u;
      l.add(f);
    }
    for(int s : around) {
      std::array<int, 3> f{ -1, -1, -1 }; int k = 1;
      for(int u : faces[s]) if(u != v) f[k++] = u;
      l.add(f);
    }
    return l;
  };
  const Vertex_link la = link(a, star_a, faces_a), lb = link(b, star_b, faces_b);
  // the link of the edge: the other two vertices of its tetrahedra and boundary faces
  std::set<std::array<int, 2> > edge_edges;
  std::set<int> edge_vertices;
  auto other = [&](const auto& cell, std::array<int, 2> e) {
    int k = 0;
    for(int u : cell) if(u != a && u != b) e[k++] = u;
    std::sort(e.begin(), e.end());
    edge_edges.insert(e);
    edge_vertices.insert(e.begin(), e.end());
  };
  for(int s : star_a) if(std::find(tets[s].begin(), tets[s].end(), b) != tets[s].end()) other(tets[s], { -1, -1 });
  for(int s : faces_a) if(std::find(faces[s].begin(), faces[s].end(), b) != faces[s].end()) other(faces[s], { -1, -1 });
  for(const std::array<int, 3>& f : la.triangles) if(lb.triangles.count(f)) return false;
  for(const std::array<int, 2>& e : la.edges) if(lb.edges.count(e) && !edge_edges.count(e)) return false;
  for(int v : la.vertices) if(lb.vertices.count(v) && !edge_vertices.count(v)) return false;
  return true;
}

} // namespace internal

namespace internal {

// see collapse_edges()
template <typename Point_3, typename FrameField>
std::size_t collapse_edges(Tetrahedral_mesh_3<Point_3>& mesh, const FrameField& field,
                           const Collapse_options& o)
{
  if(mesh.vertex_kinds.size() != mesh.points.size())
    throw std::invalid_argument("collapse_edges(): the mesh needs one particle kind per vertex");
  typedef std::array<Point_3, 4> Corners;
  auto angle_of = [&](const Corners& t) {
    const std::array<Eigen::Vector3d, 4> p = internal::isotropic_tetrahedron(field, t);
    return smallest_dihedral_angle(p[0], p[1], p[2], p[3]);
  };
  auto corners = [&](const std::array<int, 4>& t) {
    return Corners{ mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]] };
  };
  // Vertices on no boundary face go: the link of a vertex of a boundary face is not a sphere, and
  // a free particle may lie on the boundary where the tetrahedralization exposed it; a boundary
  // particle it left inside (femur: 0.12 l* from another, in a star of four) goes too. Only free
  // ones move, since the others are held to the surface.
  std::vector<char> inside(mesh.points.size(), 1);
  for(const std::array<int, 3>& f : mesh.boundary_faces)
    for(int v : f) inside[v] = 0;
  // boundary faces at each vertex, and the boundary vertices that may go
  std::vector<std::vector<int> > faces_at(mesh.points.size());
  for(std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
    for(int v : mesh.boundary_faces[f]) faces_at[v].push_back(int(f));
  std::vector<char> surface(mesh.points.size(), 0);
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    surface[v] = !faces_at[v].empty() && (mesh.vertex_kinds[v] == Particle_kind::BOUNDARY || mesh.vertex_kinds[v] == Particle_kind::FREE);
  std::vector<std::vector<int> > star(mesh.points.size());
  std::vector<double> angle(mesh.tets.size());
  std::vector<std::pair<double, int> > worst;
  for(std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for(int v : mesh.tets[t]) star[v].push_back(int(t));
    angle[t] = angle_of(corners(mesh.tets[t]));
    if(angle[t] < o.floor_angle) worst.emplace_back(angle[t], int(t));
  }
  std::sort(worst.begin(), worst.end());
  auto contains = [](const std::array<int, 4>& t, int v) { return std::find(t.begin(), t.end(), v) != t.end(); };

  // The star of b after a is merged into it, as corners with b's slot marked: the cones over
  // a's link, and b's own tetrahedra but those around the edge.
  struct Star_tet { Corners p; int k; double angle; };
  struct Score { double worst; int below; };
  auto merged_star = [&](int a, int b, std::vector<Star_tet>& out) {
    out.clear();
    for(int v : { a, b })
      for(int s : star[v]) {
        const std::array<int, 4>& t = mesh.tets[s];
        if(contains(t, v == a ? b : a)) continue;
        Star_tet e{ corners(t), int(std::find(t.begin(), t.end(), v) - t.begin()), 0. };
        out.push_back(e);
      }
  };
  auto better = [](const Score& x, const Score& y) { return x.worst > y.worst + 1e-9; };
  // smallest angle and count below the floor with b at `at`, or worst -1 if a tetrahedron is
  // not positive or, once one angle shows that the star cannot be `better()` than `bound`,
  // abandoned there: a search of b's place makes ~50 such tries over stars of ~40 tetrahedra,
  // each evaluating the field (fig9 BCC: contractions took 6.8 of 12.3 s of the mesh stage)
  auto score = [&](std::vector<Star_tet>& st, const Point_3& at, const Score& bound) {
    Score r{ 180., 0 };
    for(Star_tet& e : st) {
      e.p[e.k] = at;
      if(CGAL::orientation(e.p[0], e.p[1], e.p[2], e.p[3]) != CGAL::POSITIVE) return Score{ -1., 0 };
      e.angle = angle_of(e.p);
      if(!better(Score{ e.angle, 0 }, bound)) return Score{ -1., 0 };
      r.worst = (std::min)(r.worst, e.angle);
      r.below += e.angle < o.floor_angle;
    }
    return r;
  };
  // after an evaluation in full, the worst tetrahedra first: a try that loses usually loses on them
  auto worst_first = [](std::vector<Star_tet>& st) {
    std::stable_sort(st.begin(), st.end(), [](const Star_tet& x, const Star_tet& y) { return x.angle < y.angle; });
  };
  const Score unbounded{ -HUGE_VAL, 0 };
  // where b goes, and its score
  std::vector<Star_tet> st;
  auto place = [&](int a, int b, Point_3& at) {
    merged_star(a, b, st);
    at = mesh.points[b];
    Score best = score(st, at, unbounded);
    if(!inside[b] || mesh.vertex_kinds[b] != Particle_kind::FREE) return best;
    const Point_3 mid = CGAL::midpoint(mesh.points[a], mesh.points[b]);
    const Score m = score(st, mid, best);
    if(better(m, best)) { best = m; at = mid; }
    else score(st, at, unbounded);   // the angles of the place kept, to order the star by
    const Eigen::Matrix3d map = internal::isotropic_map_at<Point_3>(field, internal::to_eigen(at));
    double mean_edge = 0.;
    for(const Star_tet& e : st)
      for(int i = 0; i < 4; ++i)
        if(i != e.k) mean_edge += (map * (internal::to_eigen(e.p[i]) - internal::to_eigen(at))).norm() / (3. * st.size());
    std::vector<Eigen::Vector3d> directions = internal::axis_and_diagonal_directions();
    for(Eigen::Vector3d& d : directions) d /= (map * d).norm();   // unit isotropic length
    worst_first(st);
    internal::pattern_search(internal::to_eigen(at), directions, mean_edge, [&](const Eigen::Vector3d& y, Eigen::Vector3d& x) {
      const Point_3 candidate(y[0], y[1], y[2]);
      const Score c = score(st, candidate, best);
      if(!better(c, best)) return false;
      best = c; at = candidate; x = y;
      worst_first(st);
      return true;
    });
    return best;
  };

  // the boundary faces at a, moved to b, turn by at most o.boundary_turn
  const double min_cos = std::cos(o.boundary_turn * CGAL_PI / 180.);
  auto keeps_boundary = [&](int a, int b) {
    for(int f : faces_at[a]) {
      const std::array<int, 3>& u = mesh.boundary_faces[f];
      if(std::find(u.begin(), u.end(), b) != u.end()) continue;
      std::array<Eigen::Vector3d, 3> p, q;
      for(int i = 0; i < 3; ++i) { p[i] = internal::to_eigen(mesh.points[u[i]]); q[i] = u[i] == a ? internal::to_eigen(mesh.points[b]) : p[i]; }
      const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]), m = (q[1] - q[0]).cross(q[2] - q[0]);
      if(!(n.dot(m) >= min_cos * n.norm() * m.norm())) return false;
    }
    return true;
  };
  std::vector<char> dead(mesh.tets.size(), 0), removed(mesh.points.size(), 0), dead_face(mesh.boundary_faces.size(), 0);
  std::size_t collapses = 0;
  for(const std::pair<double, int>& w : worst) {
    if(dead[w.second] || angle[w.second] >= o.floor_angle) continue;
    const std::array<int, 4> t = mesh.tets[w.second];
    const bool at_boundary = angle[w.second] < o.boundary_angle;
    int best_a = -1, best_b = -1;
    Point_3 best_at;
    Score best{ -1., 0 };
    // a boundary a goes into a boundary b: a sharp-edge or corner a only along a short edge
    auto boundary_merge = [&](int a, int b) {
      if(faces_at[b].empty()) return false;
      if(!surface[a]) {
        double longest = 0.;
        for(int i = 0; i < 4; ++i)
          for(int j = i + 1; j < 4; ++j) longest = (std::max)(longest, CGAL::squared_distance(mesh.points[t[i]], mesh.points[t[j]]));
        if(CGAL::squared_distance(mesh.points[a], mesh.points[b]) > o.short_edge_ratio * o.short_edge_ratio * longest) return false;
      }
      return keeps_boundary(a, b) &&
             internal::link_condition(a, b, star[a], star[b], faces_at[a], faces_at[b], mesh.tets, mesh.boundary_faces);
    };
    for(int a : t) {
      if(!inside[a] && !(at_boundary && !faces_at[a].empty())) continue;
      for(int b : t) {
        if(b == a || (!inside[a] && !boundary_merge(a, b))) continue;
        Score before{ 180., 0 };
        for(int v : { a, b })
          for(int s : star[v])
            if(v == a || !contains(mesh.tets[s], a)) {
              before.worst = (std::min)(before.worst, angle[s]);
              before.below += angle[s] < o.floor_angle;
            }
        Point_3 at;
        const Score c = place(a, b, at);
        if(better(c, before) && c.below <= before.below && better(c, best)) { best = c; best_a = a; best_b = b; best_at = at; }
      }
    }
    if(best_a < 0) continue;
    for(int s : star[best_a]) {
      std::array<int, 4>& u = mesh.tets[s];
      if(contains(u, best_b)) {
        dead[s] = 1;
        for(int v : u)
          if(v != best_a) star[v].erase(std::find(star[v].begin(), star[v].end(), s));
      } else {
        *std::find(u.begin(), u.end(), best_a) = best_b;
        star[best_b].push_back(s);
      }
    }
    for(int f : faces_at[best_a]) {
      std::array<int, 3>& u = mesh.boundary_faces[f];
      if(std::find(u.begin(), u.end(), best_b) != u.end()) {
        dead_face[f] = 1;
        for(int v : u)
          if(v != best_a) faces_at[v].erase(std::find(faces_at[v].begin(), faces_at[v].end(), f));
      } else {
        *std::find(u.begin(), u.end(), best_a) = best_b;
        faces_at[best_b].push_back(f);
      }
    }
    faces_at[best_a].clear();
    star[best_a].clear();
    removed[best_a] = 1;
    mesh.points[best_b] = best_at;
    for(int s : star[best_b]) angle[s] = angle_of(corners(mesh.tets[s]));
    ++collapses;
  }
  if(collapses == 0) return 0;

  std::size_t live = 0;
  for(std::size_t s = 0; s < mesh.tets.size(); ++s)
    if(!dead[s]) mesh.tets[live++] = mesh.tets[s];
  mesh.tets.resize(live);
  live = 0;
  for(std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
    if(!dead_face[f]) mesh.boundary_faces[live++] = mesh.boundary_faces[f];
  mesh.boundary_faces.resize(live);
  internal::remove_vertices(mesh, removed);
  return collapses;
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Flips

Removes vertices at the worst tetrahedra by contracting one of their edges. Where a lattice
defect (a dislocation of a rotating field, an extra particle where the lattice meets a curved
boundary) leaves a cluster of bad tetrahedra sharing their vertices, neither a flip nor a move of
one vertex raises the worst of them; removing the extra vertex can. A vertex `a` of a
tetrahedron below `floor_angle` that is on no boundary face (a free particle, or a boundary one
that the tetrahedralization left inside) is merged into another vertex `b` of it: the tetrahedra around
the edge go, the others of `a`'s star become cones from `b` over `a`'s link. A free `b` inside is
then placed where the smallest angle of its new star is largest (the pattern search of
`smooth_vertices()` over the axis and diagonal directions, from `b` or the edge's midpoint); a boundary, sharp-edge or fixed `b` stays, so the boundary does not change. A
contraction is made only if every tetrahedron of the new star is positively oriented (exact
orientation tests: the cones then tile `a`'s star, so the mesh stays valid), its smallest angle
(isotropic space of `field`, B at each centroid) is above that of the stars of `a` and `b`
together, and it has no more tetrahedra below the floor; of the edges of a tetrahedron, the one
whose new star is best. Worst tetrahedra first.

With `boundary_angle` set, a vertex of the boundary that is on no sharp edge or corner, of a
tetrahedron below that angle, may also be merged into a neighbour `b` on the boundary, which
stays (a sharp-edge or corner vertex too if `b` is at most `short_edge_ratio` times the
tetrahedron's longest edge away): the boundary faces at `a` become faces at `b`. This removes the slivers whose four
vertices the surface holds, made by a short boundary edge (two particles projected close
together where the domain is thin or curved), that no flip or move within the surface raises.
Such a contraction is made only if it meets the link condition (the mesh stays a manifold with
the same topology), no boundary face turns by more than `boundary_turn_angle`, and the same
conditions on the new star as above hold. Vertices are renumbered (the others keep their order).
Needs `mesh.vertex_kinds`.

\tparam FrameField a model of `FrameField_3`

\cgalNamedParamsBegin
  \cgalParamNBegin{floor_angle}
    \cgalParamDescription{the edges of tetrahedra whose smallest dihedral angle (isotropic space, degrees) is below this are tried}
    \cgalParamType{double}
    \cgalParamDefault{40}
  \cgalParamNEnd
  \cgalParamNBegin{boundary_angle}
    \cgalParamDescription{boundary vertices of tetrahedra below this angle are contracted too, into a neighbour on the boundary; 0 keeps every boundary vertex}
    \cgalParamType{double}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{boundary_turn_angle}
    \cgalParamDescription{... if no boundary face around the vertex turns by more than this (degrees), so that the boundary keeps its shape}
    \cgalParamType{double}
    \cgalParamDefault{30}
  \cgalParamNEnd
  \cgalParamNBegin{short_edge_ratio}
    \cgalParamDescription{... and a vertex on a sharp edge or at a corner too, into a neighbour on the boundary at most this fraction of the tetrahedron's longest edge away}
    \cgalParamType{double}
    \cgalParamDefault{0.25}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of removed vertices
\throws std::invalid_argument without a particle kind per vertex, or for a named parameter out of range
*/
template <typename Point_3, typename FrameField,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t collapse_edges(Tetrahedral_mesh_3<Point_3>& mesh, const FrameField& field,
                           const NamedParameters& np = parameters::default_values())
{
  return internal::collapse_edges(mesh, field, internal::collapse_options(np));
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_COLLAPSE_EDGES_H
