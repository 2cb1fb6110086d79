// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_IO_FRAME_FIELD_H
#define CGAL_LATTICE_MESHER_3_IO_FRAME_FIELD_H

#include <CGAL/Lattice_mesher_3/Discrete_frame_field_3.h>
#include <CGAL/Lattice_mesher_3/IO/medit.h>

#include <CGAL/Bbox_3.h>

#include <Eigen/Dense>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

// File formats of discrete frame fields (see the manual, "Discrete Frame Fields and Their Files").
//
// Medit .sol files, as MMG and libMeshb write them: "SolAtVertices", the number of vertices, then
// the number of fields and their types (1 scalar, 2 vector, 3 symmetric matrix, 4 matrix: GmfSca,
// GmfVec, GmfSymMat, GmfMat in libMeshb's libmeshb7.h; MMG5_chkMetricType in mmg's
// src/common/inout.c reads 1 as an isotropic and 3 as an anisotropic metric), then the values of
// each vertex. A
// symmetric 3x3 tensor is stored as m11 m12 m22 m13 m23 m33 (the lower triangle row by row):
// MMG keeps m11 m12 m13 m22 m23 m33 in memory (its anisotropic length is m[0] ux^2 + m[3] uy^2 +
// m[5] uz^2 + 2 (m[1] ux uy + m[2] ux uz + m[4] uy uz)) and swaps the third and fourth values when
// it reads or writes a .sol (MMG5_readDoubleSol3D / MMG5_writeDoubleSol3D in mmg's
// src/common/inout.c). A metric M prescribes unit edges in the metric, |v|_M^2 = v^T M v, hence
// B = M^(1/2) and T = M^(-1/2).

