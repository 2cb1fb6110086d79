// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The whole pipeline: lattice structure on the cube, validity of the output mesh, the named
// parameters of lattice_mesh_3(), determinism, and clear errors for bad input.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/lattice_mesh_3.h>
#include <CGAL/Lattice_mesher_3/Implicit_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/IO/medit.h>
#include <CGAL/Lattice_mesher_3/IO/sizing_field.h>
#include <CGAL/Lattice_mesher_3/check_mesh.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>

#include <gtest/gtest.h>

#include "test_helpers.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <random>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace {

namespace LM = CGAL::Lattice_mesher_3;
typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Lattice_mesher_traits_3<K> Traits;
typedef LM::Polyhedral_lattice_domain_3<K> Domain;
typedef LM::Constant_frame_field_3<Traits> Field;


const Domain& cube()
{
  static const Domain d(LM::make_cube_surface_3<K>(0.1, 1.1));
  return d;
}

// Fraction of the particles deeper than 1.5 l* whose every one-ring offset l* O_k is matched by a
// particle within 0.1 l* (T = I, so offsets are axis-aligned).
double lattice_fraction(const LM::Particle_set_3<Point_3>& ps, const LM::Lattice_3& lattice, double l)
{
  std::size_t deep = 0, perfect = 0;
  for(std::size_t i = 0; i < ps.size(); ++i) {
    const Point_3& p = ps.points[i];
    if(std::sqrt(cube().project_on_surface(p).squared_distance) <= 1.5 * l || !cube().is_inside(p)) continue;
    ++deep;
    bool all = true;
    for(const Eigen::Vector3d& o : lattice.one_ring) {
      const Point_3 ideal(p.x() + l * o[0], p.y() + l * o[1], p.z() + l * o[2]);
      bool found = false;
      for(std::size_t j = 0; j < ps.size() && !found; ++j)
        found = CGAL::squared_distance(ps.points[j], ideal) < 0.01 * l * l;
      all = all && found;
    }
    perfect += all;
  }
  EXPECT_GT(deep, 100u);
  return deep == 0 ? 0. : double(perfect) / double(deep);
}

class Cube_lattice : public ::testing::TestWithParam<LM::Lattice_type> {};

TEST_P(Cube_lattice, InteriorFormsThePerfectLatticeAndTheMeshIsValid)
{
  const Field field;
  CGAL::Lattice_particle_mesher_3<Traits, Domain, Field> mesher(
      cube(), field, CGAL::parameters::lattice(GetParam()).edge_length(1. / 8.).number_of_threads(2));
  mesher.optimize();
  EXPECT_GE(lattice_fraction(mesher.particles(), mesher.lattice(), 1. / 8.), 0.95);

  const LM::Tetrahedral_mesh_3<Point_3> mesh = mesher.tetrahedralize();
  const LM::Mesh_validity_report r = LM::check_tetrahedral_mesh(mesh);
  EXPECT_TRUE(r.valid()) << r.message;
  EXPECT_EQ(r.unused_vertices, 0u);
  // every input corner is a mesh vertex
  for(const Point_3& c : cube().corners()) {
    bool found = false;
    for(const Point_3& q : mesh.points) found = found || q == c;
    EXPECT_TRUE(found) << "corner " << c << " is missing";
  }
  // every tet is inside the domain
  for(const auto& t : mesh.tets)
    EXPECT_TRUE(cube().is_inside(CGAL::centroid(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]])));
}

INSTANTIATE_TEST_SUITE_P(Lattices, Cube_lattice, ::testing::Values(LM::Lattice_type::BCC, LM::Lattice_type::FCC));

// Particle2013's baseline: the hole-less kernel starts at the final count and keeps it (no
// insertion or deletion), its free particles stay inside and its boundary particles on the
// boundary; it forms no lattice, so its edges follow no axis, yet its mesh is valid and fair
// (cube, 1,500 vertices: mean smallest dihedral angle 53.3, alignment error 21.4 degrees).
TEST(Lattice_mesh_3, HolelessKernelKeepsItsCountAndFormsNoLattice)
{
  const Field field;
  CGAL::Lattice_particle_mesher_3<Traits, Domain, Field> mesher(
      cube(), field, CGAL::parameters::lattice(LM::Lattice_type::GAUSSIAN).number_of_vertices(1500).number_of_threads(2));
  EXPECT_EQ(mesher.coarse_levels(), 0);
  mesher.optimize();
  const LM::Particle_set_3<Point_3>& ps = mesher.particles();
  EXPECT_NEAR(double(ps.size()), 1500., 1.);
  for(std::size_t i = 0; i < ps.size(); ++i) {
    const double d = std::sqrt(cube().project_on_surface(ps.points[i]).squared_distance);
    if(ps.kinds[i] == LM::Particle_kind::FREE)
      EXPECT_TRUE(cube().is_inside(ps.points[i]) && d > 0.29 * mesher.edge_length()) << "free particle " << i << " at " << d;
    else
      EXPECT_LT(d, 1e-9) << "particle " << i << " off the boundary";
  }
  EXPECT_LT(lattice_fraction(ps, mesher.lattice(), mesher.edge_length()), 0.05);

  // every particle is a vertex of the tetrahedralization; the edge contractions of the
  // improvement then remove a few interior ones (here 56 of 1501)
  EXPECT_EQ(LM::tetrahedralize_particles(ps, cube(), field).points.size(), ps.size());
  const LM::Tetrahedral_mesh_3<Point_3> mesh = mesher.tetrahedralize();
  const LM::Mesh_validity_report r = LM::check_tetrahedral_mesh(mesh);
  EXPECT_TRUE(r.valid()) << r.message;
  EXPECT_LE(mesh.points.size(), ps.size());
  EXPECT_GT(mesh.points.size(), 0.95 * ps.size());
  const LM::Mesh_quality_3 q = LM::compute_mesh_quality(mesh, field, CGAL::parameters::lattice(mesher.lattice()));
  EXPECT_GT(q.theta_min.mean, 50.);
  EXPECT_GT(q.epsilon.mean, 15.);
}

