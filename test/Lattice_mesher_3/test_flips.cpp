// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh improvement: flips, worst-element smoothing, edge contractions and sliver peeling keep the mesh valid, keep the boundary,
// and never lower the smallest dihedral angle.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lattice_mesher_3/Implicit_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/check_mesh.h>
#include <CGAL/Lattice_mesher_3/collapse_edges.h>
#include <CGAL/Lattice_mesher_3/flip_tetrahedra.h>
#include <CGAL/Lattice_mesher_3/peel_slivers.h>
#include <CGAL/Lattice_mesher_3/smooth_vertices.h>
#include <CGAL/Lattice_mesher_3/tetrahedralize_particles.h>
#include <CGAL/Lattice_mesher_traits_3.h>

#include <gtest/gtest.h>

#include "test_meshes.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <set>

namespace {

namespace LM = CGAL::Lattice_mesher_3;
typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Lattice_mesher_traits_3<K> Traits;

using test_meshes::unit_cube;
using test_meshes::jittered_mesh;

double worst_angle(const LM::Tetrahedral_mesh_3<Point_3>& mesh, const LM::Constant_frame_field_3<Traits>& field)
{
  double worst = 180.;
  for(const auto& q : LM::compute_tetrahedra_quality(mesh, field)) worst = (std::min)(worst, q.theta_min);
  return worst;
}

using test_meshes::sorted_faces;

// The boundary of `after` is the surface of the unit cube as that of `before` is: the same
// boundary vertices, every face in one facet plane, the facets' areas summing to 1 each. Only its
// triangulation may differ, by 2-2 flips of boundary edges between two faces in one plane.
void expect_same_cube_surface(const LM::Tetrahedral_mesh_3<Point_3>& before, const LM::Tetrahedral_mesh_3<Point_3>& after)
{
  auto vertices = [](const LM::Tetrahedral_mesh_3<Point_3>& m) {
    std::set<int> v;
    for(const auto& f : m.boundary_faces) v.insert(f.begin(), f.end());
    return v;
  };
  EXPECT_EQ(vertices(after), vertices(before));
  std::array<double, 6> area{};   // facets x = 0, x = 1, y = 0, ...
  for(const auto& f : after.boundary_faces) {
    int facet = -1;
    for(int a = 0; a < 3 && facet < 0; ++a)
      for(int side = 0; side < 2 && facet < 0; ++side)
        if(std::all_of(f.begin(), f.end(), [&](int v) { return after.points[v][a] == double(side); })) facet = 2 * a + side;
    ASSERT_GE(facet, 0) << "a boundary face off the cube's facets";
    area[facet] += std::sqrt(CGAL::to_double(CGAL::squared_area(after.points[f[0]], after.points[f[1]], after.points[f[2]])));
  }
  for(double a : area) EXPECT_NEAR(a, 1., 1e-12);
}

TEST(Flip_tetrahedra, ValidBoundaryKeptWorstAngleNotLowered)
{
  for(unsigned int seed : { 1u, 2u, 3u }) {
    LM::Tetrahedral_mesh_3<Point_3> mesh = jittered_mesh(seed);
    ASSERT_TRUE(LM::check_tetrahedral_mesh(mesh).valid());
    // an anisotropic field too: flips are judged in its isotropic space
    Traits::Matrix_3 t;
    t << 1.5, 0.2, 0., 0., 1., 0., 0., 0.1, 0.7;
    for(const LM::Constant_frame_field_3<Traits>& field : { LM::Constant_frame_field_3<Traits>(), LM::Constant_frame_field_3<Traits>(t) }) {
      LM::Tetrahedral_mesh_3<Point_3> m = mesh;
      const double before = worst_angle(m, field);
      const std::size_t tets_before = m.tets.size();
      const LM::Flip_result r = LM::flip_tetrahedra(m, field);
      EXPECT_GT(r.total(), 0u);
      EXPECT_GE(worst_angle(m, field), before);
      const LM::Mesh_validity_report v = LM::check_tetrahedral_mesh(m);
      EXPECT_TRUE(v.valid()) << v.message;
      expect_same_cube_surface(mesh, m);
      if(r.boundary_flips == 0) EXPECT_EQ(sorted_faces(m), sorted_faces(mesh));
      // a 2-3 flip adds a tetrahedron and a 3-2 flip removes one; larger edge removals
      // (n tetrahedra into 2n - 4) and boundary flips (n into 2n - 2) only add
      EXPECT_GE(m.tets.size() + r.flips32, tets_before + r.flips23);
    }
  }
}

// around_vertices(): after a flipping, with some vertices moved since, flipping around them
// does what flipping the whole mesh does; with no vertex flagged, nothing.
TEST(Flip_tetrahedra, AroundMovedVerticesAsOverTheWholeMesh)
{
  const LM::Constant_frame_field_3<Traits> field;
  for(unsigned int seed : { 1u, 2u, 3u }) {
    LM::Tetrahedral_mesh_3<Point_3> mesh = jittered_mesh(seed);
    LM::flip_tetrahedra(mesh, field);
    LM::Tetrahedral_mesh_3<Point_3> same = mesh;
    EXPECT_EQ(LM::flip_tetrahedra(same, field, CGAL::parameters::around_vertices(std::vector<bool>(mesh.points.size(), false))).total(), 0u);
    EXPECT_EQ(same.tets, mesh.tets);
    // the smoothing moves vertices of the worst tetrahedra; then both flip
    const LM::Tetrahedral_mesh_3<Point_3> flipped = mesh;
    ASSERT_GT(LM::smooth_vertices(mesh, unit_cube(), field, CGAL::parameters::number_of_passes(1)), 0u);
    std::vector<bool> moved(mesh.points.size());
    for(std::size_t v = 0; v < moved.size(); ++v) moved[v] = mesh.points[v] != flipped.points[v];
    LM::Tetrahedral_mesh_3<Point_3> around = mesh;
    const LM::Flip_result whole = LM::flip_tetrahedra(mesh, field);
    EXPECT_GT(whole.total(), 0u) << "seed " << seed << ": nothing to flip after the moves";
    EXPECT_EQ(LM::flip_tetrahedra(around, field, CGAL::parameters::around_vertices(moved)).total(), whole.total());
    EXPECT_EQ(around.tets, mesh.tets) << "seed " << seed;
  }
  LM::Tetrahedral_mesh_3<Point_3> mesh = jittered_mesh(1);
  EXPECT_THROW(LM::flip_tetrahedra(mesh, field, CGAL::parameters::around_vertices(std::vector<bool>(3, true))), std::invalid_argument);
}

// Threads look at batches of candidates at once and the flips are made in order, looking again
// where an earlier flip of the batch changed a tetrahedron around: the flips of one thread.
TEST(Flip_tetrahedra, TheSameFlipsOnAnyNumberOfThreads)
{
  const LM::Constant_frame_field_3<Traits> field;
  for(unsigned int seed : { 1u, 2u }) {
    const LM::Tetrahedral_mesh_3<Point_3> mesh = jittered_mesh(seed, 10);
    for(double l : { 0., .1 }) {   // the angle alone; the lattice's shapes first
      LM::Tetrahedral_mesh_3<Point_3> one = mesh;
      const LM::Flip_result r1 = LM::flip_tetrahedra(one, field, CGAL::parameters::edge_length(l).number_of_threads(1));
      ASSERT_GT(r1.total(), 100u) << "seed " << seed;
      for(int threads : { 2, 3 }) {
        LM::Tetrahedral_mesh_3<Point_3> many = mesh;
        const LM::Flip_result r = LM::flip_tetrahedra(many, field, CGAL::parameters::edge_length(l).number_of_threads(threads));
        EXPECT_EQ(many.tets, one.tets) << "seed " << seed << ", " << threads << " threads";
        EXPECT_EQ(many.boundary_faces, one.boundary_faces);
        EXPECT_EQ(r.flips23, r1.flips23);
        EXPECT_EQ(r.flips32, r1.flips32);
        EXPECT_EQ(r.edge_removals, r1.edge_removals);
      }
    }
  }
  LM::Tetrahedral_mesh_3<Point_3> mesh = jittered_mesh(1);
  EXPECT_THROW(LM::flip_tetrahedra(mesh, field, CGAL::parameters::number_of_threads(0)), std::invalid_argument);
}

// what the smoothing lowers: the squared shortfall of the smallest angles below the target
double shortfall(const LM::Tetrahedral_mesh_3<Point_3>& mesh, const LM::Constant_frame_field_3<Traits>& field,
                 double target)
{
  double s = 0.;
  for(const auto& q : LM::compute_tetrahedra_quality(mesh, field)) s += CGAL::square((std::max)(0., target - q.theta_min));
  return s;
}

std::size_t count_below(const LM::Tetrahedral_mesh_3<Point_3>& mesh, const LM::Constant_frame_field_3<Traits>& field, double angle)
{
  std::size_t n = 0;
  for(const auto& q : LM::compute_tetrahedra_quality(mesh, field)) n += q.theta_min < angle;
  return n;
}

TEST(Smooth_vertices, LowersTheShortfallRaisesTheWorstAngleAndKeepsVerticesOnTheirConstraints)
{
  const LM::Constant_frame_field_3<Traits> field;
  LM::Tetrahedral_mesh_3<Point_3> mesh = jittered_mesh(5);
  const LM::Tetrahedral_mesh_3<Point_3> original = mesh;
  const double before = worst_angle(mesh, field);
  const double target = 70.;   // smooth_vertices()' default target_angle
  const double shortfall_before = shortfall(mesh, field, target);
  EXPECT_GT(LM::smooth_vertices(mesh, unit_cube(), field, CGAL::parameters::number_of_threads(2)), 0u);
  EXPECT_GT(worst_angle(mesh, field), before);
  EXPECT_LT(shortfall(mesh, field, target), 0.9 * shortfall_before);
  const LM::Mesh_validity_report v = LM::check_tetrahedral_mesh(mesh);
  EXPECT_TRUE(v.valid()) << v.message;
  // every kind but the corners is searched (boundary vertices in their tangent plane, sharp ones
  // along their curve)
  std::size_t moved[4] = { 0, 0, 0, 0 };
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
    if(mesh.points[i] != original.points[i]) ++moved[int(mesh.vertex_kinds[i])];
  EXPECT_GT(moved[int(LM::Particle_kind::FREE)], 0u);
  EXPECT_GT(moved[int(LM::Particle_kind::BOUNDARY)], 0u);
  EXPECT_GT(moved[int(LM::Particle_kind::SHARP_EDGE)], 0u);
  for(std::size_t i = 0; i < mesh.points.size(); ++i) {
    const double d = unit_cube().project_on_surface(mesh.points[i]).squared_distance;
    switch(mesh.vertex_kinds[i]) {
      case LM::Particle_kind::FIXED: EXPECT_EQ(mesh.points[i], original.points[i]); break;
      case LM::Particle_kind::SHARP_EDGE: EXPECT_LT(unit_cube().project_on_features(mesh.points[i]).squared_distance, 1e-20); break;
      case LM::Particle_kind::BOUNDARY: EXPECT_LT(d, 1e-20); break;
      case LM::Particle_kind::FREE: EXPECT_TRUE(unit_cube().is_inside(mesh.points[i])); break;
    }
  }
  // the same result with one thread
  LM::Tetrahedral_mesh_3<Point_3> single = original;
  LM::smooth_vertices(single, unit_cube(), field, CGAL::parameters::number_of_threads(1));
  EXPECT_EQ(single.points, mesh.points);
}

// No move takes a tetrahedron of its star below the floor where the star has none below half the
// floor, and the stars moved together are disjoint: then the count below the floor never grows.
TEST(Smooth_vertices, TakesNoTetrahedronBelowTheFloor)
{
  const LM::Constant_frame_field_3<Traits> field;
  for(unsigned int seed : { 5u, 6u, 7u }) {
    LM::Tetrahedral_mesh_3<Point_3> mesh = jittered_mesh(seed);
    const double floor = (std::min)(40., 1.99 * worst_angle(mesh, field));
    const std::size_t below = count_below(mesh, field, floor);
    EXPECT_GT(LM::smooth_vertices(mesh, unit_cube(), field, CGAL::parameters::floor_angle(floor).number_of_threads(2)), 0u);
    EXPECT_LE(count_below(mesh, field, floor), below) << "seed " << seed << ", floor " << floor;
  }
}

// around_vertices(): the first pass searches only the stars that share a tetrahedron with a
// flagged vertex; with one pass, nothing else moves, and with no flag set, nothing at all.
TEST(Smooth_vertices, SearchesOnlyAroundTheFlaggedVertices)
{
  const LM::Constant_frame_field_3<Traits> field;
  const LM::Tetrahedral_mesh_3<Point_3> original = jittered_mesh(5);
  std::vector<bool> flags(original.points.size(), false);
  LM::Tetrahedral_mesh_3<Point_3> mesh = original;
  EXPECT_EQ(LM::smooth_vertices(mesh, unit_cube(), field, CGAL::parameters::around_vertices(flags)), 0u);
  EXPECT_EQ(mesh.points, original.points);
  // the vertices of the worst tetrahedron
  const std::vector<LM::Tetrahedron_quality_3> q = LM::compute_tetrahedra_quality(original, field);
  const std::size_t worst = std::size_t(std::min_element(q.begin(), q.end(), [](const auto& a, const auto& b) { return a.theta_min < b.theta_min; }) - q.begin());
  std::set<int> near;
  for(int v : original.tets[worst]) {
    flags[std::size_t(v)] = true;
    for(const auto& t : original.tets)
      if(std::find(t.begin(), t.end(), v) != t.end()) near.insert(t.begin(), t.end());
  }
  EXPECT_GT(LM::smooth_vertices(mesh, unit_cube(), field, CGAL::parameters::around_vertices(flags).number_of_passes(1)), 0u);
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    if(mesh.points[v] != original.points[v]) EXPECT_TRUE(near.count(int(v))) << "vertex " << v << " moved";
  EXPECT_THROW(LM::smooth_vertices(mesh, unit_cube(), field, CGAL::parameters::around_vertices(std::vector<bool>(3, true))), std::invalid_argument);
}

// The BCC lattice on the unit cube, l* = 1 / n: grid points (corners fixed, edges and faces on
// the surface) and cube centres.
LM::Particle_set_3<Point_3> bcc_cube_particles(int n)
{
  LM::Particle_set_3<Point_3> ps;
  for(int i = 0; i <= n; ++i) for(int j = 0; j <= n; ++j) for(int k = 0; k <= n; ++k) {
    const int on = (i == 0 || i == n) + (j == 0 || j == n) + (k == 0 || k == n);
    ps.push_back(Point_3(double(i) / n, double(j) / n, double(k) / n), test_meshes::box_particle_kind(on));
    if(i < n && j < n && k < n) ps.push_back(Point_3((i + .5) / n, (j + .5) / n, (k + .5) / n), LM::Particle_kind::FREE);
  }
  return ps;
}

// A BCC lattice filling the unit cube (l* = 1/4): besides the lattice's own tetrahedra (60
// degrees), the walls leave half pyramids of 45 degrees, the best there are. The smoothing moves
// them only when it is not told the lattice (their apex leaves its lattice position).
TEST(Smooth_vertices, LeavesLatticeTetrahedraAlone)
{
  const LM::Constant_frame_field_3<Traits> field;
  const int n = 4;
  const LM::Particle_set_3<Point_3> ps = bcc_cube_particles(n);
  const LM::Tetrahedral_mesh_3<Point_3> lattice = LM::tetrahedralize_particles(ps, unit_cube(), field);
  ASSERT_TRUE(LM::check_tetrahedral_mesh(lattice).valid());
  EXPECT_NEAR(worst_angle(lattice, field), 45., 1e-6);
  LM::Tetrahedral_mesh_3<Point_3> mesh = lattice;
  EXPECT_EQ(LM::smooth_vertices(mesh, unit_cube(), field, CGAL::parameters::edge_length(1. / n).lattice(LM::Lattice_type::BCC)), 0u);
  EXPECT_EQ(mesh.points, lattice.points);
  EXPECT_GT(LM::smooth_vertices(mesh, unit_cube(), field), 0u);   // no lattice
}

// A unit sphere of particles (l* = 1/4: surface particles a Fibonacci lattice, a BCC lattice
// at least 0.6 l* inside) without the surface particles of a cap 0.6 radians wide, and an
// interior particle half an edge under its pole: connected as they are, the boundary dips to the
// interior particles that poke through the cap's chord; the tetrahedralization adds surface
// particles above those more than l* / 4 deep, and no boundary vertex is left that deep.
TEST(Tetrahedralize_particles, FillsTheGapsOfTheSurfaceParticles)
{
  const LM::Constant_frame_field_3<Traits> field;
  const auto sphere = LM::make_sphere_domain_3<K>(CGAL::ORIGIN, 1.);
  const double l = .25;
  LM::Particle_set_3<Point_3> ps;
  const int n = 200;
  for(int i = 0; i < n; ++i) {
    const double z = 1. - (2. * i + 1.) / n, r = std::sqrt(1. - z * z), phi = i * CGAL_PI * (3. - std::sqrt(5.));
    if(z < std::cos(.6)) ps.push_back(Point_3(r * std::cos(phi), r * std::sin(phi), z), LM::Particle_kind::BOUNDARY);
  }
  for(int i = -4; i <= 4; ++i) for(int j = -4; j <= 4; ++j) for(int k = -4; k <= 4; ++k)
    for(double h : { 0., .5 }) {
      const Point_3 p((i + h) * l, (j + h) * l, (k + h) * l);
      if(std::sqrt(CGAL::squared_distance(p, Point_3(CGAL::ORIGIN))) < 1. - .6 * l) ps.push_back(p, LM::Particle_kind::FREE);
    }
  ps.push_back(Point_3(0., 0., 1. - .5 * l), LM::Particle_kind::FREE);
  auto deepest = [](const LM::Tetrahedral_mesh_3<Point_3>& mesh) {   // boundary vertex from the sphere
    double d = 0.;
    for(const auto& f : mesh.boundary_faces)
      for(int v : f) d = (std::max)(d, 1. - std::sqrt(CGAL::squared_distance(mesh.points[std::size_t(v)], Point_3(CGAL::ORIGIN))));
    return d;
  };
  LM::internal::Tetrahedralization_options o;
  o.edge_length = l;
  const LM::Tetrahedral_mesh_3<Point_3> pitted = LM::internal::connect_particles(ps, sphere, field, o, Traits());
  ASSERT_TRUE(LM::check_tetrahedral_mesh(pitted).valid());
  EXPECT_GT(deepest(pitted), .45 * l);
  const LM::Tetrahedral_mesh_3<Point_3> filled = LM::tetrahedralize_particles(ps, sphere, field, CGAL::parameters::edge_length(l));
  EXPECT_TRUE(LM::check_tetrahedral_mesh(filled).valid());
  EXPECT_GT(filled.points.size(), pitted.points.size());
  EXPECT_LT(deepest(filled), .25 * l);
  o.pit_depth = 0.;
  EXPECT_EQ(LM::internal::tetrahedralize_particles(ps, sphere, field, o, Traits()).tets, pitted.tets);
}

// The Delaunay triangulation that the tetrahedralization repairs: particle index per vertex,
// kept (1) or not (0) per cell.
typedef CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<
  CGAL::Triangulation_vertex_base_with_info_3<int, K>, CGAL::Triangulation_cell_base_with_info_3<char, K> > > Dt;

// The points of an n x n x n grid of spacing 1, each moved by up to 0.05 along each axis,
// numbered in the grid's order.
Dt jittered_grid(int n, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-.05, .05);
  std::vector<std::pair<Point_3, int> > points;
  for(int i = 0; i < n; ++i) for(int j = 0; j < n; ++j) for(int k = 0; k < n; ++k)
    points.emplace_back(Point_3(i + jitter(random), j + jitter(random), k + jitter(random)), int(points.size()));
  return Dt(points.begin(), points.end());
}

