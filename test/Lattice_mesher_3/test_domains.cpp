// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

// The domain stage: polyhedral domain (cube, fandisk, invalid inputs) and implicit domains
// (sphere, torus, invalid functions).

#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/Implicit_lattice_domain_3.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/point_generators_3.h>

#include <gtest/gtest.h>

#include "test_helpers.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace LM = CGAL::Lattice_mesher_3;
typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef LM::Polyhedral_lattice_domain_3<K> Polyhedral_domain;
typedef Polyhedral_domain::Surface_mesh Mesh;

namespace {

const double pi = 3.14159265358979323846;

// The built-in test cube.
Polyhedral_domain cube_domain(double feature_angle = 60.)
{
  return Polyhedral_domain(LM::make_cube_surface_3<K>(.1, 1.1), feature_angle);
}

void expect_near(const Point_3& a, const Point_3& b, double tol = 1e-12)
{
  EXPECT_LT(std::sqrt(CGAL::squared_distance(a, b)), tol) << a << " vs " << b;
}

void expect_near(const Vector_3& a, const Vector_3& b, double tol = 1e-12)
{
  EXPECT_LT(std::sqrt((a - b).squared_length()), tol) << a << " vs " << b;
}

const std::string tetrahedron_vertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

} // namespace

// ---- polyhedral domain: the cube ------------------------------------------------------------

TEST(PolyhedralDomain, CubeMeasuresCornersCurves)
{
  const Polyhedral_domain d = cube_domain();
  EXPECT_EQ(d.surface().number_of_faces(), 12u);
  EXPECT_EQ(d.corners().size(), 8u);
  EXPECT_EQ(d.number_of_curves(), 12u);
  EXPECT_NEAR(d.volume(), 1., 1e-12);
  EXPECT_NEAR(d.area(), 6., 1e-12);
  EXPECT_NEAR(d.curves_length(), 12., 1e-12);
  for(const Point_3& c : d.corners())
    for(int a = 0; a < 3; ++a)
      EXPECT_TRUE(c[a] == .1 || c[a] == 1.1) << c;
  for(const std::vector<Point_3>& curve : d.curves()) { // each cube edge joins two corners
    ASSERT_EQ(curve.size(), 2u);
    EXPECT_NEAR(CGAL::squared_distance(curve.front(), curve.back()), 1., 1e-12);
  }
  const CGAL::Bbox_3 b = d.bbox();
  EXPECT_EQ(b, CGAL::Bbox_3(.1, .1, .1, 1.1, 1.1, 1.1));
}

TEST(PolyhedralDomain, CubeIsInside)
{
  const Polyhedral_domain d = cube_domain();
  EXPECT_TRUE(d.is_inside(Point_3(.6, .6, .6)));
  EXPECT_TRUE(d.is_inside(Point_3(.11, 1.09, .5)));
  EXPECT_FALSE(d.is_inside(Point_3(1.2, .6, .6)));
  EXPECT_FALSE(d.is_inside(Point_3(.6, .6, 1.1))); // on the boundary: not strictly inside
  EXPECT_FALSE(d.is_inside(Point_3(-5, 0, 0)));
}

TEST(PolyhedralDomain, CubeProjectOnSurface)
{
  const Polyhedral_domain d = cube_domain();
  const Polyhedral_domain::Projection in = d.project_on_surface(Point_3(.6, .6, 1.));
  expect_near(in.point, Point_3(.6, .6, 1.1));
  expect_near(in.direction, Vector_3(0, 0, 1));
  EXPECT_NEAR(in.squared_distance, .01, 1e-12);
  EXPECT_EQ(in.index, -1);

  const Polyhedral_domain::Projection out = d.project_on_surface(Point_3(-.2, .5, .7));
  expect_near(out.point, Point_3(.1, .5, .7));
  expect_near(out.direction, Vector_3(-1, 0, 0));
  EXPECT_NEAR(out.squared_distance, .09, 1e-12);
}

TEST(PolyhedralDomain, CubeProjectOnFeatures)
{
  const Polyhedral_domain d = cube_domain();
  // nearest to the edge {y = z = 1.1}, parallel to x
  const Point_3 q(.6, 1.3, 1.4);
  const Polyhedral_domain::Projection f = d.project_on_features(q);
  expect_near(f.point, Point_3(.6, 1.1, 1.1));
  ASSERT_GE(f.index, 0);
  EXPECT_NEAR(std::abs(f.direction.x()), 1., 1e-12);
  EXPECT_NEAR(f.direction.squared_length(), 1., 1e-12);
  EXPECT_NEAR(f.squared_distance, .04 + .09, 1e-12);
  for(const Point_3& p : d.curves()[f.index]) {
    EXPECT_EQ(p.y(), 1.1);
    EXPECT_EQ(p.z(), 1.1);
  }
  const Polyhedral_domain::Projection c = d.project_on_curve(q, f.index);
  expect_near(c.point, f.point);
  EXPECT_EQ(c.index, f.index);

  // projection on a given curve stays on that curve: the edge {x = y = 0.1}, parallel to z
  std::size_t vertical = d.number_of_curves();
  for(std::size_t i = 0; i < d.number_of_curves(); ++i)
    if(d.curves()[i].front().x() == .1 && d.curves()[i].front().y() == .1
       && d.curves()[i].back().x() == .1 && d.curves()[i].back().y() == .1)
      vertical = i;
  ASSERT_LT(vertical, d.number_of_curves());
  const Polyhedral_domain::Projection v = d.project_on_curve(q, vertical);
  expect_near(v.point, Point_3(.1, .1, 1.1)); // q is above the edge's top end
  EXPECT_EQ(v.index, int(vertical));
  expect_near(Vector_3(std::abs(v.direction.x()), std::abs(v.direction.y()),
                       std::abs(v.direction.z())), Vector_3(0, 0, 1));
  EXPECT_THROW(d.project_on_curve(q, d.number_of_curves()), std::out_of_range);
}

