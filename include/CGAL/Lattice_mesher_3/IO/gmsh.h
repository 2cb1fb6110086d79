// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_IO_GMSH_H
#define CGAL_LATTICE_MESHER_3_IO_GMSH_H

#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>

#include <CGAL/Bbox_3.h>

#include <array>
#include <iomanip>
#include <ostream>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3IO
Writes `mesh` in Gmsh's MSH 4.1 ASCII format: one volume entity (tag 1, physical group 1)
bounded by one surface entity (tag 1, physical group 1), the nodes (tags 1 to n, 17 significant
digits), the boundary triangles (element type 2) on the surface and the tetrahedra (type 4) in the
volume, numbered after the triangles.

\throws std::runtime_error if the stream fails
*/
template <typename Point_3>
void write_gmsh(std::ostream& os, const Tetrahedral_mesh_3<Point_3>& mesh)
{
  CGAL::Bbox_3 box;
  for(const Point_3& p : mesh.points) box += p.bbox();
  const std::streamsize precision = os.precision();
  os << std::setprecision(17);
  const std::size_t n = mesh.points.size(), triangles = mesh.boundary_faces.size(), tets = mesh.tets.size();
  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
     << "$PhysicalNames\n2\n2 1 \"boundary\"\n3 1 \"volume\"\n$EndPhysicalNames\n"
     << "$Entities\n0 0 1 1\n"
     << "1 " << box.xmin() << ' ' << box.ymin() << ' ' << box.zmin() << ' ' << box.xmax() << ' ' << box.ymax() << ' '
     << box.zmax() << " 1 1 0\n"
     << "1 " << box.xmin() << ' ' << box.ymin() << ' ' << box.zmin() << ' ' << box.xmax() << ' ' << box.ymax() << ' '
     << box.zmax() << " 1 1 1 1\n"
     << "$EndEntities\n";
  // nodes: one block in the volume
  os << "$Nodes\n1 " << n << " 1 " << n << "\n3 1 0 " << n << '\n';
  for(std::size_t i = 1; i <= n; ++i) os << i << '\n';
  for(const Point_3& p : mesh.points) os << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  os << "$EndNodes\n";
  // elements: a block of triangles on the surface, a block of tetrahedra in the volume
  const std::size_t blocks = (triangles > 0 ? 1 : 0) + (tets > 0 ? 1 : 0);
  os << "$Elements\n" << blocks << ' ' << triangles + tets << " 1 " << triangles + tets << '\n';
  std::size_t tag = 0;
  if(triangles > 0) {
    os << "2 1 2 " << triangles << '\n';
    for(const std::array<int, 3>& f : mesh.boundary_faces)
      os << ++tag << ' ' << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
  }
  if(tets > 0) {
    os << "3 1 4 " << tets << '\n';
    for(const std::array<int, 4>& t : mesh.tets)
      os << ++tag << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << '\n';
  }
  os << "$EndElements\n";
  os.precision(precision);
  if(!os) throw std::runtime_error("write_gmsh(): the output stream failed");
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_IO_GMSH_H
