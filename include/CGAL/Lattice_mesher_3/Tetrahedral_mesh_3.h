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
  std::vector<Point_3> points;
  std::vector<Particle_kind> kinds;
  std::vector<int> feature;

  std::size_t size() const { return points.size(); }
  void clear() { points.clear(); kinds.clear(); feature.clear(); }
  void push_back(const Point_3& p, Particle_kind k, int f = -1)
  { points.push_back(p); kinds.push_back(k); feature.push_back(f); }
};

/*!
\ingroup PkgLatticeMesher3Ref
A tetrahedral mesh as plain arrays (indices into `points`, 0-based).
Every tetrahedron (a, b, c, d) is positively oriented: `CGAL::orientation(a, b, c, d)` is
`CGAL::POSITIVE`. `boundary_faces` lists the triangles of the boundary, oriented so that their
normal points out of the mesh. `vertex_kinds`, when not empty, gives each vertex's particle kind.
*/
template <typename Point_3>
struct Tetrahedral_mesh_3
{
  std::vector<Point_3> points;
  std::vector<std::array<int, 4> > tets;
  std::vector<std::array<int, 3> > boundary_faces;
  std::vector<Particle_kind> vertex_kinds;
};

namespace internal {

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

} // namespace internal

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_TETRAHEDRAL_MESH_3_H