TEST(PolyhedralDomain, CubeSampleSurface)
{
  const Polyhedral_domain d = cube_domain();
  const double spacing = .1;
  std::vector<Point_3> samples;
  d.sample_surface(spacing, std::back_inserter(samples));
  ASSERT_GT(samples.size(), 8u);
  for(const Point_3& s : samples)
    EXPECT_LT(d.project_on_surface(s).squared_distance, 1e-24);
  // every surface point is closer than `spacing` to a sample
  CGAL::Random rng(1);
  for(int i = 0; i < 200; ++i) {
    const Point_3 s = d.project_on_surface(Point_3(rng.get_double(-1, 2), rng.get_double(-1, 2),
                                                   rng.get_double(-1, 2))).point;
    double nearest = 1e9;
    for(const Point_3& t : samples)
      nearest = (std::min)(nearest, CGAL::squared_distance(s, t));
    EXPECT_LT(std::sqrt(nearest), spacing);
  }
  EXPECT_THROW(d.sample_surface(0., std::back_inserter(samples)), std::invalid_argument);
}

TEST(PolyhedralDomain, CubeWithoutFeatures)
{
  const Polyhedral_domain d = cube_domain(180.); // no dihedral angle is sharp at 180 degrees
  EXPECT_EQ(d.number_of_curves(), 0u);
  EXPECT_TRUE(d.corners().empty());
  EXPECT_EQ(d.curves_length(), 0.);
  const Polyhedral_domain::Projection f = d.project_on_features(Point_3(0, 0, 0));
  EXPECT_EQ(f.index, -1);
  EXPECT_TRUE(std::isinf(f.squared_distance));
}

TEST(PolyhedralDomain, ClosedCurvesWithoutCorners)
{
  // a prism over a regular 12-gon with polygonal caps: the rims are sharp (90 degrees) and turn
  // by 30 degrees at each vertex, the side edges turn by 30 degrees only
  const int n = 12;
  Mesh mesh;
  std::vector<Mesh::Vertex_index> bottom, top;
  for(int i = 0; i < n; ++i) {
    bottom.push_back(mesh.add_vertex(Point_3(std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), 0)));
    top.push_back(mesh.add_vertex(Point_3(std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), 1)));
  }
  for(int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.add_face(bottom[i], bottom[j], top[j]);
    mesh.add_face(bottom[i], top[j], top[i]);
  }
  mesh.add_face(top);
  mesh.add_face(std::vector<Mesh::Vertex_index>(bottom.rbegin(), bottom.rend()));
  const Polyhedral_domain d(mesh);
  EXPECT_TRUE(CGAL::is_triangle_mesh(d.surface()));
  EXPECT_NEAR(d.volume(), n / 2. * std::sin(2 * pi / n), 1e-12);
  EXPECT_TRUE(d.corners().empty());
  ASSERT_EQ(d.number_of_curves(), 2u);
  for(const std::vector<Point_3>& curve : d.curves()) {
    EXPECT_EQ(curve.size(), std::size_t(n + 1));
    EXPECT_EQ(curve.front(), curve.back());
  }
  EXPECT_NEAR(d.curves_length(), 2 * n * 2 * std::sin(pi / n), 1e-12);
  const Polyhedral_domain::Projection f = d.project_on_features(Point_3(0, 0, 2));
  EXPECT_NEAR(f.point.z(), 1., 1e-12);
  EXPECT_NEAR(f.direction.z(), 0., 1e-12);
}

TEST(PolyhedralDomain, InwardSurfaceIsReversed)
{
  Mesh mesh = LM::make_cube_surface_3<K>(.1, 1.1);
  CGAL::Polygon_mesh_processing::reverse_face_orientations(mesh);
  const Polyhedral_domain d(mesh);
  EXPECT_NEAR(d.volume(), 1., 1e-12);
  expect_near(d.project_on_surface(Point_3(.6, .6, 1.)).direction, Vector_3(0, 0, 1));
  EXPECT_TRUE(d.is_inside(Point_3(.6, .6, .6)));
}

// ---- polyhedral domain: surfaces as users have them --------------------------------------------

