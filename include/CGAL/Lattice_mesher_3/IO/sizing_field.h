// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_IO_SIZING_FIELD_H
#define CGAL_LATTICE_MESHER_3_IO_SIZING_FIELD_H

#include <CGAL/Lattice_mesher_3/IO/frame_field.h>
#include <CGAL/Lattice_mesher_3/IO/medit.h>
#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3IO
Reads sizes given at points (the largest edge length there), for a `Graded_sizing_field_3`, from
either

- a text file with one sample a line, `x y z h` ('#' starts a comment); or
- a Medit mesh (`filename` starting with `MeshVersionFormatted`, read by `read_medit()`, only its
  vertices are used) with the sizes in `data_file` (default: `filename` with the extension
  `.sol`): a Medit solution file with one `SolAtVertices` field of type 1 (a scalar a vertex), the
  isotropic size map that MMG reads and writes.

\throws std::runtime_error naming the file and the line for a missing, truncated or garbled file,
a size that is not positive and finite, a count of sizes that differs from the number of
vertices, a solution type that is not a scalar, or a file without samples
*/
template <typename K>
std::vector<std::pair<typename K::Point_3, double> >
read_size_samples(const std::string& filename, std::string data_file = std::string())
{
  typedef typename K::Point_3 Point_3;
  const std::string function = "read_size_samples()";
  std::vector<std::pair<Point_3, double> > samples;
  std::ifstream is = internal::open_input_file(function, filename);
  auto positive = [](double h) { return h > 0. && std::isfinite(h); };
  if(internal::starts_like_medit(is)) {
    Tetrahedral_mesh_3<Point_3> mesh;
    try { read_medit(is, mesh); }
    catch(const std::exception& e) { throw std::runtime_error(function + ": '" + filename + "': " + e.what()); }
    if(data_file.empty()) {
      const std::size_t dot = filename.find_last_of('.'), slash = filename.find_last_of('/');
      data_file = (dot != std::string::npos && (slash == std::string::npos || dot > slash) ? filename.substr(0, dot) : filename) + ".sol";
    }
    std::ifstream data = internal::open_input_file(function, data_file);
    const std::string where = function + ": '" + data_file + "'";
    internal::read_sol_at_vertices(data, mesh.points.size(), where,
      [](long long type) { return type == 1 ? std::string() : "solution type " + std::to_string(type) + " is not a size: expected 1 (a scalar)"; },
      [&](std::size_t i, const double* v, long long, const std::function<void(const std::string&)>& fail) {
        if(!positive(v[0])) fail("vertex " + std::to_string(i + 1) + ": the size is not positive and finite");
        samples.emplace_back(mesh.points[i], v[0]);
      });
  } else {
    std::string line;
    for(std::size_t number = 1; std::getline(is, line); ++number) {
      const std::string where = internal::file_line(function, filename, number);
      double v[4];
      const std::size_t n = internal::parse_numbers(line, v, 4, where);
      if(n == 0) continue;
      if(n != 4) throw std::runtime_error(where + ": expected 4 numbers (x y z h), got " + std::to_string(n));
      if(!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
        throw std::runtime_error(where + ": the point is not finite");
      if(!positive(v[3]))
        throw std::runtime_error(where + ": the size " + std::to_string(v[3]) + " is not positive and finite");
      samples.emplace_back(Point_3(v[0], v[1], v[2]), v[3]);
    }
    if(is.bad()) throw std::runtime_error(function + ": error while reading '" + filename + "'");
  }
  if(samples.empty()) throw std::runtime_error(function + ": '" + filename + "' holds no sample");
  return samples;
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_IO_SIZING_FIELD_H