TEST(Lattice_mesh_3, NamedParametersAndDeterminism)
{
  const Field field;
  const auto a = CGAL::lattice_mesh_3(cube(), field, CGAL::parameters::number_of_vertices(1500)
                                                       .lattice(LM::Lattice_type::FCC).random_seed(7u).number_of_threads(2));
  const auto b = CGAL::lattice_mesh_3(cube(), field, CGAL::parameters::random_seed(7u).number_of_vertices(1500)
                                                       .number_of_threads(2).lattice(LM::Lattice_type::FCC));
  EXPECT_TRUE(LM::check_tetrahedral_mesh(a).valid());
  EXPECT_NEAR(double(a.points.size()), 1500., 300.);
  ASSERT_EQ(a.points.size(), b.points.size());
  ASSERT_EQ(a.tets, b.tets);
  for(std::size_t i = 0; i < a.points.size(); ++i) EXPECT_EQ(a.points[i], b.points[i]);

  // The seed draws the random points of the start: a domain without corners grows from a deep
  // point picked at random (other seeds, other meshes); a domain with corners grows from them,
  // whatever the seed.
  auto with_seed = [&](const auto& domain, unsigned int seed) {
    return CGAL::lattice_mesh_3(domain, field, CGAL::parameters::number_of_vertices(800).coarse_levels(0)
                                                 .random_seed(seed).number_of_threads(2)).points;
  };
  const auto ball = LM::make_sphere_domain_3<K>(Point_3(0.6, 0.6, 0.6), 0.5);
  EXPECT_NE(with_seed(ball, 7u), with_seed(ball, 8u));
  EXPECT_EQ(with_seed(cube(), 7u), with_seed(cube(), 8u));
}

// A vertex count that the first mesh misses by more than 15 % is asked again, half the shortfall
// added in logarithm (n sqrt(n / m), between n / 2 and 2 n), and the mesh closer to n is kept;
// the cube [0.1, 1.1]^3 at 3,000 BCC vertices takes 5 lattice layers (2,484 vertices) at the l*
// of the count model, and 3,297 asked again gives the 6 layers of a slightly smaller l*.
TEST(Lattice_mesh_3, MissedVertexCountIsAskedAgain)
{
  std::vector<double> asked;
  auto count_of = [](double m) { return m; };
  auto runs = [&](std::vector<double> counts) {   // the mesh of each run has the next count
    asked.clear();
    return [&asked, counts](double n) { asked.push_back(n); return counts.at(asked.size() - 1); };
  };
  EXPECT_EQ(LM::internal::run_for_vertex_count(3000., runs({ 1500., 2600. }), count_of), 2600.);
  ASSERT_EQ(asked.size(), 2u);
  EXPECT_NEAR(asked[1], 3000. * std::sqrt(2.), 1e-9);
  EXPECT_EQ(LM::internal::run_for_vertex_count(3000., runs({ 1500., 6000. }), count_of), 1500.);   // worse: the first
  EXPECT_EQ(LM::internal::run_for_vertex_count(3000., runs({ 100., 1000. }), count_of), 1000.);
  EXPECT_EQ(asked[1], 6000.);   // at most twice the count
  EXPECT_EQ(LM::internal::run_for_vertex_count(3000., runs({ 3400. }), count_of), 3400.);   // within 15 %: once
  EXPECT_EQ(asked.size(), 1u);
  EXPECT_EQ(LM::internal::run_for_vertex_count(0., runs({ 10. }), count_of), 10.);   // an edge length: once
  EXPECT_EQ(asked.size(), 1u);
  // a second count that the sizes cannot meet leaves the first mesh
  auto then_refused = [](double n) { if(n < 3000.) throw std::invalid_argument("too few"); return 4000.; };
  EXPECT_EQ(LM::internal::run_for_vertex_count(3000., then_refused, count_of), 4000.);

  const auto mesh = CGAL::lattice_mesh_3(cube(), Field(), CGAL::parameters::number_of_vertices(3000).number_of_threads(2));
  EXPECT_TRUE(LM::check_tetrahedral_mesh(mesh).valid());
  EXPECT_NEAR(double(mesh.points.size()), 3000., 450.);
}

