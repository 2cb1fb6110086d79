// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

// Discrete frame fields (nearest-sample lookup, validation, coverage of a box), their files (text
// samples, Medit .mesh with a .sol frame or metric field or a plain file of frames), and the
// paper's analytic fields of Fig. 8 and Fig. 9.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lattice_mesher_traits_3.h>
#include <CGAL/Lattice_mesher_3/Discrete_frame_field_3.h>
#include <CGAL/Lattice_mesher_3/IO/frame_field.h>
#include <CGAL/Lattice_mesher_3/IO/medit.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>

#include <gtest/gtest.h>

#include "test_helpers.h"

#include <Eigen/Dense>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace LM = CGAL::Lattice_mesher_3;
typedef CGAL::Lattice_mesher_traits_3<CGAL::Epick> GT;
typedef GT::Point_3 Point_3;
typedef GT::Matrix_3 Matrix_3;
typedef LM::Discrete_frame_field_3<GT> Discrete_field;
typedef Eigen::Vector3d Vec3;

namespace {

// ---------------------------------------------------------------------------------------------
// Helpers

// A well-conditioned, non-symmetric frame: rotation x stretch (0.5 to 2) x rotation.
Matrix_3 random_frame(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> angle(0., 6.28), stretch(.5, 2.);
  std::normal_distribution<double> n;
  auto rotation = [&] { return Eigen::AngleAxisd(angle(rng), Vec3(n(rng), n(rng), n(rng)).normalized()).toRotationMatrix(); };
  return rotation() * Vec3(stretch(rng), stretch(rng), stretch(rng)).asDiagonal() * rotation();
}

std::vector<Point_3> random_points(std::mt19937_64& rng, std::size_t n)
{
  std::uniform_real_distribution<double> u(-1., 2.);
  std::vector<Point_3> points;
  for(std::size_t i = 0; i < n; ++i) points.emplace_back(u(rng), u(rng), u(rng));
  return points;
}

std::vector<Matrix_3> random_frames(std::mt19937_64& rng, std::size_t n)
{
  std::vector<Matrix_3> frames;
  for(std::size_t i = 0; i < n; ++i) frames.push_back(random_frame(rng));
  return frames;
}

// The regular grid of spacing h over [lo, hi]^3, end points included.
std::vector<Point_3> grid_points(double lo, double hi, int intervals)
{
  std::vector<Point_3> points;
  for(int i = 0; i <= intervals; ++i) for(int j = 0; j <= intervals; ++j) for(int k = 0; k <= intervals; ++k)
    points.emplace_back(lo + (hi - lo) * i / intervals, lo + (hi - lo) * j / intervals, lo + (hi - lo) * k / intervals);
  return points;
}

// A Medit .sol file with one SolAtVertices field of `type` (3 or 4), one entry a line.
std::string sol_file(int type, const std::vector<std::vector<double> >& entries)
{
  std::ostringstream os;
  os << std::setprecision(17) << "MeshVersionFormatted 2\n\nDimension 3\n\nSolAtVertices\n" << entries.size() << "\n1 " << type << "\n";
  for(const std::vector<double>& e : entries) {
    for(double v : e) os << ' ' << v;
    os << '\n';
  }
  os << "\nEnd\n";
  return os.str();
}

std::vector<double> row_by_row(const Matrix_3& t)
{ return { t(0, 0), t(0, 1), t(0, 2), t(1, 0), t(1, 1), t(1, 2), t(2, 0), t(2, 1), t(2, 2) }; }

// A symmetric matrix in Medit's order m11 m12 m22 m13 m23 m33.
std::vector<double> medit_symmetric(const Matrix_3& m)
{ return { m(0, 0), m(1, 0), m(1, 1), m(2, 0), m(2, 1), m(2, 2) }; }

// Files in a scratch directory of their own per test, removed at its end.
class Field_files : public ::testing::Test, protected Temp_dir
{
protected:
  // a Medit mesh whose vertices are `points` (the field readers need no cells)
  std::string write_mesh(const std::string& name, const std::vector<Point_3>& points) const
  {
    LM::Tetrahedral_mesh_3<Point_3> mesh;
    mesh.points = points;
    std::ofstream os(path(name));
    LM::write_medit(os, mesh);
    return path(name);
  }
};

// ---------------------------------------------------------------------------------------------
// Discrete_frame_field_3

TEST(Discrete_frame_field, nearest_sample_lookup)
{
  std::mt19937_64 rng(1);
  const std::vector<Point_3> points = random_points(rng, 500);
  const std::vector<Matrix_3> frames = random_frames(rng, points.size());
  const Discrete_field field(points, frames);
  EXPECT_EQ(field.number_of_samples(), points.size());
  for(std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(field.frame(points[i]), frames[i]) << i;

  // queries inside and around the samples' box, against a brute-force search
  std::uniform_real_distribution<double> u(-1.5, 2.5);
  for(int s = 0; s < 300; ++s) {
    const Point_3 q(u(rng), u(rng), u(rng));
    std::size_t nearest = 0;
    for(std::size_t i = 1; i < points.size(); ++i)
      if(CGAL::squared_distance(q, points[i]) < CGAL::squared_distance(q, points[nearest])) nearest = i;
    EXPECT_EQ(field.nearest_sample(q), nearest) << q;
    EXPECT_EQ(field.frame(q), frames[nearest]) << q;
  }

  // copies share the samples and stay valid after the original is gone
  const Discrete_field copy = [&] { const Discrete_field f(points, frames); return f; }();
  EXPECT_EQ(copy.frame(points[7]), frames[7]);
  EXPECT_TRUE((LM::internal::Is_frame_field_3<Discrete_field, GT>::value));
}

TEST(Discrete_frame_field, concurrent_lookups_agree)
{
  std::mt19937_64 rng(2);
  const Discrete_field field(random_points(rng, 2000), random_frames(rng, 2000));
  const std::vector<Point_3> queries = random_points(rng, 20000);
  std::vector<std::size_t> serial(queries.size()), parallel(queries.size());
  for(std::size_t i = 0; i < queries.size(); ++i) serial[i] = field.nearest_sample(queries[i]);
#pragma omp parallel for num_threads(2)
  for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(queries.size()); ++i) parallel[i] = field.nearest_sample(queries[i]);
  EXPECT_EQ(serial, parallel);
}

TEST(Discrete_frame_field, bbox_and_typical_spacing)
{
  const std::vector<Point_3> points = grid_points(0., 1., 10);
  const Discrete_field field(points, std::vector<Matrix_3>(points.size(), Matrix_3::Identity()));
  EXPECT_EQ(field.bbox(), CGAL::Bbox_3(0, 0, 0, 1, 1, 1));
  EXPECT_NEAR(field.typical_spacing(), .1, 1e-12);
  EXPECT_EQ(Discrete_field({ Point_3(1, 2, 3) }, { Matrix_3::Identity() }).typical_spacing(), 0.);
}

TEST(Discrete_frame_field, coverage_of_a_box)
{
  // spacing 0.1: the samples may fall short of the box by up to 0.05 on each side
  const std::vector<Point_3> points = grid_points(0., 1., 10);
  const Discrete_field field(points, std::vector<Matrix_3>(points.size(), Matrix_3::Identity()));
  EXPECT_NO_THROW(field.check_coverage(CGAL::Bbox_3(0, 0, 0, 1, 1, 1)));
  EXPECT_NO_THROW(field.check_coverage(CGAL::Bbox_3(-.04, .2, 0, 1, .5, 1.04)));
  expect_error<std::invalid_argument>([&] { field.check_coverage(CGAL::Bbox_3(-.2, 0, 0, 1, 1, 1.3)); },
                                      { "do not cover", "0.2 at x min", "0.3 at z max", "tolerance 0.05" });
  expect_error<std::invalid_argument>([&] { field.check_coverage(CGAL::Bbox_3(1, 1, 1, 11, 11, 11)); },
                                      { "10 at x max", "10 at y max", "10 at z max" });
}

TEST(Discrete_frame_field, rejects_bad_samples)
{
  const Matrix_3 I = Matrix_3::Identity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_error<std::invalid_argument>([&] { Discrete_field(std::vector<Point_3>(), {}); }, { "at least one" });
  expect_error<std::invalid_argument>([&] { Discrete_field({ Point_3(0, 0, 0) }, { I, I }); }, { "1 points and 2 frames" });
  expect_error<std::invalid_argument>([&] { Discrete_field({ Point_3(0, 0, 0), Point_3(nan, 0, 0) }, { I, I }); },
                                      { "sample 1", "non-finite point" });
  Matrix_3 infinite = I;
  infinite(2, 1) = std::numeric_limits<double>::infinity();
  expect_error<std::invalid_argument>([&] { Discrete_field({ Point_3(0, 0, 0), Point_3(1, 2, 3) }, { I, infinite }); },
                                      { "sample 1", "non-finite frame", "1 2 3" });
  // condition number 1e10, beyond the bound of 1e8 that the stages use
  const Matrix_3 thin = Vec3(1., 1., 1e-10).asDiagonal();
  expect_error<std::domain_error>([&] { Discrete_field({ Point_3(0, 0, 0), Point_3(1, 2, 3) }, { I, thin }); },
                                  { "sample 1", "singular", "condition number", "1 2 3" });
  Matrix_3 rank2;
  rank2 << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  expect_error<std::domain_error>([&] { Discrete_field({ Point_3(4, 5, 6) }, { rank2 }); }, { "sample 0", "singular" });
}

// ---------------------------------------------------------------------------------------------
// Files: round trips

TEST_F(Field_files, samples_round_trip)
{
  // a non-symmetric, varying field, written and read back bit for bit
  const auto sheared = LM::make_function_frame_field_3<GT>([](const Point_3& p) {
    Matrix_3 t;
    t << 1. + p.x() * p.x(), .3 * p.y(), 0.1,
         -.2, 1. / 3., std::sin(p.z()),
         p.x() * p.y(), 0., 2.;
    return t;
  });
  const CGAL::Bbox_3 box(.1, -1, 0, 1.1, 1, .3);
  LM::write_frame_field_samples(path("f.txt"), sheared, box, .1);
  const Discrete_field field = LM::read_frame_field_samples<GT>(path("f.txt"));
  EXPECT_EQ(field.number_of_samples(), 11u * 21u * 4u);
  EXPECT_EQ(field.bbox(), box);
  for(std::size_t i = 0; i < field.number_of_samples(); ++i)
    ASSERT_EQ(field.frames()[i], sheared.frame(field.points()[i])) << field.points()[i];
  EXPECT_NO_THROW(field.check_coverage(box));

  // a spacing that does not divide the box: the largest smaller one that does
  LM::write_frame_field_samples(path("g.txt"), sheared, CGAL::Bbox_3(0, 0, 0, 1, 1, 1), .3);
  EXPECT_EQ(LM::read_frame_field_samples<GT>(path("g.txt")).number_of_samples(), 5u * 5u * 5u);
}

TEST_F(Field_files, paper_field_round_trip)
{
  const LM::Planar_layer_frame_field_3<GT> fig8;
  const CGAL::Bbox_3 cube(.1, .1, .1, 1.1, 1.1, 1.1);
  LM::write_frame_field_samples(path("fig8.txt"), fig8, cube, .05);
  const Discrete_field field = LM::read_frame_field_samples<GT>(path("fig8.txt"));
  EXPECT_EQ(field.number_of_samples(), 21u * 21u * 21u);
  EXPECT_NEAR(field.typical_spacing(), .05, 1e-12);
  EXPECT_NO_THROW(field.check_coverage(cube));
  // between samples, the nearest one's frame
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(.1, 1.1);
  for(int s = 0; s < 100; ++s) {
    const Point_3 q(u(rng), u(rng), u(rng));
    const Point_3 snapped(.1 + .05 * std::round((q.x() - .1) / .05), q.y(), q.z());
    EXPECT_NEAR((field.frame(q) - fig8.frame(snapped)).norm(), 0., 1e-12) << q;
  }
}

TEST_F(Field_files, medit_sol_frames_round_trip)
{
  std::mt19937_64 rng(4);
  const std::vector<Point_3> points = random_points(rng, 60);
  const std::vector<Matrix_3> frames = random_frames(rng, points.size());
  std::vector<std::vector<double> > entries;
  for(const Matrix_3& t : frames) entries.push_back(row_by_row(t));
  const std::string mesh = write_mesh("m.mesh", points);
  const Discrete_field field = LM::read_frame_field_from_medit<GT>(mesh, write("m.sol", sol_file(4, entries)));
  EXPECT_EQ(field.points(), points);
  EXPECT_EQ(field.frames(), frames);
}

TEST_F(Field_files, medit_sol_metric_gives_its_inverse_square_root)
{
  // T T^T = M^-1 (unit lattice cubes have unit edges in the metric), T symmetric
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> eigenvalue(.25, 400.);
  const std::vector<Point_3> points = random_points(rng, 40);
  std::vector<Matrix_3> metrics;
  std::vector<std::vector<double> > entries;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const Matrix_3 r = random_frame(rng).householderQr().householderQ();
    metrics.push_back(r * Vec3(eigenvalue(rng), eigenvalue(rng), eigenvalue(rng)).asDiagonal() * r.transpose());
    entries.push_back(medit_symmetric(metrics.back()));
  }
  const std::string mesh = write_mesh("m.mesh", points);
  const Discrete_field field = LM::read_frame_field_from_medit<GT>(mesh, write("m.sol", sol_file(3, entries)));
  for(std::size_t i = 0; i < points.size(); ++i) {
    const Matrix_3& t = field.frames()[i];
    const Matrix_3 inverse = metrics[i].inverse();
    EXPECT_LT((t * t.transpose() - inverse).norm(), 1e-10 * inverse.norm()) << i;
    EXPECT_LT((t - t.transpose()).norm(), 1e-12 * t.norm()) << i;
  }