// Two boxes of a jittered grid's Delaunay cells that meet at one vertex: the boundary of the
// cells kept is pinched there. The repair leaves it manifold and puts back every cell it took
// whose return would not pinch it again, so that no cell is lost without need (a cell with an
// interior particle taken for nothing left that particle on the boundary, a pit).
TEST(Tetrahedralize_particles, RepairTakesOnlyTheCellsThatPinchTheBoundary)
{
  Dt dt = jittered_grid(4, 5);
  auto in_box = [](const Point_3& p, double lo) { return lo < p.x() && p.x() < lo + 1.5 && lo < p.y() && p.y() < lo + 1.5 && lo < p.z() && p.z() < lo + 1.5; };
  std::size_t kept = 0;
  for(auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    const Point_3 g = dt.is_infinite(c) ? Point_3(-1, -1, -1)
                                        : CGAL::centroid(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point());
    c->info() = in_box(g, 0.) || in_box(g, 1.5);
    kept += std::size_t(c->info());
  }
  ASSERT_FALSE(LM::internal::cells_around_non_manifold(dt, 1).empty());
  std::set<Dt::Cell_handle> wedges;
  LM::internal::make_boundary_manifold(dt, wedges, [](Dt::Cell_handle) { return true; }, 1);
  EXPECT_TRUE(LM::internal::cells_around_non_manifold(dt, 1).empty());
  std::size_t left = 0, could_return = 0;
  for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    left += std::size_t(c->info());
    const Point_3 g = CGAL::centroid(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point());
    if(c->info() || !(in_box(g, 0.) || in_box(g, 1.5))) continue;
    c->info() = 1;
    could_return += std::size_t(LM::internal::manifold_around(dt, Dt::Cell_handle(c)));
    c->info() = 0;
  }
  EXPECT_LT(left, kept);
  EXPECT_EQ(could_return, 0u);
}