// A size given by the user: h = 0.06 + 0.25 (x - 0.1) over the cube [0.1, 1.1]^3 (slope 0.25),
// capped by l* = 0.25: the vertices crowd where h is small, about as the density h^-3 says, and
// with a vertex count l* is chosen for it.
TEST(Lattice_mesh_3, SizeFieldGradesTheMesh)
{
  const Field field;
  auto h = [](const Point_3& p) { return .06 + .25 * (p.x() - .1); };
  auto halves = [](const LM::Tetrahedral_mesh_3<Point_3>& m) {
    std::size_t left = 0;
    for(const Point_3& p : m.points) left += p.x() < .6;
    return std::make_pair(double(left), double(m.points.size() - left));
  };
  const auto sized = CGAL::lattice_mesh_3(cube(), field, CGAL::parameters::edge_length(.25).size_field(h).number_of_threads(2));
  const LM::Mesh_validity_report r = LM::check_tetrahedral_mesh(sized);
  EXPECT_TRUE(r.valid()) << r.message;
  const auto n = halves(sized);
  // h^-3 integrated over each half: 11.9 times as many on the left (h from 0.06 to 0.185 against
  // 0.185 to 0.25, then the cap)
  EXPECT_GT(n.first, 6. * n.second) << n.first << " left, " << n.second << " right";
  EXPECT_LT(n.first, 16. * n.second) << n.first << " left, " << n.second << " right";
  // 1,500 vertices: more than h alone gives (about 1,190 at l* = 0.25), so l* is the cap where
  // h would be larger and the left half is still the denser
  const auto counted = CGAL::lattice_mesh_3(cube(), field, CGAL::parameters::number_of_vertices(1500).size_field(h).number_of_threads(2));
  EXPECT_TRUE(LM::check_tetrahedral_mesh(counted).valid());
  EXPECT_NEAR(double(counted.points.size()), 1500., 225.);
  EXPECT_GT(halves(counted).first, 2. * halves(counted).second) << halves(counted).first << " left, " << halves(counted).second << " right";
  // 1,000 vertices: h alone needs more at any l*, which no l* can give
  try {
    CGAL::lattice_mesh_3(cube(), field, CGAL::parameters::number_of_vertices(1000).size_field(h));
    ADD_FAILURE() << "no error for a count below what the size field needs";
  }
  catch(const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the sizes below l* alone need about"), std::string::npos) << e.what();
  }
}

// A slab 0.3 thick under l* = 0.5: with the size that follows the shape (the default, 1.25 cells
// across) the edge shrinks to 0.24 in it, and vertices fill its middle layer; with
// cells_across(0) the lattice of l* has no room for one, and keeps to the two faces.
TEST(Lattice_mesh_3, SizeFollowsAThinPartByDefault)
{
  Domain::Surface_mesh slab = LM::make_cube_surface_3<K>(0., 2.);
  for(auto v : slab.vertices()) {
    const Point_3 p = slab.point(v);
    slab.point(v) = Point_3(p.x(), p.y(), .15 * p.z());
  }
  const Domain d(slab);
  auto middle = [](const LM::Tetrahedral_mesh_3<Point_3>& m) {
    std::size_t k = 0;
    for(const Point_3& p : m.points) k += p.z() > .1 && p.z() < .2;
    return k;
  };
  const Field field;
  const auto sized = CGAL::lattice_mesh_3(d, field, CGAL::parameters::edge_length(.5));
  const auto uniform = CGAL::lattice_mesh_3(d, field, CGAL::parameters::edge_length(.5).cells_across(0.));
  for(const auto* m : { &sized, &uniform }) {
    const LM::Mesh_validity_report r = LM::check_tetrahedral_mesh(*m);
    EXPECT_TRUE(r.valid()) << r.message;
  }
  const LM::Mesh_quality_3 q = LM::compute_mesh_quality(sized, field, CGAL::parameters::lattice(LM::make_lattice(LM::Lattice_type::BCC)));
  std::cout << sized.points.size() << " vertices, " << middle(sized) << " in the middle layer, smallest angle "
            << q.theta_min.min << "; cells_across(0): " << uniform.points.size() << ", " << middle(uniform) << "\n";
  // the middle layer of a BCC lattice of edge 0.24 over 2 x 2: about (2 / 0.24)^2 = 69 vertices
  EXPECT_GT(middle(sized), 50u);
  EXPECT_EQ(middle(uniform), 0u);
  EXPECT_GE(q.theta_min.min, 10.);
  EXPECT_THROW(CGAL::lattice_mesh_3(d, field, CGAL::parameters::edge_length(.5).cells_across(.5)), std::invalid_argument);
  EXPECT_THROW(CGAL::lattice_mesh_3(d, field, CGAL::parameters::edge_length(.5).grading(0.)), std::invalid_argument);
}

// A surface tolerance on the unit sphere at l* = 0.5: facets of size l* leave it by about 0.08;
// asked to keep within 0.02, the size shrinks near the surface (to about sqrt(2 R 0.02) = 0.2)
// and the boundary keeps within it.
TEST(Lattice_mesh_3, SurfaceToleranceBoundsTheDistanceToTheSurface)
{
  const Field field;
  const auto ball = LM::make_sphere_domain_3<K>(Point_3(0., 0., 0.), 1.);
  const double tolerance = .02;
  const auto coarse = CGAL::lattice_mesh_3(ball, field, CGAL::parameters::edge_length(.5).number_of_threads(2));
  const auto fine = CGAL::lattice_mesh_3(ball, field, CGAL::parameters::edge_length(.5).surface_tolerance(tolerance)
                                                                        .number_of_threads(2));
  for(const auto* m : { &coarse, &fine }) {
    const LM::Mesh_validity_report r = LM::check_tetrahedral_mesh(*m);
    EXPECT_TRUE(r.valid()) << r.message;
  }
  const double far = LM::boundary_hausdorff_distance(coarse, ball, .05);
  const double near = LM::boundary_hausdorff_distance(fine, ball, .05);
  std::cout << "Hausdorff " << far << " with " << coarse.points.size() << " vertices, " << near << " with "
            << fine.points.size() << " at the tolerance " << tolerance << "\n";
  EXPECT_GT(far, 2. * tolerance);
  EXPECT_LE(near, tolerance);
  EXPECT_GE(LM::compute_mesh_quality(fine, field, CGAL::parameters::lattice(LM::make_lattice(LM::Lattice_type::BCC))).theta_min.min, 10.);
  EXPECT_THROW(CGAL::lattice_mesh_3(ball, field, CGAL::parameters::edge_length(.5).surface_tolerance(-1.)), std::invalid_argument);
}