  // Medit's order of the six values, as MMG writes them: m11 m12 m22 m13 m23 m33
  Matrix_3 m;
  m << 4., 1., .5,
       1., 3., .2,
       .5, .2, 2.;
  const std::string one = write_mesh("one.mesh", { Point_3(0, 0, 0) });
  const Matrix_3 t = LM::read_frame_field_from_medit<GT>(one, write("one.sol", sol_file(3, { { 4, 1, 3, .5, .2, 2 } }))).frames()[0];
  EXPECT_LT((t * t.transpose() * m - Matrix_3::Identity()).norm(), 1e-12);
}

TEST_F(Field_files, plain_frames_are_the_frame_vectors_one_after_the_other)
{
  std::mt19937_64 rng(6);
  const std::vector<Point_3> points = random_points(rng, 30);
  const std::vector<Matrix_3> frames = random_frames(rng, points.size());
  std::ostringstream os;
  os << std::setprecision(17) << "# t1x t1y t1z t2x t2y t2z t3x t3y t3z\n";
  for(const Matrix_3& t : frames) {
    for(int c = 0; c < 3; ++c) os << t(0, c) << ' ' << t(1, c) << ' ' << t(2, c) << ' ';
    os << "\n\n";   // blank lines are skipped
  }
  const std::string mesh = write_mesh("m.mesh", points);
  const Discrete_field field = LM::read_frame_field_from_medit<GT>(mesh, write("m.frames", os.str()));
  EXPECT_EQ(field.points(), points);
  EXPECT_EQ(field.frames(), frames);
}

