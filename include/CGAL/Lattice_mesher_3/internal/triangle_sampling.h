// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_INTERNAL_TRIANGLE_SAMPLING_H
#define CGAL_LATTICE_MESHER_3_INTERNAL_TRIANGLE_SAMPLING_H

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Lattice_mesher_3 {
namespace internal {

// Samples of a set of triangles, each vertex and edge taken once by the caller: with these and
// the vertices, every point of the triangles is closer than g to a sample, and a triangle gets
// about area / g^2 samples however thin it is.

// the points dividing ab, of the given length, into pieces at most g long, a and b excepted
template <typename Point_3, typename OutputIterator>
OutputIterator sample_segment(const Point_3& a, const Point_3& b, double length, double g, OutputIterator out)
{
  const int n = int(std::ceil(length / g));
  for(int i = 1; i < n; ++i) *out++ = a + (double(i) / n) * (b - a);
  return out;
}

template <typename Point_3, typename OutputIterator>
OutputIterator sample_segment(const Point_3& a, const Point_3& b, double g, OutputIterator out)
{
  return sample_segment(a, b, std::sqrt(CGAL::to_double((b - a).squared_length())), g, out);
}

// inside the triangle p (its edges excepted), rows parallel to its longest edge at most g from
// one another, each divided as by sample_segment()
template <typename Point_3, typename OutputIterator>
OutputIterator sample_triangle_inside(std::array<Point_3, 3> p, double g, OutputIterator out)
{
  auto length = [](const auto& v) { return std::sqrt(CGAL::to_double(v.squared_length())); };
  std::array<double, 3> side;   // side[k]: from p[k] to p[k + 1]
  for(std::size_t k = 0; k < 3; ++k) side[k] = length(p[(k + 1) % 3] - p[k]);
  const std::ptrdiff_t longest = std::max_element(side.begin(), side.end()) - side.begin();
  std::rotate(p.begin(), p.begin() + longest, p.end());
  const double base = side[std::size_t(longest)];
  if(!(base > 0.)) return out;
  const double height = length(CGAL::cross_product(p[1] - p[0], p[2] - p[0])) / base;
  const int rows = int(std::ceil(height / g));
  for(int j = 1; j < rows; ++j) {
    const double s = double(j) / rows;   // of the way from the longest edge to the opposite vertex
    out = sample_segment(p[0] + s * (p[2] - p[0]), p[1] + s * (p[2] - p[1]), (1. - s) * base, g, out);
  }
  return out;
}

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_TRIANGLE_SAMPLING_H
