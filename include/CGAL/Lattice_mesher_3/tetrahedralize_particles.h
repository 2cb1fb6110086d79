// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_TETRAHEDRALIZE_PARTICLES_H
#define CGAL_LATTICE_MESHER_3_TETRAHEDRALIZE_PARTICLES_H

#include <CGAL/Lattice_mesher_traits_3.h>
#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/flip_tetrahedra.h>
#include <CGAL/Lattice_mesher_3/internal/field_sampling.h>
#include <CGAL/Lattice_mesher_3/internal/isotropic_embedding.h>
#include <CGAL/Lattice_mesher_3/internal/stage_parameters.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/centroid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

namespace internal {

// Settings of tetrahedralize_particles().
struct Tetrahedralization_options
{
  /// A cell whose vertices all lie on the boundary is kept only if its centroid is at least this
  /// fraction of its mean edge length inside: flat cells spanning a face add no volume, only slivers.
  double flat_cell_ratio = 0.1;
  /// ... or if it is a wedge along a sharp edge: two of its vertices on feature curves (sharp-edge
  /// or corner particles) and its smallest dihedral angle (isotropic space, degrees) at least
  /// this. The wedge between an edge's two faces is no sliver, but under a stretch its centroid
  /// may lie as close to the surface (fig9 BCC: smallest angles 27-35 degrees, ratios 0.09-0.1):
  /// dropped, it left the edge chamfered (Hausdorff 0.25 to the cube of side 10). A cell that
  /// the manifold repair puts back needs the same smallest angle.
  double wedge_angle = 20.;
  /// l*, which sets the neighbourhood (1.3 l*) of the isotropic embedding under a varying
  /// stretch and the depth of the pits filled; 0: estimated from the number of particles and
  /// the isotropic volume
  double edge_length = 0.;
  /// A boundary vertex that is an interior particle more than this times l* from the surface
  /// (isotropic space) sits in a pit, where the surface particles left a gap: a boundary particle
  /// at the nearest surface point fills it (0: none). The manifold repair puts back the cells it
  /// did not need to remove where their boundary faces between surface particles (centroids and
  /// edge midpoints) lie within this times l* of the surface.
  double pit_depth = 0.25;
  int threads = 1;
};

template <typename NamedParameters>
Tetrahedralization_options tetrahedralization_options(const NamedParameters& np)
{
  Tetrahedralization_options o;
  read_parameter(np, internal_np::flatness_ratio, o.flat_cell_ratio);
  read_parameter(np, internal_np::wedge_angle, o.wedge_angle);
  read_parameter(np, internal_np::edge_length, o.edge_length);
  read_parameter(np, internal_np::number_of_threads, o.threads);
  if(!(o.flat_cell_ratio >= 0.) || !(o.wedge_angle >= 0.) || !(o.edge_length >= 0.) || !std::isfinite(o.edge_length) || o.threads < 1)
    throw std::invalid_argument("tetrahedralize_particles(): flatness_ratio(), wedge_angle() and edge_length() must be at least 0 and number_of_threads() at least 1");
  return o;
}

} // namespace internal

