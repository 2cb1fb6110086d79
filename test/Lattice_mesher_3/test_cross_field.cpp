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
#include <CGAL/Lattice_mesher_3/compute_cross_field_3.h>
#include <CGAL/Lattice_mesher_3/IO/frame_field.h>

#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
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
      exact = (std::max)(exact, LMi::angle_to_nearest_direction(p, r.col(k)));
      noisy = (std::max)(noisy, LMi::angle_to_nearest_direction(pn, r.col(k)));
    }
    // no frame is nearer to the perturbed coefficients than the projection's
    EXPECT_GE(perturbed.normalized().dot(LMi::frame_coefficients(pn)), perturbed.normalized().dot(q) - 1e-12);
  }
  EXPECT_LT(exact, 1e-6);
  EXPECT_LT(noisy, 8.);
  std::cout << "  projection of 200 random frames: largest axis error " << exact << " degrees exact, " << noisy
            << " with noise 0.05\n";
}

// the frames with a direction (an axis or a face diagonal) along a normal n: the
// projection keeps that direction, fits q at least as well as any of 720 turns about n, and
// finds the frame itself when it has the direction along n
TEST(Octahedral_frames, AlignedProjectionHasTheDirectionAlongTheNormal)
{
  const double pi = 3.14159265358979323846;
  std::mt19937 g(13);
  std::normal_distribution<double> normal;
  const std::vector<Eigen::Matrix3d> rotations = random_rotations(100, 21);
  for(LMi::Frame_direction d : { LMi::Frame_direction::AXIS, LMi::Frame_direction::FACE_DIAGONAL }) {
    double worst_angle = 0., worst_fit = 0., worst_self = 0.;
    for(const Eigen::Matrix3d& r : rotations) {
      LMi::Sh9 q;
      for(int i = 0; i < 9; ++i) q[i] = normal(g);
      const Eigen::Vector3d n = Eigen::Vector3d(normal(g), normal(g), normal(g)).normalized();
      const Eigen::Matrix3d p = LMi::nearest_aligned_frame_rotation(q, n, d);
      worst_angle = (std::max)(worst_angle, LMi::angle_to_nearest_direction(p, n, d));
      const Eigen::Matrix3d rn = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), n).toRotationMatrix();
      for(int k = 0; k < 720; ++k) {
        const Eigen::Matrix3d t = rn * Eigen::AngleAxisd(k * pi / 360., Eigen::Vector3d::UnitZ()).toRotationMatrix() * LMi::direction_to_z(d);
        worst_fit = (std::max)(worst_fit, q.dot(LMi::frame_coefficients(t)) - q.dot(LMi::frame_coefficients(p)));
      }
      const Eigen::Vector3d along = r * LMi::direction_vector(d);
      const Eigen::Matrix3d self = LMi::nearest_aligned_frame_rotation(LMi::frame_coefficients(r), along, d);
      for(int k = 0; k < 3; ++k) worst_self = (std::max)(worst_self, LMi::angle_to_nearest_direction(self, r.col(k)));
    }
    EXPECT_LT(worst_angle, 1e-6) << "direction " << int(d);
    EXPECT_LT(worst_fit, 1e-9) << "direction " << int(d);
    EXPECT_LT(worst_self, 1e-6) << "direction " << int(d);
  }
}

// the frame with a direction along z is symmetric by the turns about z that keep the direction,
// so it has only the orders they allow: 4 for an axis, 2 and 4 for a face diagonal
TEST(Octahedral_frames, FrameWithADirectionAlongZHasTheOrdersOfItsSymmetry)
{
  EXPECT_EQ(LMi::frame_orders(LMi::frame_with_direction_along_z(LMi::Frame_direction::AXIS)), std::vector<int>({ 4 }));
  EXPECT_EQ(LMi::frame_orders(LMi::frame_with_direction_along_z(LMi::Frame_direction::FACE_DIAGONAL)), std::vector<int>({ 2, 4 }));
  for(LMi::Frame_direction d : { LMi::Frame_direction::AXIS, LMi::Frame_direction::FACE_DIAGONAL })
    EXPECT_LT(LMi::angle_to_nearest_direction(LMi::direction_to_z(d).transpose(), Eigen::Vector3d::UnitZ(), d), 1e-9);
}