namespace {

// The cube [lo, hi]^3 appended to `mesh`, oriented outward or inward.
void add_cube(Mesh& mesh, double lo, double hi, bool outward)
{
  Mesh cube = LM::make_cube_surface_3<K>(lo, hi);
  if(!outward) CGAL::Polygon_mesh_processing::reverse_face_orientations(cube);
  mesh.join(cube);
}

// The box `lo` + [0, side]^3 with n x n squares a face, each two triangles, consistently oriented.
Mesh refined_cube(const Point_3& lo, double side, int n)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > triangles;
  std::map<std::array<int, 3>, std::size_t> index;
  auto id = [&](std::array<int, 3> c) {
    const auto it = index.emplace(c, points.size());
    if(it.second) points.push_back(lo + side / n * Vector_3(c[0], c[1], c[2]));
    return it.first->second;
  };
  for(int a = 0; a < 3; ++a)
    for(int fixed : { 0, n })
      for(int u = 0; u < n; ++u)
        for(int v = 0; v < n; ++v) {
          std::array<std::size_t, 4> q;
          const int du[4] = { 0, 1, 1, 0 }, dv[4] = { 0, 0, 1, 1 };
          for(int k = 0; k < 4; ++k) {
            std::array<int, 3> c;
            c[a] = fixed; c[(a + 1) % 3] = u + du[k]; c[(a + 2) % 3] = v + dv[k];
            q[k] = id(c);
          }
          triangles.push_back({ q[0], q[1], q[2] });
          triangles.push_back({ q[0], q[2], q[3] });
        }
  PMP::orient_polygon_soup(points, triangles);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return mesh;
}

} // namespace

// A closed shell inside another bounds a cavity, whichever way either is oriented: the points in
// it are outside, also for the cell grid, whose cells there no ray from the outside reaches
// (it once called all of them inside).
TEST(PolyhedralDomain, CavityIsOutside)
{
  for(int orientation = 0; orientation < 4; ++orientation) {
    Mesh mesh;
    add_cube(mesh, 0., 10., orientation & 1);
    add_cube(mesh, 3., 7., orientation & 2);
    const Polyhedral_domain d(mesh);
    EXPECT_NEAR(d.volume(), 1000. - 64., 1e-9) << orientation;
    EXPECT_TRUE(d.warnings().empty()) << orientation;
    for(double x : { 3.5, 4.2, 5., 5.9, 6.5 }) {
      EXPECT_FALSE(d.is_inside(Point_3(x, 5., 5.))) << orientation << " at x = " << x;
      EXPECT_EQ(d.inside_distance_bound(Point_3(x, 5., 5.)), 0.) << orientation << " at x = " << x;
    }
    for(double x : { .5, 1.5, 2.5, 7.5, 8.5, 9.5 })
      EXPECT_TRUE(d.is_inside(Point_3(x, 5., 5.))) << orientation << " at x = " << x;
    // the wall x = 3, whose outward normal points into the cavity
    expect_near(d.project_on_surface(Point_3(4., 5., 5.)).direction, Vector_3(1, 0, 0));
    expect_near(d.project_on_surface(Point_3(2., 5., 5.)).direction, Vector_3(1, 0, 0));
  }
}

// An island inside the cavity is part of the volume again.
TEST(PolyhedralDomain, IslandInCavity)
{
  Mesh mesh;
  add_cube(mesh, 0., 10., true);
  add_cube(mesh, 2., 8., true);
  add_cube(mesh, 4., 6., false);
  const Polyhedral_domain d(mesh);
  EXPECT_NEAR(d.volume(), 1000. - 216. + 8., 1e-9);
  EXPECT_TRUE(d.is_inside(Point_3(1., 5., 5.)));
  EXPECT_FALSE(d.is_inside(Point_3(3., 5., 5.)));
  EXPECT_TRUE(d.is_inside(Point_3(5., 5., 5.)));
}

