// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_TETRAHEDRAL_MESH_3_H
#define CGAL_LATTICE_MESHER_3_TETRAHEDRAL_MESH_3_H

#include <array>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/// What a particle is constrained to, from most to least constrained.
enum class Particle_kind : unsigned char { FIXED = 0, SHARP_EDGE = 1, BOUNDARY = 2, FREE = 3 };

/*!
\ingroup PkgLatticeMesher3Ref
A particle system: positions with their constraint kind. `feature[i]` is the index of the
feature curve a sharp-edge particle lies on, or of the corner a fixed particle sits at
(-1 for the other kinds).
*/
template <typename Point_3>
struct Particle_set_3
{
  std::vector<Point_3> points;       ///< the positions of the particles
  std::vector<Particle_kind> kinds;  ///< the constraint kind of each particle
  std::vector<int> feature;          ///< the feature curve or corner of each particle, or -1

  /// the number of particles
  std::size_t size() const { return points.size(); }
  /// removes all the particles
  void clear() { points.clear(); kinds.clear(); feature.clear(); }
  /// appends a particle at `p` of kind `k` on the feature curve or at the corner `f` (-1: none)
  void push_back(const Point_3& p, Particle_kind k, int f = -1)
  { points.push_back(p); kinds.push_back(k); feature.push_back(f); }
};

/*!
\ingroup PkgLatticeMesher3Ref
A tetrahedral mesh as plain arrays (indices into `points`, 0-based).
Every tetrahedron (a, b, c, d) is positively oriented: `CGAL::orientation(a, b, c, d)` is
`CGAL::POSITIVE`. `boundary_faces` lists the triangles of the boundary, oriented so that their
normal points out of the mesh. `vertex_kinds`, when not empty, gives each vertex's particle kind.
`subdomains` and `boundary_patches`, when not empty, give each tetrahedron's subdomain index and
each boundary face's surface patch index (from 1, the references of the Medit and Gmsh
outputs): `Lattice_particle_mesher_3::tetrahedralize()` and `lattice_mesh_3()` fill them with the
domain's (a `Polyhedral_lattice_domain_3`'s patches are the parts of the surface between its
sharp edges); a stage that changes the tetrahedra or the boundary leaves them as they were, to be
filled again.
*/
template <typename Point_3>
struct Tetrahedral_mesh_3
{
  std::vector<Point_3> points;                      ///< the vertices
  std::vector<std::array<int, 4> > tets;            ///< the tetrahedra, positively oriented
  std::vector<std::array<int, 3> > boundary_faces;  ///< the boundary triangles, oriented outward
  std::vector<Particle_kind> vertex_kinds;          ///< the particle kind of each vertex, or empty
  std::vector<int> subdomains;                      ///< the subdomain index of each tetrahedron, or empty
  std::vector<int> boundary_patches;                ///< the surface patch index (from 1) of each boundary face, or empty
};

namespace internal {

// The label of element i: labels[i], or 1 without labels.
inline int label(const std::vector<int>& labels, std::ptrdiff_t i) { return labels.empty() ? 1 : labels[std::size_t(i)]; }

// Drops the vertices flagged in `removed`, which no tetrahedron or boundary face uses any more,
// keeping the order of the others, and renumbers the tetrahedra and the boundary faces.
template <typename Point_3>
void remove_vertices(Tetrahedral_mesh_3<Point_3>& mesh, const std::vector<char>& removed)
{
  std::vector<int> index(mesh.points.size(), -1);
  std::size_t kept = 0;
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    if(!removed[v]) {
      index[v] = int(kept);
      mesh.points[kept] = mesh.points[v];
      if(!mesh.vertex_kinds.empty()) mesh.vertex_kinds[kept] = mesh.vertex_kinds[v];
      ++kept;
    }
  mesh.points.resize(kept);
  if(!mesh.vertex_kinds.empty()) mesh.vertex_kinds.resize(kept);
  for(std::array<int, 4>& t : mesh.tets)
    for(int& v : t) v = index[v];
  for(std::array<int, 3>& f : mesh.boundary_faces)
    for(int& v : f) v = index[v];
}

// The vertices of the tetrahedra that hold a flagged vertex (flagged[v] true), the flagged ones
// included: those whose star changes when the flagged ones move.
template <typename Flags>
std::vector<char> vertices_around(const std::vector<std::array<int, 4> >& tets, const Flags& flagged)
{
  std::vector<char> around(flagged.size(), 0);
  for(const std::array<int, 4>& t : tets)
    if(flagged[t[0]] || flagged[t[1]] || flagged[t[2]] || flagged[t[3]])
      for(int v : t) around[v] = 1;
  return around;
}

} // namespace internal

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_TETRAHEDRAL_MESH_3_H