typedef CGAL::Epick K;
typedef CGAL::Lattice_mesher_3::Constant_frame_field_3<CGAL::Lattice_mesher_traits_3<K> > Identity;

// The largest angle (degrees) between an axis of r and the nearest axis of s.
double frame_angle(const Eigen::Matrix3d& r, const Eigen::Matrix3d& s)
{
  double worst = 0.;
  for(int k = 0; k < 3; ++k) worst = (std::max)(worst, LMi::angle_to_nearest_direction(s, r.col(k)));
  return worst;
}

typedef CGAL::Lattice_mesher_traits_3<K> GT;
typedef CGAL::Lattice_mesher_3::Discrete_frame_field_3<GT> Discrete_field;

// Points drawn uniformly in the box [lo, hi]^3.
std::vector<K::Point_3> random_points(int n, double lo, double hi, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<K::Point_3> p;
  for(int i = 0; i < n; ++i) { const double x = u(g), y = u(g); p.emplace_back(x, y, u(g)); }
  return p;
}

const CGAL::Lattice_mesher_3::Implicit_lattice_domain_3<K, CGAL::Lattice_mesher_3::Implicit_sphere_3<K> >& ball()
{
  namespace LM = CGAL::Lattice_mesher_3;
  static const LM::Implicit_lattice_domain_3<K, LM::Implicit_sphere_3<K> > b(LM::Implicit_sphere_3<K>{ K::Point_3(0., 0., 0.), 1. },
                                                                            CGAL::Bbox_3(-1, -1, -1, 1, 1, 1));
  return b;
}

const Discrete_field& ball_field()
{
  static const Discrete_field f = CGAL::Lattice_mesher_3::compute_cross_field_3(ball(), CGAL::parameters::edge_length(0.25));
  return f;
}

TEST(Octahedral_frames, BestCubeRotationUndoesACubeRotation)
{
  const std::vector<Eigen::Matrix3d> r = random_rotations(50, 11);
  std::vector<Eigen::Matrix3d> cube;   // the 24 rotations of the cube: signed permutations of determinant 1
  for(const Eigen::Matrix3d& m : r) {
    Eigen::Matrix3d p = LMi::best_cube_rotation(m);
    EXPECT_NEAR(p.determinant(), 1., 1e-12);
    EXPECT_TRUE((p.transpose() * p).isIdentity(1e-12));
    if(std::find_if(cube.begin(), cube.end(), [&](const Eigen::Matrix3d& q) { return q.isApprox(p); }) == cube.end()) cube.push_back(p);
  }
  for(std::size_t i = 0; i < r.size(); ++i) {
    // r_i P is the representative of r_i's frame nearest to r_0: no other does better
    const Eigen::Matrix3d p = LMi::best_cube_rotation(r[0].transpose() * r[i]);
    const double best = (r[0].transpose() * r[i] * p).trace();
    for(const Eigen::Matrix3d& q : cube) EXPECT_LE((r[0].transpose() * r[i] * q).trace(), best + 1e-12);
    // and it undoes a cube rotation applied to r_0
    const Eigen::Matrix3d& q = cube[i % cube.size()];
    EXPECT_TRUE((r[0] * q * LMi::best_cube_rotation(q)).isApprox(r[0], 1e-12));
  }
  EXPECT_GE(cube.size(), 12u);
}