// ---------------------------------------------------------------------------------------------
// Files: errors name the file and the line

TEST_F(Field_files, missing_files)
{
  const std::string missing = path("missing.txt");
  expect_error<std::runtime_error>([&] { LM::read_frame_field_samples<GT>(missing); }, { "cannot open", missing });
  const std::string mesh = write_mesh("m.mesh", { Point_3(0, 0, 0) });
  expect_error<std::runtime_error>([&] { LM::read_frame_field_from_medit<GT>(missing, mesh); }, { "cannot open", missing });
  expect_error<std::runtime_error>([&] { LM::read_frame_field_from_medit<GT>(mesh, missing); }, { "cannot open", missing });
}

TEST_F(Field_files, bad_sample_files)
{
  const std::string good = "0 0 0  1 0 0  0 1 0  0 0 1\n";
  const std::string truncated = write("truncated.txt", "# x y z T\n" + good + "1 0 0  1 0 0  0 1\n");
  expect_error<std::runtime_error>([&] { LM::read_frame_field_samples<GT>(truncated); },
                                   { truncated, "line 3", "expected 12 numbers", "got 8" });
  const std::string garbled = write("garbled.txt", good + "1 0 0  1 0 0  0 one 0  0 0 1\n");
  expect_error<std::runtime_error>([&] { LM::read_frame_field_samples<GT>(garbled); }, { garbled, "line 2", "'one' is not a number" });
  const std::string nan = write("nan.txt", good + "1 0 0  1 0 0  0 nan 0  0 0 1\n");
  expect_error<std::runtime_error>([&] { LM::read_frame_field_samples<GT>(nan); }, { nan, "line 2", "non-finite frame" });
  const std::string singular = write("singular.txt", good + "1 0 0  1 0 0  0 1 0  1 1 0\n");
  expect_error<std::runtime_error>([&] { LM::read_frame_field_samples<GT>(singular); },
                                   { singular, "line 2", "singular", "condition number", "1 0 0" });
  const std::string empty = write("empty.txt", "# nothing\n\n");
  expect_error<std::runtime_error>([&] { LM::read_frame_field_samples<GT>(empty); }, { empty, "no sample" });
}