namespace internal {

// The cells around v (its star), by a walk through the faces that hold v: the triangulation's
// own incident_cells() marks the cells it visits, which threads cannot share.
template <typename Vertex_handle, typename Cell_handle>
void star_of(Vertex_handle v, std::vector<Cell_handle>& cells)
{
  cells.assign(1, v->cell());
  for(std::size_t k = 0; k < cells.size(); ++k) {
    const Cell_handle c = cells[k];
    const int iv = c->index(v);
    for(int i = 0; i < 4; ++i) {
      if(i == iv) continue;
      const Cell_handle nb = c->neighbor(i);
      if(std::find(cells.begin(), cells.end(), nb) == cells.end()) cells.push_back(nb);
    }
  }
}

// Whether v is manifold: the kept cells of its star (info 1), connected through the faces that
// hold v, form one component, and the others one.
template <typename Vertex_handle, typename Cell_handle>
bool manifold_vertex(Vertex_handle v, const std::vector<Cell_handle>& star)
{
  std::vector<char> reached(star.size(), 0);
  for(char side = 0; side < 2; ++side) {
    int components = 0;
    for(std::size_t s = 0; s < star.size(); ++s) {
      if(star[s]->info() != side || reached[s]) continue;
      if(++components > 1) return false;
      std::vector<std::size_t> stack(1, s);
      reached[s] = 1;
      while(!stack.empty()) {
        const Cell_handle c = star[stack.back()];
        stack.pop_back();
        const int iv = c->index(v);
        for(int i = 0; i < 4; ++i) {
          if(i == iv || c->neighbor(i)->info() != side) continue;
          const std::size_t k = std::size_t(std::find(star.begin(), star.end(), c->neighbor(i)) - star.begin());
          if(!reached[k]) { reached[k] = 1; stack.push_back(k); }
        }
      }
    }
  }
  return true;
}

// The distance from g to the domain's surface in the isotropic space of b.
template <typename Domain, typename Point_3>
double isotropic_surface_distance(const Domain& domain, const Mat3& b, const Point_3& g)
{
  return (b * (to_eigen(g) - to_eigen(domain.project_on_surface(g).point))).norm();
}

// Whether the edge e is in at most two boundary faces: around it, the kept cells (info 1) and
// the others form at most one run each. `ring` receives the cells around e.
template <typename Dt>
bool manifold_edge(const Dt& dt, const typename Dt::Edge& e, std::vector<typename Dt::Cell_handle>& ring)
{
  ring.clear();
  auto cc = dt.incident_cells(e), done = cc;
  do { ring.push_back(cc); ++cc; } while(cc != done);
  int changes = 0;
  for(std::size_t r = 0; r < ring.size(); ++r) changes += ring[r]->info() != ring[(r + 1) % ring.size()]->info();
  return changes <= 2;
}

// The kept cells (info 1) around the edges in more than two boundary faces and the vertices whose
// boundary faces form several fans. Only the edges and vertices of boundary faces can be such:
// each is looked at once, by all threads at once.
template <typename Dt>
std::set<typename Dt::Cell_handle> cells_around_non_manifold(const Dt& dt, int threads)
{
  typedef typename Dt::Cell_handle Cell_handle;
  typedef typename Dt::Vertex_handle Vertex_handle;
  typedef typename Dt::Edge Edge;
  std::vector<Edge> edges;
  std::vector<Vertex_handle> vertices;
  for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    if(!c->info()) continue;
    for(int i = 0; i < 4; ++i) {
      if(c->neighbor(i)->info()) continue;
      for(int a = 0; a < 4; ++a) {
        if(a == i) continue;
        vertices.push_back(c->vertex(a));
        for(int b = a + 1; b < 4; ++b) if(b != i) edges.emplace_back(Cell_handle(c), a, b);
      }
    }
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  auto key = [](const Edge& e) {
    const Vertex_handle a = e.first->vertex(e.second), b = e.first->vertex(e.third);
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  };
  std::sort(edges.begin(), edges.end(), [&](const Edge& x, const Edge& y) { return key(x) < key(y); });
  edges.erase(std::unique(edges.begin(), edges.end(), [&](const Edge& x, const Edge& y) { return key(x) == key(y); }), edges.end());
  std::set<Cell_handle> cells;
#pragma omp parallel num_threads(threads)
  {
    std::vector<Cell_handle> ring, star, found;
#pragma omp for schedule(dynamic, 256) nowait
    for(std::ptrdiff_t k = 0; k < std::ptrdiff_t(edges.size()); ++k) {
      if(!manifold_edge(dt, edges[k], ring))
        for(Cell_handle c : ring) if(c->info()) found.push_back(c);
    }
#pragma omp for schedule(dynamic, 256)
    for(std::ptrdiff_t k = 0; k < std::ptrdiff_t(vertices.size()); ++k) {
      star_of(vertices[k], star);
      if(!manifold_vertex(vertices[k], star))
        for(Cell_handle c : star) if(c->info()) found.push_back(c);
    }
#pragma omp critical(lattice_mesher_3_tetrahedralize)
    cells.insert(found.begin(), found.end());
  }
  return cells;
}

// Whether the boundary of the kept cells (info 1) is manifold at the edges and vertices of c.
template <typename Dt>
bool manifold_around(const Dt& dt, typename Dt::Cell_handle c)
{
  std::vector<typename Dt::Cell_handle> cells;
  for(int a = 0; a < 4; ++a)
    for(int b = a + 1; b < 4; ++b)
      if(!manifold_edge(dt, typename Dt::Edge(c, a, b), cells)) return false;
  for(int a = 0; a < 4; ++a) {
    star_of(c->vertex(a), cells);
    if(!manifold_vertex(c->vertex(a), cells)) return false;
  }
  return true;
}

// Puts the removed cells `group` back together (info 1) if, with all of them in, the boundary
// is manifold around each and `may_return` accepts each; otherwise leaves them out. Returns
// whether they went in.
template <typename Dt, typename Cells, typename MayReturn>
bool put_back(const Dt& dt, const Cells& group, const MayReturn& may_return)
{
  for(const auto& c : group) c->info() = 1;
  bool back = true;   // the combinatorial test first: the caller's test projects
  for(auto c = group.begin(); c != group.end() && back; ++c) back = manifold_around(dt, *c) && may_return(*c);
  if(!back) for(const auto& c : group) c->info() = 0;
  return back;
}

// Makes the boundary of the kept cells (info 1) of dt manifold by removing the kept cells around
// each non-manifold edge or vertex that have a face on the boundary (peeling), repeated until
// nothing changes: each pass removes cells, so it ends, but where the domain is thin one removal
// may expose the next (cheese and rotor at 3,000 vertices: more than 20 passes), hence the
// generous bound. Then the removed cells go back, one at a time, wherever the boundary stays
// manifold around them and `may_return(c)` accepts the cell (kept while it is asked): of all the
// cells around a non-manifold place, most were not needed to go, and those that held an interior
// particle left it on the boundary, a pit one cell deep (bunny, FCC in its cross field, 60,000
// vertices: 12 such particles, the deepest 0.020 from the surface, the mesh's Hausdorff
// distance). The cells go back in the order of their vertices' infos (the particles), not of
// their addresses.
template <typename Dt, typename MayReturn>
void make_boundary_manifold(Dt& dt, std::set<typename Dt::Cell_handle>& wedges, const MayReturn& may_return, int threads)
{
  typedef typename Dt::Cell_handle Cell_handle;
  auto is_boundary_facet = [](Cell_handle c, int i) { return c->info() != c->neighbor(i)->info(); };
  std::vector<Cell_handle> removed;
  for(int pass = 0; pass < 200;) {
    const std::set<Cell_handle> to_remove = cells_around_non_manifold(dt, threads);
    if(to_remove.empty()) break;
    // the wedges kept against the flat test that the boundary cannot take go first, alone: the
    // repair then goes on as without them (fandisk kept them all: Hausdorff 0.0145 -> 0.0222)
    std::vector<Cell_handle> unkept;
    for(Cell_handle c : to_remove) if(wedges.erase(c)) unkept.push_back(c);
    for(Cell_handle c : unkept) c->info() = 0;
    if(!unkept.empty()) continue;   // not counted as a pass: at most one per wedge
    // remove only cells that touch the boundary, so that repairs stay local; decided before any
    // removal, so that the result does not depend on the order of the set (cell addresses)
    std::vector<Cell_handle> touching;
    for(Cell_handle c : to_remove) {
      bool touches = false;
      for(int i = 0; i < 4; ++i) touches = touches || is_boundary_facet(c, i);
      if(touches) touching.push_back(c);
    }
    if(touching.empty()) touching.assign(to_remove.begin(), to_remove.end());
    for(Cell_handle c : touching) c->info() = 0;
    removed.insert(removed.end(), touching.begin(), touching.end());
    ++pass;
  }
  auto particles = [](Cell_handle c) {
    std::array<std::decay_t<decltype(c->vertex(0)->info())>, 4> ids{ c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info() };
    std::sort(ids.begin(), ids.end());
    return ids;
  };
  std::sort(removed.begin(), removed.end(), [&](Cell_handle a, Cell_handle b) { return particles(a) < particles(b); });
  for(bool changed = true; changed;) {   // a cell put back may let another one back
    changed = false;
    for(Cell_handle c : removed)
      if(!c->info() && put_back(dt, std::array<Cell_handle, 1>{ c }, may_return)) changed = true;
  }
}

// Closes the pits that interior particles still make in the boundary of the kept cells (info 1):
// the cells around such a particle v that are not kept go in together, so that v becomes
// interior, where v is their only interior particle (their faces opposite v, the new boundary,
// are then all between surface particles), none is infinite, the boundary stays manifold around
// each and `may_return(c)` accepts each. One cell at a time cannot fill such a pit where each
// cell alone would pinch the boundary, nor where the cells' centroids lie outside a concave
// surface. The particles are taken in the order of their infos.
template <typename Dt, typename IsInterior, typename MayReturn>
void close_pits(Dt& dt, const IsInterior& is_interior, const MayReturn& may_return)
{
  typedef typename Dt::Vertex_handle Vertex_handle;
  typedef typename Dt::Cell_handle Cell_handle;
  std::vector<Vertex_handle> exposed;   // on the boundary; the cells that go in expose no other
  for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    for(int i = 0; i < 4; ++i)
      if(c->info() && !c->neighbor(i)->info())
        for(int k = 1; k < 4; ++k)
          if(is_interior(c->vertex((i + k) & 3))) exposed.push_back(c->vertex((i + k) & 3));
  std::sort(exposed.begin(), exposed.end(), [](Vertex_handle a, Vertex_handle b) { return a->info() < b->info(); });
  exposed.erase(std::unique(exposed.begin(), exposed.end()), exposed.end());
  std::vector<Cell_handle> star, open;
  for(bool changed = true; changed;) {
    changed = false;
    for(Vertex_handle v : exposed) {
      star_of(v, star);
      open.clear();
      bool kept = false, closable = true;
      for(Cell_handle c : star) {
        if(c->info()) { kept = true; continue; }
        open.push_back(c);
        for(int i = 0; i < 4 && closable; ++i)
          closable = !dt.is_infinite(c->vertex(i)) && (c->vertex(i) == v || !is_interior(c->vertex(i)));
      }
      if(kept && !open.empty() && closable && put_back(dt, open, may_return)) changed = true;
    }
  }
}

// Whether a cell that the manifold repair removed may go back (its neighbours' infos tell which
// are kept): it must be no sliver (smallest dihedral angle in the isotropic space at least
// `wedge_angle`) and the faces it puts on the boundary between three surface particles must lie
// within `pit_depth` l* of the surface, at their centroids and edge midpoints. Without the face
// test a cell whose centroid only is inside bridges a gap of the domain (rotor at 3,000
// vertices: faces across it 1.8 l* off the surface); a face to an interior particle is exempt,
// since that particle is on the boundary already and the cells around it go back one at a time
// (a pit of several cells stayed open: bunny, FCC in its cross field, Hausdorff 0.0166 against
// 0.0103); without the angle test, such a cell may be a sliver (man at 3,000 vertices: 0.55
// degrees).
template <typename Cell_handle, typename Point_3, typename Domain, typename FrameField>
bool may_put_back(Cell_handle c, const Particle_set_3<Point_3>& ps, const Domain& domain, const FrameField& field,
                  const Tetrahedralization_options& o)
{
  auto P = [&](int i) -> const Point_3& { return ps.points[std::size_t(c->vertex(i)->info())]; };
  const Point_3 g = CGAL::centroid(P(0), P(1), P(2), P(3));
  const Mat3 b = isotropic_map(field.frame(g), g);
  std::array<Vec3, 4> q;
  for(int i = 0; i < 4; ++i) q[i] = b * to_eigen(P(i));
  if(!(smallest_dihedral_angle(q[0], q[1], q[2], q[3]) >= o.wedge_angle)) return false;
  for(int i = 0; i < 4; ++i) {
    if(c->neighbor(i)->info()) continue;
    auto on_surface = [&](int k) { return ps.kinds[std::size_t(c->vertex((i + k) & 3)->info())] != Particle_kind::FREE; };
    if(!on_surface(1) || !on_surface(2) || !on_surface(3)) continue;
    const Point_3 &u = P((i + 1) & 3), &v = P((i + 2) & 3), &w = P((i + 3) & 3);
    for(const Point_3& m : { CGAL::centroid(u, v, w), CGAL::midpoint(u, v), CGAL::midpoint(v, w), CGAL::midpoint(w, u) })
      if(!(isotropic_surface_distance(domain, isotropic_map(field.frame(m), m), m) <= o.pit_depth * o.edge_length)) return false;
  }
  return true;
}

// The Delaunay tetrahedralization of the particles placed at y, restricted to the domain and
// repaired (see tetrahedralize_particles()); every geometric test but the Delaunay one is on
// the particles' own positions.
template <typename Domain, typename FrameField, typename Point_3, typename GT>
Tetrahedral_mesh_3<Point_3> restricted_delaunay(const Particle_set_3<Point_3>& ps, const std::vector<Vec3>& y,
                                                const Domain& domain, const FrameField& field,
                                                const Tetrahedralization_options& o, const GT& gt)
{
  typedef GT K;
  typedef CGAL::Triangulation_vertex_base_with_info_3<int, K> Vb;
  typedef CGAL::Triangulation_cell_base_with_info_3<char, K> Cb;
  typedef CGAL::Triangulation_data_structure_3<Vb, Cb> Tds;
  typedef CGAL::Delaunay_triangulation_3<K, Tds> Dt;
  typedef typename Dt::Cell_handle Cell_handle;
  typedef typename Dt::Vertex_handle Vertex_handle;

  std::vector<std::pair<typename K::Point_3, int> > input(ps.size());
  for(std::size_t i = 0; i < ps.size(); ++i) input[i] = { typename K::Point_3(y[i][0], y[i][1], y[i][2]), int(i) };
  Dt dt(input.begin(), input.end(), gt);
  if(dt.dimension() < 3)
    throw std::invalid_argument("tetrahedralize_particles(): the particles are coplanar");
  auto P = [&](Vertex_handle v) -> const Point_3& { return ps.points[v->info()]; };

  auto on_boundary = [&](Vertex_handle v) { return ps.kinds[v->info()] != Particle_kind::FREE; };

  // 1. Cells inside the domain.
  std::vector<Cell_handle> cells;
  for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) cells.push_back(c);
  std::vector<char> wedge(cells.size(), 0);
  bool failed = false;
  std::string what;
#pragma omp parallel for num_threads(o.threads) schedule(dynamic, 256)
  for(std::ptrdiff_t k = 0; k < std::ptrdiff_t(cells.size()); ++k) try {
    const Cell_handle c = cells[k];
    const Point_3 g = CGAL::centroid(P(c->vertex(0)), P(c->vertex(1)), P(c->vertex(2)), P(c->vertex(3)));
    char inside = domain.is_inside(g) ? 1 : 0;
    if(inside && on_boundary(c->vertex(0)) && on_boundary(c->vertex(1)) &&
       on_boundary(c->vertex(2)) && on_boundary(c->vertex(3))) {
      // both lengths in the isotropic space: under a stretch the Euclidean edges are those of
      // the long direction, and cells along a sharp edge would all look flat
      const Mat3 b = isotropic_map(field.frame(g), g);
      std::array<Vec3, 4> q;   // the vertices mapped
      int on_curves = 0;
      for(int i = 0; i < 4; ++i) {
        q[i] = b * to_eigen(P(c->vertex(i)));
        const Particle_kind kind = ps.kinds[c->vertex(i)->info()];
        on_curves += kind == Particle_kind::SHARP_EDGE || kind == Particle_kind::FIXED;
      }
      double mean_edge = 0.;
      for(int i = 0; i < 4; ++i) for(int j = i + 1; j < 4; ++j) mean_edge += (q[i] - q[j]).norm();
      mean_edge /= 6.;
      if(isotropic_surface_distance(domain, b, g) < o.flat_cell_ratio * mean_edge) {
        wedge[k] = on_curves >= 2 && smallest_dihedral_angle(q[0], q[1], q[2], q[3]) >= o.wedge_angle;
        if(!wedge[k]) inside = 0;
      }
    }
    c->info() = inside;
  } catch(const std::exception& e) {
#pragma omp critical(lattice_mesher_3_tetrahedralize)
    { if(!failed) { failed = true; what = e.what(); } }
  }
  if(failed) throw std::domain_error(what);
  for(auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c)
    if(dt.is_infinite(c)) c->info() = 0;
  std::set<Cell_handle> wedges;
  for(std::size_t k = 0; k < cells.size(); ++k) if(wedge[k]) wedges.insert(cells[k]);