// Two cubes that overlap: Mesh_3 users mesh such models (limbs through a body, CAD parts
// unioned by hand). The volume is their union, including the overlap that ray parity calls
// outside; the faces buried in the other cube bound nothing and are not projected on.
TEST(PolyhedralDomain, OverlappingComponentsMeshTheirUnion)
{
  // A = [0, 2]^3, B = (1.1, 1.2, 1.3) + [0, 2]^3, 20 x 20 squares a face: most triangles are
  // either buried in the other cube or not
  Mesh mesh = refined_cube(Point_3(0., 0., 0.), 2., 20);
  Mesh b = refined_cube(Point_3(1.1, 1.2, 1.3), 2., 20);
  CGAL::Polygon_mesh_processing::reverse_face_orientations(b);   // inconsistently oriented as well
  mesh.join(b);
  const Polyhedral_domain d(mesh);
  EXPECT_GT(d.number_of_self_intersections(), 0u);
  ASSERT_EQ(d.warnings().size(), 1u);
  EXPECT_NE(d.warnings()[0].find("self-intersects"), std::string::npos) << d.warnings()[0];
  EXPECT_TRUE(d.is_inside(Point_3(1.5, 1.5, 1.5)));     // in both cubes: ray parity says outside
  EXPECT_TRUE(d.is_inside(Point_3(1.5, 1.9, 1.5)));
  EXPECT_TRUE(d.is_inside(Point_3(.5, .5, .5)));
  EXPECT_TRUE(d.is_inside(Point_3(2.9, 3.1, 3.2)));
  EXPECT_FALSE(d.is_inside(Point_3(.5, 2.9, .5)));
  EXPECT_FALSE(d.is_inside(Point_3(2.5, .5, 2.5)));
  // every face of boundary() has the outside within a triangle (0.1) of its centroid, and
  // the faces buried in the other cube are gone
  auto in_a = [](const Point_3& p) { return p.x() > 0. && p.y() > 0. && p.z() > 0. && p.x() < 2. && p.y() < 2. && p.z() < 2.; };
  auto in_b = [&](const Point_3& p) { return in_a(p - Vector_3(1.1, 1.2, 1.3)); };
  auto deep = [&](const Point_3& p) {   // in the union, the cube of side 0.2 around it too
    for(int k = 0; k < 8; ++k) {
      const Point_3 q = p + .1 * Vector_3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
      if(!in_a(q) && !in_b(q)) return false;
    }
    return true;
  };
  // near the walls, where the cells of the inside test's grid are touched and a point is
  // classified from a nearby untouched cell (in the overlap, of winding number 2)
  CGAL::Random rng(11);
  for(int i = 0; i < 4000; ++i) {
    const Vector_3 corner = rng.get_int(0, 2) ? Vector_3(0., 0., 0.) : Vector_3(1.1, 1.2, 1.3);
    double c[3];
    for(int a = 0; a < 3; ++a) c[a] = corner[a] + rng.get_double(-.1, 2.1);
    const int axis = rng.get_int(0, 3);
    c[axis] = corner[axis] + (rng.get_int(0, 2) ? 2. : 0.) + rng.get_double(-.02, .02);
    const Point_3 p(c[0], c[1], c[2]);
    ASSERT_EQ(d.is_inside(p), in_a(p) || in_b(p)) << p;
  }
  EXPECT_LT(d.boundary().number_of_faces(), d.surface().number_of_faces() - 200);
  for(Mesh::Face_index f : d.boundary().faces()) {
    const Mesh::Halfedge_index h = d.boundary().halfedge(f);
    const Point_3 c = CGAL::centroid(d.boundary().point(d.boundary().source(h)), d.boundary().point(d.boundary().target(h)),
                                     d.boundary().point(d.boundary().target(d.boundary().next(h))));
    ASSERT_FALSE(deep(c)) << "a buried face at " << c;
  }
  // from the overlap, the closest boundary point is on a wall of the union, outward normal
  const Polyhedral_domain::Projection s = d.project_on_surface(Point_3(1.5, 1.9, 1.5));
  EXPECT_FALSE(deep(s.point)) << s.point;
  EXPECT_NEAR(s.point.y(), 2., 1e-12);
  expect_near(s.direction, Vector_3(0, 1, 0));
  // the features are the exposed cube edges: none deep inside the union
  EXPECT_GT(d.number_of_curves(), 0u);
  for(std::size_t c = 0; c < d.number_of_curves(); ++c)
    for(const Point_3& p : d.curves()[c]) ASSERT_FALSE(deep(p)) << "a feature point inside the union: " << p;
}

// Files as users have them: a polygon soup whose faces each list their own copies of the
// points, and faces of inconsistent orientation, are merged and oriented.
TEST(PolyhedralDomain, SoupsAndInconsistentOrientation)
{
  const Temp_dir dir;
  const std::string soup = dir.write("soup.off", "OFF\n12 4 0\n" + tetrahedron_vertices + tetrahedron_vertices
                                     + tetrahedron_vertices + "3 0 2 1\n3 4 5 7\n3 8 11 10\n3 1 2 3\n");
  const Polyhedral_domain a = LM::read_polyhedral_lattice_domain_3<K>(soup);
  EXPECT_EQ(a.surface().number_of_vertices(), 4u);
  EXPECT_NEAR(a.volume(), 1. / 6., 1e-12);
  // two faces turned the other way
  const std::string shuffled = dir.write("shuffled.off", "OFF\n4 4 0\n" + tetrahedron_vertices
                                         + "3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n");
  const Polyhedral_domain b = LM::read_polyhedral_lattice_domain_3<K>(shuffled);
  EXPECT_NEAR(b.volume(), 1. / 6., 1e-12);
  EXPECT_TRUE(b.is_inside(Point_3(.1, .1, .1)));
  expect_near(b.project_on_surface(Point_3(.1, .1, -1.)).direction, Vector_3(0, 0, -1));
}

TEST(PolyhedralDomain, PolygonalFacesFromObj)
{
  const Temp_dir dir;
  const std::string file = dir.write("cube.obj",
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
      "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n");
  const Polyhedral_domain d = LM::read_polyhedral_lattice_domain_3<K>(file);
  EXPECT_EQ(d.surface().number_of_faces(), 12u);
  EXPECT_NEAR(d.volume(), 1., 1e-12);
  EXPECT_EQ(d.corners().size(), 8u);
  EXPECT_EQ(d.number_of_curves(), 12u);
}

// ---- polyhedral domain: fandisk ---------------------------------------------------------------

