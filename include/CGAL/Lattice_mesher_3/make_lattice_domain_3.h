// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_MAKE_LATTICE_DOMAIN_3_H
#define CGAL_LATTICE_MESHER_3_MAKE_LATTICE_DOMAIN_3_H

#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>

#include <CGAL/Mesh_3/Has_features.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {
namespace internal {

// a model of LatticeMeshDomain_3 (Polyhedral_mesh_domain_3 also has a project_on_surface())
template <typename D, typename = void> struct Is_lattice_mesh_domain_3 : std::false_type {};
template <typename D>
struct Is_lattice_mesh_domain_3<D, std::void_t<typename D::Geom_traits, typename D::Projection,
                                               decltype(std::declval<const D&>().inside_distance_bound(
                                                 std::declval<const typename D::Point_3&>()))> > : std::true_type {};

// the kernel of a Mesh_3 domain (its R may be a traits class over it)
template <typename D> using Mesh_domain_kernel = typename Kernel_traits<typename D::R::Point_3>::Kernel;

// a model of Mesh_3's MeshDomain_3: an inside test (is_in_domain_object()) over the kernel R
template <typename D, typename = void> struct Is_mesh_domain_3 : std::false_type {};
template <typename D>
struct Is_mesh_domain_3<D, std::void_t<typename D::R, decltype(std::declval<const D&>().is_in_domain_object())> >
  : std::true_type {};

// Polyhedral_mesh_domain_3 and Polyhedral_mesh_domain_with_features_3 keep their surfaces
template <typename D, typename = void> struct Has_polyhedra : std::false_type {};
template <typename D>
struct Has_polyhedra<D, std::void_t<decltype(std::declval<const D&>().polyhedra()),
                                    decltype(std::declval<const D&>().bounding_aabb_tree_ptr())> > : std::true_type {};

// The point type of what `lattice_mesh_3()` makes of a domain; none for other types.
template <typename D, typename = void> struct Domain_point_3 {};
template <typename D>
struct Domain_point_3<D, std::enable_if_t<Is_lattice_mesh_domain_3<D>::value> >
{ typedef typename D::Geom_traits::Point_3 type; };
template <typename D>
struct Domain_point_3<D, std::enable_if_t<!Is_lattice_mesh_domain_3<D>::value && Is_mesh_domain_3<D>::value> >
{ typedef typename Mesh_domain_kernel<D>::Point_3 type; };

inline double bbox_diagonal(const Bbox_3& b)
{
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

// The feature curves of a MeshDomainWithFeatures_3 as polylines with points at most `spacing`
// apart (through its curve interface: the curves added by the user's add_features() too), and
// its corners.
template <typename MeshDomain>
void feature_polylines(const MeshDomain& domain, double spacing,
                       std::vector<std::vector<typename Mesh_domain_kernel<MeshDomain>::Point_3> >& curves,
                       std::vector<typename Mesh_domain_kernel<MeshDomain>::Point_3>& corners)
{
  typedef typename Mesh_domain_kernel<MeshDomain>::Point_3 Point_3;
  typedef typename MeshDomain::Index Index;
  std::vector<std::pair<typename MeshDomain::Corner_index, Point_3> > given_corners;
  domain.get_corners(std::back_inserter(given_corners));
  for(const auto& c : given_corners) corners.push_back(c.second);
  std::vector<std::tuple<typename MeshDomain::Curve_index, std::pair<Point_3, Index>, std::pair<Point_3, Index> > > given;
  domain.get_curves(std::back_inserter(given));
  for(const auto& c : given) {
    const Point_3& start = std::get<1>(c).first;
    const Point_3& end = std::get<2>(c).first;
    const double length = CGAL::to_double(domain.curve_length(std::get<0>(c)));
    // a loop keeps three segments at least: the curves keep the order of get_curves()
    const std::size_t n = (std::max)(std::size_t(start == end ? 3 : 1), std::size_t(std::ceil(length / spacing)));
    std::vector<Point_3> curve{ start };
    for(std::size_t k = 1; k < n; ++k)
      curve.push_back(domain.construct_point_on_curve(start, std::get<0>(c), length * double(k) / double(n)));
    curve.push_back(end);   // a loop ends where it starts
    curves.push_back(std::move(curve));
  }
}

// The boundary of the union of the subdomains of any MeshDomain_3, as Mesh_3's surface mesher
// samples it (facets of `size` within size / 25 of the surface, at least 25 degrees, manifold,
// the features protected): the facets between a cell of a subdomain and one outside all.
template <typename MeshDomain>
CGAL::Surface_mesh<typename Mesh_domain_kernel<MeshDomain>::Point_3> sampled_surface(const MeshDomain& domain, double size)
{
  typedef typename Mesh_domain_kernel<MeshDomain>::Point_3 Point_3;
  typedef typename CGAL::Mesh_triangulation_3<MeshDomain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3t3;
  namespace P = CGAL::parameters;
  const CGAL::Mesh_criteria_3<Tr> criteria(P::edge_size = size, P::facet_angle = 25., P::facet_size = size,
                                           P::facet_distance = size / 25.);
  C3t3 c3t3;
  if constexpr(Mesh_3::internal::Has_features<MeshDomain>::value)
    c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, P::features(domain), P::manifold(), P::no_perturb(), P::no_exude());
  else
    c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, P::no_features(), P::manifold(), P::no_perturb(), P::no_exude());
  const Tr& tr = c3t3.triangulation();
  auto point = tr.geom_traits().construct_point_3_object();
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::map<typename Tr::Vertex_handle, std::size_t> index;
  auto id = [&](typename Tr::Vertex_handle v) {
    const auto it = index.emplace(v, points.size());
    if(it.second) points.push_back(point(tr.point(v)));
    return it.first->second;
  };
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    typename Tr::Cell_handle c = f->first;
    int i = f->second;
    const typename Tr::Cell_handle n = c->neighbor(i);
    if(c3t3.is_in_complex(c) == c3t3.is_in_complex(n)) continue;   // between two subdomains
    if(!c3t3.is_in_complex(c)) { i = n->index(c); c = n; }
    std::array<std::size_t, 3> t{ id(c->vertex((i + 1) & 3)), id(c->vertex((i + 2) & 3)), id(c->vertex((i + 3) & 3)) };
    // outward: the cell's fourth vertex behind the facet
    if(CGAL::orientation(points[t[0]], points[t[1]], points[t[2]], point(tr.point(c, i))) == CGAL::POSITIVE)
      std::swap(t[1], t[2]);
    triangles.push_back(t);
  }
  if(triangles.empty())
    throw std::invalid_argument("the domain has no boundary that Mesh_3 finds at facet size " + std::to_string(size)
                                + " (an empty domain, or one smaller than that size)");
  namespace PMP = CGAL::Polygon_mesh_processing;
  PMP::orient_polygon_soup(points, triangles);   // splits the vertices that are not manifold
  CGAL::Surface_mesh<Point_3> surface;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, surface);
  return surface;
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Domains

