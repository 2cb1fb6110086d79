// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

// Quality measures, mesh validity check, Medit/VTU output and the Hausdorff distance.

#include <CGAL/Lattice_mesher_3/Boundary_projection_3.h>
#include <CGAL/Lattice_mesher_3/IO/medit.h>
#include <CGAL/Lattice_mesher_3/IO/vtu.h>
#include <CGAL/Lattice_mesher_3/check_mesh.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lattice_mesher_traits_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Lattice_mesher_traits_3<K> GT;
typedef K::Point_3 Point;
typedef CGAL::Lattice_mesher_3::Tetrahedral_mesh_3<Point> Mesh;
typedef CGAL::Lattice_mesher_3::Constant_frame_field_3<GT> Constant_field;

using namespace CGAL::Lattice_mesher_3;

const double regular_dihedral = std::acos(1. / 3.) * 180. / M_PI;                  // 70.5288 degrees
const double face_diagonal_to_bcc = std::atan(1. / std::sqrt(2.)) * 180. / M_PI;  // 35.2644 degrees

// The one-tet faces of `tets`, oriented outward geometrically: an oracle independent of the
// combinatorial one in check_mesh.h.
std::vector<std::array<int, 3> > outward_boundary(const Mesh& m)
{
  std::map<std::array<int, 3>, std::vector<std::array<int, 4> > > faces;  // sorted face -> (face, opposite)
  for(const auto& t : m.tets)
    for(int i = 0; i < 4; ++i) {
      std::array<int, 3> f = { t[(i + 1) % 4], t[(i + 2) % 4], t[(i + 3) % 4] }, key = f;
      std::sort(key.begin(), key.end());
      faces[key].push_back({ f[0], f[1], f[2], t[i] });
    }
  std::vector<std::array<int, 3> > boundary;
  for(const auto& f : faces) {
    if(f.second.size() != 1) continue;
    std::array<int, 4> g = f.second[0];
    if(CGAL::orientation(m.points[g[0]], m.points[g[1]], m.points[g[2]], m.points[g[3]]) == CGAL::POSITIVE)
      std::swap(g[1], g[2]);
    boundary.push_back({ g[0], g[1], g[2] });
  }
  return boundary;
}

// Swaps two vertices of every negative tet, then computes the boundary.
void orient_and_close(Mesh& m)
{
  for(auto& t : m.tets)
    if(CGAL::orientation(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]) == CGAL::NEGATIVE)
      std::swap(t[0], t[1]);
  m.boundary_faces = outward_boundary(m);
}

Mesh tet_mesh(const Point& a, const Point& b, const Point& c, const Point& d)
{
  Mesh m;
  m.points = { a, b, c, d };
  m.tets = { { 0, 1, 2, 3 } };
  orient_and_close(m);
  return m;
}

// [0, size]^3 + shift cut into n^3 cubes of 6 Kuhn tets each (conforming: same diagonal).
Mesh cube_mesh(int n, double size = 1., double shift = 0.)
{
  Mesh m;
  auto index = [n](int i, int j, int k) { return (i * (n + 1) + j) * (n + 1) + k; };
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j <= n; ++j)
      for(int k = 0; k <= n; ++k)
        m.points.emplace_back(shift + size * i / n, size * j / n, size * k / n);
  const int permutations[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      for(int k = 0; k < n; ++k)
        for(const auto& p : permutations) {
          std::array<int, 3> c = { i, j, k };
          std::array<int, 4> t;
          t[0] = index(c[0], c[1], c[2]);
          for(int s = 0; s < 3; ++s) {
            ++c[p[s]];
            t[s + 1] = index(c[0], c[1], c[2]);
          }
          m.tets.push_back(t);
        }
  orient_and_close(m);
  return m;
}

// The boundary surface of [0,1]^3, as a LatticeMeshDomain_3 would give it.
struct Unit_cube_domain
{
  typedef K Geom_traits;
  typedef K::Point_3 Point_3;
  typedef Boundary_projection_3<K> Projection;