TEST(PolyhedralDomain, Fandisk)
{
  const Polyhedral_domain d = LM::read_polyhedral_lattice_domain_3<K>(
      std::string(LATTICE_MESHER_3_DATA_DIR) + "/meshes/fandisk.off");
  // the corners and polylines of Polyhedral_mesh_domain_with_features_3 at 60 degrees
  EXPECT_EQ(d.corners().size(), 25u);
  EXPECT_EQ(d.number_of_curves(), 35u);
  EXPECT_NEAR(d.curves_length(), 12.9105, 1e-3);
  EXPECT_GT(d.volume(), 0.);
  // values from the Mesh_3 domain and AABB trees in domain_features_demo.cpp
  const Point_3 q(.1, .2, .3);
  EXPECT_TRUE(d.is_inside(q));
  EXPECT_NEAR(std::sqrt(d.project_on_surface(q).squared_distance), .0334826, 1e-6);
  const Polyhedral_domain::Projection f = d.project_on_features(q);
  EXPECT_NEAR(std::sqrt(f.squared_distance), .0645669, 1e-6);
  EXPECT_NEAR(f.direction.squared_length(), 1., 1e-12);
  const Polyhedral_domain::Projection c = d.project_on_curve(q, f.index);
  expect_near(c.point, f.point);
  std::size_t corner_ends = 0; // open curves end at corners
  for(const std::vector<Point_3>& curve : d.curves())
    for(const Point_3& end : {curve.front(), curve.back()})
      for(const Point_3& corner : d.corners())
        corner_ends += (end == corner);
  EXPECT_EQ(corner_ends, 2 * d.number_of_curves());
}

// anchor's long CAD triangles: the samples cover the surface as on the cube, at most
// area / g^2 + edge length / g + vertices of them (g = spacing / 2; a grid in each triangle's
// axes puts 741,349 at a spacing of 0.014, 13 times the first term)
TEST(PolyhedralDomain, AnchorSampleSurface)
{
  const Polyhedral_domain d = LM::read_polyhedral_lattice_domain_3<K>(
      std::string(LATTICE_MESHER_3_DATA_DIR) + "/meshes/anchor.off");
  const double spacing = .014, g = .5 * spacing;
  std::vector<Point_3> samples;
  d.sample_surface(spacing, std::back_inserter(samples));
  double edges = 0.;
  for(auto e : d.boundary().edges())
    edges += std::sqrt(CGAL::squared_distance(d.boundary().point(d.boundary().vertex(e, 0)),
                                              d.boundary().point(d.boundary().vertex(e, 1))));
  const double bound = d.area() / (g * g) + edges / g + double(d.boundary().number_of_vertices());
  EXPECT_LE(double(samples.size()), bound);
  EXPECT_GT(double(samples.size()), .5 * d.area() / (g * g));
  for(std::size_t i = 0; i < samples.size(); i += 97)
    EXPECT_LT(d.project_on_surface(samples[i]).squared_distance, 1e-20);
  CGAL::Random rng(3);
  const CGAL::Bbox_3 box = d.bbox();
  for(int i = 0; i < 200; ++i) {
    const Point_3 s = d.project_on_surface(Point_3(rng.get_double(box.xmin(), box.xmax()), rng.get_double(box.ymin(), box.ymax()),
                                                   rng.get_double(box.zmin(), box.zmax()))).point;
    double nearest = 1e9;
    for(const Point_3& t : samples)
      nearest = (std::min)(nearest, CGAL::squared_distance(s, t));
    ASSERT_LT(std::sqrt(nearest), spacing) << s;
  }
}

TEST(PolyhedralDomain, ConcurrentQueries)
{
  const Polyhedral_domain d = LM::read_polyhedral_lattice_domain_3<K>(
      std::string(LATTICE_MESHER_3_DATA_DIR) + "/meshes/fandisk.off");
  const Polyhedral_domain copy = d; // shares the data
  CGAL::Random rng(3);
  std::vector<Point_3> points;
  for(int i = 0; i < 2000; ++i)
    points.emplace_back(rng.get_double(-.6, .6), rng.get_double(-.3, .3), rng.get_double(-.6, .6));
  std::vector<Point_3> serial, parallel(points.size());
  std::vector<int> serial_inside, parallel_inside(points.size());
  for(const Point_3& p : points) {
    serial.push_back(d.project_on_features(p).point);
    serial_inside.push_back(d.is_inside(p));
  }
#pragma omp parallel for
  for(int i = 0; i < int(points.size()); ++i) {
    parallel[i] = copy.project_on_features(points[i]).point;
    parallel_inside[i] = copy.is_inside(points[i]);
  }
  EXPECT_EQ(serial, parallel);
  EXPECT_EQ(serial_inside, parallel_inside);
}

