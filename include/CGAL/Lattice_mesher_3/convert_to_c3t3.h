// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_CONVERT_TO_C3T3_H
#define CGAL_LATTICE_MESHER_3_CONVERT_TO_C3T3_H

#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/make_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>
#include <CGAL/Lattice_mesher_3/internal/domain_indices.h>

#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3Ref
A `Mesh_complex_3_in_triangulation_3` for the meshes of a `LatticeMeshDomain_3` over the kernel
`K`: the triangulation of a `Labeled_mesh_domain_3<K>` (subdomain indices `int`, surface patch
indices pairs of subdomain indices), as `CGAL::make_mesh_3()` makes for an implicit domain.
*/
template <typename K>
using Mesh_complex_3 = CGAL::Mesh_complex_3_in_triangulation_3<
  typename CGAL::Mesh_triangulation_3<CGAL::Labeled_mesh_domain_3<K> >::type, int, int>;

namespace internal {

// The indices of a Mesh_3 domain's own: the subdomain at a cell's centroid, the surface patch
// where the segment across a boundary facet meets the surface, the curves in the order of
// get_curves() (make_lattice_domain_3()'s), the nearest corner of get_corners().
template <typename C3t3, typename MeshDomain>
struct Mesh_domain_indices
{
  typedef typename C3t3::Subdomain_index Subdomain_index;
  typedef typename C3t3::Surface_patch_index Surface_patch_index;
  typedef typename Mesh_domain_kernel<MeshDomain>::Point_3 Point_3;
  const MeshDomain& domain;
  Subdomain_index fallback;   // a cell inside the mesh whose centroid the domain puts outside
  std::vector<typename C3t3::Curve_index> curves;
  std::vector<std::pair<typename C3t3::Corner_index, Point_3> > corners;