  // 2. A manifold boundary.
  auto may_return = [&](Cell_handle c) { return may_put_back(c, ps, domain, field, o); };
  make_boundary_manifold(dt, wedges, may_return, o.threads);
  close_pits(dt, [&](Vertex_handle v) { return !on_boundary(v); }, may_return);

  // 3. Output, with the particles that are used renumbered.
  Tetrahedral_mesh_3<Point_3> mesh;
  std::vector<int> index(ps.size(), -1);
  auto vid = [&](Vertex_handle v) {
    int& id = index[v->info()];
    if(id < 0) { id = int(mesh.points.size()); mesh.points.push_back(ps.points[v->info()]); mesh.vertex_kinds.push_back(ps.kinds[v->info()]); }
    return id;
  };
  for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    if(!c->info()) continue;
    mesh.tets.push_back({ vid(c->vertex(0)), vid(c->vertex(1)), vid(c->vertex(2)), vid(c->vertex(3)) });
    for(int i = 0; i < 4; ++i) {
      if(c->neighbor(i)->info()) continue;
      // (a, b, c) with the cell's own vertex d behind it: orientation(a, b, c, d) is negative
      // for the outward normal
      int a = (i + 1) & 3, b = (i + 2) & 3, d3 = (i + 3) & 3;
      if(CGAL::orientation(P(c->vertex(a)), P(c->vertex(b)), P(c->vertex(d3)), P(c->vertex(i))) != CGAL::NEGATIVE)
        std::swap(a, b);
      mesh.boundary_faces.push_back({ vid(c->vertex(a)), vid(c->vertex(b)), vid(c->vertex(d3)) });
    }
  }
  return mesh;
}

