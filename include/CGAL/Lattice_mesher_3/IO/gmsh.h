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
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3IO
Writes `mesh` in Gmsh's MSH 4.1 ASCII format: a volume entity per subdomain index and a surface
entity per surface patch index (`subdomains`, `boundary_patches`; one of each where these are
empty), each with its index as tag and in the physical group of that tag ("subdomain k",
"patch k"), the nodes (tags 1 to n, 17 significant digits, all in the first volume), the boundary
triangles (element type 2) on their surfaces and the tetrahedra (type 4) in their volumes,
numbered after the triangles.

\throws std::runtime_error if the stream fails
*/
template <typename Point_3>
void write_gmsh(std::ostream& os, const Tetrahedral_mesh_3<Point_3>& mesh)
{
  CGAL::Bbox_3 box;
  for(const Point_3& p : mesh.points) box += p.bbox();
  const std::streamsize precision = os.precision();
  os << std::setprecision(17);
  // the elements of each entity, by tag
  std::map<int, std::vector<std::size_t> > surfaces, volumes;
  for(std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) surfaces[internal::label(mesh.boundary_patches, std::ptrdiff_t(f))].push_back(f);
  for(std::size_t t = 0; t < mesh.tets.size(); ++t) volumes[internal::label(mesh.subdomains, std::ptrdiff_t(t))].push_back(t);
  if(volumes.empty()) volumes[1];
  std::ostringstream bounds;
  bounds << box.xmin() << ' ' << box.ymin() << ' ' << box.zmin() << ' ' << box.xmax() << ' ' << box.ymax() << ' ' << box.zmax();
  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n" << surfaces.size() + volumes.size() << '\n';
  for(const auto& s : surfaces) os << "2 " << s.first << " \"patch " << s.first << "\"\n";
  for(const auto& v : volumes) os << "3 " << v.first << " \"subdomain " << v.first << "\"\n";
  os << "$EndPhysicalNames\n$Entities\n0 0 " << surfaces.size() << ' ' << volumes.size() << '\n';
  for(const auto& s : surfaces) os << s.first << ' ' << bounds.str() << " 1 " << s.first << " 0\n";
  for(const auto& v : volumes) {
    os << v.first << ' ' << bounds.str() << " 1 " << v.first << ' ' << surfaces.size();
    for(const auto& s : surfaces) os << ' ' << s.first;
    os << '\n';
  }
  os << "$EndEntities\n";
  const std::size_t n = mesh.points.size();
  os << "$Nodes\n1 " << n << " 1 " << n << "\n3 " << volumes.begin()->first << " 0 " << n << '\n';
  for(std::size_t i = 1; i <= n; ++i) os << i << '\n';
  for(const Point_3& p : mesh.points) os << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  os << "$EndNodes\n";
  const std::size_t elements = mesh.boundary_faces.size() + mesh.tets.size();
  std::size_t blocks = surfaces.size();
  for(const auto& v : volumes) blocks += !v.second.empty();
  os << "$Elements\n" << blocks << ' ' << elements << " 1 " << elements << '\n';
  std::size_t tag = 0;
  for(const auto& s : surfaces) {
    os << "2 " << s.first << " 2 " << s.second.size() << '\n';
    for(std::size_t f : s.second) {
      const std::array<int, 3>& v = mesh.boundary_faces[f];
      os << ++tag << ' ' << v[0] + 1 << ' ' << v[1] + 1 << ' ' << v[2] + 1 << '\n';
    }
  }
  for(const auto& e : volumes) {
    if(e.second.empty()) continue;
    os << "3 " << e.first << " 4 " << e.second.size() << '\n';
    for(std::size_t t : e.second) {
      const std::array<int, 4>& v = mesh.tets[t];
      os << ++tag << ' ' << v[0] + 1 << ' ' << v[1] + 1 << ' ' << v[2] + 1 << ' ' << v[3] + 1 << '\n';
    }
  }
  os << "$EndElements\n";
  os.precision(precision);
  if(!os) throw std::runtime_error("write_gmsh(): the output stream failed");
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_IO_GMSH_H
