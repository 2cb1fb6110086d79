// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_BOUNDARY_PROJECTION_3_H
#define CGAL_LATTICE_MESHER_3_BOUNDARY_PROJECTION_3_H

namespace CGAL {
namespace Lattice_mesher_3 {

/// Result of a projection onto a domain's boundary surface or onto one of its feature curves.
template <typename K>
struct Boundary_projection_3
{
  typename K::Point_3 point;      ///< the closest point
  typename K::Vector_3 direction; ///< unit outward normal (surface) or unit tangent (curve)
  int index = -1;                 ///< feature curve index, -1 for the surface or when none
  double squared_distance = 0.;   ///< from the query point to `point`
};

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_BOUNDARY_PROJECTION_3_H