TEST_F(Field_files, bad_sol_files)
{
  const std::string mesh = write_mesh("m.mesh", { Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0) });
  const std::vector<double> I = row_by_row(Matrix_3::Identity());
  auto expect_sol_error = [&](const std::string& name, const std::string& contents, const std::vector<std::string>& words) {
    const std::string file = write(name, contents);
    std::vector<std::string> all = words;
    all.push_back(file);
    expect_error<std::runtime_error>([&] { LM::read_frame_field_from_medit<GT>(mesh, file); }, all);
  };
  const std::string whole = sol_file(4, { I, I, I });
  const std::string truncated = write("truncated.sol", whole.substr(0, whole.find("\n 1 0 0 0 1 0 0 0 1\n\nEnd")));
  try {
    LM::read_frame_field_from_medit<GT>(mesh, truncated);
    ADD_FAILURE() << "no exception";
  }
  catch(const std::runtime_error& e) {   // the reader names itself once, not read_medit()
    EXPECT_EQ(std::string(e.what()),
              "read_frame_field_from_medit(): '" + truncated + "': unexpected end of file in SolAtVertices (line 9)");
  }
  std::string nan = whole;
  nan.replace(nan.rfind("0 1\n\nEnd"), 1, "nan");
  expect_sol_error("nan.sol", nan, { "vertex 3", "non-finite", "line 10" });
  expect_sol_error("singular.sol", sol_file(4, { I, { 1, 0, 0, 0, 1, 0, 0, 1e-12, 0 }, I }),
                   { "vertex 2", "singular", "condition number", "line 9" });
  expect_sol_error("indefinite.sol", sol_file(3, { { 1, 0, 1, 0, 0, 1 }, { 1, 2, 1, 0, 0, 1 }, { 1, 0, 1, 0, 0, 1 } }),
                   { "vertex 2", "not positive definite", "-1" });
  expect_sol_error("scalar.sol", "MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n3\n1 1\n1\n1\n1\nEnd\n",
                   { "type 1 (scalar) is not a frame" });
  expect_sol_error("count.sol", sol_file(4, { I, I }), { "2 entries for a mesh of 3 vertices" });
  expect_sol_error("garbled.sol", sol_file(4, { I, { 1, 0, 0, 0, 1, 0, 0, 0 }, I }), { "expected a number" });
}