// On a cube, whose creases and corners hold the whole frame, the smooth field whose axes hold the
// normals (FCC's) is the identity (up to the cube's symmetries) everywhere, between the samples
// too; it has no singular edge.
TEST(Cross_field, CubeFieldIsTheIdentity)
{
  namespace LM = CGAL::Lattice_mesher_3;
  const LM::Polyhedral_lattice_domain_3<K> cube(LM::make_cube_surface_3<K>(0., 1.));
  const LM::Tetrahedral_mesh_3<K::Point_3> mesh = CGAL::lattice_mesh_3(cube, Identity(), CGAL::parameters::edge_length(0.2));
  const std::vector<LMi::Frame_constraint> constraints = LMi::boundary_frame_constraints(mesh, cube);
  std::size_t full = 0;
  for(const LMi::Frame_constraint& c : constraints) full += c.kind == LMi::Frame_constraint::FULL;
  EXPECT_GT(full, 8u);
  const auto fcc = CGAL::parameters::lattice(LM::Lattice_type::FCC);
  const Discrete_field field = LM::compute_cross_field_3(cube, fcc.edge_length(0.2).number_of_iterations(20));
  EXPECT_EQ(field.mesh().tets.size(), mesh.tets.size());
  double worst = 0.;
  for(const Eigen::Matrix3d& r : field.frames()) worst = (std::max)(worst, frame_angle(r, Eigen::Matrix3d::Identity()));
  for(const K::Point_3& p : random_points(2000, 0., 1., 3)) worst = (std::max)(worst, frame_angle(field.frame(p), Eigen::Matrix3d::Identity()));
  EXPECT_LT(worst, 1.);
  const LM::Frame_field_diagnostics d = LM::compute_frame_field_diagnostics(field, fcc);
  EXPECT_LT(d.energy, 1e-6);
  EXPECT_LT(d.max_boundary_alignment, 1.);
  EXPECT_TRUE(d.singular_edges.empty()) << d.singular_edges.size() << " singular edges";
  std::cout << "  cube: " << mesh.points.size() << " vertices, largest angle to the identity " << worst << " degrees\n";
}

// lambda_1 of the graph Laplacian sets the MBO's diffusion (tau_0 = 50 / lambda_1): on a knot,
// whose first mode runs along the tube, it is many times the longest coordinate's Rayleigh
// quotient, and the inverse iteration must find the dense solver's value.
TEST(Cross_field, FirstEigenvalueOfAKnotMatchesTheDenseSolver)
{
  namespace LM = CGAL::Lattice_mesher_3;
  const LM::Polyhedral_lattice_domain_3<K> knot =
    LM::read_polyhedral_lattice_domain_3<K>(std::string(LATTICE_MESHER_3_DATA_DIR) + "/meshes/knot1.off");
  const LM::Tetrahedral_mesh_3<K::Point_3> mesh = CGAL::lattice_mesh_3(knot, Identity(), CGAL::parameters::number_of_vertices(800));
  const LMi::Weighted_edges edges = LMi::weighted_edges(mesh);
  const Eigen::Index n = Eigen::Index(mesh.points.size());
  Eigen::MatrixXd laplacian = Eigen::MatrixXd::Zero(n, n);
  for(const auto& e : edges) {
    const int i = e.first.first, j = e.first.second;
    laplacian(i, i) += e.second; laplacian(j, j) += e.second;
    laplacian(i, j) -= e.second; laplacian(j, i) -= e.second;
  }
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(laplacian, Eigen::EigenvaluesOnly).eigenvalues();
  ASSERT_LT(std::abs(eigenvalues[0]), 1e-9);   // one component
  const double lambda = LMi::laplacian_first_eigenvalue(mesh, edges);
  EXPECT_NEAR(lambda, eigenvalues[1], 0.01 * eigenvalues[1]);
  // the Rayleigh quotient of the coordinate along which the knot is longest: no estimate of it
  Eigen::MatrixXd p(n, 3);
  for(Eigen::Index v = 0; v < n; ++v) p.row(v) = LMi::to_eigen(mesh.points[std::size_t(v)]).transpose();
  int axis = 0;
  (p.colwise().maxCoeff() - p.colwise().minCoeff()).maxCoeff(&axis);
  Eigen::VectorXd x = p.col(axis);
  x.array() -= x.mean();
  const double quotient = x.dot(laplacian * x) / x.squaredNorm();
  EXPECT_GT(quotient, 3. * lambda);
  std::cout << "  knot1, " << n << " vertices: lambda_1 " << lambda << " (dense " << eigenvalues[1] << ", x's quotient " << quotient << ")\n";
}

