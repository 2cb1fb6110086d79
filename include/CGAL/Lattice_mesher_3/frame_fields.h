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
  typedef typename GT::Point_3  Point_3;  ///< the point type
  typedef typename GT::Matrix_3 Matrix_3; ///< the frame type, a 3x3 matrix

  /// constructs the field whose frame is `t` everywhere
  explicit Constant_frame_field_3(const Matrix_3& t = Matrix_3::Identity()) : t_(t) {}
  /// the frame `t`, at every point
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
  typedef typename GT::Point_3  Point_3;  ///< the point type
  typedef typename GT::Matrix_3 Matrix_3; ///< the frame type, a 3x3 matrix

  /// constructs the field from the callable `f`
  explicit Function_frame_field_3(F f) : f_(std::move(f)) {}
  /// the frame T(p) = `f(p)`
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
  typedef typename GT::Point_3  Point_3;  ///< the point type
  typedef typename GT::Matrix_3 Matrix_3; ///< the frame type, a 3x3 matrix

  /// constructs the field whose cube edges have length `scale`
  explicit Rotation_y_frame_field_3(double scale = 1.) : scale_(scale) {}
  /// the frame T(p), whose columns are the lattice cube edges at p
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

/*!
\ingroup PkgLatticeMesher3FrameFields
The paper's field of Fig. 8, on the cube [0.1, 1.1]^3: axis-aligned cubes that flatten in x
towards the plane x = 0.6,

  B(p) = diag((1.0125 - exp(-|p_x - 0.6|))^-1, 1, 1),  T(p) = diag(1.0125 - exp(-|p_x - 0.6|), 1, 1),

so that the cube's x edge shrinks from about 0.41 at the cube's faces x = 0.1 and 1.1 to 0.0125
(80 times thinner than its other edges) on the plane.
*/
template <typename GT>
class Planar_layer_frame_field_3
{
public:
  typedef typename GT::Point_3  Point_3;  ///< the point type
  typedef typename GT::Matrix_3 Matrix_3; ///< the frame type, a 3x3 matrix

  /// the frame T(p), whose columns are the lattice cube edges at p
  Matrix_3 frame(const Point_3& p) const
  {
    Matrix_3 t = Matrix_3::Identity();
    t(0, 0) = 1.0125 - std::exp(-std::abs(CGAL::to_double(p.x()) - 0.6));
    return t;
  }
};

/*!
\ingroup PkgLatticeMesher3FrameFields
The paper's field of Fig. 9, on the cube [1, 11]^3: cubes aligned with the cylinder of axis z
and radius 7, flattened in the radial direction towards it. B = S R with

  S = diag((1.05 - exp(-0.01 |x^2 + y^2 - 49|))^-1, 1, 1),  R = rows (x, y, 0)/r, (-y, x, 0)/r, (0, 0, 1),

r = sqrt(x^2 + y^2): T = R^T S^-1 has the columns s (x, y, 0)/r (radial, s = 1.05 -
exp(-0.01 |r^2 - 49|)), (-y, x, 0)/r (tangential) and (0, 0, 1) (axial); the radial edge is 20
times shorter than the others at r = 7. The paper prints R's first two rows as (-x, y, 0)/r and
(-y, x, 0)/r, which are not orthogonal (their dot product is 2xy/r^2): a sign typo, corrected here
as the radial direction. On the z axis (r = 0), where the radial direction is undefined, x is
taken as radial.
*/
template <typename GT>
class Cylindrical_layer_frame_field_3
{
public:
  typedef typename GT::Point_3  Point_3;  ///< the point type
  typedef typename GT::Matrix_3 Matrix_3; ///< the frame type, a 3x3 matrix

  /// the frame T(p), whose columns are the lattice cube edges at p
  Matrix_3 frame(const Point_3& p) const
  {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    const double r = std::sqrt(x * x + y * y);
    const double c = r > 0. ? x / r : 1., s = r > 0. ? y / r : 0.;
    const double radial = 1.05 - std::exp(-0.01 * std::abs(r * r - 49.));
    Matrix_3 t;
    t << radial * c, -s, 0.,
         radial * s,  c, 0.,
         0.,         0., 1.;
    return t;
  }
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
