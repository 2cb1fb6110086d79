// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

// Frame fields (Rotation_y, Function, Constant), the isotropic map B = T^-1 and its rejection of
// singular or non-finite frames, and the lattices as data (one-rings, holes, names).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lattice_mesher_traits_3.h>
#include <CGAL/Lattice_mesher_3/Lattice_3.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>

#include <gtest/gtest.h>

#include "test_helpers.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace LM = CGAL::Lattice_mesher_3;
typedef CGAL::Lattice_mesher_traits_3<CGAL::Epick> GT;
typedef GT::Point_3 Point_3;
typedef GT::Matrix_3 Matrix_3;
typedef Eigen::Vector3d Vec3;

namespace {


// ---------------------------------------------------------------------------------------------
// Frame fields

TEST(Frame_fields, rotation_y_is_radial_vertical_tangential)
{
  const LM::Rotation_y_frame_field_3<GT> field;
  // points in every quadrant of the xz plane, at several heights and radii
  const std::vector<Point_3> points = { {3, 0, 0}, {0, 1, 2}, {-1.5, -2, .5}, {-.2, 4, -.7},
                                        {2, .3, -5}, {1e-3, 0, 1e-3}, {-7, 1, 0} };
  for(const Point_3& p : points) {
    const Matrix_3 t = field.frame(p);
    const Vec3 radial = Vec3(p.x(), 0., p.z()).normalized();
    EXPECT_LT((t.col(0) - radial).norm(), 1e-15) << p;
    EXPECT_EQ(t.col(1), Vec3(0., 1., 0.)) << p;
    // tangential: orthogonal to the radial direction and to the axis, completing a right-handed frame
    EXPECT_LT(std::abs(t.col(2).dot(radial)), 1e-15) << p;
    EXPECT_EQ(t.col(2)[1], 0.) << p;
    EXPECT_LT((t.col(2) - t.col(0).cross(t.col(1))).norm(), 1e-15) << p;
    EXPECT_LT((t.transpose() * t - Matrix_3::Identity()).norm(), 1e-15) << p;
    EXPECT_NEAR(t.determinant(), 1., 1e-15) << p;
  }
}

TEST(Frame_fields, rotation_y_is_identity_on_the_axis_and_scales)
{
  const LM::Rotation_y_frame_field_3<GT> field;
  for(double y : { -3., 0., 2.5 })
    EXPECT_EQ(field.frame(Point_3(0, y, 0)), Matrix_3::Identity()) << y;

  const LM::Rotation_y_frame_field_3<GT> scaled(2.5);
  const Point_3 p(1, 2, -3);
  EXPECT_LT((scaled.frame(p) - 2.5 * field.frame(p)).norm(), 1e-15);
}

TEST(Frame_fields, function_field_wraps_a_lambda)
{
  // a shear growing with x: the field must return exactly what the lambda computes at p
  auto shear = [](const Point_3& p) {
    Matrix_3 t = Matrix_3::Identity();
    t(0, 1) = p.x();
    t(2, 2) = 1. + p.y() * p.y();
    return t;
  };
  const auto field = LM::make_function_frame_field_3<GT>(shear);
  for(const Point_3& p : { Point_3(0, 0, 0), Point_3(1.5, -2, 3), Point_3(-4, .25, 1) })
    EXPECT_EQ(field.frame(p), shear(p)) << p;
  EXPECT_TRUE((LM::internal::Is_frame_field_3<decltype(field), GT>::value));
}

TEST(Frame_fields, constant_field)
{
  EXPECT_EQ(LM::Constant_frame_field_3<GT>().frame(Point_3(1, 2, 3)), Matrix_3::Identity());
  Matrix_3 t;
  t << 2, .3, 0,  -.1, 1, .4,  0, .2, .5;
  const LM::Constant_frame_field_3<GT> field(t);
  EXPECT_EQ(field.frame(Point_3(-5, 0, 7)), t);
  EXPECT_TRUE((LM::internal::Is_frame_field_3<LM::Constant_frame_field_3<GT>, GT>::value));
  EXPECT_TRUE((LM::internal::Is_frame_field_3<LM::Rotation_y_frame_field_3<GT>, GT>::value));
  EXPECT_FALSE((LM::internal::Is_frame_field_3<int, GT>::value));
}

// ---------------------------------------------------------------------------------------------
// Isotropic map B = T^-1

TEST(Isotropic_map, returns_the_inverse)
{
  Matrix_3 t;
  t << 2, .3, -.4,  -.1, 1, .4,  .7, .2, .5;    // non-symmetric, well conditioned
  const Matrix_3 b = LM::internal::isotropic_map(t, Point_3(0, 0, 0));
  EXPECT_EQ(b, Matrix_3(t.inverse()));
  EXPECT_LT((t * b - Matrix_3::Identity()).norm(), 1e-14);

  // condition number 1e7, below the documented limit of 1e8: accepted
  const Matrix_3 thin = Vec3(1., 1., 1e-7).asDiagonal();
  EXPECT_NO_THROW(LM::internal::isotropic_map(thin, Point_3(0, 0, 0)));
}

TEST(Isotropic_map, rejects_singular_frames)
{
  const Point_3 where(1, 2, 3);
  Matrix_3 rank2;
  rank2 << 1, 2, 3,  4, 5, 6,  7, 8, 9;
  expect_error<std::domain_error>([&] { LM::internal::isotropic_map(rank2, where); }, { "singular", "1 2 3" });
  const Matrix_3 zero_column = (Matrix_3() << 1, 0, 0,  0, 1, 0,  0, 0, 0).finished();
  expect_error<std::domain_error>([&] { LM::internal::isotropic_map(zero_column, where); }, { "singular" });
  // condition numbers 1e9 and 1e10, rotated so that the matrix is not diagonal
  const Matrix_3 r = Eigen::AngleAxisd(.8, Vec3(1, -2, .5).normalized()).toRotationMatrix();
  for(double c : { 1e9, 1e10 }) {
    const Matrix_3 ill = r * Vec3(1., 2., 1. / c).asDiagonal() * r.transpose();
    expect_error<std::domain_error>([&] { LM::internal::isotropic_map(ill, where); }, { "singular" });
  }
}

TEST(Isotropic_map, rejects_non_finite_frames)
{
  const Point_3 where(-1, .5, 4);
  for(double bad : { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() }) {
    Matrix_3 t = Matrix_3::Identity();
    t(1, 2) = bad;
    expect_error<std::domain_error>([&] { LM::internal::isotropic_map(t, where); }, { "non-finite", "-1 0.5 4" });
  }
}

// ---------------------------------------------------------------------------------------------
// Lattices as data

struct Lattice_case
{
  LM::Lattice_type type;
  const char* name;
  std::size_t ring_size;
  double closest;
};

class Lattice_data : public ::testing::TestWithParam<Lattice_case> {};

TEST_P(Lattice_data, one_ring)
{
  const Lattice_case& c = GetParam();
  const LM::Lattice_3 l = LM::make_lattice(c.type);
  EXPECT_EQ(l.name, c.name);
  EXPECT_EQ(LM::lattice_type_from_name(c.name), c.type);
  ASSERT_EQ(l.one_ring.size(), c.ring_size);

  double closest = HUGE_VAL;
  for(std::size_t k = 0; k < l.one_ring.size(); ++k) {
    const Vec3& o = l.one_ring[k];
    closest = (std::min)(closest, o.norm());
    // closed under negation (E_ij = E_ji needs O = -O), without duplicates
    const auto opposite = std::find(l.one_ring.begin(), l.one_ring.end(), Vec3(-o));
    EXPECT_NE(opposite, l.one_ring.end()) << "offset " << o.transpose() << " has no opposite";
    EXPECT_EQ(std::count(l.one_ring.begin(), l.one_ring.end(), o), 1) << o.transpose();
  }
  EXPECT_DOUBLE_EQ(closest, c.closest);
  EXPECT_DOUBLE_EQ(l.closest_distance, c.closest);
  EXPECT_DOUBLE_EQ(l.ring_radius(), 1.);
  EXPECT_DOUBLE_EQ(l.sigma(), .3 * c.closest);
}

INSTANTIATE_TEST_SUITE_P(All, Lattice_data,
                         ::testing::Values(Lattice_case{ LM::Lattice_type::BCC, "bcc", 14, std::sqrt(3.) / 2. },
                                           Lattice_case{ LM::Lattice_type::FCC, "fcc", 18, std::sqrt(2.) / 2. },
                                           Lattice_case{ LM::Lattice_type::GAUSSIAN, "gaussian", 14, std::sqrt(3.) / 2. }),
                         [](const ::testing::TestParamInfo<Lattice_case>& i) { return std::string(i.param.name); });

TEST(Lattices, holes)
{
  // the GHK's holes are the one-ring; the Particle2013 kernel has none but inserts along BCC
  for(const LM::Lattice_3& l : { LM::bcc_lattice(), LM::fcc_lattice() }) {
    EXPECT_TRUE(l.has_holes()) << l.name;
    EXPECT_EQ(l.holes, l.one_ring) << l.name;
  }
  const LM::Lattice_3 g = LM::gaussian_kernel_lattice();
  EXPECT_FALSE(g.has_holes());
  EXPECT_TRUE(g.holes.empty());
  EXPECT_EQ(g.one_ring, LM::bcc_lattice().one_ring);
}

TEST(Lattices, unknown_name)
{
  expect_error<std::invalid_argument>([] { LM::lattice_type_from_name("a15"); }, { "a15" });
  expect_error<std::invalid_argument>([] { LM::lattice_type_from_name("BCC"); }, { "BCC" });
  expect_error<std::invalid_argument>([] { LM::lattice_type_from_name(""); }, {});
}

} // namespace