// Moves a free vertex of each inverted tetrahedron towards the centroid of its neighbours (by a
// quarter, a half, three quarters, all the way) or towards its mirror image across the opposite
// face (by 0.6, 0.8, all the way), the first move that makes every tetrahedron around it
// positive: an interior sliver of the embedding that no flip removes. Returns the number of
// inverted tetrahedra left.
template <typename Point_3>
std::size_t untangle_by_moves(Tetrahedral_mesh_3<Point_3>& mesh)
{
  const std::size_t nv = mesh.points.size();
  std::vector<std::vector<int> > around(nv);
  for(std::size_t t = 0; t < mesh.tets.size(); ++t)
    for(int v : mesh.tets[t]) around[v].push_back(int(t));
  auto positive = [&](int t) {
    const auto& q = mesh.tets[t];
    return CGAL::orientation(mesh.points[q[0]], mesh.points[q[1]], mesh.points[q[2]], mesh.points[q[3]]) == CGAL::POSITIVE;
  };
  std::size_t left = 0;
  for(std::size_t t = 0; t < mesh.tets.size(); ++t) {
    if(positive(int(t))) continue;
    bool fixed = false;
    for(int k = 0; k < 4 && !fixed; ++k) {
      const int v = mesh.tets[t][k];
      if(mesh.vertex_kinds.empty() || mesh.vertex_kinds[v] != Particle_kind::FREE) continue;
      Vec3 c = Vec3::Zero();
      int count = 0;
      for(int s : around[v]) for(int w : mesh.tets[s]) if(w != v) { c += to_eigen(mesh.points[w]); ++count; }
      c /= double(count);
      const Vec3 start = to_eigen(mesh.points[v]);
      const Vec3 a = to_eigen(mesh.points[mesh.tets[t][(k + 1) % 4]]), b = to_eigen(mesh.points[mesh.tets[t][(k + 2) % 4]]),
                 e = to_eigen(mesh.points[mesh.tets[t][(k + 3) % 4]]);
      const Vec3 normal = (b - a).cross(e - a).normalized();
      const Vec3 mirror = start - 2. * normal.dot(start - a) * normal;
      const Point_3 original = mesh.points[v];
      for(const auto& target : { std::make_pair(c, .25), std::make_pair(c, .5), std::make_pair(c, .75), std::make_pair(c, 1.),
                                 std::make_pair(mirror, .6), std::make_pair(mirror, .8), std::make_pair(mirror, 1.) }) {
        const Vec3 p = (1. - target.second) * start + target.second * target.first;
        mesh.points[v] = Point_3(p[0], p[1], p[2]);
        fixed = p.allFinite() && std::all_of(around[v].begin(), around[v].end(), positive);
        if(fixed) break;
      }
      if(!fixed) mesh.points[v] = original;
    }
    left += !fixed;
  }
  return left;
}

} // namespace internal

