// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_IO_VTU_H
#define CGAL_LATTICE_MESHER_3_IO_VTU_H

#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>

#include <array>
#include <iomanip>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

namespace internal {

// `s` with the five XML special characters escaped, for attribute values.
inline std::string xml_escaped(const std::string& s)
{
  std::string out;
  for(char c : s) {
    switch(c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

} // namespace internal

namespace internal {

// An ASCII VTK XML unstructured grid of cells of N vertices, all of VTK type `vtk_type`, with
// the point array `particle_kind` if `kinds` is not empty and the cell arrays of `cell_data`.
template <typename Point_3, std::size_t N>
void write_vtu_cells(std::ostream& os, const std::string& function, const std::vector<Point_3>& points,
                     const std::vector<std::array<int, N> >& cells, int vtk_type, const std::vector<Particle_kind>& kinds,
                     const std::map<std::string, std::vector<double> >& cell_data)
{
  for(const auto& array : cell_data)
    if(array.second.size() != cells.size())
      throw std::invalid_argument(function + ": cell array '" + array.first + "' has " + std::to_string(array.second.size()) +
                                  " values for " + std::to_string(cells.size()) + " cells");
  const std::streamsize precision = os.precision();
  os << std::setprecision(17);

  os << "<?xml version=\"1.0\"?>\n"
     << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
     << "  <UnstructuredGrid>\n"
     << "    <Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\"" << cells.size() << "\">\n";
  if(!kinds.empty()) {
    os << "      <PointData Scalars=\"particle_kind\">\n"
       << "        <DataArray type=\"UInt8\" Name=\"particle_kind\" format=\"ascii\">\n";
    for(Particle_kind k : kinds) os << int(k) << '\n';
    os << "        </DataArray>\n"
       << "      </PointData>\n";
  }
  if(!cell_data.empty()) {
    os << "      <CellData Scalars=\"" << xml_escaped(cell_data.begin()->first) << "\">\n";
    for(const auto& array : cell_data) {
      os << "        <DataArray type=\"Float64\" Name=\"" << xml_escaped(array.first) << "\" format=\"ascii\">\n";
      for(double v : array.second) os << v << '\n';
      os << "        </DataArray>\n";
    }
    os << "      </CellData>\n";
  }
  os << "      <Points>\n"
     << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for(const Point_3& p : points) os << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  os << "        </DataArray>\n"
     << "      </Points>\n"
     << "      <Cells>\n"
     << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for(const std::array<int, N>& c : cells)
    for(std::size_t k = 0; k < N; ++k) os << c[k] << (k + 1 == N ? '\n' : ' ');
  os << "        </DataArray>\n"
     << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for(std::size_t c = 1; c <= cells.size(); ++c) os << N * c << '\n';
  os << "        </DataArray>\n"
     << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for(std::size_t c = 0; c < cells.size(); ++c) os << vtk_type << '\n';
  os << "        </DataArray>\n"
     << "      </Cells>\n"
     << "    </Piece>\n"
     << "  </UnstructuredGrid>\n"
     << "</VTKFile>\n";
  os.precision(precision);
  if(!os) throw std::runtime_error(function + ": the output stream failed");
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3IO
Writes the tetrahedra of `mesh` as an ASCII VTK XML unstructured grid (`.vtu`, cell type
`VTK_TETRA`), for ParaView. The particle kinds, when present, become the point array
`particle_kind`; every entry of `cell_data` becomes a cell array of that name (e.g. the
`theta_min` of `compute_tetrahedra_quality()`).

\throws std::invalid_argument if an array of `cell_data` does not have one value per tetrahedron
\throws std::runtime_error if the stream fails
*/
template <typename Point_3>
void write_vtu(std::ostream& os, const Tetrahedral_mesh_3<Point_3>& mesh,
               const std::map<std::string, std::vector<double> >& cell_data = {})
{
  internal::write_vtu_cells(os, "write_vtu()", mesh.points, mesh.tets, 10 /* VTK_TETRA */, mesh.vertex_kinds, cell_data);
}

/*!
\ingroup PkgLatticeMesher3IO
Writes line segments between `points` (pairs of indices into `points`), such as the singular
edges of a frame field (`Frame_field_diagnostics::singular_edges`), as an ASCII VTK XML
unstructured grid (`.vtu`, cell type `VTK_LINE`), for ParaView; every entry of `cell_data`
becomes a cell array of that name.

\throws std::invalid_argument if an array of `cell_data` does not have one value per segment
\throws std::runtime_error if the stream fails
*/
template <typename Point_3>
void write_vtu_segments(std::ostream& os, const std::vector<Point_3>& points, const std::vector<std::array<int, 2> >& segments,
                        const std::map<std::string, std::vector<double> >& cell_data = {})
{
  internal::write_vtu_cells(os, "write_vtu_segments()", points, segments, 3 /* VTK_LINE */, std::vector<Particle_kind>(), cell_data);
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_IO_VTU_H
