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

namespace CGAL {
namespace Lattice_mesher_3 {
namespace internal {

// |det B| over the domain: its mean (isotropic volume = volume x mean) and its maximum.
struct Det_b_samples
{
  double mean = 1.;
  double max = 1.;
};

// Samples up to `n` points inside the domain with a fixed seed, so that the estimate, and the
// particle count derived from it, do not change from run to run.
template <typename Domain, typename FrameField>
Det_b_samples sample_det_b(const Domain& domain, const FrameField& field, std::size_t n)
{
  typedef typename Domain::Geom_traits::Point_3 Point_3;
  const CGAL::Bbox_3 bb = domain.bbox();
  std::mt19937_64 g(0x5eed);
  auto u = [&] { return double(g() >> 11) * 0x1.0p-53; };
  double sum = 0., max = 0.;
  std::size_t inside = 0;
  for(std::size_t tries = 0; inside < n && tries < 200 * n; ++tries) {
    const Point_3 p(bb.xmin() + u() * (bb.xmax() - bb.xmin()), bb.ymin() + u() * (bb.ymax() - bb.ymin()),
                    bb.zmin() + u() * (bb.zmax() - bb.zmin()));
    if(!domain.is_inside(p)) continue;
    const double d = std::abs(isotropic_map(field.frame(p), p).determinant());
    sum += d;
    max = (std::max)(max, d);
    ++inside;
  }
  if(inside == 0)
    throw std::invalid_argument("the domain is empty: no point of its bounding box is inside");
  return { sum / double(inside), max };
}

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_FIELD_SAMPLING_H
