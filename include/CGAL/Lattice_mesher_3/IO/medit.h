// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_IO_MEDIT_H
#define CGAL_LATTICE_MESHER_3_IO_MEDIT_H

#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <iomanip>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3IO
Writes `mesh` in the ASCII Medit format (`.mesh`, as `CGAL::IO::write_MEDIT`): the vertices,
the boundary faces as `Triangles` and the tetrahedra, with 1-based indices and full double
precision (`MeshVersionFormatted 2`, which tells readers the coordinates are doubles). The reference of a vertex is its particle kind + 1 (0 when `mesh.vertex_kinds` is
empty), so that `read_medit()` restores the kinds; a triangle's is its surface patch index and a
tetrahedron's its subdomain index (`boundary_patches`, `subdomains`; 1 where these are empty).

\throws std::runtime_error if the stream fails
*/
template <typename Point_3>
void write_medit(std::ostream& os, const Tetrahedral_mesh_3<Point_3>& mesh)
{
  const std::streamsize precision = os.precision();
  os << std::setprecision(17);
  os << "MeshVersionFormatted 2\nDimension 3\n";
  os << "Vertices\n" << mesh.points.size() << '\n';
  for(std::size_t i = 0; i < mesh.points.size(); ++i) {
    const int ref = mesh.vertex_kinds.empty() ? 0 : int(mesh.vertex_kinds[i]) + 1;
    os << mesh.points[i].x() << ' ' << mesh.points[i].y() << ' ' << mesh.points[i].z() << ' ' << ref << '\n';
  }
  os << "Triangles\n" << mesh.boundary_faces.size() << '\n';
  for(std::size_t k = 0; k < mesh.boundary_faces.size(); ++k) {
    const std::array<int, 3>& f = mesh.boundary_faces[k];
    os << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << ' ' << internal::label(mesh.boundary_patches, std::ptrdiff_t(k)) << '\n';
  }
  os << "Tetrahedra\n" << mesh.tets.size() << '\n';
  for(std::size_t k = 0; k < mesh.tets.size(); ++k) {
    const std::array<int, 4>& t = mesh.tets[k];
    os << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << ' ' << internal::label(mesh.subdomains, std::ptrdiff_t(k)) << '\n';
  }
  os << "End\n";
  os.precision(precision);
  if(!os) throw std::runtime_error("write_medit(): the output stream failed");
}

namespace internal {

// Whitespace-separated tokens of a Medit file, without '#' comments, with line numbers for
// the error messages, which start with `where`: the name of the reading function, and the
// file's if it knows it.
class Medit_tokenizer
{
public:
  Medit_tokenizer(std::istream& is, std::string where) : is_(is), where_(std::move(where)) {}

  // false at the end of the file
  bool next(std::string& token)
  {
    while(!(line_ >> token)) {
      std::string line;
      if(!std::getline(is_, line)) return false;
      ++line_number_;
      line_.clear();
      line_.str(line.substr(0, line.find('#')));
    }
    return true;
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    std::ostringstream os;
    os << where_ << ": " << what << " (line " << line_number_ << ")";
    throw std::runtime_error(os.str());
  }

  std::string expect_token(const std::string& context)
  {
    std::string token;
    if(!next(token)) fail("unexpected end of file in " + context);
    return token;
  }

  double read_double(const std::string& context)
  {
    const std::string token = expect_token(context);
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(token.c_str(), &end);
    if(end != token.c_str() + token.size() || errno == ERANGE)
      fail("expected a number in " + context + ", got '" + token + "'");
    return value;
  }

  long long read_integer(const std::string& context, long long min, long long max)
  {
    const std::string token = expect_token(context);
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(token.c_str(), &end, 10);
    if(end != token.c_str() + token.size() || errno == ERANGE)
      fail("expected an integer in " + context + ", got '" + token + "'");
    if(value < min || value > max) {
      std::ostringstream os;
      os << "value " << value << " out of range [" << min << ", " << max << "] in " << context;
      fail(os.str());
    }
    return value;
  }