TEST(Lattice_mesh_3, SurfaceMeshOverloadTakesTheFeatureAngle)
{
  const Field field;
  const auto mesh = CGAL::lattice_mesh_3(LM::make_cube_surface_3<K>(0., 1.), field,
                                         CGAL::parameters::edge_length(0.25).feature_angle(45.));
  EXPECT_TRUE(LM::check_tetrahedral_mesh(mesh).valid());
}

// Refinement turns a lattice of edge 2l into the lattice of edge l: for BCC and FCC, every point
// of the finer lattice 2l away from the boundary is there once, and nothing else is (steps along
// the axes alone would give only its simple cubic part: half of BCC's points, a quarter of FCC's).
TEST(Lattice_mesh_3, RefinementGivesTheLatticeOfHalfTheEdge)
{
  const Field field;
  const double l = 0.125;   // the cube [0.1, 1.1]^3: 4 cells of the coarse lattice, 8 of the fine one
  auto point = [](const Eigen::Vector3d& u, double edge) { return Point_3(0.1 + edge * u[0], 0.1 + edge * u[1], 0.1 + edge * u[2]); };
  for(const LM::Lattice_3& lattice : { LM::bcc_lattice(), LM::fcc_lattice() }) {
    LM::Particle_set_3<Point_3> ps;
    const Lattice_block coarse = lattice_block(lattice, 4, 1e-6);   // its interior points
    for(std::size_t i = 0; i < coarse.u.size(); ++i)
      if(coarse.central[i]) ps.push_back(point(coarse.u[i], 2. * l), LM::Particle_kind::FREE);
    EXPECT_GT(LM::refine_particles(ps, cube(), field, CGAL::parameters::edge_length(l).lattice(lattice)), 0u);
    const Lattice_block fine = lattice_block(lattice, 8, 2.);   // central: 2l inside
    std::size_t expected = 0, found_once = 0, particles_deep = 0;
    for(std::size_t i = 0; i < fine.u.size(); ++i) {
      if(!fine.central[i]) continue;
      ++expected;
      const Point_3 q = point(fine.u[i], l);
      std::size_t near = 0;
      for(const Point_3& p : ps.points) near += CGAL::squared_distance(p, q) < CGAL::square(0.1 * l);
      found_once += near == 1;
    }
    for(const Point_3& p : ps.points)
      particles_deep += std::min({ p.x(), p.y(), p.z() }) > 0.1 + 2. * l - 1e-9 && std::max({ p.x(), p.y(), p.z() }) < 1.1 - 2. * l + 1e-9;
    EXPECT_GT(expected, 100u) << lattice.name;
    EXPECT_EQ(found_once, expected) << lattice.name;
    EXPECT_EQ(particles_deep, expected) << lattice.name;
  }
}

// Every stage is a function with named parameters, usable on its own.
TEST(Lattice_mesh_3, StagesAsNamedParameterFunctions)
{
  const Field field;
  CGAL::Lattice_particle_mesher_3<Traits, Domain, Field> mesher(cube(), field, CGAL::parameters::edge_length(0.25));
  // the mesher's start: the corners, and the lattice grown from them
  mesher.initialize_particles(0.25);
  EXPECT_EQ(mesher.particles().kinds[0], LM::Particle_kind::FIXED);
  EXPECT_NEAR(double(mesher.particles().size()), mesher.expected_vertices(0.25), 0.2 * mesher.expected_vertices(0.25));
  // the stages on their own, from the corners and a few particles at random
  LM::Particle_set_3<Point_3> ps;
  for(std::size_t c = 0; c < cube().corners().size(); ++c) ps.push_back(cube().corners()[c], LM::Particle_kind::FIXED, int(c));
  std::mt19937 g(3);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  for(int i = 0; i < 40; ++i) ps.push_back(Point_3(u(g), u(g), u(g)), LM::Particle_kind::FREE);
  const auto np = CGAL::parameters::edge_length(0.25).lattice(LM::Lattice_type::BCC).number_of_threads(2);
  LM::Particle_set_3<Point_3> grown;
  grown.push_back(Point_3(0.5, 0.5, 0.5), LM::Particle_kind::FREE);
  EXPECT_GT(LM::grow_particles(grown, cube(), field, np), 50u);
  const LM::Optimization_result r = LM::optimize_particles(ps, cube(), field, np.number_of_iterations(5));
  EXPECT_LE(r.iterations, 5);
  EXPECT_LT(r.energy, 0.);
  const std::size_t before = ps.size();
  const std::size_t deleted = LM::delete_particles(ps, cube(), field, np);
  const std::size_t inserted = LM::insert_particles(ps, cube(), field, np);
  EXPECT_EQ(ps.size(), before - deleted + inserted);
  EXPECT_GT(deleted + inserted, 0u);
  const auto mesh = LM::tetrahedralize_particles(ps, cube(), field, np);
  EXPECT_TRUE(LM::check_tetrahedral_mesh(mesh).valid());
  expect_error([&] { LM::optimize_particles(ps, cube(), field, CGAL::parameters::number_of_threads(2)); }, { "optimize_particles()", "edge_length" });
  LM::Tetrahedral_mesh_3<Point_3> copy = mesh;
  expect_error([&] { LM::flip_tetrahedra(copy, field, CGAL::parameters::maximum_ring_size(2)); }, { "flip_tetrahedra()", "maximum_ring_size" });
}