// The cell grid's answers against a ray cast and the closest point: the same inside test, a
// distance bound never above the distance and positive for most points well inside. Points are
// drawn near the surface too (projections moved along the normal), where the cells are touched,
// and on the planes of the box; the cube's faces lie on its bounding box, its corners touch the
// cells next to it (the flood fill of the outside once started from such a cell: every untouched
// cell was inside).
TEST(PolyhedralDomain, CellGridAgreesWithRayCastAndProjection)
{
  auto check = [](const Polyhedral_domain& d, const char* name) {
    const CGAL::Side_of_triangle_mesh<Polyhedral_domain::Surface_mesh, K> ray_cast(d.surface());
    const CGAL::Bbox_3 b = d.bbox();
    const double extent = (std::max)({ b.xmax() - b.xmin(), b.ymax() - b.ymin(), b.zmax() - b.zmin() });
    CGAL::Random rng(5);
    int deep = 0, bounded = 0;
    for(int i = 0; i < 20000; ++i) {
      double c[3];
      for(int a = 0; a < 3; ++a)
        c[a] = rng.get_int(0, 10) == 0 ? (rng.get_int(0, 2) ? b.min_coord(a) : b.max_coord(a))
                                       : rng.get_double(b.min_coord(a) - .1 * extent, b.max_coord(a) + .1 * extent);
      Point_3 p(c[0], c[1], c[2]);
      if(i % 2) {   // within a few cells of the surface, either side
        const auto s = d.project_on_surface(p);
        p = s.point + rng.get_double(-.05, .05) * extent * s.direction;
      }
      const bool inside = ray_cast(p) == CGAL::ON_BOUNDED_SIDE;
      ASSERT_EQ(d.is_inside(p), inside) << name << " at " << p;
      const double bound = d.inside_distance_bound(p), distance = std::sqrt(d.project_on_surface(p).squared_distance);
      if(!inside) { EXPECT_EQ(bound, 0.) << name << " at " << p; continue; }
      EXPECT_LE(bound, distance) << name << " at " << p;
      if(distance > .03 * extent) { ++deep; bounded += (bound >= .5 * distance - .02 * extent); }
    }
    EXPECT_GT(deep, 500) << name;   // fandisk is thin: about one point in 20
    EXPECT_GT(bounded, .95 * deep) << name;   // 128 cells along the longest side: within 2 cells of the distance
    EXPECT_EQ(d.inside_distance_bound(Point_3(std::nan(""), 0., 0.)), 0.) << name;
  };
  check(LM::read_polyhedral_lattice_domain_3<K>(std::string(LATTICE_MESHER_3_DATA_DIR) + "/meshes/fandisk.off"), "fandisk");
  check(Polyhedral_domain(LM::make_cube_surface_3<K>(1., 11.)), "cube");
}

// A point on the surface is not inside. The insertion puts many candidates exactly there, in the
// plane of an axis-aligned face; the inside test finds the triangle under them with its first
// segment, whose winding number is not that of the cell it leads to.
TEST(PolyhedralDomain, PointsOnTheSurfaceAreNotInside)
{
  auto check = [](const Polyhedral_domain& d, const char* name) {
    const double lo = d.bbox().xmin(), hi = d.bbox().xmax();   // a cube: the same on every axis
    ASSERT_EQ(lo, d.bbox().zmin());
    ASSERT_EQ(hi, d.bbox().zmax());
    CGAL::Random rng(3);
    for(int i = 0; i < 2000; ++i) {
      double c[3];
      for(int a = 0; a < 3; ++a) c[a] = rng.get_double(lo, hi);
      const int axis = rng.get_int(0, 3);
      c[axis] = rng.get_int(0, 2) ? lo : hi;
      const Point_3 p(c[0], c[1], c[2]);
      ASSERT_FALSE(d.is_inside(p)) << name << " at " << p;
      // just inside, the same cell: inside
      c[axis] += c[axis] == lo ? 1e-9 : -1e-9;
      ASSERT_TRUE(d.is_inside(Point_3(c[0], c[1], c[2]))) << name << " at " << p;
    }
  };
  check(Polyhedral_domain(LM::make_cube_surface_3<K>(1., 11.)), "cube");
  check(Polyhedral_domain(refined_cube(Point_3(0., 0., 0.), 2., 20)), "cube of 2,400 triangles");
}

// OFF files may list vertices that no face uses (prim.off in CGAL's data): the domain drops them,
// where orient_to_bound_a_volume() dereferenced their null halfedge.
TEST(PolyhedralDomain, IsolatedVerticesAreRemoved)
{
  const Temp_dir dir;
  const std::string file = dir.write("isolated.off", "OFF\n6 4 0\n0 0 0\n5 5 5\n1 0 0\n0 1 0\n0 0 1\n"
                                     "6 5 5\n3 0 3 2\n3 0 2 4\n3 0 4 3\n3 2 3 4\n");
  const Polyhedral_domain d = LM::read_polyhedral_lattice_domain_3<K>(file);
  EXPECT_EQ(d.surface().number_of_vertices(), 4u);
  EXPECT_EQ(d.surface().number_of_faces(), 4u);
  EXPECT_NEAR(d.volume(), 1. / 6., 1e-12);
  EXPECT_EQ(d.corners().size(), 4u);
  EXPECT_TRUE(d.is_inside(Point_3(.1, .1, .1)));
  EXPECT_FALSE(d.is_inside(Point_3(5, 5, 5)));
}

// ---- polyhedral domain: invalid input -------------------------------------------------------