  // references are integers of any sign and size (CGAL writes surface patch indices)
  long long read_reference(const std::string& context)
  {
    return read_integer(context + " (reference)", std::numeric_limits<long long>::min(),
                        std::numeric_limits<long long>::max());
  }

private:
  std::istream& is_;
  std::string where_;
  std::istringstream line_;
  int line_number_ = 0;
};

// Numbers per entry of the sections read_medit() skips (3D files).
inline int medit_skipped_entry_size(const std::string& keyword)
{
  static const std::pair<const char*, int> sizes[] = {
    { "Edges", 3 }, { "Corners", 1 }, { "Ridges", 1 }, { "RequiredVertices", 1 },
    { "RequiredEdges", 1 }, { "RequiredTriangles", 1 }, { "RequiredTetrahedra", 1 },
    { "Quadrilaterals", 5 }, { "Hexahedra", 9 }, { "Prisms", 7 }, { "Normals", 3 },
    { "NormalAtVertices", 2 }, { "NormalAtTriangleVertices", 3 }, { "Tangents", 3 },
    { "TangentAtVertices", 2 }, { "TangentAtEdges", 3 } };
  for(const auto& s : sizes)
    if(keyword == s.first) return s.second;
  return 0;
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3IO
Reads an ASCII Medit file (as written by `write_medit()` or `CGAL::IO::write_MEDIT`) into
`mesh`: `Vertices`, `Triangles` (into `boundary_faces`, as given, their references into
`boundary_patches`) and `Tetrahedra` (as given, their references into `subdomains`).
The other sections of 3D meshes (`Edges`, `Corners`, `Ridges`, `Required*`, ...) are skipped,
as are comments ('#'). `vertex_kinds` is filled when every vertex reference is a particle kind
+ 1, as `write_medit()` writes them, and left empty otherwise. `mesh` is only modified on success.

\throws std::runtime_error naming the line, for a truncated or garbled file, an unknown
section, or an index out of range
*/
template <typename Point_3>
void read_medit(std::istream& is, Tetrahedral_mesh_3<Point_3>& mesh)
{
  internal::Medit_tokenizer in(is, "read_medit()");
  const long long max_count = std::numeric_limits<int>::max();
  Tetrahedral_mesh_3<Point_3> result;
  std::vector<long long> vertex_refs;

  std::string keyword;
  if(!in.next(keyword) || keyword != "MeshVersionFormatted")
    in.fail("not a Medit file: expected 'MeshVersionFormatted', got '" + keyword + "'");
  in.read_integer("MeshVersionFormatted", 1, 2);
  bool ended = false;
  while(!ended && in.next(keyword)) {
    if(keyword == "End") {
      ended = true;
    } else if(keyword == "Dimension") {
      in.read_integer("Dimension (only 3D meshes are read)", 3, 3);
    } else if(keyword == "Vertices") {
      const long long n = in.read_integer("the number of Vertices", 0, max_count);
      result.points.reserve(std::size_t(n));
      vertex_refs.reserve(std::size_t(n));
      for(long long i = 0; i < n; ++i) {
        const double x = in.read_double("Vertices"), y = in.read_double("Vertices"), z = in.read_double("Vertices");
        result.points.emplace_back(x, y, z);
        vertex_refs.push_back(in.read_reference("Vertices"));
      }
    } else if(keyword == "Triangles" || keyword == "Tetrahedra") {
      const bool triangles = keyword == "Triangles";
      const long long n = in.read_integer("the number of " + keyword, 0, max_count);
      for(long long i = 0; i < n; ++i) {
        std::array<int, 4> v;
        for(int k = 0; k < (triangles ? 3 : 4); ++k)
          v[k] = int(in.read_integer(keyword + " (vertex index)", 1, (long long)(result.points.size()))) - 1;
        const long long ref = in.read_reference(keyword);
        if(triangles) { result.boundary_faces.push_back({ v[0], v[1], v[2] }); result.boundary_patches.push_back(int(ref)); }
        else { result.tets.push_back(v); result.subdomains.push_back(int(ref)); }
      }
    } else if(const int size = internal::medit_skipped_entry_size(keyword)) {
      const long long n = in.read_integer("the number of " + keyword, 0, max_count);
      for(long long i = 0; i < n * size; ++i) in.read_double(keyword);
    } else {
      in.fail("unknown or misplaced keyword '" + keyword + "'");
    }
  }
  if(!ended) in.fail("unexpected end of file: missing 'End'");

  bool refs_are_kinds = !vertex_refs.empty();
  for(long long ref : vertex_refs) refs_are_kinds = refs_are_kinds && ref >= 1 && ref <= 4;
  if(refs_are_kinds)
    for(long long ref : vertex_refs) result.vertex_kinds.push_back(Particle_kind(ref - 1));
  mesh = std::move(result);
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_IO_MEDIT_H