// Between the samples the field is a rotation times the interpolated size: here a rotation, and
// twice one for the frames doubled.
TEST(Cross_field, InterpolatedFrameIsARotationTimesTheSize)
{
  const Discrete_field& field = ball_field();
  std::vector<Eigen::Matrix3d> doubled;
  for(const Eigen::Matrix3d& t : field.frames()) doubled.push_back(2. * t);
  const Discrete_field twice(field.mesh(), doubled);
  std::size_t checked = 0;
  for(const K::Point_3& p : random_points(3000, -1.1, 1.1, 5)) {
    const Eigen::Matrix3d t = field.frame(p), t2 = twice.frame(p);
    ASSERT_TRUE((t.transpose() * t).isIdentity(1e-9)) << p << "\n" << t;
    ASSERT_NEAR(t.determinant(), 1., 1e-9) << p;
    ASSERT_TRUE((t2.transpose() * t2).isApprox(4. * Eigen::Matrix3d::Identity(), 1e-9)) << p << "\n" << t2;
    checked += 1;
  }
  EXPECT_EQ(checked, 3000u);
  // at a sample, its own frame
  for(std::size_t i = 0; i < field.number_of_samples(); i += 7)
    EXPECT_LT(frame_angle(field.frame(field.points()[i]), field.frames()[i]), 1e-6) << i;
}

// A field saved in either format reads back to the same frames at the samples, and the Medit
// format, which keeps the tetrahedra, to the same field between them.
TEST(Cross_field, SavedFieldReloadsToTheSameFrames)
{
  namespace LM = CGAL::Lattice_mesher_3;
  const Discrete_field& field = ball_field();
  const std::string mesh_file = ::testing::TempDir() + "cross_field.mesh", sol = ::testing::TempDir() + "cross_field.sol",
                    text = ::testing::TempDir() + "cross_field.txt";
  LM::write_frame_field_to_medit(mesh_file, sol, field);
  LM::write_frame_field_samples(text, field);
  const Discrete_field medit = LM::read_frame_field_from_medit<GT>(mesh_file, sol);
  const Discrete_field samples = LM::read_frame_field_samples<GT>(text);
  EXPECT_EQ(medit.points(), field.points());
  EXPECT_EQ(medit.frames(), field.frames());
  EXPECT_EQ(medit.mesh().tets, field.mesh().tets);
  EXPECT_EQ(samples.points(), field.points());
  EXPECT_EQ(samples.frames(), field.frames());
  for(const K::Point_3& p : random_points(500, -1., 1., 7)) ASSERT_EQ(medit.frame(p), field.frame(p)) << p;
  for(const std::string& f : { mesh_file, sol, text }) std::remove(f.c_str());
}