TEST_F(Field_files, bad_plain_frame_files)
{
  const std::string mesh = write_mesh("m.mesh", { Point_3(0, 0, 0), Point_3(1, 0, 0) });
  const std::string I = "1 0 0 0 1 0 0 0 1\n";
  const std::string short_line = write("short.frames", I + "1 0 0 0 1 0 0 0\n");
  expect_error<std::runtime_error>([&] { LM::read_frame_field_from_medit<GT>(mesh, short_line); },
                                   { short_line, "line 2", "expected 9 numbers", "got 8" });
  const std::string few = write("few.frames", I);
  expect_error<std::runtime_error>([&] { LM::read_frame_field_from_medit<GT>(mesh, few); }, { few, "ends after 1 frames", "a mesh of 2 vertices" });
  const std::string many = write("many.frames", I + I + I);
  expect_error<std::runtime_error>([&] { LM::read_frame_field_from_medit<GT>(mesh, many); }, { many, "line 3", "more frames" });
  const std::string nan = write("nan.frames", I + "1 0 0 0 1 0 0 0 NaN\n");
  expect_error<std::runtime_error>([&] { LM::read_frame_field_from_medit<GT>(mesh, nan); }, { nan, "line 2", "non-finite" });
  const std::string bad_mesh = write("bad.mesh", "MeshVersionFormatted 1\nDimension 3\nVertices\n2\n0 0 0 1\n");
  expect_error<std::runtime_error>([&] { LM::read_frame_field_from_medit<GT>(bad_mesh, few); }, { bad_mesh, "unexpected end of file" });
}