TEST(PolyhedralDomain, InvalidInput)
{
  const Temp_dir dir;
  const std::string missing = dir.path("missing.off");
  expect_error<std::runtime_error>([&] { LM::read_polyhedral_lattice_domain_3<K>(missing); },
                                   {missing, "cannot open"});

  const std::string empty = dir.write("empty.off", "");
  expect_error<std::runtime_error>([&] { LM::read_polyhedral_lattice_domain_3<K>(empty); },
                                   {empty, "empty"});

  const std::string garbage = dir.write("garbage.off", "this is not an OFF file\n");
  expect_error<std::runtime_error>([&] { LM::read_polyhedral_lattice_domain_3<K>(garbage); },
                                   {garbage, "cannot read"});

  const std::string no_faces = dir.write("no_faces.off", "OFF\n4 0 0\n" + tetrahedron_vertices);
  expect_error<std::invalid_argument>([&] { LM::read_polyhedral_lattice_domain_3<K>(no_faces); },
                                      {no_faces, "no faces"});

  // a tetrahedron with one face removed: 3 border edges
  const std::string open = dir.write("open.off", "OFF\n4 3 0\n" + tetrahedron_vertices
                                     + "3 0 2 1\n3 0 1 3\n3 0 3 2\n");
  expect_error<std::invalid_argument>([&] { LM::read_polyhedral_lattice_domain_3<K>(open); },
                                      {open, "not closed", "3 border edges"});


  const std::string tetrahedron = dir.write("tetrahedron.off", "OFF\n4 4 0\n" + tetrahedron_vertices
                                            + "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  EXPECT_NEAR(LM::read_polyhedral_lattice_domain_3<K>(tetrahedron).volume(), 1. / 6., 1e-12);
  expect_error<std::invalid_argument>([&] { LM::read_polyhedral_lattice_domain_3<K>(tetrahedron, 0.); },
                                      {tetrahedron, "feature angle"});
  expect_error<std::invalid_argument>([&] { LM::read_polyhedral_lattice_domain_3<K>(tetrahedron, 181.); },
                                      {"feature angle"});

  // finite coordinates whose volume overflows
  const std::string huge = dir.write("huge.off", "OFF\n4 4 0\n0 0 0\n1e110 0 0\n0 1e110 0\n0 0 1e110\n"
                                     "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  expect_error<std::invalid_argument>([&] { LM::read_polyhedral_lattice_domain_3<K>(huge); },
                                      {huge, "non-finite volume"});

  // A binary STL can carry a NaN; text readers reject "nan" as malformed.
  const std::string nan_file = dir.path("nan.stl");
  {
    const float v[4][3] = {{0, 0, 0}, {1, 0, std::nanf("")}, {0, 1, 0}, {0, 0, 1}};
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    std::ofstream stl(nan_file, std::ios::binary);
    const std::string header(80, ' ');
    const std::uint32_t n = 4;
    const float normal[3] = {0, 0, 0};
    const std::uint16_t attribute = 0;
    stl.write(header.data(), 80);
    stl.write(reinterpret_cast<const char*>(&n), 4);
    for(const auto& f : faces) {
      stl.write(reinterpret_cast<const char*>(normal), 12);
      for(int i : f)
        stl.write(reinterpret_cast<const char*>(v[i]), 12);
      stl.write(reinterpret_cast<const char*>(&attribute), 2);
    }
  }
  expect_error<std::invalid_argument>([&] { LM::read_polyhedral_lattice_domain_3<K>(nan_file); },
                                      {nan_file, "non-finite coordinate"});
  const std::string nan_off = dir.write("nan.off", "OFF\n4 4 0\n0 0 0\n1 0 nan\n0 1 0\n0 0 1\n"
                                        "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  expect_error<std::runtime_error>([&] { LM::read_polyhedral_lattice_domain_3<K>(nan_off); },
                                   {nan_off, "cannot read", "nan"});

  Mesh nan_mesh = LM::make_cube_surface_3<K>(0., 1.);
  nan_mesh.point(*nan_mesh.vertices().begin()) = Point_3(std::nan(""), 0, 0);
  expect_error<std::invalid_argument>([&] { Polyhedral_domain d(nan_mesh); }, {"non-finite"});
}

// ---- implicit domains -----------------------------------------------------------------------

TEST(ImplicitDomain, Sphere)
{
  const Point_3 center(.3, -.2, .1);
  const double r = 1.;
  const auto d = LM::make_sphere_domain_3<K>(center, r);
  EXPECT_EQ(d.number_of_curves(), 0u);
  EXPECT_TRUE(d.corners().empty());
  EXPECT_EQ(d.curves_length(), 0.);
  EXPECT_EQ(d.project_on_features(center).index, -1);
  EXPECT_THROW(d.project_on_curve(center, 0), std::out_of_range);
  EXPECT_TRUE(d.is_inside(center));
  EXPECT_TRUE(d.is_inside(center + Vector_3(0, 0, .99)));
  EXPECT_FALSE(d.is_inside(center + Vector_3(0, 0, 1.01)));

  EXPECT_NEAR(d.volume(), 4. / 3. * pi, .02 * 4. / 3. * pi);
  EXPECT_NEAR(d.area(), 4. * pi, .02 * 4. * pi);

  // offset from the center, tolerance on the closest point: far away, the finite-difference
  // gradient at the query limits the accuracy (the point is still on the surface)
  const std::vector<std::pair<Vector_3, double> > queries = {
      {Vector_3(.5, 0, 0), 1e-9},  {Vector_3(0, -1.7, .2), 1e-9}, {Vector_3(.1, .2, -.3), 1e-9},
      {Vector_3(0, 0, 1e-9), 1e-9}, {Vector_3(30, 40, 0), 1e-6}};
  for(const auto& q : queries) {
    const Vector_3& v = q.first;
    const LM::Boundary_projection_3<K> pr = d.project_on_surface(center + v);
    const Vector_3 radial = v / std::sqrt(v.squared_length());
    EXPECT_LT(std::abs(d.function()(pr.point)), 1e-9) << v;
    expect_near(pr.point, center + r * radial, q.second);
    expect_near(pr.direction, radial, 1e-6);
    EXPECT_NEAR(std::sqrt(pr.squared_distance), std::abs(std::sqrt(v.squared_length()) - r), 1e-9);
  }
  // the center is a critical point of f: any surface point will do
  const LM::Boundary_projection_3<K> pc = d.project_on_surface(center);
  EXPECT_LT(std::abs(d.function()(pc.point)), 1e-9);
  EXPECT_NEAR(pc.direction.squared_length(), 1., 1e-9);

  std::vector<Point_3> samples;
  const double spacing = .15;
  d.sample_surface(spacing, std::back_inserter(samples));
  ASSERT_FALSE(samples.empty());
  for(const Point_3& s : samples)
    ASSERT_LT(std::abs(d.function()(s)), 1e-9);
  CGAL::Random rng(2);
  CGAL::Random_points_on_sphere_3<Point_3> on_sphere(r, rng);
  for(int i = 0; i < 100; ++i, ++on_sphere) {
    const Point_3 s = center + (*on_sphere - CGAL::ORIGIN);
    double nearest = 1e9;
    for(const Point_3& t : samples)
      nearest = (std::min)(nearest, CGAL::squared_distance(s, t));
    EXPECT_LT(std::sqrt(nearest), spacing);
  }
}

TEST(ImplicitDomain, Torus)
{
  const double R = 1., r = .4;
  const auto d = LM::make_torus_domain_3<K>();
  // the axis is y: the tube circles around y, in the xz plane
  EXPECT_EQ(d.bbox(), CGAL::Bbox_3(-1.4, -.4, -1.4, 1.4, .4, 1.4));
  EXPECT_TRUE(d.is_inside(Point_3(1, 0, 0)));
  EXPECT_TRUE(d.is_inside(Point_3(0, 0, -1)));
  EXPECT_FALSE(d.is_inside(Point_3(0, 1, 0)));
  EXPECT_FALSE(d.is_inside(Point_3(0, 0, 0)));

  EXPECT_NEAR(d.volume(), 2. * pi * pi * R * r * r, .02 * 2. * pi * pi * R * r * r);
  EXPECT_NEAR(d.area(), 4. * pi * pi * R * r, .02 * 4. * pi * pi * R * r);

  // query, expected distance to the surface
  const std::vector<std::pair<Point_3, double> > queries = {
      {Point_3(2, 0, 0), .6},        {Point_3(0, 0, -1.2), .2},  {Point_3(.7, .1, .7), 0.},
      {Point_3(0, 0, 0), .6},        {Point_3(0, .1, 0), 0.},    {Point_3(1, 0, 0), .4},
      {Point_3(0, 3, 1), 0.},        {Point_3(-50, 20, 5), 0.}};
  for(const auto& q : queries) {
    const LM::Boundary_projection_3<K> pr = d.project_on_surface(q.first);
    EXPECT_LT(std::abs(d.function()(pr.point)), 1e-9) << q.first;
    EXPECT_NEAR(pr.direction.squared_length(), 1., 1e-9);
    if(q.second > 0.) {
      EXPECT_NEAR(std::sqrt(pr.squared_distance), q.second, 1e-9) << q.first;
    }
  }
  // outward normal off the critical set: from the tube's core circle to the point
  const LM::Boundary_projection_3<K> top = d.project_on_surface(Point_3(0, .3, 1));
  expect_near(top.point, Point_3(0, .4, 1), 1e-9);
  expect_near(top.direction, Vector_3(0, 1, 0), 1e-6);
  // on the axis the gradient has no x, z component and Newton fails: the bisection fallback
  // lands close to (not exactly at) the closest distance sqrt(1.01) - 0.4
  const LM::Boundary_projection_3<K> axis = d.project_on_surface(Point_3(0, .1, 0));
  EXPECT_NEAR(std::sqrt(axis.squared_distance), std::sqrt(1.01) - .4, .02);
}

TEST(ImplicitDomain, InvalidInput)
{
  const CGAL::Bbox_3 box(-2, -2, -2, 2, 2, 2);
  auto ball = [](const Point_3& p) { return std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z()) - 1.; };
  typedef LM::Implicit_lattice_domain_3<K, std::function<double(const Point_3&)> > Domain;

  expect_error<std::invalid_argument>([&] { Domain(ball, CGAL::Bbox_3(0, 0, 0, 1, 0, 1)); },
                                      {"bounding box is empty"});
  expect_error<std::invalid_argument>([&] { Domain([](const Point_3&) { return 1.; }, box); },
                                      {"nowhere negative"});
  expect_error<std::invalid_argument>([&] { Domain(ball, CGAL::Bbox_3(-.5, -2, -2, 2, 2, 2)); },
                                      {"does not contain the domain"});
  expect_error<std::domain_error>(
      [&] { Domain([&](const Point_3& p) { return p.x() > .5 ? std::nan("") : ball(p); }, box); },
      {"NaN"});
  // NaN found by a query after construction
  const Domain d([&](const Point_3& p) { return p.x() > 10. ? std::nan("") : ball(p); }, box);
  EXPECT_TRUE(d.is_inside(Point_3(0, 0, 0)));
  expect_error<std::domain_error>([&] { d.project_on_surface(Point_3(11, 0, 0)); }, {"NaN"});
  expect_error<std::invalid_argument>([] { LM::make_torus_domain_3<K>(.4, 1.); }, {"minor_radius"});
}