  Projection project_on_surface(const Point_3& p) const
  {
    double q[3] = { p.x(), p.y(), p.z() };
    const bool inside = std::all_of(q, q + 3, [](double c) { return c >= 0. && c <= 1.; });
    int axis = 0;
    double side = 0.;
    if(inside) {
      // closest face
      double best = 2.;
      for(int a = 0; a < 3; ++a)
        for(double s : { 0., 1. })
          if(std::abs(q[a] - s) < best) { best = std::abs(q[a] - s); axis = a; side = s; }
      q[axis] = side;
    } else {
      for(double& c : q) c = std::clamp(c, 0., 1.);
    }
    Projection r;
    r.point = Point_3(q[0], q[1], q[2]);
    r.squared_distance = CGAL::squared_distance(p, r.point);
    return r;
  }

  template <typename OutputIterator>
  OutputIterator sample_surface(double spacing, OutputIterator out) const
  {
    const int n = int(std::ceil(1. / spacing));
    for(int a = 0; a < 3; ++a)
      for(double s : { 0., 1. })
        for(int i = 0; i <= n; ++i)
          for(int j = 0; j <= n; ++j) {
            double q[3];
            q[a] = s;
            q[(a + 1) % 3] = double(i) / n;
            q[(a + 2) % 3] = double(j) / n;
            *out++ = Point_3(q[0], q[1], q[2]);
          }
    return out;
  }
};

// Reads the number after `"key":` at or after `from` in a JSON text.
double json_number(const std::string& json, const std::string& key, std::size_t from = 0)
{
  const std::size_t at = json.find('"' + key + "\":", from);
  if(at == std::string::npos) ADD_FAILURE() << "missing key " << key;
  return at == std::string::npos ? NAN : std::strtod(json.c_str() + at + key.size() + 3, nullptr);
}

// ---------------------------------------------------------------------------------------------
// Quality measures

TEST(TetrahedronQuality, RegularTetrahedron)
{
  const Mesh m = tet_mesh(Point(1, 1, 1), Point(1, -1, -1), Point(-1, 1, -1), Point(-1, -1, 1));
  const Mesh_quality_3 q = compute_mesh_quality(m, Constant_field(), CGAL::parameters::lattice(bcc_lattice()));
  EXPECT_NEAR(q.theta_min.min, regular_dihedral, 1e-9);
  EXPECT_NEAR(q.theta_max.max, regular_dihedral, 1e-9);
  EXPECT_NEAR(q.rho.min, 1., 1e-12);
  EXPECT_NEAR(q.kappa.min, 1., 1e-12);
  EXPECT_EQ(q.theta_min.std, 0.);
  EXPECT_EQ(q.vertices, 4u);
  EXPECT_EQ(q.tets, 1u);
  EXPECT_EQ(q.below40, 0u);
  EXPECT_LT(q.hausdorff, 0.);
  // every edge is a cube face diagonal, atan(1/sqrt(2)) from the closest BCC direction (1,1,1)/2
  EXPECT_NEAR(q.epsilon.mean, face_diagonal_to_bcc, 1e-9);
  EXPECT_NEAR(q.epsilon.std, 0., 1e-9);
}