namespace internal {

// The surface points nearest to the boundary vertices that are interior particles more than
// `depth` l* from the surface (isotropic space), but for those within l* / 2 of a boundary vertex
// around them or of one another.
template <typename Point_3, typename Domain, typename FrameField>
std::vector<Point_3> pit_fillers(const Tetrahedral_mesh_3<Point_3>& mesh, const Domain& domain, const FrameField& field,
                                 double l, double depth)
{
  std::vector<std::vector<int> > ring(mesh.points.size());
  for(const std::array<int, 3>& f : mesh.boundary_faces)
    for(int i = 0; i < 3; ++i) ring[std::size_t(f[i])].insert(ring[std::size_t(f[i])].end(), { f[(i + 1) % 3], f[(i + 2) % 3] });
  std::vector<Point_3> fillers;
  for(std::size_t v = 0; v < mesh.points.size(); ++v) {
    if(ring[v].empty() || mesh.vertex_kinds[v] != Particle_kind::FREE) continue;
    const Point_3 q = domain.project_on_surface(mesh.points[v]).point;
    const Mat3 b = isotropic_map(field.frame(q), q);
    auto within = [&](const Point_3& p, double r) { return (b * (to_eigen(p) - to_eigen(q))).norm() < r * l; };
    if(within(mesh.points[v], depth) ||
       std::any_of(ring[v].begin(), ring[v].end(), [&](int w) { return within(mesh.points[std::size_t(w)], .5); }) ||
       std::any_of(fillers.begin(), fillers.end(), [&](const Point_3& p) { return within(p, .5); }))
      continue;
    fillers.push_back(q);
  }
  return fillers;
}

// see tetrahedralize_particles()
template <typename Domain, typename FrameField, typename Point_3, typename GT>
Tetrahedral_mesh_3<Point_3> connect_particles(const Particle_set_3<Point_3>& ps, const Domain& domain,
                                              const FrameField& field, const Tetrahedralization_options& o, const GT& gt)
{
  typedef typename Domain::Geom_traits K;
  const std::vector<internal::Vec3> x = internal::to_vectors(ps.points);
  const double l = o.edge_length;
  bool uniform = true;
  const std::vector<internal::Vec3> y = internal::isotropic_embedding<K>(x, field, 1.3 * l, o.threads, uniform);
  if(uniform) return internal::restricted_delaunay(ps, y, domain, field, o, gt);
  // A cell flat in the embedding may come out inverted: flips remove it, else a small move of a
  // free vertex. A few that resist both (slivers of nearly collinear particles along fig9's
  // circles) usually do not survive a slight change of the embedding: 5%, then 15% of the
  // particles' own positions (scaled to the mean stretch) mixed in. Failing all, the Euclidean
  // Delaunay tetrahedralization, always valid, is taken.
  double scale = 0.;
  for(std::size_t i = 0; i < x.size(); ++i) scale += (y[i] - y[0]).norm() / (std::max)((x[i] - x[0]).norm(), 1e-300);
  scale /= double(x.size());
  auto folded = [](const Tetrahedral_mesh_3<Point_3>& m) {
    std::size_t n = 0;
    for(const auto& t : m.tets)
      n += CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) != CGAL::POSITIVE;
    return n;
  };
  for(double mix : { 0., .05, .15 }) {
    std::vector<internal::Vec3> z(y);
    for(std::size_t i = 0; i < z.size(); ++i) z[i] = (1. - mix) * y[i] + mix * scale * x[i];
    Tetrahedral_mesh_3<Point_3> mesh = internal::restricted_delaunay(ps, z, domain, field, o, gt);
    const std::size_t before = folded(mesh);
    std::size_t after = before;
    if(before > 0) {
      internal::Flip_options untangle;
      untangle.target_angle = 0.;
      untangle.max_ring_size = 12;   // a handful of edges: the largest rings are affordable
      internal::flip_tetrahedra(mesh, field, untangle);
      after = folded(mesh);
      if(after > 0) after = internal::untangle_by_moves(mesh);
    }
#ifdef CGAL_LATTICE_MESHER_3_VERBOSE
    std::cerr << "  isotropic embedding (" << mix << " of the positions): " << before << " of " << mesh.tets.size()
              << " cells folded, " << after << " after flips and moves\n";
#endif
    if(after == 0) return mesh;
  }
  Tetrahedral_mesh_3<Point_3> mesh = internal::restricted_delaunay(ps, x, domain, field, o, gt);
  return mesh;
}