// The stage functions, called alone with their defaults and l*, chain into exactly what the
// mesher does: the same particles after the optimization, the same mesh after the improvement
// (a field turned against the cube's faces, so that every improvement stage has work).
TEST(Lattice_mesh_3, StagesCalledAloneDoWhatThePipelineDoes)
{
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1., 2., 3.).normalized()).toRotationMatrix();
  const Field field(turn);
  const double l = 1. / 6.;
  const auto np = CGAL::parameters::edge_length(l).lattice(LM::Lattice_type::BCC).number_of_threads(2);
  CGAL::Lattice_particle_mesher_3<Traits, Domain, Field> pipeline(cube(), field, np.coarse_levels(0));
  pipeline.optimize();

  // the optimization at one level (coarse_levels(0)): rounds of 13, then 8 iterations, with
  // deletion and insertion between them, until nothing changes or the energy no longer falls;
  // then a last deletion, insertion and deletion, and a closing round to the tight tolerance
  CGAL::Lattice_particle_mesher_3<Traits, Domain, Field> start(cube(), field, np);
  start.initialize_particles(l);
  LM::Particle_set_3<Point_3> ps = start.particles();
  LM::Optimization_result r = LM::optimize_particles(ps, cube(), field, np.number_of_iterations(13));
  auto insert = [&] {
    const std::size_t inserted = LM::insert_particles(ps, cube(), field, np);
    return inserted + LM::insert_feature_particles(ps, cube(), field, np);
  };
  for(int round = 1; round <= 16; ++round) {
    const std::size_t deleted = LM::delete_particles(ps, cube(), field, np);
    if(deleted + insert() == 0) break;
    const double previous = r.energy;
    r = LM::optimize_particles(ps, cube(), field, np.number_of_iterations(round < 5 ? 13 : 8));
    if(round >= 4 && r.energy > previous - 1e-4 * std::abs(previous)) break;
  }
  LM::delete_particles(ps, cube(), field, np);
  insert();
  LM::delete_particles(ps, cube(), field, np);
  LM::optimize_particles(ps, cube(), field, np.number_of_iterations(0).gradient_tolerance(3e-3));
  ASSERT_EQ(ps.points, pipeline.particles().points);
  ASSERT_EQ(ps.kinds, pipeline.particles().kinds);

  // the mesh: the tetrahedralization, flips and two rounds of smoothing (contractions before
  // the second), the worst tetrahedra alone, a round around the vertices that moved, contractions
  // on the boundary, and the peeling
  LM::Tetrahedral_mesh_3<Point_3> mesh = LM::tetrahedralize_particles(ps, cube(), field, np);
  LM::flip_tetrahedra(mesh, field, np);
  auto smooth_and_flip = [&](const auto& smoothing) {
    const std::size_t moves = LM::smooth_vertices(mesh, cube(), field, smoothing);
    if(moves > 0) LM::flip_tetrahedra(mesh, field);
    return moves;
  };
  for(int round = 0; round < 2; ++round) {
    if(round > 0) LM::collapse_edges(mesh, field);
    if(smooth_and_flip(np) == 0) break;
  }
  const std::vector<Point_3> before = mesh.points;
  smooth_and_flip(np.selection_angle(40.).worst_angle(41.).worst_weight(200.));
  std::vector<bool> moved(before.size());
  for(std::size_t v = 0; v < before.size(); ++v) moved[v] = before[v] != mesh.points[v];
  EXPECT_GT(std::count(moved.begin(), moved.end(), true), 0);
  smooth_and_flip(np.around_vertices(moved));
  LM::collapse_edges(mesh, field, CGAL::parameters::boundary_angle(20.));
  LM::peel_boundary_slivers(mesh, field);

  const LM::Tetrahedral_mesh_3<Point_3> expected = pipeline.tetrahedralize();
  EXPECT_GT(expected.tets.size(), 1000u);
  EXPECT_EQ(mesh.points, expected.points);
  EXPECT_EQ(mesh.tets, expected.tets);
  EXPECT_EQ(mesh.boundary_faces, expected.boundary_faces);
}

// A traits class whose orientation predicate counts its calls: the object given to geom_traits()
// is the one the tetrahedralization asks, and the mesh is the same as with the default traits.
struct Counting_traits : CGAL::Lattice_mesher_traits_3<K>
{
  struct Orientation_3
  {
    std::shared_ptr<std::size_t> calls;
    CGAL::Orientation operator()(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s) const
    {
      ++*calls;
      return K().orientation_3_object()(p, q, r, s);
    }
  };
  Orientation_3 orientation_3_object() const { return Orientation_3{ calls }; }
  std::shared_ptr<std::size_t> calls = std::make_shared<std::size_t>(0);
};

TEST(Lattice_mesh_3, GeomTraitsObjectIsTheOneUsed)
{
  const Field field;
  const auto np = CGAL::parameters::edge_length(0.2).number_of_threads(2);
  const LM::Tetrahedral_mesh_3<Point_3> plain = CGAL::lattice_mesh_3(cube(), field, np);
  const Counting_traits gt;
  const LM::Tetrahedral_mesh_3<Point_3> counted = CGAL::lattice_mesh_3(cube(), field, np.geom_traits(gt));
  EXPECT_GT(*gt.calls, plain.tets.size());
  EXPECT_EQ(counted.points, plain.points);
  EXPECT_EQ(counted.tets, plain.tets);
  const std::size_t calls = *gt.calls;
  CGAL::Lattice_particle_mesher_3<Counting_traits, Domain, Field> mesher(cube(), field, np.geom_traits(gt));
  mesher.optimize();
  EXPECT_EQ(mesher.geom_traits().calls, gt.calls);
  EXPECT_EQ(mesher.tetrahedralize().tets, plain.tets);
  EXPECT_GT(*gt.calls, calls);
}