// A jittered 5 x 5 x 5 grid's Delaunay cells, all kept but those around its centre particle, of
// which one stays: a cavity, whose boundary the centre is on. close_pits() puts the others back all
// at once where the callback accepts them, none where it refuses one, and none where another
// particle of theirs is interior too (their faces to it would go on the boundary untested).
TEST(Tetrahedralize_particles, ClosesAPitAtAnInteriorParticle)
{
  Dt dt = jittered_grid(5, 3);
  const int centre = 62;   // (2, 2, 2)
  std::size_t open = 0;
  for(auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    c->info() = !dt.is_infinite(c);
    bool at_centre = false;
    for(int i = 0; i < 4; ++i) at_centre = at_centre || (!dt.is_infinite(c->vertex(i)) && c->vertex(i)->info() == centre);
    if(at_centre && open++ > 0) c->info() = 0;
  }
  ASSERT_GT(open, 2u);
  ASSERT_TRUE(LM::internal::cells_around_non_manifold(dt, 1).empty());
  auto kept = [&] {
    std::size_t n = 0;
    for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) n += std::size_t(c->info());
    return n;
  };
  const std::size_t pitted = kept();
  ASSERT_EQ(pitted, dt.number_of_finite_cells() - open + 1);
  auto accept = [](Dt::Cell_handle) { return true; };
  LM::internal::close_pits(dt, [](Dt::Vertex_handle v) { return v->info() == centre; }, [](Dt::Cell_handle) { return false; });
  EXPECT_EQ(kept(), pitted);
  LM::internal::close_pits(dt, [](Dt::Vertex_handle v) { return v->info() == centre || v->info() == centre + 1; }, accept);
  EXPECT_EQ(kept(), pitted);
  LM::internal::close_pits(dt, [](Dt::Vertex_handle v) { return v->info() == centre; }, accept);
  EXPECT_EQ(kept(), dt.number_of_finite_cells());
}