TEST(TetrahedronQuality, BccDelaunayTetrahedron)
{
  const Mesh m = tet_mesh(Point(0, 0, 0), Point(1, 0, 0), Point(.5, .5, .5), Point(.5, .5, -.5));
  const Mesh_quality_3 q = compute_mesh_quality(m, Constant_field(), CGAL::parameters::lattice(bcc_lattice()));
  EXPECT_NEAR(q.theta_min.min, 60., 1e-9);
  EXPECT_NEAR(q.theta_max.max, 90., 1e-9);
  // 2 edges of length 1, 4 of sqrt(3)/2, circumradius sqrt(5)/4: rho = kappa = 3 sqrt(2) / (2 sqrt(5))
  EXPECT_NEAR(q.rho.min, 3. * std::sqrt(2.) / (2. * std::sqrt(5.)), 1e-12);
  EXPECT_NEAR(q.kappa.min, 3. * std::sqrt(2.) / (2. * std::sqrt(5.)), 1e-12);
  // every edge is a BCC one-ring direction
  EXPECT_NEAR(q.epsilon.max, 0., 1e-12);
  EXPECT_EQ(q.below20, 0u);
  EXPECT_EQ(q.below40, 0u);

  // in FCC the 2 axis edges are aligned, the 4 diagonals are atan(1/sqrt(2)) from (1,1,0)/2
  const std::vector<double> eps = compute_edge_alignment_errors(m, Constant_field(), fcc_lattice());
  ASSERT_EQ(eps.size(), 6u);
  const double diagonal = face_diagonal_to_bcc;  // the same angle, body diagonal to face diagonal
  EXPECT_EQ(std::count_if(eps.begin(), eps.end(), [](double e) { return std::abs(e) < 1e-9; }), 2);
  EXPECT_EQ(std::count_if(eps.begin(), eps.end(), [&](double e) { return std::abs(e - diagonal) < 1e-9; }), 4);
  const Mesh_quality_3 f = compute_mesh_quality(m, Constant_field(), CGAL::parameters::lattice(fcc_lattice()));
  EXPECT_NEAR(f.epsilon.mean, 4. * diagonal / 6., 1e-9);
  EXPECT_NEAR(f.epsilon.std, std::sqrt(2. / 9.) * diagonal, 1e-9);  // values {0,0,d,d,d,d}
}

TEST(TetrahedronQuality, SliverCountsAsBad)
{
  const double h = 0.01;
  const Mesh m = tet_mesh(Point(0, 0, 0), Point(1, 1, 0), Point(1, 0, h), Point(0, 1, h));
  const Mesh_quality_3 q = compute_mesh_quality(m, Constant_field(), CGAL::parameters::lattice(bcc_lattice()));
  EXPECT_LT(q.theta_min.min, 2.);
  EXPECT_GT(q.theta_max.max, 178.);
  EXPECT_LT(q.kappa.min, 0.05);
  // the edge-radius ratio does not see slivers: its four points lie near a circle of radius
  // sqrt(2)/2 and its shortest edge is ~1, so rho ~ sqrt(3)/2
  EXPECT_NEAR(q.rho.min, std::sqrt(3.) / 2., 1e-3);
  EXPECT_EQ(q.below20, 1u);
  EXPECT_EQ(q.below40, 1u);

  // theta_min 32 degrees: below 40 only
  const Mesh m30 = tet_mesh(Point(0, 0, 0), Point(1, 1, 0), Point(1, 0, .3), Point(0, 1, .3));
  const Mesh_quality_3 q30 = compute_mesh_quality(m30, Constant_field(), CGAL::parameters::lattice(bcc_lattice()));
  ASSERT_GT(q30.theta_min.min, 20.);
  ASSERT_LT(q30.theta_min.min, 40.);
  EXPECT_EQ(q30.below20, 0u);
  EXPECT_EQ(q30.below40, 1u);
}

TEST(TetrahedronQuality, DegenerateTetrahedronHasZeroQuality)
{
  const Tetrahedron_quality_3 q = tetrahedron_quality(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                                      Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(q.rho, 0.);
  EXPECT_EQ(q.kappa, 0.);
  EXPECT_NEAR(q.theta_min, 0., 1e-12);
  EXPECT_NEAR(q.theta_max, 180., 1e-12);
}

TEST(TetrahedronQuality, MeasuredInTheIsotropicSpace)
{
  Eigen::Matrix3d t;
  t << 2., .5, 0.,
       0., 1., .3,
       .1, 0., .5;
  const std::array<Eigen::Vector3d, 4> p = { Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, -1, -1),
                                             Eigen::Vector3d(-1, 1, -1), Eigen::Vector3d(-1, -1, 1) };
  auto stretched = [&](int i) { const Eigen::Vector3d q = t * p[i]; return Point(q[0], q[1], q[2]); };
  const Mesh m = tet_mesh(stretched(0), stretched(1), stretched(2), stretched(3));

  const Mesh_quality_3 q = compute_mesh_quality(m, Constant_field(t), CGAL::parameters::lattice(bcc_lattice()));
  EXPECT_NEAR(q.theta_min.min, regular_dihedral, 1e-9);
  EXPECT_NEAR(q.theta_max.max, regular_dihedral, 1e-9);
  EXPECT_NEAR(q.rho.min, 1., 1e-12);
  EXPECT_NEAR(q.kappa.min, 1., 1e-12);
  EXPECT_NEAR(q.epsilon.mean, face_diagonal_to_bcc, 1e-9);

  // measured in physical space, the same tet is far from regular
  const Mesh_quality_3 physical = compute_mesh_quality(m, Constant_field(), CGAL::parameters::lattice(bcc_lattice()));
  EXPECT_LT(physical.theta_min.min, 60.);
  EXPECT_LT(physical.rho.min, 0.9);
}