namespace CGAL {
namespace Lattice_mesher_3 {

namespace internal {

// Reads the whitespace-separated numbers of `line`, up to a '#', into `values` (at most
// `capacity`); returns how many there are (more than `capacity` if there are more), or throws
// std::runtime_error prefixed by `where` at a token that is not a number.
inline std::size_t parse_numbers(const std::string& line, double* values, std::size_t capacity, const std::string& where)
{
  std::size_t count = 0;
  const char* p = line.c_str();
  for(;;) {
    while(*p == ' ' || *p == '\t' || *p == '\r') ++p;
    if(*p == '\0' || *p == '#') return count;
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if(end == p || (*end != '\0' && *end != ' ' && *end != '\t' && *end != '\r' && *end != '#')) {
      const char* stop = p;
      while(*stop != '\0' && *stop != ' ' && *stop != '\t' && *stop != '\r') ++stop;
      throw std::runtime_error(where + ": '" + std::string(p, stop) + "' is not a number");
    }
    if(count < capacity) values[count] = v;
    ++count;
    p = end;
  }
}

inline std::ifstream open_input_file(const std::string& function, const std::string& filename)
{
  std::ifstream is(filename);
  if(!is) throw std::runtime_error(function + ": cannot open '" + filename + "'");
  return is;
}

// "function: 'file' line n"
inline std::string file_line(const std::string& function, const std::string& filename, std::size_t line)
{ return function + ": '" + filename + "' line " + std::to_string(line); }

// Calls f(); rethrows its std::invalid_argument or std::domain_error (a non-finite or singular
// sample) as the std::runtime_error of a bad file, prefixed by `where`.
template <typename F>
void as_file_error(const std::string& where, F f)
{
  try { f(); }
  catch(const std::logic_error& e) { throw std::runtime_error(where + ": " + e.what()); }
}

// T = M^(-1/2) from a metric in .sol order m11 m12 m22 m13 m23 m33; false unless M is symmetric
// positive definite.
inline bool frame_from_metric(const double m[6], Eigen::Matrix3d& t, Eigen::Vector3d& eigenvalues)
{
  Eigen::Matrix3d metric;
  metric << m[0], m[1], m[3],
            m[1], m[2], m[4],
            m[3], m[4], m[5];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(metric);
  eigenvalues = eigen.eigenvalues();
  if(eigen.info() != Eigen::Success || !(eigenvalues.minCoeff() > 0.)) return false;
  t = eigen.operatorInverseSqrt();
  return true;
}

// Reads the one SolAtVertices section of `n` entries and one field of a Medit .sol file: `check(type)`
// says why a solution type is not taken (empty if it is), and `vertex(i, values, type, fail)` takes
// the values of vertex i (1, 3, 6 or 9 for the types 1 to 4), calling `fail(message)` on a bad one.
// The errors start with `where`.
template <typename Check, typename Vertex>
void read_sol_at_vertices(std::istream& is, std::size_t n, const std::string& where, const Check& check, const Vertex& vertex)
{
  Medit_tokenizer in(is, where);
  const std::function<void(const std::string&)> fail = [&](const std::string& what) { in.fail(what); };
  std::string keyword;
  if(!in.next(keyword) || keyword != "MeshVersionFormatted")
    in.fail("not a Medit .sol file: expected 'MeshVersionFormatted', got '" + keyword + "'");
  in.read_integer("MeshVersionFormatted", 1, 4);
  bool ended = false, read = false;
  while(!ended && in.next(keyword)) {
    if(keyword == "End") {
      ended = true;
    } else if(keyword == "Dimension") {
      in.read_integer("Dimension (only 3D fields are read)", 3, 3);
    } else if(keyword == "SolAtVertices" && !read) {
      const long long count = in.read_integer("the number of SolAtVertices", 0, std::numeric_limits<int>::max());
      if(std::size_t(count) != n)
        in.fail("SolAtVertices has " + std::to_string(count) + " entries for a mesh of " + std::to_string(n) + " vertices");
      in.read_integer("the number of solution fields (one field is read)", 1, 1);
      const long long type = in.read_integer("the solution type", 1, 4);
      const std::string refused = check(type);
      if(!refused.empty()) in.fail(refused);
      const int values = type == 1 ? 1 : type == 2 ? 3 : type == 3 ? 6 : 9;
      for(std::size_t i = 0; i < n; ++i) {
        double v[9];
        for(int k = 0; k < values; ++k)
          if(!std::isfinite(v[k] = in.read_double("SolAtVertices"))) in.fail("vertex " + std::to_string(i + 1) + ": non-finite value");
        vertex(i, v, type, fail);
      }
      read = true;
    } else {
      in.fail("unknown or misplaced keyword '" + keyword + "' (one SolAtVertices section is read)");
    }
  }
  if(!read) in.fail("no SolAtVertices section");
  if(!ended) in.fail("unexpected end of file: missing 'End'");
}

// The frames of a Medit .sol file, one per point: a "SolAtVertices" section with one field of
// type 4 (9 values: T row by row) or 3 (6 values: a metric M, T = M^(-1/2)). The errors start
// with `where`.
template <typename Point_3>
std::vector<Eigen::Matrix3d> read_sol_frames(std::istream& is, const std::vector<Point_3>& points,
                                             const std::string& where)
{
  std::vector<Eigen::Matrix3d> frames;
  auto check = [](long long type) {
    return type == 3 || type == 4 ? std::string()
         : "solution type " + std::to_string(type) + (type == 1 ? " (scalar)" : " (vector)")
           + " is not a frame: expected 4 (a 3x3 frame, 9 values) or 3 (a symmetric metric, 6 values)";
  };
  read_sol_at_vertices(is, points.size(), where, check,
    [&](std::size_t i, const double* v, long long type, const std::function<void(const std::string&)>& fail) {
      const std::string vertex = "vertex " + std::to_string(i + 1);
      Eigen::Matrix3d t;
      Eigen::Vector3d eigenvalues;
      if(type == 4) {
        t = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> >(v);
      } else if(!frame_from_metric(v, t, eigenvalues)) {
        std::ostringstream os;
        os << vertex << ": the metric is not positive definite (eigenvalues " << eigenvalues.transpose() << ")";
        fail(os.str());
      }
      try { check_frame_sample(vertex, points[i], t); }
      catch(const std::exception& e) { fail(e.what()); }
      frames.push_back(t);
    });
  return frames;
}

// The frames of a plain file, one line of 9 numbers per point: the frame vectors t1, t2, t3 one
// after the other (T column by column).
template <typename Point_3>
std::vector<Eigen::Matrix3d> read_plain_frames(std::istream& is, const std::vector<Point_3>& points,
                                               const std::string& function, const std::string& filename)
{
  std::vector<Eigen::Matrix3d> frames;
  std::string line;
  for(std::size_t number = 1; std::getline(is, line); ++number) {
    const std::string where = file_line(function, filename, number);
    double v[9];
    const std::size_t n = parse_numbers(line, v, 9, where);
    if(n == 0) continue;
    if(n != 9) throw std::runtime_error(where + ": expected 9 numbers (t1, t2, t3), got " + std::to_string(n));
    if(frames.size() == points.size())
      throw std::runtime_error(where + ": more frames than the " + std::to_string(points.size()) + " mesh vertices");
    frames.push_back(Eigen::Map<const Eigen::Matrix3d>(v));
    as_file_error(where, [&] { check_frame_sample("vertex " + std::to_string(frames.size()), points[frames.size() - 1], frames.back()); });
  }
  if(is.bad()) throw std::runtime_error(function + ": error while reading '" + filename + "'");
  if(frames.size() != points.size())
    throw std::runtime_error(function + ": '" + filename + "' ends after " + std::to_string(frames.size())
                             + " frames, for a mesh of " + std::to_string(points.size()) + " vertices");
  return frames;
}

// True if the first token of the stream, comments skipped, is Medit's first keyword.
inline bool starts_like_medit(std::istream& is)
{
  std::string line, token;
  while(std::getline(is, line)) {
    std::istringstream tokens(line.substr(0, line.find('#')));
    if(tokens >> token) break;
  }
  is.clear();
  is.seekg(0);
  return token == "MeshVersionFormatted";
}

// Writes v with the shortest decimal form that reads back to the same double, then `separator`.
inline void put_double(std::ostream& os, double v, char separator)
{
  char buffer[32];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), v);
  os.write(buffer, r.ptr - buffer);
  os.put(separator);
}

inline std::ofstream open_output_file(const std::string& function, const std::string& filename)
{
  std::ofstream os(filename);
  if(!os) throw std::runtime_error(function + ": cannot write '" + filename + "'");
  return os;
}

inline void close_output_file(const std::string& function, const std::string& filename, std::ofstream& os)
{
  os.close();
  if(!os) throw std::runtime_error(function + ": error while writing '" + filename + "'");
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3IO
Reads a discrete frame field from a text file with one sample a line,

    x y z t11 t12 t13 t21 t22 t23 t31 t32 t33

that is the point, then the frame T row by row (its columns t1, t2, t3 are the lattice cube
edges). Blank lines and comments (from '#' to the end of the line) are skipped.
`write_frame_field_samples()` writes this format.

\throws std::runtime_error naming the file and the line, for a missing file, a line that does
not hold 12 numbers, a non-finite value, or a near-singular frame (with its condition number);
and for a file without samples
*/
template <typename GT>
Discrete_frame_field_3<GT> read_frame_field_samples(const std::string& filename)
{
  typedef typename GT::Point_3 Point_3;
  const std::string function = "read_frame_field_samples()";
  std::ifstream is = internal::open_input_file(function, filename);
  std::vector<Point_3> points;
  std::vector<typename GT::Matrix_3> frames;
  std::string line;
  for(std::size_t number = 1; std::getline(is, line); ++number) {
    const std::string where = internal::file_line(function, filename, number);
    double v[12];
    const std::size_t n = internal::parse_numbers(line, v, 12, where);
    if(n == 0) continue;
    if(n != 12)
      throw std::runtime_error(where + ": expected 12 numbers (x y z, then T row by row), got " + std::to_string(n));
    points.emplace_back(v[0], v[1], v[2]);
    frames.push_back(Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> >(v + 3));
    internal::as_file_error(where, [&] {
      internal::check_frame_sample("sample " + std::to_string(points.size() - 1), points.back(), frames.back());
    });
  }
  if(is.bad()) throw std::runtime_error(function + ": error while reading '" + filename + "'");
  if(points.empty()) throw std::runtime_error(function + ": '" + filename + "' holds no sample");
  return Discrete_frame_field_3<GT>(std::move(points), std::move(frames));
}

/*!
\ingroup PkgLatticeMesher3IO
Reads a discrete frame field whose samples are the vertices of a Medit mesh (`mesh_file`, read
by `read_medit()`), with the frames in `data_file`, which is either

- a Medit solution file (`.sol`, ASCII, as MMG writes them) with one `SolAtVertices`
  field, of type 4 (9 values a vertex: T row by row) or of type 3 (6 values a vertex: a symmetric
  metric tensor M, in Medit's order m11 m12 m22 m13 m23 m33; then T = M^(-1/2), the frame whose
  unit lattice cube has unit edges in the metric); or
- a plain text file with 9 numbers a line, one line per vertex in the mesh's order: the frame
  vectors one after the other, t1x t1y t1z t2x t2y t2z t3x t3y t3z (T column by column), as
  frame-field generators write their frames; '#' starts a comment.

The kind of `data_file` is recognized by its first keyword (`MeshVersionFormatted` for `.sol`).
If the mesh has tetrahedra, the field interpolates the frames in them (see
`Discrete_frame_field_3`). `write_frame_field_to_medit()` writes these two files.

\throws std::runtime_error naming the file and the line (in a `.sol` file, the line of the
vertex's last value), for a missing, truncated or garbled file, a count of frames that differs
from the number of vertices, a non-finite value, a metric that is not positive definite, a
solution type that is not a frame or a metric, or a near-singular frame (with its condition number)
*/
template <typename GT>
Discrete_frame_field_3<GT> read_frame_field_from_medit(const std::string& mesh_file, const std::string& data_file)
{
  const std::string function = "read_frame_field_from_medit()";
  Tetrahedral_mesh_3<typename GT::Point_3> mesh;
  {
    std::ifstream is = internal::open_input_file(function, mesh_file);
    try { read_medit(is, mesh); }
    catch(const std::exception& e) { throw std::runtime_error(function + ": '" + mesh_file + "': " + e.what()); }
  }
  std::ifstream is = internal::open_input_file(function, data_file);
  std::vector<typename GT::Matrix_3> frames;
  if(internal::starts_like_medit(is))
    frames = internal::read_sol_frames(is, mesh.points, function + ": '" + data_file + "'");
  else
    frames = internal::read_plain_frames(is, mesh.points, function, data_file);
  return Discrete_frame_field_3<GT>(std::move(mesh), std::move(frames));
}

/*!
\ingroup PkgLatticeMesher3IO
Samples `field` (a model of `FrameField_3`) on the regular grid that spans `bbox` with a spacing
of at most `spacing` along each axis (its end points included), and writes the samples in the
format `read_frame_field_samples()` reads, with the shortest decimal forms that read back to
the same doubles.

\throws std::invalid_argument if `spacing` is not positive or `bbox` not finite or empty, or if
the grid would exceed 1e8 samples
\throws std::runtime_error naming the file if it cannot be written
*/
template <typename FrameField>
void write_frame_field_samples(const std::string& filename, const FrameField& field, const CGAL::Bbox_3& bbox,
                               double spacing)
{
  typedef typename FrameField::Point_3 Point_3;
  const std::string function = "write_frame_field_samples()";
  if(!(spacing > 0.) || !std::isfinite(spacing))
    throw std::invalid_argument(function + ": the spacing must be positive, got " + std::to_string(spacing));
  std::size_t count[3];
  double total = 1.;
  for(int a = 0; a < 3; ++a) {
    const double extent = bbox.max_coord(a) - bbox.min_coord(a);
    if(!(extent >= 0.) || !std::isfinite(extent))
      throw std::invalid_argument(function + ": the box must be finite and not empty");
    const double intervals = std::ceil(extent / spacing * (1. - 1e-12));   // 1.0 / 0.1 gives 10, not 11
    total *= intervals + 1.;
    if(total > 1e8)
      throw std::invalid_argument(function + ": a spacing of " + std::to_string(spacing) + " gives more than 1e8 samples");
    count[a] = std::size_t(intervals) + 1;
  }
  auto coordinate = [&](int a, std::size_t i) {   // the box's faces exactly: the samples cover it
    const double lo = bbox.min_coord(a), hi = bbox.max_coord(a);
    return i + 1 == count[a] ? hi : lo + (hi - lo) * double(i) / double(count[a] - 1);
  };

  std::ofstream os = internal::open_output_file(function, filename);
  os << "# frame field samples: x y z t11 t12 t13 t21 t22 t23 t31 t32 t33 (T row by row, its columns are the\n"
        "# lattice cube edges), on a " << count[0] << " x " << count[1] << " x " << count[2] << " grid\n";
  auto put = [&](double v, char separator) { internal::put_double(os, v, separator); };
  for(std::size_t i = 0; i < count[0]; ++i)
    for(std::size_t j = 0; j < count[1]; ++j)
      for(std::size_t k = 0; k < count[2]; ++k) {
        const double x = coordinate(0, i), y = coordinate(1, j), z = coordinate(2, k);
        const Eigen::Matrix3d t = field.frame(Point_3(x, y, z));
        put(x, ' '); put(y, ' '); put(z, ' ');
        for(int r = 0; r < 3; ++r)
          for(int c = 0; c < 3; ++c) put(t(r, c), r == 2 && c == 2 ? '\n' : ' ');
      }
  internal::close_output_file(function, filename, os);
}

/*!
\ingroup PkgLatticeMesher3IO
Writes the samples of `field` in the format `read_frame_field_samples()` reads (one line
`x y z t11 ... t33` a sample), with the shortest decimal forms that read back to the same doubles.
A field built on a tetrahedral mesh loses its tetrahedra in this format: read back, it is the
field of its samples alone; `write_frame_field_to_medit()` keeps them.
\throws std::runtime_error naming the file if it cannot be written
*/
template <typename GT>
void write_frame_field_samples(const std::string& filename, const Discrete_frame_field_3<GT>& field)
{
  const std::string function = "write_frame_field_samples()";
  std::ofstream os = internal::open_output_file(function, filename);
  os << "# frame field samples: x y z t11 t12 t13 t21 t22 t23 t31 t32 t33 (T row by row, its columns are the\n"
        "# lattice cube edges), " << field.number_of_samples() << " samples\n";
  for(std::size_t i = 0; i < field.number_of_samples(); ++i) {
    const auto& p = field.points()[i];
    const Eigen::Matrix3d& t = field.frames()[i];
    internal::put_double(os, p.x(), ' '); internal::put_double(os, p.y(), ' '); internal::put_double(os, p.z(), ' ');
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 3; ++c) internal::put_double(os, t(r, c), r == 2 && c == 2 ? '\n' : ' ');
  }
  internal::close_output_file(function, filename, os);
}

/*!
\ingroup PkgLatticeMesher3IO
Writes `field` as `read_frame_field_from_medit()` reads it: its samples' mesh (`field.mesh()`,
with its tetrahedra) to the Medit file `mesh_file`, and the frames to the Medit solution file
`data_file` (one `SolAtVertices` field of type 4: T row by row), with the shortest decimal forms
that read back to the same doubles.
\throws std::runtime_error naming the file if one cannot be written
*/
template <typename GT>
void write_frame_field_to_medit(const std::string& mesh_file, const std::string& data_file,
                                const Discrete_frame_field_3<GT>& field)
{
  const std::string function = "write_frame_field_to_medit()";
  {
    std::ofstream os = internal::open_output_file(function, mesh_file);
    write_medit(os, field.mesh());
    internal::close_output_file(function, mesh_file, os);
  }
  std::ofstream os = internal::open_output_file(function, data_file);
  os << "MeshVersionFormatted 2\n\nDimension 3\n\nSolAtVertices\n" << field.number_of_samples() << "\n1 4\n";
  for(const Eigen::Matrix3d& t : field.frames())
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 3; ++c) internal::put_double(os, t(r, c), r == 2 && c == 2 ? '\n' : ' ');
  os << "\nEnd\n";
  internal::close_output_file(function, data_file, os);
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_IO_FRAME_FIELD_H