// Single cells under the north pole of the unit sphere (l* = 0.2) that the manifold repair
// might put back, alone in the mesh: a regular one with a face on the sphere goes back, its other
// faces being to an interior particle; the same with that particle on the surface does not (its
// faces are l* / 3 deep), nor does a sliver whose faces all hug the sphere. Each is refused by
// its own test only: with a larger depth or no smallest angle it would go back.
TEST(Tetrahedralize_particles, PutsBackNoSliverAndNoFaceOffTheSurface)
{
  const LM::Constant_frame_field_3<Traits> field;
  const auto sphere = LM::make_sphere_domain_3<K>(CGAL::ORIGIN, 1.);
  const double l = .2;
  auto may_put_back = [&](const LM::Particle_set_3<Point_3>& ps, const LM::internal::Tetrahedralization_options& o) {
    std::vector<std::pair<Point_3, int> > points;
    for(std::size_t i = 0; i < ps.size(); ++i) points.emplace_back(ps.points[i], int(i));
    Dt dt(points.begin(), points.end());
    EXPECT_EQ(dt.number_of_finite_cells(), 1u);
    for(auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) c->info() = !dt.is_infinite(c);
    return LM::internal::may_put_back(Dt::Cell_handle(dt.finite_cells_begin()), ps, sphere, field, o);
  };
  LM::internal::Tetrahedralization_options o;
  o.edge_length = l;
  const double r = l / std::sqrt(3.), z = std::sqrt(1. - r * r);
  LM::Particle_set_3<Point_3> regular, deep, sliver;
  for(int k = 0; k < 3; ++k) {
    const Point_3 p(r * std::cos(2. * CGAL_PI * k / 3.), r * std::sin(2. * CGAL_PI * k / 3.), z);
    regular.push_back(p, LM::Particle_kind::BOUNDARY);
    deep.push_back(p, LM::Particle_kind::BOUNDARY);
  }
  regular.push_back(Point_3(0., 0., z - l * std::sqrt(2. / 3.)), LM::Particle_kind::FREE);
  deep.push_back(regular.points.back(), LM::Particle_kind::BOUNDARY);
  for(int k = 0; k < 4; ++k) {   // a square of side l on the sphere, one diagonal lowered by l / 10
    const double x = (k & 1 ? .5 : -.5) * l, y = (k & 2 ? .5 : -.5) * l;
    sliver.push_back(Point_3(x, y, std::sqrt(1. - x * x - y * y) - ((k == 1 || k == 2) ? .1 * l : 0.)), LM::Particle_kind::BOUNDARY);
  }
  EXPECT_TRUE(may_put_back(regular, o));
  EXPECT_FALSE(may_put_back(deep, o));
  EXPECT_FALSE(may_put_back(sliver, o));
  LM::internal::Tetrahedralization_options no_angle = o, no_depth = o;
  no_angle.wedge_angle = 0.;
  no_depth.pit_depth = 1.;
  EXPECT_TRUE(may_put_back(sliver, no_angle));
  EXPECT_TRUE(may_put_back(deep, no_depth));
}