template <typename Domain, typename FrameField, typename Point_3, typename GT>
Tetrahedral_mesh_3<Point_3> tetrahedralize_particles(const Particle_set_3<Point_3>& ps, const Domain& domain,
                                                     const FrameField& field, const Tetrahedralization_options& options,
                                                     const GT& gt)
{
  if(ps.size() < 4)
    throw std::invalid_argument("tetrahedralize_particles(): fewer than 4 particles");
  Tetrahedralization_options o = options;
  if(!(o.edge_length > 0.))   // the cube edge of the sparsest lattice (FCC) for this many particles
    o.edge_length = std::cbrt(4. * domain.volume() * internal::sample_det_b(domain, field, 4096).mean / double(ps.size()));
  Tetrahedral_mesh_3<Point_3> mesh = connect_particles(ps, domain, field, o, gt);
  const std::vector<Point_3> fillers = o.pit_depth > 0. ? pit_fillers(mesh, domain, field, o.edge_length, o.pit_depth)
                                                         : std::vector<Point_3>();
  if(fillers.empty()) return mesh;
  Particle_set_3<Point_3> filled = ps;
  for(const Point_3& p : fillers) filled.push_back(p, Particle_kind::BOUNDARY);
  return connect_particles(filled, domain, field, o, gt);
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Tetrahedralization

Connects particles into a tetrahedral mesh: the Delaunay tetrahedralization of all particles
(CGAL `Delaunay_triangulation_3`, exact predicates) in the isotropic space of the field,
restricted to the domain by keeping the cells whose centroid is inside it; cells whose four
vertices are boundary particles and whose centroid lies within `flatness_ratio` x their mean
edge length of the boundary are dropped (they would be slivers lying on the surface), but for
the wedges along sharp edges (`wedge_angle`). The boundary is then repaired into a closed
2-manifold: cells are removed around non-manifold edges and vertices until none remains, the
kept wedges first; then each removed cell goes back if the boundary stays manifold around it,
its smallest dihedral angle is at least `wedge_angle` and its boundary faces between three surface
particles (their centroids and edge midpoints) lie within l* / 4 of the surface (isotropic space);
where an interior particle is still on the boundary, the cells around it that are not kept go in
together on the same terms if it is their only interior particle. A boundary vertex that is an
interior particle more than l* / 4 from the surface (isotropic space) sits in a pit, where the
surface particles left a gap: a boundary particle is added at the surface point nearest to it
(unless one lies within l* / 2 of that point) and the particles are connected again. Particles
that end up in no tetrahedron are not output. The tetrahedra are positively oriented and
`boundary_faces` are oriented outward.

The isotropic space is where the field's metric B^T B is Euclidean: the particles themselves
under a cross field or a constant frame, and under a varying stretch the least-squares
embedding of their isotropic neighbour vectors (exact when the metric is flat, as fig8's).
Should that embedding fold a kept cell over in the physical space (a strongly curved metric),
the Euclidean Delaunay tetrahedralization is used instead, and the flips must then do all the
work.

Delaunay rather than TetGen's constrained tetrahedralization: the boundary particles lie on
the surface and the interior ones at least 0.3 l* inside, so the restricted Delaunay complex
already conforms to the boundary; CGAL's triangulation is exact and robust on degenerate
(cospherical lattice) input, on which TetGen 1.5 may crash, and it keeps the package GPL.

\tparam Domain a model of `LatticeMeshDomain_3`
\tparam FrameField a model of `FrameField_3`

\cgalNamedParamsBegin
  \cgalParamNBegin{flatness_ratio}
    \cgalParamDescription{a cell whose four vertices lie on the boundary is dropped if its centroid is less than this fraction of its mean edge length inside}
    \cgalParamType{double}
    \cgalParamDefault{0.1}
  \cgalParamNEnd
  \cgalParamNBegin{wedge_angle}
    \cgalParamDescription{... unless it is a wedge along a sharp edge: two of its vertices on feature curves and its smallest dihedral angle (isotropic space, degrees) at least this; a cell that the manifold repair removed goes back only with this smallest angle}
    \cgalParamType{double}
    \cgalParamDefault{20}
  \cgalParamNEnd
  \cgalParamNBegin{edge_length}
    \cgalParamDescription{l*, which sets the neighbourhood (1.3 l*) of the isotropic embedding under a varying stretch and the depth of the pits filled}
    \cgalParamType{double}
    \cgalParamDefault{0: estimated from the number of particles and the isotropic volume}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{OpenMP threads}
    \cgalParamType{int}
    \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{the traits object whose predicates decide the Delaunay tetrahedralization}
    \cgalParamType{a model of `DelaunayTriangulationTraits_3` with the point type of `Domain::Geom_traits`}
    \cgalParamDefault{`Lattice_mesher_traits_3<Domain::Geom_traits>()`, as `Lattice_particle_mesher_3`'s}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument with fewer than 4 particles, or a named parameter out of range
*/
template <typename Domain, typename FrameField, typename Point_3,
          typename NamedParameters = parameters::Default_named_parameters>
Tetrahedral_mesh_3<Point_3> tetrahedralize_particles(const Particle_set_3<Point_3>& ps, const Domain& domain,
                                                     const FrameField& field,
                                                     const NamedParameters& np = parameters::default_values())
{
  typedef typename internal_np::Lookup_named_param_def<internal_np::geom_traits_t, NamedParameters,
                                                       Lattice_mesher_traits_3<typename Domain::Geom_traits> >::type GT;
  return internal::tetrahedralize_particles(ps, domain, field, internal::tetrahedralization_options(np),
                                            parameters::choose_parameter<GT>(parameters::get_parameter(np, internal_np::geom_traits)));
}


} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_TETRAHEDRALIZE_PARTICLES_H