// A visitor may stop the optimization: the mesh is then made of the particles as they are
// (here those of the first round, at the coarse level 2 l*).
TEST(Lattice_mesh_3, VisitorStopsTheOptimization)
{
  struct Stop_after_first
  {
    int rounds = 0;
    std::vector<std::string> stages;
    bool round_done(const LM::Round_report&) { return ++rounds < 1; }
    void stage_done(const char* stage, double) { stages.push_back(stage); }
  } visitor;
  const Field field;
  const LM::Tetrahedral_mesh_3<Point_3> mesh =
      CGAL::lattice_mesh_3(cube(), field, CGAL::parameters::edge_length(0.125).coarse_levels(1).visitor(std::ref(visitor)));
  EXPECT_EQ(visitor.rounds, 1);
  ASSERT_FALSE(visitor.stages.empty());
  EXPECT_EQ(visitor.stages.front(), "tetrahedralization");
  EXPECT_EQ(visitor.stages.back(), "labels");
  EXPECT_TRUE(LM::check_tetrahedral_mesh(mesh).valid());
  // stopped at the coarse level: about an eighth of the vertices
  const std::size_t full = CGAL::lattice_mesh_3(cube(), field, CGAL::parameters::edge_length(0.125).coarse_levels(1)).points.size();
  EXPECT_LT(mesh.points.size(), full / 3);
}

// Stage_times_visitor adds up each stage once: the insertions, the L-BFGS iterations of each
// level, the deletions, then the stages of the mesh improvement, none negative and together no
// longer than the call.
TEST(Lattice_mesh_3, StageTimesAddUpTheRun)
{
  LM::Stage_times_visitor times;
  const auto start = std::chrono::steady_clock::now();
  const LM::Tetrahedral_mesh_3<Point_3> mesh =
      CGAL::lattice_mesh_3(cube(), Field(), CGAL::parameters::edge_length(0.125).coarse_levels(1).visitor(std::ref(times)));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(LM::check_tetrahedral_mesh(mesh).valid());
  std::vector<std::string> names;
  for(const auto& s : times.stages()) {
    names.push_back(s.first);
    EXPECT_GE(s.second, 0.) << s.first;
  }
  const std::vector<std::string> expected = { "insertion", "optimization, level 1", "deletion", "optimization, level 0",
                                              "tetrahedralization", "flips", "smoothing", "contractions", "peeling", "labels" };
  EXPECT_EQ(names, expected);
  EXPECT_GT(times.total(), 0.);
  EXPECT_LE(times.total(), wall);
  times.add("output", 1.5);
  times.add("output", 1.);
  EXPECT_EQ(times.stages().back(), std::make_pair(std::string("output"), 2.5));
}

// The mesh carries the domain's labels: the cube's six faces are six surface patches, each
// boundary face in the patch of the side it lies on; one subdomain. Medit keeps them.
TEST(Lattice_mesh_3, BoundaryFacesCarryTheSurfacePatches)
{
  EXPECT_EQ(cube().number_of_surface_patches(), 6);
  const LM::Tetrahedral_mesh_3<Point_3> mesh = CGAL::lattice_mesh_3(cube(), Field(), CGAL::parameters::edge_length(0.2));
  ASSERT_EQ(mesh.subdomains, std::vector<int>(mesh.tets.size(), 1));
  ASSERT_EQ(mesh.boundary_patches.size(), mesh.boundary_faces.size());
  std::map<int, std::set<std::pair<int, double> > > sides;   // patch -> (axis, coordinate) of its faces
  for(std::size_t k = 0; k < mesh.boundary_faces.size(); ++k) {
    const std::array<int, 3>& f = mesh.boundary_faces[k];
    for(int axis = 0; axis < 3; ++axis) {
      const double c = mesh.points[f[0]][axis];
      if(mesh.points[f[1]][axis] == c && mesh.points[f[2]][axis] == c) sides[mesh.boundary_patches[k]].insert({ axis, c });
    }
  }
  EXPECT_EQ(sides.size(), 6u);
  for(const auto& s : sides) EXPECT_EQ(s.second.size(), 1u) << "patch " << s.first << " spans several sides";
  std::stringstream file;
  LM::write_medit(file, mesh);
  LM::Tetrahedral_mesh_3<Point_3> back;
  LM::read_medit(file, back);
  EXPECT_EQ(back.boundary_patches, mesh.boundary_patches);
  EXPECT_EQ(back.subdomains, mesh.subdomains);
}

TEST(Lattice_mesh_3, ClearErrors)
{
  const Field field;
  expect_error([&] { CGAL::lattice_mesh_3(cube(), field, CGAL::parameters::edge_length(0.)); }, { "edge_length" });
  expect_error([&] { CGAL::lattice_mesh_3(cube(), field, CGAL::parameters::edge_length(-0.1)); }, { "edge_length" });
  expect_error([&] { CGAL::lattice_mesh_3(cube(), field, CGAL::parameters::edge_length(1e-5)); }, { "larger edge length" });
  // counts and tolerances out of range: an error, not the defaults or an endless round
  const auto l = CGAL::parameters::edge_length(0.2);
  expect_error([&] { CGAL::lattice_mesh_3(cube(), field, l.max_rounds(-2)); }, { "max_rounds" });
  expect_error([&] { CGAL::lattice_mesh_3(cube(), field, l.number_of_smoothing_rounds(-1)); }, { "smoothing_rounds" });
  expect_error([&] { CGAL::lattice_mesh_3(cube(), field, l.neighbor_radius_ratio(0.)); }, { "neighbor_radius" });
  expect_error([&] { CGAL::lattice_mesh_3(cube(), field, l.gradient_tolerance(-1e-2)); }, { "gradient tolerances" });
  expect_error([&] { CGAL::lattice_mesh_3(cube(), field, l.sigma_ratio(std::nan(""))); }, { "sigma_ratio" });

  Traits::Matrix_3 singular;
  singular << 1, 0, 0, 0, 1, 0, 1, 1, 0;
  const Field bad(singular);
  expect_error([&] { CGAL::lattice_mesh_3(cube(), bad, CGAL::parameters::edge_length(0.2)); }, { "singular" });

  const std::string dir = ::testing::TempDir();
  const std::string empty = dir + "/lattice_mesher_empty.off";
  { std::ofstream os(empty); }
  expect_error([&] { LM::read_polyhedral_lattice_domain_3<K>(empty); }, { "empty" });
  const std::string open = dir + "/lattice_mesher_open.off";
  { std::ofstream os(open); os << "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n"; }
  expect_error([&] { LM::read_polyhedral_lattice_domain_3<K>(open); }, { "border edges" });
}