// On a sphere every boundary frame has the direction of its lattice along the normal (BCC's field
// a face diagonal, FCC's an axis), and the MBO iterations lower the energy of the initial
// projection by a tenth at least, never raising it.
TEST(Cross_field, SphereFieldIsAlignedWithTheNormal)
{
  namespace LM = CGAL::Lattice_mesher_3;
  const LM::Tetrahedral_mesh_3<K::Point_3> mesh = CGAL::lattice_mesh_3(ball(), Identity(), CGAL::parameters::edge_length(0.25));
  const LMi::Cross_field_result solved = LMi::Cross_field_solver(mesh, LMi::boundary_frame_constraints(mesh, ball())).solve(60);
  ASSERT_GE(solved.energies.size(), 2u);
  EXPECT_LT(solved.energies.back(), 0.9 * solved.energies.front());
  for(std::size_t k = 1; k < solved.energies.size(); ++k) EXPECT_LE(solved.energies[k], solved.energies[k - 1]) << "iteration " << k;

  const auto fcc = CGAL::parameters::lattice(LM::Lattice_type::FCC);
  const Discrete_field fcc_field = LM::compute_cross_field_3(ball(), fcc.edge_length(0.25));
  // the largest angle (degrees) between a boundary vertex's normal and the nearest direction d
  auto worst_at_vertices = [](const Discrete_field& field, LMi::Frame_direction d) {
    double worst = 0.;
    const LM::Tetrahedral_mesh_3<K::Point_3>& background = field.mesh();
    for(const auto& f : background.boundary_faces)
      for(int v : f)
        worst = (std::max)(worst, LMi::angle_to_nearest_direction(field.frames()[std::size_t(v)], LMi::to_eigen(background.points[std::size_t(v)]), d));
    return worst;
  };
  const double bcc_worst = worst_at_vertices(ball_field(), LMi::Frame_direction::FACE_DIAGONAL);
  const double fcc_worst = worst_at_vertices(fcc_field, LMi::Frame_direction::AXIS);
  EXPECT_LT(bcc_worst, 2.);
  EXPECT_LT(fcc_worst, 2.);
  // a ball's field cannot be smooth everywhere: it has singular curves
  const LM::Frame_field_diagnostics d = LM::compute_frame_field_diagnostics(fcc_field, fcc);
  EXPECT_GT(d.singular_edges.size(), 0u);
  EXPECT_LT(d.mean_boundary_alignment, 5.);
  std::cout << "  ball: " << mesh.points.size() << " vertices, " << solved.energies.size() - 1 << " iterations, energy "
            << solved.energies.front() << " -> " << solved.energies.back() << "; largest boundary angle to the normal "
            << bcc_worst << " degrees (BCC, face diagonals), " << fcc_worst << " (FCC, axes); FCC on the faces "
            << d.mean_boundary_alignment << " mean, " << d.max_boundary_alignment << " max; " << d.singular_edges.size() << " singular edges\n";
}

// lattice-mesh --field cross: prints the field's figures, writes its singular edges and the
// field, which meshes again from the file; the options that go with it are refused without it.
TEST(Cross_field_program, ComputesSavesAndReusesTheField)
{
  const std::string dir = ::testing::TempDir(), exe = LATTICE_MESH_EXECUTABLE;
  const std::string field = dir + "lm_cross.mesh", edges = dir + "lm_cross_singular.vtu", log = dir + "lm_cross.txt";
  auto text = [](const std::string& file) {
    std::ifstream is(file);
    return std::string((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
  };
  ASSERT_EQ(std::system((exe + " --domain sphere --field cross --field-vertices 800 --write-field " + field +
                         " --singularities " + edges + " > " + log).c_str()), 0);
  const std::string printed = text(log);
  for(const char* figure : { "cross field: ", "smoothness energy", "boundary alignment", "singular edges" })
    EXPECT_NE(printed.find(figure), std::string::npos) << printed;
  const std::string vtu = text(edges);
  EXPECT_NE(vtu.find("<VTKFile type=\"UnstructuredGrid\""), std::string::npos);
  EXPECT_EQ(vtu.find("NumberOfCells=\"0\""), std::string::npos) << "a ball's field has singular edges";
  const Discrete_field saved = CGAL::Lattice_mesher_3::read_frame_field_from_medit<GT>(field, dir + "lm_cross.sol");
  EXPECT_GT(saved.mesh().tets.size(), 0u);
  for(const Eigen::Matrix3d& t : saved.frames()) ASSERT_TRUE((t.transpose() * t).isIdentity(1e-9)) << t;
  EXPECT_EQ(std::system((exe + " --domain sphere --field " + field + " --vertices 1500 --quiet -o " + dir + "lm_cross_out.mesh").c_str()), 0);
  EXPECT_NE(std::system((exe + " --domain sphere --vertices 1500 --singularities " + edges + " -o " + dir + "lm_x.mesh 2> " + log).c_str()), 0);
  EXPECT_NE(text(log).find("--singularities and --field-vertices go with --field cross"), std::string::npos) << text(log);
}

} // namespace
