// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Octahedral frames as degree-4 spherical harmonics: the basis, the rotation action, the
// projection onto the frames and onto the frames with an axis along a normal.

#include <CGAL/Lattice_mesher_3/internal/octahedral_frames.h>
#include <CGAL/Lattice_mesher_3/internal/cross_field_solver.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/lattice_mesh_3.h>
#include <CGAL/Lattice_mesher_3/Implicit_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>

#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

#include <iostream>
#include <random>
#include <vector>

namespace {

namespace LMi = CGAL::Lattice_mesher_3::internal;

double value(const LMi::Sh9& q, const Eigen::Vector3d& u) { return q.dot(LMi::degree_4_harmonics(u.normalized())); }

std::vector<Eigen::Matrix3d> random_rotations(int n, unsigned seed)
{
  std::mt19937 g(seed);
  std::normal_distribution<double> normal;
  std::vector<Eigen::Matrix3d> r;
  for(int i = 0; i < n; ++i)
    r.push_back(Eigen::Quaterniond(normal(g), normal(g), normal(g), normal(g)).normalized().toRotationMatrix());
  return r;
}

// the frame's function is largest on its axes (0.64636) and smallest on the diagonals (-0.43091)
TEST(Octahedral_frames, AxisAlignedFrameIsLargestOnItsAxes)
{
  const LMi::Sh9 q0 = LMi::axis_aligned_frame();
  EXPECT_NEAR(q0.norm(), 1., 1e-15);
  for(int k = 0; k < 3; ++k) EXPECT_NEAR(value(q0, Eigen::Vector3d::Unit(k)), 0.64636, 1e-5);
  EXPECT_NEAR(value(q0, Eigen::Vector3d(1., 1., 1.)), -0.43091, 1e-5);
  EXPECT_NEAR(value(q0, Eigen::Vector3d(-1., 1., -1.)), -0.43091, 1e-5);
}

// D(exp([w]x)) = exp(w . L), computed by the ZYZ closed form; D is an orthogonal representation
TEST(Octahedral_frames, WignerMatricesRepresentTheRotations)
{
  const std::array<LMi::Sh9_matrix, 3>& l = LMi::rotation_generators();
  std::mt19937 g(7);
  std::uniform_real_distribution<double> u(-2., 2.);
  double worst = 0.;
  for(int i = 0; i < 100; ++i) {
    const Eigen::Vector3d w(u(g), u(g), u(g));
    const Eigen::Matrix3d r = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
    const LMi::Sh9_matrix expected = (w[0] * l[0] + w[1] * l[1] + w[2] * l[2]).exp();
    worst = (std::max)(worst, (LMi::wigner(r) - expected).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-10);
  const std::vector<Eigen::Matrix3d> r = random_rotations(20, 3);
  for(std::size_t i = 0; i + 1 < r.size(); ++i) {
    EXPECT_LT((LMi::wigner(r[i] * r[i + 1]) - LMi::wigner(r[i]) * LMi::wigner(r[i + 1])).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((LMi::wigner(r[i]).transpose() * LMi::wigner(r[i]) - LMi::Sh9_matrix::Identity()).cwiseAbs().maxCoeff(), 1e-12);
  }
  // the rotations about z through the poles, where the Euler angles degenerate
  for(double a : { 0., .3, 3.14159265358979 }) {
    const Eigen::Matrix3d rz = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3d flip = Eigen::AngleAxisd(3.14159265358979323846, Eigen::Vector3d::UnitX()).toRotationMatrix() * rz;
    EXPECT_LT((LMi::wigner(rz) - (a * l[2]).exp()).cwiseAbs().maxCoeff(), 1e-10);
    EXPECT_LT((LMi::wigner(flip) - LMi::wigner(flip * rz.transpose()) * LMi::wigner(rz)).cwiseAbs().maxCoeff(), 1e-10);
  }
}

// the frame of D(R) q0 has the columns of R as axes, and the 24 rotations of the cube fix q0
TEST(Octahedral_frames, FrameOfARotationHasItsColumnsAsAxes)
{
  for(const Eigen::Matrix3d& r : random_rotations(50, 5)) {
    const LMi::Sh9 q = LMi::frame_coefficients(r);
    for(int k = 0; k < 3; ++k) EXPECT_NEAR(value(q, r.col(k)), 0.64636, 1e-5);
    EXPECT_NEAR(value(q, r * Eigen::Vector3d(1., -1., 1.)), -0.43091, 1e-5);
  }
  const double quarter = 1.57079632679489661923;
  std::vector<Eigen::Matrix3d> group = { Eigen::Matrix3d::Identity() };
  for(std::size_t i = 0; i < group.size(); ++i)
    for(int axis = 0; axis < 3; ++axis) {
      const Eigen::Matrix3d g = (Eigen::AngleAxisd(quarter, Eigen::Vector3d::Unit(axis)).toRotationMatrix() * group[i]).array().round().matrix();
      bool known = false;
      for(const Eigen::Matrix3d& h : group) known = known || (g - h).cwiseAbs().maxCoeff() < 1e-9;
      if(!known) group.push_back(g);
    }
  ASSERT_EQ(group.size(), 24u);
  for(const Eigen::Matrix3d& g : group)
    EXPECT_LT((LMi::frame_coefficients(g) - LMi::axis_aligned_frame()).norm(), 1e-12);
}

// the projection recovers a frame exactly, and a noisy one to within a few degrees
TEST(Octahedral_frames, ProjectionRecoversTheFrame)
{
  std::mt19937 g(11);
  std::normal_distribution<double> noise(0., 0.05);
  double exact = 0., noisy = 0.;
  for(const Eigen::Matrix3d& r : random_rotations(200, 9)) {
    const LMi::Sh9 q = LMi::frame_coefficients(r);
    const Eigen::Matrix3d p = LMi::nearest_frame_rotation(q);
    LMi::Sh9 perturbed = q;
    for(int i = 0; i < 9; ++i) perturbed[i] += noise(g);
    const Eigen::Matrix3d pn = LMi::nearest_frame_rotation(perturbed);
    for(int k = 0; k < 3; ++k) {
      exact = (std::max)(exact, LMi::angle_to_nearest_axis(p, r.col(k)));
      noisy = (std::max)(noisy, LMi::angle_to_nearest_axis(pn, r.col(k)));
    }
    // no frame is nearer to the perturbed coefficients than the projection's
    EXPECT_GE(perturbed.normalized().dot(LMi::frame_coefficients(pn)), perturbed.normalized().dot(q) - 1e-12);
  }
  EXPECT_LT(exact, 1e-6);
  EXPECT_LT(noisy, 8.);
  std::cout << "  projection of 200 random frames: largest axis error " << exact << " degrees exact, " << noisy
            << " with noise 0.05\n";
}

// the frames with an axis along a normal n: the projection keeps that axis, and finds the frame
// itself when it has one along n
TEST(Octahedral_frames, AlignedProjectionHasAnAxisAlongTheNormal)
{
  std::mt19937 g(13);
  std::normal_distribution<double> normal;
  for(const Eigen::Matrix3d& r : random_rotations(100, 21)) {
    LMi::Sh9 q;
    for(int i = 0; i < 9; ++i) q[i] = normal(g);
    const Eigen::Vector3d n = Eigen::Vector3d(normal(g), normal(g), normal(g)).normalized();
    EXPECT_LT(LMi::angle_to_nearest_axis(LMi::nearest_aligned_frame_rotation(q, n), n), 1e-6);
    const Eigen::Matrix3d a = LMi::nearest_aligned_frame_rotation(LMi::frame_coefficients(r), r.col(1));
    for(int k = 0; k < 3; ++k) EXPECT_LT(LMi::angle_to_nearest_axis(a, r.col(k)), 1e-6);
  }
}

typedef CGAL::Epick K;
typedef CGAL::Lattice_mesher_3::Constant_frame_field_3<CGAL::Lattice_mesher_traits_3<K> > Identity;

// The largest angle (degrees) between an axis of r and the nearest axis of s.
double frame_angle(const Eigen::Matrix3d& r, const Eigen::Matrix3d& s)
{
  double worst = 0.;
  for(int k = 0; k < 3; ++k) worst = (std::max)(worst, LMi::angle_to_nearest_axis(s, r.col(k)));
  return worst;
}

// On a cube, whose creases and corners hold the whole frame, the smooth field is the identity
// (up to the cube's symmetries) everywhere; its energy falls across the iterations.
TEST(Cross_field, CubeFieldIsTheIdentity)
{
  namespace LM = CGAL::Lattice_mesher_3;
  const LM::Polyhedral_lattice_domain_3<K> cube(LM::make_cube_surface_3<K>(0., 1.));
  const LM::Tetrahedral_mesh_3<K::Point_3> mesh = CGAL::lattice_mesh_3(cube, Identity(), CGAL::parameters::edge_length(0.2));
  const std::vector<LMi::Frame_constraint> constraints = LMi::boundary_frame_constraints(mesh, cube);
  std::size_t full = 0;
  for(const LMi::Frame_constraint& c : constraints) full += c.kind == LMi::Frame_constraint::FULL;
  EXPECT_GT(full, 8u);
  const LMi::Cross_field_result field = LMi::Cross_field_solver(mesh, constraints).solve(20);
  double worst = 0.;
  for(const Eigen::Matrix3d& r : field.rotations) worst = (std::max)(worst, frame_angle(r, Eigen::Matrix3d::Identity()));
  EXPECT_LT(worst, 1.);
  ASSERT_GE(field.energies.size(), 1u);
  EXPECT_LT(field.energies.back(), 1e-6);
  std::cout << "  cube: " << mesh.points.size() << " vertices, largest angle to the identity " << worst << " degrees\n";
}

// On a sphere every boundary frame has an axis along the normal, and the MBO iterations lower
// the energy of the initial projection by a tenth at least.
TEST(Cross_field, SphereFieldIsAlignedWithTheNormal)
{
  namespace LM = CGAL::Lattice_mesher_3;
  const LM::Implicit_lattice_domain_3<K, LM::Implicit_sphere_3<K> > ball(LM::Implicit_sphere_3<K>{ K::Point_3(0., 0., 0.), 1. },
                                                                         CGAL::Bbox_3(-1, -1, -1, 1, 1, 1));
  const LM::Tetrahedral_mesh_3<K::Point_3> mesh = CGAL::lattice_mesh_3(ball, Identity(), CGAL::parameters::edge_length(0.25));
  const LMi::Cross_field_result field = LMi::Cross_field_solver(mesh, LMi::boundary_frame_constraints(mesh, ball)).solve(60);
  double worst = 0.;
  std::vector<char> on_boundary(mesh.points.size(), 0);
  for(const auto& f : mesh.boundary_faces) for(int v : f) on_boundary[std::size_t(v)] = 1;
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    if(on_boundary[v]) worst = (std::max)(worst, LMi::angle_to_nearest_axis(field.rotations[v], LMi::to_eigen(mesh.points[v])));
  EXPECT_LT(worst, 2.);
  ASSERT_GE(field.energies.size(), 2u);
  EXPECT_LT(field.energies.back(), 0.9 * field.energies.front());
  for(std::size_t k = 1; k < field.energies.size(); ++k) EXPECT_LE(field.energies[k], field.energies[k - 1]) << "iteration " << k;
  std::cout << "  ball: " << mesh.points.size() << " vertices, " << field.energies.size() - 1 << " iterations, energy "
            << field.energies.front() << " -> " << field.energies.back() << ", largest boundary angle to the normal " << worst
            << " degrees\n";
}

} // namespace