  explicit Mesh_domain_indices(const MeshDomain& d, Subdomain_index f) : domain(d), fallback(f)
  {
    if constexpr(Mesh_3::internal::Has_features<MeshDomain>::value) {
      std::vector<std::tuple<typename MeshDomain::Curve_index, std::pair<Point_3, typename MeshDomain::Index>,
                             std::pair<Point_3, typename MeshDomain::Index> > > given;
      domain.get_curves(std::back_inserter(given));
      for(const auto& c : given) curves.push_back(std::get<0>(c));
      domain.get_corners(std::back_inserter(corners));
    }
  }
  Subdomain_index subdomain(const Point_3& p) const
  {
    const auto s = domain.is_in_domain_object()(p);
    return s ? Subdomain_index(*s) : fallback;
  }
  Surface_patch_index patch(const Point_3& in, const Point_3& out) const
  {
    const auto hit = domain.construct_intersection_object()(typename Mesh_domain_kernel<MeshDomain>::Segment_3(in, out));
    if(std::get<2>(hit) != 0) return domain.surface_patch_index(std::get<1>(hit));
    if constexpr(Is_pair<Surface_patch_index>::value) return Surface_patch_index(subdomain(in), 0);
    else return Surface_patch_index();
  }
  typename C3t3::Curve_index curve(int c) const
  {
    return std::size_t(c) < curves.size() ? curves[std::size_t(c)] : typename C3t3::Curve_index(c + 1);
  }
  typename C3t3::Corner_index corner(const Point_3& p) const
  {
    if(corners.empty()) return typename C3t3::Corner_index(1);
    return corners[nearest(p, corners, [](const auto& c) { return c.second; })].first;
  }
};

// Inserts the points with zero weight, in spatial order; returns each point's vertex.
template <typename Tr, typename Point_3>
std::vector<typename Tr::Vertex_handle> insert_points(Tr& tr, const std::vector<Point_3>& points)
{
  typedef typename Kernel_traits<Point_3>::Kernel K;
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  typedef typename CGAL::Pointer_property_map<Point_3>::const_type Map;
  const Map map = CGAL::make_property_map(points);
  CGAL::spatial_sort(order.begin(), order.end(), CGAL::Spatial_sort_traits_adapter_3<K, Map>(map));
  auto weighted = tr.geom_traits().construct_weighted_point_3_object();
  std::vector<typename Tr::Vertex_handle> vertex(points.size());
  typename Tr::Cell_handle hint;
  for(std::size_t i : order) {
    vertex[i] = tr.insert(weighted(points[i]), hint);
    hint = vertex[i]->cell();
  }
  return vertex;
}

template <typename C3t3, typename Point_3, typename LatticeDomain, typename Indices>
void add_features_to_c3t3(const Tetrahedral_mesh_3<Point_3>& mesh, const LatticeDomain& domain, const Indices& indices,
                          const std::vector<typename C3t3::Triangulation::Vertex_handle>& vertex, C3t3& c3t3);

template <typename C3t3, typename Point_3, typename LatticeDomain, typename Indices>
void convert_to_c3t3(const Tetrahedral_mesh_3<Point_3>& mesh, const LatticeDomain& domain, const Indices& indices, C3t3& c3t3)
{
  typedef typename C3t3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  c3t3.clear();
  Tr& tr = c3t3.triangulation();
  const std::vector<Vertex_handle> vertex = insert_points(tr, mesh.points);
  std::unordered_map<Vertex_handle, int, CGAL::Handle_hash_function> index;
  for(std::size_t i = 0; i < vertex.size(); ++i)
    if(!index.emplace(vertex[i], int(i)).second)
      throw std::invalid_argument("convert_to_c3t3(): the mesh has two vertices at the same point");
  // a cell is in the complex if it is a tetrahedron of the mesh or its centroid is inside the
  // mesh's boundary (the Delaunay cells differ from the mesh's where flips made them), unless
  // it lies flat on the surface: four surface vertices, a height below a tenth of its edges
  // (Delaunay joins the surface vertices of a planar part in such slivers, which the mesh's
  // boundary faces cut through)
  auto flat_on_surface = [&](const std::array<int, 4>& t) {
    if(mesh.vertex_kinds.size() != mesh.points.size()) return false;
    for(int v : t) if(mesh.vertex_kinds[v] == Particle_kind::FREE) return false;
    return internal::height_over_mean_edge(to_eigen(mesh.points[t[0]]), to_eigen(mesh.points[t[1]]),
                                           to_eigen(mesh.points[t[2]]), to_eigen(mesh.points[t[3]])) < .1;
  };
  std::set<std::array<int, 4> > tets;
  for(std::array<int, 4> t : mesh.tets) { std::sort(t.begin(), t.end()); tets.insert(t); }
  CGAL::Surface_mesh<Point_3> boundary;
  {
    std::vector<std::vector<std::size_t> > faces;
    for(const auto& f : mesh.boundary_faces) faces.push_back({ std::size_t(f[0]), std::size_t(f[1]), std::size_t(f[2]) });
    std::vector<Point_3> points = mesh.points;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, boundary);
  }
  const CGAL::Side_of_triangle_mesh<CGAL::Surface_mesh<Point_3>, typename Kernel_traits<Point_3>::Kernel> side(boundary);
  auto point = tr.geom_traits().construct_point_3_object();
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    std::array<int, 4> t{ index.at(c->vertex(0)), index.at(c->vertex(1)), index.at(c->vertex(2)), index.at(c->vertex(3)) };
    std::sort(t.begin(), t.end());
    const Point_3 g = CGAL::centroid(point(tr.point(c, 0)), point(tr.point(c, 1)), point(tr.point(c, 2)), point(tr.point(c, 3)));
    if(tets.count(t) || (side(g) == CGAL::ON_BOUNDED_SIDE && !flat_on_surface(t))) c3t3.add_to_complex(c, indices.subdomain(g));
  }
  // vertices: of the volume, then of the surface, curves and corners as the mesh says
  for(Vertex_handle v : vertex) { c3t3.set_dimension(v, 3); }
  for(auto f = tr.finite_facets_begin(); f != tr.finite_facets_end(); ++f) {
    Cell_handle c = f->first;
    int i = f->second;
    const Cell_handle n = c->neighbor(i);
    if(c3t3.subdomain_index(c) == c3t3.subdomain_index(n)) continue;
    if(!c3t3.is_in_complex(c)) { i = n->index(c); c = n; }   // from the subdomain side
    const Point_3 a = point(tr.point(c, (i + 1) & 3)), b = point(tr.point(c, (i + 2) & 3)), d = point(tr.point(c, (i + 3) & 3));
    const Point_3 g = CGAL::centroid(a, b, d);
    const Point_3 apex = point(tr.point(c, i));
    // across the facet, from behind it (toward the cell) to as far in front
    const Point_3 in = g + (apex - g) * .5, out = g - (apex - g) * .5;
    const typename C3t3::Surface_patch_index patch = indices.patch(in, out);
    c3t3.add_to_complex(c, i, patch);
    for(int k = 1; k < 4; ++k) {
      const Vertex_handle v = c->vertex((i + k) & 3);
      if(c3t3.in_dimension(v) > 2) { c3t3.set_dimension(v, 2); c3t3.set_index(v, typename C3t3::Index(patch)); }
    }
  }
  for(Vertex_handle v : vertex)
    if(c3t3.in_dimension(v) == 3) c3t3.set_index(v, typename C3t3::Index(c3t3.subdomain_index(v->cell())));
  internal::add_features_to_c3t3(mesh, domain, indices, vertex, c3t3);
  // Last, as the vertex handles go: the weights of Mesh_3's sliver exuder (which moves the
  // volume's vertices alone) take out what slivers Delaunay's connectivity made (fandisk, 2,526
  // vertices: smallest dihedral angle 2.4 -> 17.6 degrees, the mesh's own 33.0).
  CGAL::exude_mesh_3(c3t3);
}