// The boundary faces as triples of points (contractions renumber the vertices).
std::set<std::array<Point_3, 3> > boundary_triangles(const LM::Tetrahedral_mesh_3<Point_3>& mesh)
{
  std::set<std::array<Point_3, 3> > faces;
  for(const auto& f : mesh.boundary_faces) {
    std::array<Point_3, 3> t{ mesh.points[f[0]], mesh.points[f[1]], mesh.points[f[2]] };
    std::sort(t.begin(), t.end());
    faces.insert(t);
  }
  return faces;
}

// A BCC lattice on the unit cube (l* = 1/4) with one extra particle (of kind `kind`) near a
// lattice point.
LM::Tetrahedral_mesh_3<Point_3> bcc_cube_with_extra(const Point_3& extra, const LM::Constant_frame_field_3<Traits>& field,
                                                    LM::Particle_kind kind = LM::Particle_kind::FREE)
{
  LM::Particle_set_3<Point_3> ps = bcc_cube_particles(4);
  ps.push_back(extra, kind);
  return LM::tetrahedralize_particles(ps, unit_cube(), field);
}

// The extra particle a fifth of an edge from a cube centre makes the Delaunay tetrahedra around
// the pair slivers. Contracting their edge gives back a star of lattice quality; nothing else
// changes. A boundary particle that the tetrahedralization left inside (on no boundary face)
// goes the same way as a free one.
TEST(Collapse_edges, RemovesTheExtraVertexOfADefect)
{
  const LM::Constant_frame_field_3<Traits> field;
  for(LM::Particle_kind extra : { LM::Particle_kind::FREE, LM::Particle_kind::BOUNDARY }) {
    LM::Tetrahedral_mesh_3<Point_3> mesh = bcc_cube_with_extra(Point_3(.3875, .3825, .4), field, extra);
    ASSERT_TRUE(LM::check_tetrahedral_mesh(mesh).valid());
    const LM::Tetrahedral_mesh_3<Point_3> original = mesh;
    const double before = worst_angle(mesh, field);
    ASSERT_LT(before, 20.);
    EXPECT_EQ(LM::collapse_edges(mesh, field), 1u);
    EXPECT_EQ(mesh.points.size(), original.points.size() - 1);
    const double after = worst_angle(mesh, field);
    std::cout << "worst angle " << before << " -> " << after << " degrees\n";
    EXPECT_GE(after, 45. - 1e-9);   // the walls' half pyramids, the lattice mesh's own worst
    const LM::Mesh_validity_report v = LM::check_tetrahedral_mesh(mesh);
    EXPECT_TRUE(v.valid()) << v.message;
    EXPECT_EQ(boundary_triangles(mesh), boundary_triangles(original));
    // only the extra vertex goes; the others keep their kinds and their order
    for(LM::Particle_kind k : { LM::Particle_kind::FIXED, LM::Particle_kind::SHARP_EDGE, LM::Particle_kind::BOUNDARY, LM::Particle_kind::FREE })
      EXPECT_EQ(std::count(mesh.vertex_kinds.begin(), mesh.vertex_kinds.end(), k) + (k == extra),
                std::count(original.vertex_kinds.begin(), original.vertex_kinds.end(), k));
    // a lattice mesh has nothing to contract
    EXPECT_EQ(LM::collapse_edges(mesh, field), 0u);
  }
}

