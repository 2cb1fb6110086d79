// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_INTERNAL_DOMAIN_INDICES_H
#define CGAL_LATTICE_MESHER_3_INTERNAL_DOMAIN_INDICES_H

#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>

#include <CGAL/centroid.h>
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {
namespace internal {

template <typename T> struct Is_pair : std::false_type {};
template <typename A, typename B> struct Is_pair<std::pair<A, B> > : std::true_type {};

// The index types of the labels of Tetrahedral_mesh_3 (a C3t3 has the same four typedefs).
struct Int_indices
{
  typedef int Subdomain_index;
  typedef int Surface_patch_index;
  typedef int Curve_index;
  typedef int Corner_index;
};

// surface_patch_index(p) of a LatticeMeshDomain_3 is optional: without it, one patch.
template <typename Domain, typename = void> struct Has_surface_patches : std::false_type {};
template <typename Domain>
struct Has_surface_patches<Domain, std::void_t<decltype(std::declval<const Domain&>().surface_patch_index(
                                     std::declval<const typename Domain::Geom_traits::Point_3&>()))> > : std::true_type {};

template <typename Domain, typename Point_3>
int surface_patch(const Domain& domain, const Point_3& p)
{
  if constexpr(Has_surface_patches<Domain>::value) return domain.surface_patch_index(p);
  else return 1;
}

// The position in `points` (pairs of an index and a point, or points) of the one nearest to p.
template <typename Point_3, typename Range, typename PointOf>
std::size_t nearest(const Point_3& p, const Range& points, PointOf point_of)
{
  std::size_t best = 0;
  for(std::size_t k = 1; k < points.size(); ++k)
    if(CGAL::squared_distance(p, point_of(points[k])) < CGAL::squared_distance(p, point_of(points[best]))) best = k;
  return best;
}

// The indices of a LatticeMeshDomain_3's mesh: one subdomain (1), its surface patches (the pair
// (1, 0) between the subdomain and the outside if patches are pairs), curve c + 1, corners 1, 2,
// ... by position.
template <typename Indices, typename LatticeDomain>
struct Lattice_domain_indices
{
  typedef typename Indices::Subdomain_index Subdomain_index;
  typedef typename Indices::Surface_patch_index Surface_patch_index;
  const LatticeDomain& domain;

  template <typename Point_3> Subdomain_index subdomain(const Point_3&) const { return Subdomain_index(1); }
  template <typename Point_3> Surface_patch_index patch(const Point_3& in, const Point_3& out) const
  {
    if constexpr(Is_pair<Surface_patch_index>::value) return Surface_patch_index(1, 0);
    else return Surface_patch_index(surface_patch(domain, CGAL::midpoint(in, out)));
  }
  typename Indices::Curve_index curve(int c) const { return typename Indices::Curve_index(c + 1); }
  template <typename Point_3> typename Indices::Corner_index corner(const Point_3& p) const
  {
    return typename Indices::Corner_index(nearest(p, domain.corners(), [](const Point_3& q) { return q; }) + 1);
  }
};

// The index types of a Mesh_3 domain, for the labels of the arrays.
template <typename MeshDomain>
struct Mesh_domain_index_types
{
  typedef typename MeshDomain::Subdomain_index Subdomain_index;
  typedef typename MeshDomain::Surface_patch_index Surface_patch_index;
  typedef int Curve_index;
  typedef int Corner_index;
};

// Writes in `mesh.subdomains` and `mesh.boundary_patches` the indices `indices` gives (at each
// tetrahedron's centroid; across each boundary face, from behind it to as far in front), as
// integers: arithmetic indices as they are, others (pairs of subdomains) numbered 1, 2, ... in
// the order they come.
template <typename Point_3, typename Indices>
void label_mesh(Tetrahedral_mesh_3<Point_3>& mesh, const Indices& indices)
{
  auto as_int = [](const auto& index, auto& numbers) {
    if constexpr(std::is_arithmetic<std::decay_t<decltype(index)> >::value) return int(index);
    else return numbers.emplace(index, int(numbers.size()) + 1).first->second;
  };
  std::map<typename Indices::Subdomain_index, int> subdomain_numbers;
  std::map<typename Indices::Surface_patch_index, int> patch_numbers;
  auto sorted = [](std::array<int, 3> f) { std::sort(f.begin(), f.end()); return f; };
  std::map<std::array<int, 3>, std::size_t> boundary;   // sorted boundary face -> its index
  for(std::size_t k = 0; k < mesh.boundary_faces.size(); ++k) boundary.emplace(sorted(mesh.boundary_faces[k]), k);
  std::vector<int> apex(mesh.boundary_faces.size(), -1);   // of each boundary face's tetrahedron
  mesh.subdomains.assign(mesh.tets.size(), 1);
  for(std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const std::array<int, 4>& c = mesh.tets[t];
    const Point_3 g = CGAL::centroid(mesh.points[c[0]], mesh.points[c[1]], mesh.points[c[2]], mesh.points[c[3]]);
    mesh.subdomains[t] = as_int(indices.subdomain(g), subdomain_numbers);
    for(int i = 0; i < 4; ++i) {
      const auto f = boundary.find(sorted({ c[(i + 1) % 4], c[(i + 2) % 4], c[(i + 3) % 4] }));
      if(f != boundary.end()) apex[f->second] = c[i];
    }
  }
  mesh.boundary_patches.assign(mesh.boundary_faces.size(), 1);
  for(std::size_t k = 0; k < mesh.boundary_faces.size(); ++k) {
    if(apex[k] < 0) continue;
    const std::array<int, 3>& f = mesh.boundary_faces[k];
    const Point_3 g = CGAL::centroid(mesh.points[f[0]], mesh.points[f[1]], mesh.points[f[2]]);
    const auto half = (mesh.points[std::size_t(apex[k])] - g) * .5;
    mesh.boundary_patches[k] = as_int(indices.patch(g + half, g - half), patch_numbers);
  }
}

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_DOMAIN_INDICES_H
