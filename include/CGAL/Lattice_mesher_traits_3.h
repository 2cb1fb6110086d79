// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_TRAITS_3_H
#define CGAL_LATTICE_MESHER_TRAITS_3_H

#include <CGAL/number_utils.h>
#include <Eigen/Dense>

namespace CGAL {

/*!
\ingroup PkgLatticeMesher3Ref

The default model of `LatticeMesherTraits_3`: the kernel `K` plus the dense matrix and
vector types in which frames and isotropic-space vectors are expressed.

\tparam K a CGAL kernel with `double`-convertible coordinates, e.g. `Epick`.
*/
template <typename K>
class Lattice_mesher_traits_3 : public K
{
public:
  typedef K                                Kernel;   ///< the kernel
  typedef typename K::FT                   FT;       ///< the number type
  typedef typename K::Point_3              Point_3;  ///< the point type
  typedef typename K::Vector_3             Vector_3; /*!< \brief the vector type */
  /// 3x3 frame: its columns are the lattice cube edges t1, t2, t3.
  typedef Eigen::Matrix<double, 3, 3>      Matrix_3;
  /// Dense 3-vector used in the hot loops.
  typedef Eigen::Matrix<double, 3, 1>      Vector_d3;

  /// constructs the traits from the kernel object `k`
  Lattice_mesher_traits_3(const K& k = K()) : K(k) {}
};

} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_TRAITS_3_H