TEST(TetrahedronQuality, SingularFrameThrows)
{
  const Mesh m = tet_mesh(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1));
  EXPECT_THROW(compute_mesh_quality(m, Constant_field(Eigen::Matrix3d::Zero()), CGAL::parameters::lattice(bcc_lattice())), std::domain_error);
}

TEST(MeshQuality, SameResultForAnyThreadCount)
{
  Mesh m = cube_mesh(6);
  // deterministic jitter, small enough to keep every tet positive
  for(std::size_t i = 0; i < m.points.size(); ++i) {
    const double d = 0.02 * std::sin(12.9898 * double(i));
    m.points[i] = Point(m.points[i].x() + d, m.points[i].y() - .5 * d, m.points[i].z() + .7 * d);
  }
  const Rotation_y_frame_field_3<GT> field(.5);
  auto measure = [&](int threads) {
    return compute_mesh_quality(m, field, CGAL::parameters::lattice(fcc_lattice()).number_of_threads(threads));
  };
  const Mesh_quality_3 a = measure(1), b = measure(2);
  std::ostringstream ja, jb;
  write_quality_json(ja, a);
  write_quality_json(jb, b);
  EXPECT_EQ(ja.str(), jb.str());
  EXPECT_EQ(a.theta_min.mean, b.theta_min.mean);  // bitwise, not just to 10 digits
  EXPECT_EQ(a.kappa.std, b.kappa.std);
  EXPECT_EQ(a.epsilon.mean, b.epsilon.mean);
  EXPECT_EQ(a.tets, 6u * 216u);
  EXPECT_THROW(measure(0), std::invalid_argument);
}