// The command-line program: a run that writes every output, and a clear error for bad input.
TEST(Lattice_mesh_program, WritesOutputsAndRejectsBadInput)
{
  const std::string dir = ::testing::TempDir();
  const std::string exe = LATTICE_MESH_EXECUTABLE;
  const std::string out = dir + "/lm_cube.mesh", json = dir + "/lm_cube.json", vtu = dir + "/lm_cube.vtu";
  ASSERT_EQ(std::system((exe + " --domain cube --edge-length 0.25 --quiet -o " + out + " --stats " + json +
                         " -o " + vtu + " > " + dir + "/lm_log.txt").c_str()), 0);
  std::ifstream vs(vtu);
  const std::string vtu_text((std::istreambuf_iterator<char>(vs)), std::istreambuf_iterator<char>());
  for(const char* array : { "\"theta_min\"", "\"rho\"", "\"kappa\"", "\"particle_kind\"" })
    EXPECT_NE(vtu_text.find(array), std::string::npos) << array;
  std::ifstream js(json);
  const std::string text((std::istreambuf_iterator<char>(js)), std::istreambuf_iterator<char>());
  for(const char* key : { "\"vertices\"", "\"tets\"", "\"theta_min\"", "\"below40\"", "\"hausdorff\"", "\"seconds\"" })
    EXPECT_NE(text.find(key), std::string::npos) << key;
  LM::Tetrahedral_mesh_3<Point_3> mesh;
  std::ifstream ms(out);
  LM::read_medit(ms, mesh);
  EXPECT_TRUE(LM::check_tetrahedral_mesh(mesh).valid());

  // Two processes (different heap layouts) write the same file: nothing depends on addresses.
  // elephant's thin parts exercise the boundary repair of the tetrahedralization.
  const std::string elephant = std::string(LATTICE_MESHER_3_DATA_DIR) + "/meshes/elephant.off";
  auto run_elephant = [&](const std::string& name) {
    EXPECT_EQ(std::system((exe + " " + elephant + " --vertices 2500 --threads 2 --quiet -o " + dir + name + " > " +
                           dir + "/lm_log.txt").c_str()), 0);
    std::ifstream is(dir + name);
    return std::string((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
  };
  const std::string first = run_elephant("/lm_e1.mesh");
  EXPECT_FALSE(first.empty());
  EXPECT_EQ(first, run_elephant("/lm_e2.mesh"));

  auto error_of = [&](const std::string& args) {
    EXPECT_NE(std::system((exe + " " + args + " -o " + out + " 2> " + dir + "/lm_err.txt").c_str()), 0) << args;
    std::ifstream es(dir + "/lm_err.txt");
    return std::string((std::istreambuf_iterator<char>(es)), std::istreambuf_iterator<char>());
  };
  std::string err = error_of("/nonexistent/file.off --vertices 100");
  EXPECT_NE(err.find("cannot open"), std::string::npos) << err;
  err = error_of("--domain cube --edge-length -1");
  EXPECT_NE(err.find("edge-length"), std::string::npos) << err;
  // messages name the option as the user gave it
  err = error_of("--domain cube --vertices 0");
  EXPECT_NE(err.find("--vertices must be at least 4, got 0"), std::string::npos) << err;
  err = error_of("--domain cube --vertices 100 --field /nonexistent/field.txt");
  EXPECT_NE(err.find("--field /nonexistent/field.txt: the field file does not exist"), std::string::npos) << err;
  err = error_of("--domain cube --vertices 100 --field spiral");
  EXPECT_NE(err.find("--field spiral: unknown field"), std::string::npos) << err;
  // outputs are checked before the work: an unknown format, a path that cannot be written
  err = error_of("--domain cube --edge-length 0.25 -o " + dir + "/lm_cube.stl");
  EXPECT_NE(err.find("unknown format '.stl'"), std::string::npos) << err;
  err = error_of("--domain cube --edge-length 0.25 -o /nonexistent/dir/lm.vtu");
  EXPECT_NE(err.find("cannot write '/nonexistent/dir/lm.vtu'"), std::string::npos) << err;
  // counts and seeds are whole numbers in range: 1.5 threads or seed -5 is refused, not rounded or wrapped
  for(const char* bad : { "--threads 1.5", "--threads 0", "--seed -5", "--max-rounds -2", "--smoothing-rounds -1" }) {
    err = error_of(std::string("--domain cube --edge-length 0.25 ") + bad);
    EXPECT_NE(err.find(std::string(bad).substr(0, std::string(bad).find(' '))), std::string::npos) << err;
    EXPECT_NE(err.find("whole number"), std::string::npos) << err;
  }
}

// A self-intersecting surface (elk: seven pairs of faces cross) meshes, with a warning that
// counts them, into a valid mesh.
// Sizes from files: 'x y z h' lines, and a Medit mesh with a .sol of one scalar a vertex (MMG's
// isotropic size map), read back exactly; bad files give errors that name the file and the
// problem; and lattice-mesh --size-field grades the mesh as the size_field named parameter does.
TEST(Lattice_mesh_program, SizeFieldFromFiles)
{
  const std::string dir = ::testing::TempDir();
  auto h = [](const Point_3& p) { return .06 + .25 * (p.x() - .1); };
  const std::string text = dir + "/lm_sizes.txt";
  std::vector<Point_3> grid;
  for(int i = 0; i <= 10; ++i) for(int j = 0; j <= 10; ++j) for(int k = 0; k <= 10; ++k)
    grid.emplace_back(.1 + .1 * i, .1 + .1 * j, .1 + .1 * k);
  {
    std::ofstream os(text);
    os.precision(17);
    os << "# x y z h\n";
    for(const Point_3& p : grid) os << p << " " << h(p) << "\n";
  }
  const auto samples = LM::read_size_samples<K>(text);
  ASSERT_EQ(samples.size(), grid.size());
  for(std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_EQ(samples[i].first, grid[i]);
    EXPECT_EQ(samples[i].second, h(grid[i]));
  }
  // a Medit mesh (a tetrahedron) with its sizes
  LM::Tetrahedral_mesh_3<Point_3> tet;
  tet.points = { Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0, 0, 1) };
  tet.tets = { { 0, 1, 2, 3 } };
  const std::string mesh = dir + "/lm_sizes.mesh", sol = dir + "/lm_sizes.sol";
  { std::ofstream os(mesh); LM::write_medit(os, tet); }
  auto write_sol = [&](const std::string& body) { std::ofstream os(sol); os << "MeshVersionFormatted 2\nDimension 3\n" << body << "End\n"; };
  write_sol("SolAtVertices\n4\n1 1\n0.5\n0.25\n0.125\n1e-3\n");
  const auto medit = LM::read_size_samples<K>(mesh);
  ASSERT_EQ(medit.size(), 4u);
  EXPECT_EQ(medit[1].first, Point_3(1, 0, 0));
  EXPECT_EQ(medit[3].second, 1e-3);
  write_sol("SolAtVertices\n4\n1 3\n1 0 1 0 0 1\n1 0 1 0 0 1\n1 0 1 0 0 1\n1 0 1 0 0 1\n");
  expect_error([&] { LM::read_size_samples<K>(mesh); }, { "lm_sizes.sol", "is not a size" });
  write_sol("SolAtVertices\n4\n1 1\n0.5\n-0.25\n0.125\n1\n");
  expect_error([&] { LM::read_size_samples<K>(mesh); }, { "lm_sizes.sol", "vertex 2", "not positive" });
  write_sol("SolAtVertices\n3\n1 1\n0.5\n0.25\n0.125\n");
  expect_error([&] { LM::read_size_samples<K>(mesh); }, { "3 entries", "4 vertices" });
  const std::string bad = dir + "/lm_sizes_bad.txt";
  { std::ofstream os(bad); os << "0 0 0 0.1\n0 0 1\n"; }
  expect_error([&] { LM::read_size_samples<K>(bad); }, { "lm_sizes_bad.txt", "line 2", "expected 4 numbers" });
  { std::ofstream os(bad); os << "0 0 0 0\n"; }
  expect_error([&] { LM::read_size_samples<K>(bad); }, { "line 1", "not positive" });

  // the program: the vertices crowd where the file's sizes are small, as with size_field
  const std::string exe = LATTICE_MESH_EXECUTABLE, out = dir + "/lm_sized.mesh";
  ASSERT_EQ(std::system((exe + " --domain cube --edge-length 0.25 --size-field " + text + " --quiet -o " + out +
                         " > " + dir + "/lm_sized_log.txt").c_str()), 0);
  LM::Tetrahedral_mesh_3<Point_3> sized;
  std::ifstream ms(out);
  LM::read_medit(ms, sized);
  EXPECT_TRUE(LM::check_tetrahedral_mesh(sized).valid());
  std::size_t left = 0;
  for(const Point_3& p : sized.points) left += p.x() < .6;
  const double right = double(sized.points.size() - left);
  EXPECT_GT(double(left), 6. * right) << left << " left, " << right << " right";
  EXPECT_LT(double(left), 16. * right) << left << " left, " << right << " right";
  EXPECT_NE(std::system((exe + " --domain cube --edge-length 0.25 --size-field " + bad + " --quiet -o " + out +
                         " 2> " + dir + "/lm_sized_err.txt").c_str()), 0);
  std::ifstream es(dir + "/lm_sized_err.txt");
  const std::string err((std::istreambuf_iterator<char>(es)), std::istreambuf_iterator<char>());
  EXPECT_NE(err.find("not positive"), std::string::npos) << err;
}

TEST(Lattice_mesh_program, SelfIntersectingSurfaceMeshesWithAWarning)
{
  const std::string dir = ::testing::TempDir();
  const std::string exe = LATTICE_MESH_EXECUTABLE;
  const std::string elk = std::string(LATTICE_MESHER_3_DATA_DIR) + "/meshes/elk.off";
  const std::string out = dir + "/lm_elk.mesh", err = dir + "/lm_elk_err.txt";
  EXPECT_EQ(std::system((exe + " " + elk + " --vertices 3000 --quiet -o " + out + " 2> " + err).c_str()), 0);
  std::ifstream es(err);
  const std::string text((std::istreambuf_iterator<char>(es)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("warning"), std::string::npos) << text;
  EXPECT_NE(text.find("self-intersects (7 pairs of faces)"), std::string::npos) << text;
  LM::Tetrahedral_mesh_3<Point_3> mesh;
  std::ifstream ms(out);
  LM::read_medit(ms, mesh);
  const LM::Mesh_validity_report r = LM::check_tetrahedral_mesh(mesh);
  EXPECT_TRUE(r.valid()) << r.message;
  EXPECT_GT(mesh.points.size(), 2000u);
}

} // namespace
