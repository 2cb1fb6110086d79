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

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_TETRAHEDRAL_MESH_3_H