TEST(MeshQuality, JsonHasExactlyTheKeysAndRoundTrips)
{
  Mesh m = cube_mesh(2);
  Mesh_quality_3 q = compute_mesh_quality(m, Constant_field(), CGAL::parameters::lattice(bcc_lattice()));
  q.hausdorff = 0.012345678901;
  q.hausdorff_over_size = 0.75;
  q.edge_length = 0.0625;
  q.seconds.optimize = 1.5;
  q.seconds.mesh = 2.25;
  q.seconds.total = 4.125;
  std::ostringstream os;
  write_quality_json(os, q);
  const std::string json = os.str();

  std::vector<std::string> keys;
  for(std::size_t at = json.find('"'); at != std::string::npos; at = json.find('"', at + 1)) {
    const std::size_t end = json.find('"', at + 1);
    ASSERT_NE(end, std::string::npos);
    EXPECT_EQ(json[end + 1], ':') << "a string that is not a key in " << json;
    keys.push_back(json.substr(at + 1, end - at - 1));
    at = end;
  }
  const std::vector<std::string> expected = {
    "vertices", "tets", "theta_min", "min", "mean", "std", "theta_max", "max", "mean", "std",
    "rho", "min", "mean", "std", "kappa", "min", "mean", "std", "epsilon", "mean", "std",
    "below20", "below40", "hausdorff", "hausdorff_over_size", "edge_length", "seconds", "optimize", "mesh", "total" };
  EXPECT_EQ(keys, expected);
  EXPECT_EQ(std::count(json.begin(), json.end(), '{'), std::count(json.begin(), json.end(), '}'));

  auto section = [&](const char* key) { return json.find(std::string("\"") + key + "\":"); };
  auto near = [](double read, double value) { return std::abs(read - value) <= 1e-9 * (1. + std::abs(value)); };
  EXPECT_EQ(json_number(json, "vertices"), double(q.vertices));
  EXPECT_EQ(json_number(json, "tets"), double(q.tets));
  EXPECT_TRUE(near(json_number(json, "min", section("theta_min")), q.theta_min.min));
  EXPECT_TRUE(near(json_number(json, "mean", section("theta_min")), q.theta_min.mean));
  EXPECT_TRUE(near(json_number(json, "std", section("theta_min")), q.theta_min.std));
  EXPECT_TRUE(near(json_number(json, "max", section("theta_max")), q.theta_max.max));
  EXPECT_TRUE(near(json_number(json, "std", section("theta_max")), q.theta_max.std));
  EXPECT_TRUE(near(json_number(json, "min", section("rho")), q.rho.min));
  EXPECT_TRUE(near(json_number(json, "mean", section("kappa")), q.kappa.mean));
  EXPECT_TRUE(near(json_number(json, "mean", section("epsilon")), q.epsilon.mean));
  EXPECT_TRUE(near(json_number(json, "std", section("epsilon")), q.epsilon.std));
  EXPECT_EQ(json_number(json, "below20"), double(q.below20));
  EXPECT_EQ(json_number(json, "below40"), double(q.below40));
  EXPECT_TRUE(near(json_number(json, "hausdorff"), q.hausdorff));
  EXPECT_EQ(json_number(json, "hausdorff_over_size"), 0.75);
  EXPECT_EQ(json_number(json, "edge_length"), 0.0625);
  EXPECT_EQ(json_number(json, "optimize"), 1.5);
  EXPECT_EQ(json_number(json, "mesh", section("seconds")), 2.25);
  EXPECT_EQ(json_number(json, "total"), 4.125);

  // Kuhn tets: dihedral angles 45, 60 and 90 degrees
  EXPECT_NEAR(q.theta_min.min, 45., 1e-9);
  EXPECT_NEAR(q.theta_max.max, 90., 1e-9);

  std::ostringstream table;
  print_quality_table(table, q);
  EXPECT_NE(table.str().find("theta_min"), std::string::npos);
  EXPECT_NE(table.str().find("45.0000"), std::string::npos);
  EXPECT_NE(table.str().find("0.0123"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Validity check

TEST(CheckMesh, AcceptsCubeMeshes)
{
  for(int n : { 1, 3 }) {
    const Mesh m = cube_mesh(n);
    const Mesh_validity_report r = check_tetrahedral_mesh(m);
    EXPECT_TRUE(r.valid()) << r.message;
    EXPECT_EQ(r.connected_components, 1u);
    EXPECT_EQ(r.unused_vertices, 0u);
    EXPECT_EQ(r.boundary_faces, std::size_t(12 * n * n));
    EXPECT_EQ(r.message.find("invalid"), std::string::npos);
  }
  // order of boundary_faces and rotation of each face do not matter; unused vertices are no error
  Mesh m = cube_mesh(2);
  std::reverse(m.boundary_faces.begin(), m.boundary_faces.end());
  for(auto& f : m.boundary_faces) std::rotate(f.begin(), f.begin() + 1, f.end());
  m.points.emplace_back(5., 5., 5.);
  const Mesh_validity_report r = check_tetrahedral_mesh(m);
  EXPECT_TRUE(r.valid()) << r.message;
  EXPECT_EQ(r.unused_vertices, 1u);
}

TEST(CheckMesh, FlagsInvertedTet)
{
  Mesh m = cube_mesh(2);
  std::swap(m.tets[5][0], m.tets[5][1]);
  const Mesh_validity_report r = check_tetrahedral_mesh(m);
  EXPECT_FALSE(r.valid());
  EXPECT_EQ(r.number_of_non_positive_tets, 1u);
  EXPECT_NE(r.message.find("not positively oriented (first: tet 5"), std::string::npos) << r.message;
}

TEST(CheckMesh, FlagsMissingTetAndWrongBoundaryFaces)
{
  {  // a tet removed, boundary_faces left as they were: a hole in the boundary
    Mesh m = cube_mesh(2);
    m.tets.erase(m.tets.begin() + 7);
    const Mesh_validity_report r = check_tetrahedral_mesh(m);
    EXPECT_FALSE(r.valid());
    EXPECT_GT(r.number_of_missing_boundary_faces + r.number_of_extra_boundary_faces, 0u) << r.message;
  }
  {  // one boundary face dropped
    Mesh m = cube_mesh(2);
    m.boundary_faces.pop_back();
    const Mesh_validity_report r = check_tetrahedral_mesh(m);
    EXPECT_EQ(r.number_of_missing_boundary_faces, 1u);
    EXPECT_FALSE(r.valid());
  }
  {  // one boundary face turned inward, one listed twice
    Mesh m = cube_mesh(2);
    std::swap(m.boundary_faces[3][0], m.boundary_faces[3][1]);
    m.boundary_faces.push_back(m.boundary_faces[0]);
    const Mesh_validity_report r = check_tetrahedral_mesh(m);
    EXPECT_EQ(r.number_of_misoriented_boundary_faces, 1u);
    EXPECT_EQ(r.number_of_extra_boundary_faces, 1u);
    EXPECT_EQ(r.number_of_missing_boundary_faces, 0u);
  }
  {  // an interior face listed as boundary
    Mesh m = cube_mesh(1);
    const auto& t = m.tets[0];
    m.boundary_faces.push_back({ t[1], t[2], t[3] });
    m.boundary_faces.push_back({ t[0], t[3], t[2] });
    const Mesh_validity_report r = check_tetrahedral_mesh(m);
    EXPECT_GE(r.number_of_extra_boundary_faces, 1u);
  }
}

TEST(CheckMesh, FlagsPinchedVertexAndEdge)
{
  {  // two tets sharing only a vertex
    Mesh m;
    m.points = { Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1),
                 Point(-1, 0, 0), Point(0, -1, 0), Point(0, 0, -1) };
    m.tets = { { 0, 1, 2, 3 }, { 0, 4, 5, 6 } };
    orient_and_close(m);
    const Mesh_validity_report r = check_tetrahedral_mesh(m);
    EXPECT_FALSE(r.valid());
    EXPECT_EQ(r.number_of_pinched_vertices, 1u) << r.message;
    EXPECT_EQ(r.number_of_non_manifold_boundary_edges, 0u);
    EXPECT_EQ(r.number_of_missing_boundary_faces + r.number_of_extra_boundary_faces, 0u);
    EXPECT_EQ(r.connected_components, 2u);
    EXPECT_NE(r.message.find("first: vertex 0"), std::string::npos) << r.message;
  }
  {  // two tets sharing only an edge
    Mesh m;
    m.points = { Point(0, 0, 0), Point(0, 0, 1), Point(1, 0, 0), Point(0, 1, 0), Point(-1, 0, 0), Point(0, -1, 0) };
    m.tets = { { 0, 1, 2, 3 }, { 0, 1, 4, 5 } };
    orient_and_close(m);
    const Mesh_validity_report r = check_tetrahedral_mesh(m);
    EXPECT_FALSE(r.valid());
    EXPECT_EQ(r.number_of_non_manifold_boundary_edges, 1u) << r.message;
  }
}

TEST(CheckMesh, FlagsBadIndicesDuplicatesAndKinds)
{
  Mesh m = cube_mesh(1);
  m.tets.push_back(m.tets[2]);
  m.tets.push_back({ 0, 1, 2, 99 });
  m.tets.push_back({ 0, 1, 1, 2 });
  m.vertex_kinds.assign(3, Particle_kind::FREE);
  const Mesh_validity_report r = check_tetrahedral_mesh(m);
  EXPECT_FALSE(r.valid());
  EXPECT_EQ(r.number_of_duplicate_tets, 1u);
  EXPECT_EQ(r.number_of_bad_indices, 1u);
  EXPECT_EQ(r.number_of_degenerate_tets, 1u);
  EXPECT_EQ(r.number_of_bad_vertex_kinds, 1u);
  // the duplicate makes its 4 faces two-tet faces or three-tet faces
  EXPECT_GT(r.number_of_non_manifold_faces + r.number_of_extra_boundary_faces, 0u);
}

// ---------------------------------------------------------------------------------------------
// Files

Mesh jittered_cube_with_kinds()
{
  Mesh m = cube_mesh(2);
  for(std::size_t i = 0; i < m.points.size(); ++i) {
    const double d = 1e-3 * std::sin(78.233 * double(i)) / 3.;  // not a short decimal
    m.points[i] = Point(m.points[i].x() + d, m.points[i].y() + d / 7., m.points[i].z() - d);
    m.vertex_kinds.push_back(Particle_kind(i % 4));
  }
  return m;
}

TEST(Medit, RoundTripIsExact)
{
  for(bool kinds : { true, false }) {
    Mesh m = jittered_cube_with_kinds();
    if(!kinds) m.vertex_kinds.clear();
    std::stringstream ss;
    write_medit(ss, m);
    Mesh r;
    read_medit(ss, r);
    ASSERT_EQ(r.points.size(), m.points.size());
    for(std::size_t i = 0; i < m.points.size(); ++i) EXPECT_EQ(r.points[i], m.points[i]);
    EXPECT_EQ(r.tets, m.tets);
    EXPECT_EQ(r.boundary_faces, m.boundary_faces);
    EXPECT_EQ(r.vertex_kinds, m.vertex_kinds);
  }
}

TEST(Medit, ReadsCgalStyleFilesWithOtherSections)
{
  const std::string text =
    "MeshVersionFormatted 1\n"
    "# a comment line\n"
    "Dimension\n3\n"
    "Vertices\n4\n"
    "0 0 0 7\n1 0 0 7   # trailing comment\n0 1 0 7\n0 0 1 7\n"
    "Corners\n1\n1\n"
    "Edges\n2\n1 2 5\n2 3 5\n"
    "Ridges\n1\n1\n"
    "Triangles\n1\n2 3 4 12\n"
    "Tetrahedra\n1\n1 2 3 4 3\n"
    "End\n";
  std::istringstream is(text);
  Mesh m;
  read_medit(is, m);
  EXPECT_EQ(m.points.size(), 4u);
  EXPECT_EQ(m.points[3], Point(0, 0, 1));
  ASSERT_EQ(m.tets.size(), 1u);
  EXPECT_EQ(m.tets[0], (std::array<int, 4>{ 0, 1, 2, 3 }));
  ASSERT_EQ(m.boundary_faces.size(), 1u);
  EXPECT_EQ(m.boundary_faces[0], (std::array<int, 3>{ 1, 2, 3 }));
  EXPECT_TRUE(m.vertex_kinds.empty());  // references 7 are not particle kinds
}

TEST(Medit, BadFilesThrow)
{
  std::stringstream ss;
  write_medit(ss, cube_mesh(1));
  const std::string text = ss.str();
  auto read = [](const std::string& s) {
    std::istringstream is(s);
    Mesh m;
    read_medit(is, m);
  };
  // truncated anywhere: in a number list, at a section boundary, or just before End
  for(std::size_t cut : { text.size() / 3, text.size() / 2, text.find("Tetrahedra"), text.find("End") })
    EXPECT_THROW(read(text.substr(0, cut)), std::runtime_error) << "cut at " << cut;
  std::string garbled = text;
  garbled.replace(garbled.find("Tetrahedra\n6\n") + 13, 1, "x");
  try {
    read(garbled);
    ADD_FAILURE() << "garbled file read";
  } catch(const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("expected an integer in Tetrahedra"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("line"), std::string::npos) << e.what();
  }
  std::string out_of_range = text;
  out_of_range.replace(out_of_range.find("Tetrahedra\n6\n") + 13, 1, "9");
  EXPECT_THROW(read(out_of_range), std::runtime_error);
  EXPECT_THROW(read("OFF\n3 1 0\n"), std::runtime_error);
  EXPECT_THROW(read(text.substr(0, text.find("End")) + "Pyramids\n0\nEnd\n"), std::runtime_error);

  // a failed read leaves the mesh untouched
  Mesh m = cube_mesh(1);
  std::istringstream is(text.substr(0, text.size() / 2));
  EXPECT_THROW(read_medit(is, m), std::runtime_error);
  EXPECT_EQ(m.tets.size(), 6u);
}

TEST(Vtu, WritesCellArrays)
{
  const Mesh m = jittered_cube_with_kinds();
  const std::vector<Tetrahedron_quality_3> q = compute_tetrahedra_quality(m, Constant_field());
  std::vector<double> theta_min;
  for(const auto& t : q) theta_min.push_back(t.theta_min);
  std::ostringstream os;
  write_vtu(os, m, { { "theta_min", theta_min }, { "a<b>&\"c\"", std::vector<double>(m.tets.size(), 1.) } });
  const std::string vtu = os.str();
  EXPECT_NE(vtu.find("NumberOfPoints=\"27\" NumberOfCells=\"48\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"theta_min\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"a&lt;b&gt;&amp;&quot;c&quot;\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"particle_kind\""), std::string::npos);
  EXPECT_EQ(vtu.rfind("</VTKFile>\n"), vtu.size() - 11);

  std::ostringstream bad;
  EXPECT_THROW(write_vtu(bad, m, { { "short", std::vector<double>(3, 0.) } }), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Hausdorff distance

TEST(Hausdorff, CubeMeshAgainstCubeSurface)
{
  const Unit_cube_domain cube;
  EXPECT_LT(boundary_hausdorff_distance(cube_mesh(3), cube, 0.05), 1e-12);
  // shifted by 0.1 along x: the faces x = 0 and x = 1 are 0.1 away, nothing is farther
  EXPECT_NEAR(boundary_hausdorff_distance(cube_mesh(3, 1., .1), cube, 0.05), .1, 1e-12);
  // a smaller cube in the corner: the surface point (1,1,1) is sqrt(3) * 0.2 from it
  EXPECT_NEAR(boundary_hausdorff_distance(cube_mesh(2, .8), cube, 0.05), .2 * std::sqrt(3.), 1e-12);
  EXPECT_THROW(boundary_hausdorff_distance(cube_mesh(1), cube, 0.), std::invalid_argument);
}

// Relative to a size: the shifted cube's faces x = 0 and x = 1 are 0.1 away, the size there 0.5
// and 0.25 (h = 0.5 - 0.25 x).
TEST(Hausdorff, RelativeToTheLocalSize)
{
  const Unit_cube_domain cube;
  auto size = [](const Point& p) { return .5 - .25 * p.x(); };
  const Boundary_distances_3<Point> shifted = boundary_distances(cube_mesh(3, 1., .1), cube, 0.05, size);
  EXPECT_NEAR(shifted.hausdorff, .1, 1e-12);
  // at x = 1.1 on the mesh (size 0.225) and x = 1 on the surface (0.25): the mesh's side counts
  EXPECT_NEAR(shifted.over_size, .1 / .225, 1e-12);
  EXPECT_FALSE(shifted.worst_on_surface);
  EXPECT_NEAR(shifted.worst_sample.x(), 1.1, 1e-12);
  // the mesh shifted the other way: the surface's face x = 1 (size 0.25) is 0.1 from the mesh,
  // the mesh's face x = -0.1 (size 0.525) 0.1 from the surface
  const Boundary_distances_3<Point> back = boundary_distances(cube_mesh(3, 1., -.1), cube, 0.05, size);
  EXPECT_NEAR(back.over_size, .1 / .25, 1e-12);
  EXPECT_TRUE(back.worst_on_surface);
  EXPECT_NEAR(back.worst_sample.x(), 1., 1e-12);
  EXPECT_LT(boundary_distances(cube_mesh(3), cube, 0.05, size).over_size, 1e-12);
  // on one thread or two, the same
  const Boundary_distances_3<Point> one = boundary_distances(cube_mesh(3, 1., .1), cube, 0.05, size, CGAL::parameters::number_of_threads(1));
  EXPECT_EQ(one.hausdorff, shifted.hausdorff);
  EXPECT_EQ(one.over_size, shifted.over_size);
  EXPECT_THROW(boundary_distances(cube_mesh(3), cube, 0.05, size, CGAL::parameters::number_of_threads(0)), std::invalid_argument);
}

} // namespace
