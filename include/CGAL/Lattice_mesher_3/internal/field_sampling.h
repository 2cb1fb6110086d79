// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_INTERNAL_FIELD_SAMPLING_H
#define CGAL_LATTICE_MESHER_3_INTERNAL_FIELD_SAMPLING_H

#include <CGAL/Lattice_mesher_3/frame_fields.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {
namespace internal {

// |det B| over the domain: its mean (isotropic volume = volume x mean) and its maximum.
struct Det_b_samples
{
  double mean = 1.;
  double max = 1.;
};

// A point of the box drawn with `u`, a generator of uniform numbers in [0, 1): three calls in a
// fixed order (z, y, x: the order GCC gave the calls written as constructor arguments, whose
// order C++ leaves open), so that every platform draws the same points.
template <typename Point_3, typename Uniform>
Point_3 random_point(const CGAL::Bbox_3& bb, Uniform& u)
{
  const double z = bb.zmin() + u() * (bb.zmax() - bb.zmin());
  const double y = bb.ymin() + u() * (bb.ymax() - bb.ymin());
  return Point_3(bb.xmin() + u() * (bb.xmax() - bb.xmin()), y, z);
}

// Up to `n` points inside the domain, uniform in its bounding box, from a fixed seed, so that the
// estimates made from them, and the particle count derived from these, do not change from run
// to run.
template <typename Domain>
std::vector<typename Domain::Geom_traits::Point_3> inside_samples(const Domain& domain, std::size_t n)
{
  typedef typename Domain::Geom_traits::Point_3 Point_3;
  const CGAL::Bbox_3 bb = domain.bbox();
  std::mt19937_64 g(0x5eed);
  auto u = [&] { return double(g() >> 11) * 0x1.0p-53; };
  std::vector<Point_3> points;
  for(std::size_t tries = 0; points.size() < n && tries < 200 * n; ++tries) {
    const Point_3 p = random_point<Point_3>(bb, u);
    if(domain.is_inside(p)) points.push_back(p);
  }
  if(points.empty())
    throw std::invalid_argument("the domain is empty: no point of its bounding box is inside");
  return points;
}

// |det B| of `field` at the points.
template <typename Point_3, typename FrameField>
Det_b_samples det_b_at(const std::vector<Point_3>& points, const FrameField& field)
{
  double sum = 0., max = 0.;
  for(const Point_3& p : points) {
    const double d = std::abs(isotropic_map(field.frame(p), p).determinant());
    sum += d;
    max = (std::max)(max, d);
  }
  return { sum / double(points.size()), max };
}

// |det B| at `n` inside_samples().
template <typename Domain, typename FrameField>
Det_b_samples sample_det_b(const Domain& domain, const FrameField& field, std::size_t n)
{
  return det_b_at(inside_samples(domain, n), field);
}

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_FIELD_SAMPLING_H