// A free particle on the boundary (as where a tetrahedralization exposes one) is a vertex of
// boundary faces: removing it would open the boundary, so it stays, however bad its tetrahedra.
TEST(Collapse_edges, KeepsAFreeParticleExposedOnTheBoundary)
{
  const LM::Constant_frame_field_3<Traits> field;
  const Point_3 extra(.2625, 0., .255);   // on the facet y = 0, near the lattice point (1/4, 0, 1/4)
  LM::Tetrahedral_mesh_3<Point_3> mesh = bcc_cube_with_extra(extra, field);
  ASSERT_TRUE(LM::check_tetrahedral_mesh(mesh).valid());
  const LM::Tetrahedral_mesh_3<Point_3> original = mesh;
  ASSERT_LT(worst_angle(mesh, field), 20.);
  LM::collapse_edges(mesh, field);
  EXPECT_NE(std::find(mesh.points.begin(), mesh.points.end(), extra), mesh.points.end());
  const LM::Mesh_validity_report v = LM::check_tetrahedral_mesh(mesh);
  EXPECT_TRUE(v.valid()) << v.message;
  EXPECT_EQ(boundary_triangles(mesh), boundary_triangles(original));
}

// With boundary contractions on, the same exposed particle is merged into a lattice vertex of
// its facet: its slivers go, the mesh stays valid, every boundary vertex stays on the cube's
// surface and the volume stays that of the cube (the facet is plane).
TEST(Collapse_edges, MergesAnExposedParticleIntoTheBoundaryWhenAsked)
{
  const LM::Constant_frame_field_3<Traits> field;
  const Point_3 extra(.2625, 0., .255);
  LM::Tetrahedral_mesh_3<Point_3> mesh = bcc_cube_with_extra(extra, field);
  const double before = worst_angle(mesh, field);
  EXPECT_GE(LM::collapse_edges(mesh, field, CGAL::parameters::boundary_angle(20.)), 1u);
  EXPECT_EQ(std::find(mesh.points.begin(), mesh.points.end(), extra), mesh.points.end());
  const LM::Mesh_validity_report v = LM::check_tetrahedral_mesh(mesh);
  ASSERT_TRUE(v.valid()) << v.message;
  const double after = worst_angle(mesh, field);
  std::cout << "worst angle " << before << " -> " << after << " degrees\n";
  EXPECT_GT(after, 20.);
  double volume = 0.;
  for(const std::array<int, 4>& t : mesh.tets)
    volume += CGAL::volume(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]);
  EXPECT_NEAR(volume, 1., 1e-12);
  for(const std::array<int, 3>& f : mesh.boundary_faces)
    for(int i : f) {
      const Point_3& p = mesh.points[i];
      const double d = (std::min)({ p.x(), p.y(), p.z(), 1. - p.x(), 1. - p.y(), 1. - p.z() });
      EXPECT_NEAR(d, 0., 1e-12);
    }
}