TEST_F(Field_files, write_rejects_bad_arguments)
{
  const LM::Constant_frame_field_3<GT> identity;
  const CGAL::Bbox_3 box(0, 0, 0, 1, 1, 1);
  expect_error<std::invalid_argument>([&] { LM::write_frame_field_samples(path("a.txt"), identity, box, 0.); }, { "spacing" });
  expect_error<std::invalid_argument>([&] { LM::write_frame_field_samples(path("a.txt"), identity, box, 1e-4); }, { "1e8 samples" });
  expect_error<std::invalid_argument>([&] { LM::write_frame_field_samples(path("a.txt"), identity, CGAL::Bbox_3(), .1); }, { "box" });
  expect_error<std::runtime_error>([&] { LM::write_frame_field_samples(path("no/such/dir.txt"), identity, box, .1); }, { "cannot write" });
}

// ---------------------------------------------------------------------------------------------
// The paper's analytic fields

TEST(Paper_fields, planar_layer_of_fig8)
{
  const LM::Planar_layer_frame_field_3<GT> fig8;
  EXPECT_LT((fig8.frame(Point_3(.6, .3, .9)) - Matrix_3(Vec3(.0125, 1., 1.).asDiagonal())).norm(), 1e-15);
  for(double x : { .1, .35, .8, 1.1 }) {
    const Matrix_3 t = fig8.frame(Point_3(x, .5, .2));
    EXPECT_NEAR(t.inverse()(0, 0), 1. / (1.0125 - std::exp(-std::abs(x - .6))), 1e-12) << x;
    EXPECT_EQ(t - Matrix_3(t.diagonal().asDiagonal()), Matrix_3::Zero()) << x;
    EXPECT_EQ(Eigen::Vector2d(t.diagonal().tail<2>()), Eigen::Vector2d(1., 1.)) << x;
  }
}

TEST(Paper_fields, cylindrical_layer_of_fig9)
{
  // B = S R: R's rows radial, tangential, axial (the paper's typo corrected), S stretches radially
  const LM::Cylindrical_layer_frame_field_3<GT> fig9;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(1., 11.);
  for(int s = 0; s < 50; ++s) {
    const double x = u(rng), y = u(rng), z = u(rng), r = std::hypot(x, y);
    Matrix_3 R;
    R << x / r, y / r, 0.,
         -y / r, x / r, 0.,
         0., 0., 1.;
    const Matrix_3 S = Vec3(1. / (1.05 - std::exp(-.01 * std::abs(x * x + y * y - 49.))), 1., 1.).asDiagonal();
    const Matrix_3 t = fig9.frame(Point_3(x, y, z));
    EXPECT_LT((t.inverse() - S * R).norm(), 1e-12 * (S * R).norm()) << x << " " << y;
    EXPECT_NEAR(t.col(0).dot(t.col(1)), 0., 1e-15);
  }
  // on the cylinder r = 7 the radial edge is 20 times shorter than the others
  const Matrix_3 t = fig9.frame(Point_3(7. / std::sqrt(2.), 7. / std::sqrt(2.), 4.));
  EXPECT_NEAR(t.col(0).norm(), .05, 1e-12);
  EXPECT_NEAR(t.col(1).norm(), 1., 1e-15);
  EXPECT_NEAR(t.col(0).normalized().dot(Vec3(1., 1., 0.).normalized()), 1., 1e-15);
  // on the axis, x is taken as radial
  EXPECT_LT((fig9.frame(Point_3(0, 0, 3)) - Matrix_3(Vec3(1.05 - std::exp(-.49), 1., 1.).asDiagonal())).norm(), 1e-15);
}

} // namespace