// The corners, and the mesh edges along a feature curve, as Mesh_3 marks them.
template <typename C3t3, typename Point_3, typename LatticeDomain, typename Indices>
void add_features_to_c3t3(const Tetrahedral_mesh_3<Point_3>& mesh, const LatticeDomain& domain, const Indices& indices,
                          const std::vector<typename C3t3::Triangulation::Vertex_handle>& vertex, C3t3& c3t3)
{
  typedef typename C3t3::Triangulation::Cell_handle Cell_handle;
  const typename C3t3::Triangulation& tr = c3t3.triangulation();
  if(mesh.vertex_kinds.size() != mesh.points.size()) return;
  for(std::size_t i = 0; i < vertex.size(); ++i)
    if(mesh.vertex_kinds[i] == Particle_kind::FIXED) {
      const typename C3t3::Corner_index k = indices.corner(mesh.points[i]);
      c3t3.add_to_complex(vertex[i], k);
      c3t3.set_dimension(vertex[i], 0);
      c3t3.set_index(vertex[i], typename C3t3::Index(k));
    }
  auto on_feature = [&](int v) { return mesh.vertex_kinds[v] == Particle_kind::FIXED || mesh.vertex_kinds[v] == Particle_kind::SHARP_EDGE; };
  std::set<std::pair<int, int> > done;
  for(const auto& f : mesh.boundary_faces)
    for(int e = 0; e < 3; ++e) {
      const int a = (std::min)(f[e], f[(e + 1) % 3]), b = (std::max)(f[e], f[(e + 1) % 3]);
      if(!on_feature(a) || !on_feature(b) || !done.insert({ a, b }).second) continue;
      const Point_3 m = CGAL::midpoint(mesh.points[a], mesh.points[b]);
      const auto on = domain.project_on_features(m);
      const double length2 = CGAL::to_double(CGAL::squared_distance(mesh.points[a], mesh.points[b]));
      if(on.index < 0 || !(on.squared_distance <= 1e-6 * length2)) continue;   // across a face, not along a curve
      Cell_handle c;
      int ia, ib;
      if(!tr.is_edge(vertex[a], vertex[b], c, ia, ib)) continue;
      const typename C3t3::Curve_index curve = indices.curve(on.index);
      c3t3.add_to_complex(vertex[a], vertex[b], curve);
      for(int v : { a, b })
        if(mesh.vertex_kinds[v] == Particle_kind::SHARP_EDGE) {
          c3t3.set_dimension(vertex[v], 1);
          c3t3.set_index(vertex[v], typename C3t3::Index(curve));
        }
    }
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Ref

Fills `c3t3` with the mesh `mesh` of `domain` (a model of `LatticeMeshDomain_3`) as \cgal's 3D
mesh generator would: its triangulation is the regular triangulation of the mesh's vertices with
zero weights (their Delaunay triangulation, valid for its type), whose cells in the complex are
the mesh's tetrahedra and the cells whose centroid is inside the mesh (subdomain 1): where flips
made the mesh's connectivity differ from Delaunay's, the cells are Delaunay's. The facets between
a cell in the complex and one outside are in the complex (with the domain's surface patch index
if `C3t3`'s are integers, the pair (1, 0) if they are pairs),
the mesh's edges along a feature curve are (curve c + 1), and the corners (1, 2, ... in the
order of `domain.corners()`); each vertex has the dimension and index of the lowest-dimensional
part it is on. Last, Mesh_3's sliver exuder (`CGAL::exude_mesh_3()`) weights the vertices of the
volume to take out the slivers that Delaunay's connectivity makes. `c3t3` is cleared first.

`lattice_mesh_3<C3t3>()` calls it, with the indices of a Mesh_3 domain for such a domain.

\tparam C3t3 a `Mesh_complex_3_in_triangulation_3` (e.g. `Lattice_mesher_3::Mesh_complex_3<K>`)
\tparam LatticeDomain a model of `LatticeMeshDomain_3`
*/
template <typename C3t3, typename Point_3, typename LatticeDomain>
void convert_to_c3t3(const Tetrahedral_mesh_3<Point_3>& mesh, const LatticeDomain& domain, C3t3& c3t3)
{
  internal::convert_to_c3t3(mesh, domain, internal::Lattice_domain_indices<C3t3, LatticeDomain>{ domain }, c3t3);
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_CONVERT_TO_C3T3_H