returns the `Polyhedral_lattice_domain_3` of a Mesh_3 domain `domain`, a model of `MeshDomain_3`
or `MeshDomainWithFeatures_3`, which `lattice_mesh_3()` calls for such a domain:
- a `Polyhedral_mesh_domain_3` or `Polyhedral_mesh_domain_with_features_3` gives its surfaces
  as they are: all of them, or with a bounding polyhedron that one alone (the volume it bounds,
  without the inner surfaces between subdomains);
- any other domain (`Labeled_mesh_domain_3` from an implicit function or a labeled image, with
  or without `Mesh_domain_with_polyline_features_3`) is sampled by Mesh_3's surface mesher:
  the boundary of the union of its subdomains (interfaces between two subdomains are not
  kept), with facets of size l* / 3 within l* / 75 of the surface.

The features of a domain with features (those detected by `detect_features()` and those added
by `add_features()`) become the feature curves, as polylines with points at most l* / 16 apart,
and its corners the corners. A domain without features has none.

\tparam MeshDomain a model of `MeshDomain_3`

\cgalNamedParamsBegin
  \cgalParamNBegin{edge_length}
    \cgalParamDescription{the lattice cube edge l* the domain will be meshed with, which sets how
      finely a surface is sampled and the curves are traced}
    \cgalParamType{double}
    \cgalParamDefault{the diagonal of `domain.bbox()` / 25}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws std::invalid_argument if the surface does not bound a volume (the message names the
problem) or if `edge_length` is not positive and finite
*/
template <typename MeshDomain, typename NamedParameters = parameters::Default_named_parameters>
Polyhedral_lattice_domain_3<internal::Mesh_domain_kernel<MeshDomain> >
make_lattice_domain_3(const MeshDomain& domain, const NamedParameters& np = parameters::default_values())
{
  typedef internal::Mesh_domain_kernel<MeshDomain> K;
  typedef Polyhedral_lattice_domain_3<K> Domain;
  static_assert(internal::Is_mesh_domain_3<MeshDomain>::value,
                "make_lattice_domain_3(domain): the domain must be a model of Mesh_3's MeshDomain_3");
  const double diagonal = internal::bbox_diagonal(domain.bbox());
  const double l = parameters::choose_parameter(parameters::get_parameter(np, internal_np::edge_length), diagonal / 25.);
  if(!(l > 0.) || !std::isfinite(l))
    throw std::invalid_argument("make_lattice_domain_3(): edge_length() must be positive and finite");
  typename Domain::Surface_mesh surface;
  if constexpr(internal::Has_polyhedra<MeshDomain>::value) {
    const auto& polyhedra = domain.polyhedra();
    const std::size_t first = domain.bounding_aabb_tree_ptr() != nullptr ? polyhedra.size() - 1 : 0;
    for(std::size_t i = first; i < polyhedra.size(); ++i) CGAL::copy_face_graph(polyhedra[i], surface);
  }
  else
    surface = internal::sampled_surface(domain, l / 3.);
  if constexpr(Mesh_3::internal::Has_features<MeshDomain>::value) {
    std::vector<typename Domain::Polyline> curves;
    std::vector<typename K::Point_3> corners;
    internal::feature_polylines(domain, l / 16., curves, corners);
    return Domain(surface, curves, corners);
  }
  else
    return Domain(surface, std::vector<typename Domain::Polyline>());
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_MAKE_LATTICE_DOMAIN_3_H