// On jittered meshes, in an anisotropic field too: the smallest angle never falls, the mesh
// stays valid and its boundary the same.
TEST(Collapse_edges, KeepsTheBoundaryAndNeverLowersTheWorstAngle)
{
  Traits::Matrix_3 t;
  t << 1.5, 0.2, 0., 0., 1., 0., 0., 0.1, 0.7;
  std::size_t total = 0;
  for(unsigned int seed : { 1u, 2u, 3u })
    for(const LM::Constant_frame_field_3<Traits>& field : { LM::Constant_frame_field_3<Traits>(), LM::Constant_frame_field_3<Traits>(t) }) {
      LM::Tetrahedral_mesh_3<Point_3> mesh = jittered_mesh(seed);
      const LM::Tetrahedral_mesh_3<Point_3> original = mesh;
      const double before = worst_angle(mesh, field);
      const std::size_t collapses = LM::collapse_edges(mesh, field);
      total += collapses;
      EXPECT_EQ(mesh.points.size(), original.points.size() - collapses);
      EXPECT_GE(worst_angle(mesh, field), before);
      const LM::Mesh_validity_report v = LM::check_tetrahedral_mesh(mesh);
      EXPECT_TRUE(v.valid()) << v.message;
      EXPECT_EQ(boundary_triangles(mesh), boundary_triangles(original));
    }
  EXPECT_GT(total, 0u);
}

} // namespace

namespace {

// A positive tetrahedron of `points` (its last two corners swapped if needed).
std::array<int, 4> positive(const std::vector<Point_3>& p, std::array<int, 4> t)
{
  if(CGAL::orientation(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) != CGAL::POSITIVE) std::swap(t[2], t[3]);
  return t;
}

// Two tetrahedra under the square p0 p1 p2 p3 (split along p0 p2), apex 4 below, and on top the
// tetrahedron of the square itself, whose corner p3 is raised by `lift`: a sliver lying on the
// two lower ones, with its two upper faces on the boundary.
LM::Tetrahedral_mesh_3<Point_3> capped_pyramid(double lift)
{
  LM::Tetrahedral_mesh_3<Point_3> m;
  m.points = { Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, lift), Point_3(.5, .5, -.7) };
  m.tets = { positive(m.points, { 0, 1, 2, 4 }), positive(m.points, { 0, 2, 3, 4 }), positive(m.points, { 0, 1, 2, 3 }) };
  m.boundary_faces = LM::internal::one_tet_faces(m.tets);
  return m;
}

} // namespace

