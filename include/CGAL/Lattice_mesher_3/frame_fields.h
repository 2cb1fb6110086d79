// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_FRAME_FIELDS_H
#define CGAL_LATTICE_MESHER_3_FRAME_FIELDS_H

#include <CGAL/Lattice_mesher_traits_3.h>

#include <Eigen/Dense>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Lattice_mesher_3 {

// Models of `FrameField_3`: `Matrix_3 frame(const Point_3& p) const` returns T(p), whose
// columns are the lattice cube edges at p. B(p) = T(p)^-1 maps physical to isotropic space.

/*!
\ingroup PkgLatticeMesher3FrameFields
The same frame everywhere: the identity (axis-aligned unit cubes) by default, or any
invertible matrix (a rotation, a constant stretch or shear).
*/
template <typename GT>
class Constant_frame_field_3
{
public:
  typedef typename GT::Point_3  Point_3;
  typedef typename GT::Matrix_3 Matrix_3;

  explicit Constant_frame_field_3(const Matrix_3& t = Matrix_3::Identity()) : t_(t) {}
  const Matrix_3& frame(const Point_3&) const { return t_; }

private:
  Matrix_3 t_;
};

/*!
\ingroup PkgLatticeMesher3FrameFields
Any callable `Point_3 -> Matrix_3` (analytic fields, lambdas).
*/
template <typename GT, typename F>
class Function_frame_field_3
{
public:
  typedef typename GT::Point_3  Point_3;
  typedef typename GT::Matrix_3 Matrix_3;

  explicit Function_frame_field_3(F f) : f_(std::move(f)) {}
  Matrix_3 frame(const Point_3& p) const { return f_(p); }

private:
  F f_;
};

template <typename GT, typename F>
Function_frame_field_3<GT, F> make_function_frame_field_3(F f)
{ return Function_frame_field_3<GT, F>(std::move(f)); }

/*!
\ingroup PkgLatticeMesher3FrameFields
The paper's torus field Ry: at p, the identity frame rotated about the y axis by the azimuth
phi = atan2(p_z, p_x), so that t1 is radial, t2 = y and t3 tangential. On the y axis
(p_x = p_z = 0), where phi is undefined, the identity is returned. `scale` multiplies every
column (a uniform cube size).
*/
template <typename GT>
class Rotation_y_frame_field_3
{
public:
  typedef typename GT::Point_3  Point_3;
  typedef typename GT::Matrix_3 Matrix_3;

  explicit Rotation_y_frame_field_3(double scale = 1.) : scale_(scale) {}
  Matrix_3 frame(const Point_3& p) const
  {
    const double x = CGAL::to_double(p.x()), z = CGAL::to_double(p.z());
    const double r = std::sqrt(x * x + z * z);
    const double c = r > 0. ? x / r : 1., s = r > 0. ? z / r : 0.;
    Matrix_3 t;
    t << c, 0., -s,
         0., 1., 0.,
         s, 0., c;
    return scale_ * t;
  }

private:
  double scale_;
};

namespace internal {

template <typename Point_3>
Eigen::Vector3d to_eigen(const Point_3& p)
{ return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())); }

// Compile-time check of the FrameField_3 requirement, for a one-line error.
template <typename Field, typename GT, typename = void>
struct Is_frame_field_3 : std::false_type {};
template <typename Field, typename GT>
struct Is_frame_field_3<Field, GT, std::void_t<decltype(
    std::declval<typename GT::Matrix_3&>() =
      std::declval<const Field&>().frame(std::declval<const typename GT::Point_3&>()))> >
  : std::true_type {};

// Frames whose condition number exceeds this are rejected as singular: beyond it the
// isotropic space is numerically meaningless.
constexpr double max_frame_condition_number = 1e8;

// B = T^-1, or std::domain_error naming the point when T is singular or not finite.
// Called for every particle pair in every round, so the condition number is bounded by
// ||T||_F ||T^-1||_F (at most 3 times the 2-norm one) instead of computed by an SVD.
template <typename Point_3>
Eigen::Matrix3d isotropic_map(const Eigen::Matrix3d& t, const Point_3& where)
{
  auto fail = [&](const std::string& what) {
    std::ostringstream os;
    os << "frame field: " << what << " frame at point (" << where << ")";
    throw std::domain_error(os.str());
  };
  if(!t.allFinite()) fail("non-finite");
  const double det = t.determinant();
  const Eigen::Matrix3d b = t.inverse();
  const double condition = t.norm() * b.norm();
  if(!(det != 0.) || !b.allFinite() || !(condition < max_frame_condition_number)) {
    std::ostringstream os;
    os << "singular (condition number about " << (b.allFinite() ? condition : HUGE_VAL) << ")";
    fail(os.str());
  }
  return b;
}

// Largest singular value of T: how far the isotropic unit ball reaches in physical space.
inline double max_stretch(const Eigen::Matrix3d& t)
{ return Eigen::JacobiSVD<Eigen::Matrix3d>(t).singularValues()[0]; }

} // namespace internal

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_FRAME_FIELDS_H