// A flat sliver on the boundary goes (the boundary now the other diagonal of the square), the
// mesh stays valid and its unused vertices go too; a poor tetrahedron that is not flat stays.
TEST(Peel_boundary_slivers, RemovesFlatBoundarySliversOnly)
{
  const LM::Constant_frame_field_3<Traits> field;
  LM::Tetrahedral_mesh_3<Point_3> flat = capped_pyramid(.02);
  ASSERT_TRUE(LM::check_tetrahedral_mesh(flat).valid());
  ASSERT_LT(worst_angle(flat, field), 5.);
  EXPECT_EQ(LM::peel_boundary_slivers(flat, field), 1u);
  EXPECT_TRUE(LM::check_tetrahedral_mesh(flat).valid()) << LM::check_tetrahedral_mesh(flat).message;
  EXPECT_EQ(flat.tets.size(), 2u);
  EXPECT_GT(worst_angle(flat, field), 20.);

  // p3 raised by 0.25: the capping tetrahedron is poor (13.6 degrees), its height 0.2 of its mean
  // edge: it stays for flatness_ratio(0.1), and goes at the default 0.4
  LM::Tetrahedral_mesh_3<Point_3> tall = capped_pyramid(.25);
  ASSERT_LT(worst_angle(tall, field), 20.);
  EXPECT_EQ(LM::peel_boundary_slivers(tall, field, CGAL::parameters::flatness_ratio(.1)), 0u);
  EXPECT_EQ(tall.tets.size(), 3u);
  EXPECT_EQ(LM::peel_boundary_slivers(tall, field), 1u);
  EXPECT_TRUE(LM::check_tetrahedral_mesh(tall).valid()) << LM::check_tetrahedral_mesh(tall).message;
  EXPECT_EQ(tall.tets.size(), 2u);
  // p3 raised by 0.7: 29.8 degrees, above the peeling angle, and the tetrahedron stays
  LM::Tetrahedral_mesh_3<Point_3> good = capped_pyramid(.7);
  ASSERT_GT(worst_angle(good, field), 20.);
  EXPECT_EQ(LM::peel_boundary_slivers(good, field), 0u);

  // the sliver on one tetrahedron under half of it (three faces on the boundary): its removal
  // leaves p3 in no tetrahedron, and p3 goes
  LM::Tetrahedral_mesh_3<Point_3> half = capped_pyramid(.02);
  half.tets.erase(half.tets.begin() + 1);
  half.boundary_faces = LM::internal::one_tet_faces(half.tets);
  ASSERT_TRUE(LM::check_tetrahedral_mesh(half).valid());
  EXPECT_EQ(LM::peel_boundary_slivers(half, field), 1u);
  EXPECT_TRUE(LM::check_tetrahedral_mesh(half).valid()) << LM::check_tetrahedral_mesh(half).message;
  EXPECT_EQ(half.points.size(), 4u);
  EXPECT_EQ(half.tets.size(), 1u);
}

// A flat sliver T = (a, b, c, d) between two tetrahedra X and Y that meet it on its faces acd and
// bcd and share only the edge cd with each other: without T, cd would be in four boundary faces
// and c, d pinched. T stays; a sliver that may go, in a capped pyramid beside it, goes.
TEST(Peel_boundary_slivers, KeepsThoseWhoseRemovalWouldPinchTheBoundary)
{
  const LM::Constant_frame_field_3<Traits> field;
  LM::Tetrahedral_mesh_3<Point_3> mesh = capped_pyramid(.02);   // vertices 0-4
  for(Point_3& p : mesh.points) p = Point_3(p.x() + 5., p.y(), p.z());
  const int a = 5, b = 6, c = 7, d = 8, x = 9, y = 10;
  for(const Point_3& p : { Point_3(0, 0, 0), Point_3(1, 1, 0), Point_3(1, 0, .02), Point_3(0, 1, .02), Point_3(.2, .2, 1), Point_3(.8, .8, 1) })
    mesh.points.push_back(p);
  const std::array<int, 4> sliver = positive(mesh.points, { a, b, c, d });
  for(const std::array<int, 4>& t : { sliver, positive(mesh.points, { a, c, d, x }), positive(mesh.points, { b, c, d, y }) })
    mesh.tets.push_back(t);
  mesh.boundary_faces = LM::internal::one_tet_faces(mesh.tets);
  ASSERT_TRUE(LM::check_tetrahedral_mesh(mesh).valid()) << LM::check_tetrahedral_mesh(mesh).message;
  LM::Tetrahedral_mesh_3<Point_3> without = mesh;   // T removed: the boundary is pinched
  without.tets.erase(std::find(without.tets.begin(), without.tets.end(), sliver));
  without.boundary_faces = LM::internal::one_tet_faces(without.tets);
  const LM::Mesh_validity_report pinched = LM::check_tetrahedral_mesh(without);
  ASSERT_EQ(pinched.number_of_non_manifold_boundary_edges, 1u) << pinched.message;
  ASSERT_EQ(pinched.number_of_pinched_vertices, 2u) << pinched.message;
  for(std::size_t t = 4; t < mesh.tets.size(); ++t) {   // X and Y are no candidates
    const std::array<Eigen::Vector3d, 4> q = LM::internal::isotropic_tetrahedron(mesh, field, t);
    ASSERT_GT(LM::smallest_dihedral_angle(q[0], q[1], q[2], q[3]), 20.);
  }

  EXPECT_EQ(LM::peel_boundary_slivers(mesh, field), 1u);
  EXPECT_TRUE(LM::check_tetrahedral_mesh(mesh).valid()) << LM::check_tetrahedral_mesh(mesh).message;
  EXPECT_EQ(mesh.tets.size(), 5u);
  EXPECT_NE(std::find(mesh.tets.begin(), mesh.tets.end(), sliver), mesh.tets.end());
  EXPECT_EQ(mesh.boundary_faces, LM::internal::one_tet_faces(mesh.tets));
}
