// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Connectivity under a varying stretch: the isotropic embedding recovers a flat metric, the
// Delaunay tetrahedralization in it follows the field where the Euclidean one does not, the
// shape flips lower the lattice shape energy, an inverted sliver folded on a flat boundary is
// flipped away, and the whole pipeline aligns an FCC mesh with the field of the paper's fig. 8.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/lattice_mesh_3.h>
#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/check_mesh.h>
#include <CGAL/Lattice_mesher_3/flip_tetrahedra.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/internal/isotropic_embedding.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>
#include <CGAL/Lattice_mesher_3/tetrahedralize_particles.h>
#include <CGAL/Lattice_mesher_traits_3.h>

#include <gtest/gtest.h>

#include "test_meshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <set>
#include <vector>

namespace {

namespace LM = CGAL::Lattice_mesher_3;
typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Lattice_mesher_traits_3<K> Traits;
typedef LM::Polyhedral_lattice_domain_3<K> Domain;
typedef LM::Planar_layer_frame_field_3<Traits> Fig8_field;
typedef LM::internal::Vec3 Vec3;
typedef LM::Tetrahedral_mesh_3<Point_3> Mesh;

const double lo = 0.1, hi = 1.1;   // fig8's cube
const double a8 = 1.0125;          // fig8: T_xx = a8 - exp(-|x - 0.6|)

const Domain& fig8_cube()
{
  static const Domain d(LM::make_cube_surface_3<K>(lo, hi));
  return d;
}

// fig8's isotropic x coordinate, the exact integral of B_xx = 1 / (a8 - exp(-|x - 0.6|)) from 0.6
double fig8_s(double x)
{
  const double u = std::abs(x - 0.6);
  const double s = (std::log(a8 * std::exp(u) - 1.) - std::log(a8 - 1.)) / a8;
  return x < 0.6 ? -s : s;
}

// its inverse
double fig8_x(double s)
{
  const double u = std::log((1. + (a8 - 1.) * std::exp(a8 * std::abs(s))) / a8);
  return s < 0. ? 0.6 - u : 0.6 + u;
}

// Particles of a BCC lattice in fig8's isotropic coordinates (s, y, z), mapped back to x: cube
// corners at (s_min + i h, lo + j l, lo + k l), with an even number of cells along s so that a
// lattice plane lies on the kink x = 0.6 of the field, and cube centres in between. Corners of
// the domain are FIXED (feature: the corner's index in the domain), particles on two faces
// SHARP_EDGE, on one face BOUNDARY, the others (the centres) FREE. `iso` receives the
// isotropic coordinates of each particle.
LM::Particle_set_3<Point_3> fig8_lattice(double l, std::vector<Vec3>& iso, double jitter = 0., unsigned int seed = 1)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> delta(-jitter, jitter);
  const double s_min = fig8_s(lo), s_max = fig8_s(hi);
  int nx = int(std::lround((s_max - s_min) / l));
  nx += nx % 2;
  const int n = int(std::lround((hi - lo) / l));
  const double h = (s_max - s_min) / nx, g = (hi - lo) / n;
  LM::Particle_set_3<Point_3> ps;
  iso.clear();
  auto add = [&](double s, double y, double z, int on) {
    if(on == 0 && jitter > 0.) { s += delta(random) * h; y += delta(random) * g; z += delta(random) * g; }
    const Point_3 p(fig8_x(s), y, z);
    int corner = -1;
    if(on == 3)
      for(std::size_t c = 0; c < fig8_cube().corners().size(); ++c)
        if(CGAL::squared_distance(fig8_cube().corners()[c], p) < 1e-20) corner = int(c);
    ps.push_back(on == 3 ? fig8_cube().corners()[corner] : p, test_meshes::box_particle_kind(on), corner);
    iso.emplace_back(s, y, z);
  };
  // the end coordinates exactly on the cube's faces
  auto sc = [&](int i) { return i == 0 ? s_min : i == nx ? s_max : s_min + i * h; };
  auto yc = [&](int j) { return j == 0 ? lo : j == n ? hi : lo + j * g; };
  for(int i = 0; i <= nx; ++i) for(int j = 0; j <= n; ++j) for(int k = 0; k <= n; ++k)
    add(sc(i), yc(j), yc(k), (i == 0 || i == nx) + (j == 0 || j == n) + (k == 0 || k == n));
  for(int i = 0; i < nx; ++i) for(int j = 0; j < n; ++j) for(int k = 0; k < n; ++k)
    add(s_min + (i + .5) * h, lo + (j + .5) * g, lo + (k + .5) * g, 0);
  return ps;
}

std::size_t non_positive(const Mesh& mesh)
{
  std::size_t count = 0;
  for(const auto& t : mesh.tets)
    count += CGAL::orientation(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]) != CGAL::POSITIVE;
  return count;
}

// ---------------------------------------------------------------------------------------------
// Isotropic embedding

TEST(Isotropic_embedding, FlatLayeredMetricIsRecovered)
{
  const double l = 0.2;
  std::vector<Vec3> iso;
  const LM::Particle_set_3<Point_3> ps = fig8_lattice(l, iso);
  const std::vector<Vec3> x = LM::internal::to_vectors(ps.points);
  ASSERT_GT(x.size(), 2000u);
  bool uniform = true;
  const std::vector<Vec3> y = LM::internal::isotropic_embedding<K>(x, Fig8_field(), 1.3 * l, 2, uniform);
  ASSERT_EQ(y.size(), x.size());
  EXPECT_FALSE(uniform);

  // every pair of lattice neighbours (isotropic distance <= 1.1 l): the embedded vector is the
  // isotropic one; the physical one (what a Euclidean Delaunay sees) is far from it
  std::vector<double> errors, euclidean;
  double worst_relative = 0.;   // over all pairs: the embedding is globally flat
  for(std::size_t i = 0; i < x.size(); ++i)
    for(std::size_t j = i + 1; j < x.size(); ++j) {
      const Vec3 d = iso[i] - iso[j];
      const double e = (y[i] - y[j] - d).norm();
      worst_relative = (std::max)(worst_relative, e / d.norm());
      if(d.norm() > 1.1 * l) continue;
      errors.push_back(e / l);
      euclidean.push_back((x[i] - x[j] - d).norm() / l);
    }
  ASSERT_GT(errors.size(), 10000u);
  std::sort(errors.begin(), errors.end());
  std::sort(euclidean.begin(), euclidean.end());
  const double max = errors.back(), median = errors[errors.size() / 2];
  std::cout << "  neighbour pairs " << errors.size() << ": error / l max " << max << ", median " << median
            << "; all pairs: max relative error " << worst_relative << "; Euclidean: max "
            << euclidean.back() << ", median " << euclidean[euclidean.size() / 2] << "\n";
  // the largest errors are at the kink x = 0.6 of the field, where the midpoint rule is off by
  // 5% for the pairs that straddle it and the least squares spreads that over their neighbours
  EXPECT_LT(max, 0.03);
  EXPECT_LT(median, 0.003);
  EXPECT_LT(worst_relative, 0.03);
  // the test discriminates: the physical positions are off by most of an edge
  EXPECT_GT(euclidean[euclidean.size() / 2], 0.1);
  EXPECT_GT(euclidean.back(), 0.9);
}

TEST(Isotropic_embedding, CrossFieldKeepsPositions)
{
  std::mt19937 g(11);
  std::uniform_real_distribution<double> u(-1., 2.);
  std::vector<Vec3> x(300);
  for(Vec3& p : x) p = Vec3(u(g), u(g), u(g));

  // cross fields: rotations, varying or constant, of any cube size; the metric is Euclidean
  // (up to a uniform scale, which changes no Delaunay test): x itself, bit for bit
  Traits::Matrix_3 r;
  const double c = std::cos(0.7), s = std::sin(0.7);
  r << c, -s, 0., s, c, 0., 0., 0., 1.;
  bool uniform = false;
  std::vector<Vec3> y = LM::internal::isotropic_embedding<K>(x, LM::Rotation_y_frame_field_3<Traits>(), 0.3, 2, uniform);
  EXPECT_TRUE(uniform);
  EXPECT_EQ(y, x);
  uniform = false;
  y = LM::internal::isotropic_embedding<K>(x, LM::Rotation_y_frame_field_3<Traits>(0.25), 0.3, 2, uniform);
  EXPECT_TRUE(uniform);
  EXPECT_EQ(y, x);
  uniform = false;
  y = LM::internal::isotropic_embedding<K>(x, LM::Constant_frame_field_3<Traits>(r), 0.3, 2, uniform);
  EXPECT_TRUE(uniform);
  EXPECT_EQ(y, x);

  // a constant stretch: x mapped by the metric root, B = diag(20, 1, 1)
  const Traits::Matrix_3 t = Eigen::Vector3d(0.05, 1., 1.).asDiagonal();
  uniform = false;
  y = LM::internal::isotropic_embedding<K>(x, LM::Constant_frame_field_3<Traits>(t), 0.3, 2, uniform);
  EXPECT_TRUE(uniform);
  ASSERT_EQ(y.size(), x.size());
  for(std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_NEAR(y[i][0], 20. * x[i][0], 1e-12);
    EXPECT_NEAR(y[i][1], x[i][1], 1e-12);
    EXPECT_NEAR(y[i][2], x[i][2], 1e-12);
  }
  // the same stretch rotated: the rotation is dropped, the metric kept
  const Traits::Matrix_3 rt = r * t;   // stretched along r e_x: B^T B = r diag(400, 1, 1) r^T
  y = LM::internal::isotropic_embedding<K>(x, LM::Constant_frame_field_3<Traits>(rt), 0.3, 2, uniform);
  EXPECT_TRUE(uniform);
  const Eigen::Matrix3d root = LM::internal::metric_root(rt.inverse());
  EXPECT_NEAR((root.transpose() * root - (rt * rt.transpose()).inverse()).norm(), 0., 1e-10);
  for(std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR((y[i] - root * x[i]).norm(), 0., 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Tetrahedralization

TEST(Tetrahedralize_particles, Fig8ConnectivityFollowsTheField)
{
  // Jittered by 5% of the cell in the isotropic space: the Delaunay tetrahedralization of the
  // perfect lattice happens to be the same in both spaces (an axis-aligned BCC lattice keeps its
  // combinatorics under a stretch along x), that of a slightly perturbed one does not.
  const double l = 0.2;
  std::vector<Vec3> iso;
  const LM::Particle_set_3<Point_3> ps = fig8_lattice(l, iso, 0.05);
  const Fig8_field field;
  const LM::Lattice_3 bcc = LM::make_lattice(LM::Lattice_type::BCC);
  const auto np = CGAL::parameters::edge_length(l).number_of_threads(2);

  const Mesh mesh = LM::tetrahedralize_particles(ps, fig8_cube(), field, np);
  const LM::Mesh_validity_report v = LM::check_tetrahedral_mesh(mesh);
  EXPECT_TRUE(v.valid()) << v.message;
  EXPECT_EQ(non_positive(mesh), 0u);
  EXPECT_EQ(mesh.points.size(), ps.size());
  const LM::Mesh_quality_3 q = LM::compute_mesh_quality(mesh, field, CGAL::parameters::lattice(bcc));

  // the same particles, Euclidean Delaunay, measured in the same (fig8's isotropic) space
  const Mesh euclidean = LM::tetrahedralize_particles(ps, fig8_cube(), LM::Constant_frame_field_3<Traits>(), np);
  EXPECT_TRUE(LM::check_tetrahedral_mesh(euclidean).valid());
  const LM::Mesh_quality_3 qe = LM::compute_mesh_quality(euclidean, field, CGAL::parameters::lattice(bcc));

  std::cout << "  fig8 BCC lattice, " << ps.size() << " particles: embedding: " << q.tets << " tets, theta_min mean "
            << q.theta_min.mean << " min " << q.theta_min.min << ", below 40: " << q.below40 << ", epsilon mean "
            << q.epsilon.mean << "; Euclidean: " << qe.tets << " tets, theta_min mean " << qe.theta_min.mean
            << " min " << qe.theta_min.min << ", below 40: " << qe.below40 << ", epsilon mean " << qe.epsilon.mean << "\n";
  EXPECT_GT(q.theta_min.mean, 50.);
  EXPECT_LT(qe.theta_min.mean, 40.);
  EXPECT_LT(q.below40, q.tets / 100);
  EXPECT_GT(qe.below40, qe.tets / 2);
}

// ---------------------------------------------------------------------------------------------
// Flips

using test_meshes::unit_cube;
using test_meshes::jittered_mesh;

template <typename Field>
double shape_energy(const Mesh& mesh, const Field& field, const LM::Lattice_3& lattice, double l)
{
  double e = 0.;
  for(std::size_t t = 0; t < mesh.tets.size(); ++t)
    e += LM::lattice_shape_energy(LM::internal::isotropic_tetrahedron(mesh, field, t), lattice, l);
  return e;
}

template <typename Field>
double worst_angle(const Mesh& mesh, const Field& field)
{
  double worst = 180.;
  for(const auto& q : LM::compute_tetrahedra_quality(mesh, field)) worst = (std::min)(worst, q.theta_min);
  return worst;
}

using test_meshes::sorted_faces;

TEST(Flip_tetrahedra, ShapeFlipsNeverRaiseTheShapeEnergyNorInvert)
{
  const int n = 6;
  const double l = 1. / n;
  Traits::Matrix_3 t;
  t << 1.5, 0.2, 0., 0., 1., 0., 0., 0.1, 0.7;
  for(unsigned int seed : { 1u, 2u, 3u })
    for(LM::Lattice_type type : { LM::Lattice_type::BCC, LM::Lattice_type::FCC })
      for(bool stretched : { false, true }) {
        const LM::Constant_frame_field_3<Traits> field = stretched ? LM::Constant_frame_field_3<Traits>(t)
                                                                   : LM::Constant_frame_field_3<Traits>();
        Mesh mesh = jittered_mesh(seed, n);
        ASSERT_TRUE(LM::check_tetrahedral_mesh(mesh).valid());
        const std::set<std::array<int, 3> > boundary = sorted_faces(mesh);
        const LM::Lattice_3 lattice = LM::make_lattice(type);
        const double before = shape_energy(mesh, field, lattice, l), worst_before = worst_angle(mesh, field);
        // no angle pass: only the shape flips (and inverted tets, of which there are none)
        const LM::Flip_result r = LM::flip_tetrahedra(mesh, field, CGAL::parameters::lattice(type).edge_length(l).target_angle(0.));
        const double after = shape_energy(mesh, field, lattice, l);
        SCOPED_TRACE(testing::Message() << "seed " << seed << ", " << lattice.name << ", field "
                                        << (stretched ? "stretched" : "identity"));
        EXPECT_GT(r.total(), 0u);
        EXPECT_EQ(r.boundary_flips, 0u);
        EXPECT_LE(after, before);
        EXPECT_LT(after, before - 1e-6 * before);
        // a shape flip keeps the smallest angle of what it replaces above min(that angle, floor)
        EXPECT_GE(worst_angle(mesh, field), (std::min)(worst_before, 40.) - 1e-9);
        EXPECT_EQ(non_positive(mesh), 0u);
        const LM::Mesh_validity_report v = LM::check_tetrahedral_mesh(mesh);
        EXPECT_TRUE(v.valid()) << v.message;
        EXPECT_EQ(sorted_faces(mesh), boundary);
        if(seed == 1u)
          std::cout << "  seed 1, " << lattice.name << (stretched ? ", stretched" : ", identity") << ": " << r.total() << " flips, shape energy " << before << " -> " << after << "\n";
      }
}

// Two tetrahedra on the plane z = 0: (a, b, c, d) and (a, c, e, d) sharing (a, c, d), with the
// boundary faces (a, b, c) and (c, a, e) in the plane. Folded: b moved across ac to e's side,
// just off the segment, so that (a, b, c, d) is inverted and the boundary triangle (a, b, c)
// lies folded over (c, a, e). No interior flip undoes that; the 2-2 flip of the boundary edge ac
// does: (a, b, e, d) and (b, c, e, d), with (a, b, e) and (b, c, e) on the boundary.
Mesh folded_pair(double by)
{
  Mesh m;
  enum { A, B, C, D, E };
  m.points = { Point_3(0, 0, 0), Point_3(0.5, by, 0), Point_3(1, 0, 0), Point_3(0.5, 0.2, 0.6), Point_3(0.5, 1, 0) };
  m.tets = { { A, B, C, D }, { A, C, E, D } };
  // outward when unfolded (by < 0)
  m.boundary_faces = { { A, C, B }, { C, A, E }, { A, B, D }, { B, C, D }, { C, E, D }, { E, A, D } };
  m.vertex_kinds.assign(5, LM::Particle_kind::BOUNDARY);
  return m;
}

TEST(Flip_tetrahedra, InvertedSliverOnFlatBoundaryIsFlippedAway)
{
  const LM::Constant_frame_field_3<Traits> field;
  const auto o = CGAL::parameters::target_angle(0.);   // only inverted tetrahedra

  // the unfolded pair is valid, and nothing is flipped
  Mesh unfolded = folded_pair(-0.3);
  ASSERT_TRUE(LM::check_tetrahedral_mesh(unfolded).valid()) << LM::check_tetrahedral_mesh(unfolded).message;
  const Mesh copy = unfolded;
  EXPECT_EQ(LM::flip_tetrahedra(unfolded, field, o).total(), 0u);
  EXPECT_EQ(unfolded.tets, copy.tets);
  EXPECT_EQ(unfolded.boundary_faces, copy.boundary_faces);

  // folded: one inverted tetrahedron, flipped away by one boundary 2-2 flip
  Mesh folded = folded_pair(0.02);
  const LM::Mesh_validity_report before = LM::check_tetrahedral_mesh(folded);
  EXPECT_EQ(before.number_of_non_positive_tets, 1u);
  EXPECT_EQ(non_positive(folded), 1u);
  const LM::Flip_result r = LM::flip_tetrahedra(folded, field, o);
  EXPECT_EQ(r.boundary_flips, 1u);
  EXPECT_EQ(r.total(), 1u);
  EXPECT_EQ(non_positive(folded), 0u);
  const LM::Mesh_validity_report after = LM::check_tetrahedral_mesh(folded);
  EXPECT_TRUE(after.valid()) << after.message;
  EXPECT_EQ(folded.tets.size(), 2u);
  enum { A, B, C, D, E };
  std::set<std::array<int, 4> > tets;
  for(auto t : folded.tets) { std::sort(t.begin(), t.end()); tets.insert(t); }
  EXPECT_EQ(tets, (std::set<std::array<int, 4> >{ { A, B, D, E }, { B, C, D, E } }));
  EXPECT_EQ(sorted_faces(folded), (std::set<std::array<int, 3> >{ { A, B, D }, { A, B, E }, { A, D, E },
                                                                  { B, C, D }, { B, C, E }, { C, D, E } }));
  // the volume is the signed volume of the folded pair
  auto volume = [](const Mesh& m) {
    double v = 0.;
    for(const auto& t : m.tets) v += CGAL::volume(m.points[t[0]], m.points[t[1]], m.points[t[2]], m.points[t[3]]);
    return v;
  };
  EXPECT_NEAR(volume(folded), volume(folded_pair(0.02)), 1e-15);
}

// Not folded but thin: b just off ac, so that (a, b, c, d) is a cap of the thin boundary triangle
// (a, b, c), below 40 degrees whatever the interior does. The 2-2 flip of ac on the flat boundary
// removes it; off a plane (e lifted) the boundary is kept as it is.
TEST(Flip_tetrahedra, CapOfThinTriangleOnFlatBoundaryIsFlippedAway)
{
  const LM::Constant_frame_field_3<Traits> field;
  const auto o = CGAL::parameters::default_values();
  const double floor_angle = 40.;   // flip_tetrahedra()'s default
  enum { A, B, C, D, E };
  Mesh thin = folded_pair(-0.02);
  ASSERT_TRUE(LM::check_tetrahedral_mesh(thin).valid());
  const double before = worst_angle(thin, field);
  ASSERT_LT(before, floor_angle);
  const LM::Flip_result r = LM::flip_tetrahedra(thin, field, o);
  EXPECT_EQ(r.boundary_flips, 1u);
  EXPECT_EQ(r.total(), 1u);
  const LM::Mesh_validity_report v = LM::check_tetrahedral_mesh(thin);
  EXPECT_TRUE(v.valid()) << v.message;
  EXPECT_GT(worst_angle(thin, field), before + 10.);
  std::set<std::array<int, 4> > tets;
  for(auto t : thin.tets) { std::sort(t.begin(), t.end()); tets.insert(t); }
  EXPECT_EQ(tets, (std::set<std::array<int, 4> >{ { A, B, D, E }, { B, C, D, E } }));
  std::cout << "  cap of a thin boundary triangle: smallest angle " << before << " -> " << worst_angle(thin, field) << "\n";

  // disabled, or the two boundary faces not in one plane: nothing to flip
  const auto off = CGAL::parameters::boundary_flatness(0.);
  Mesh kept = folded_pair(-0.02);
  EXPECT_EQ(LM::flip_tetrahedra(kept, field, off).total(), 0u);
  EXPECT_EQ(kept.tets, folded_pair(-0.02).tets);
  Mesh bent = folded_pair(-0.02);
  bent.points[E] = Point_3(0.5, 1, 0.01);
  ASSERT_TRUE(LM::check_tetrahedral_mesh(bent).valid());
  EXPECT_EQ(LM::flip_tetrahedra(bent, field, o).boundary_flips, 0u);
  EXPECT_EQ(bent.boundary_faces, folded_pair(-0.02).boundary_faces);
}

// ---------------------------------------------------------------------------------------------
// The whole pipeline

// The whole pipeline on fig8 at 2,500 vertices, two threads, measured in the field's isotropic space.
LM::Mesh_quality_3 fig8_pipeline(LM::Lattice_type lattice)
{
  const Fig8_field field;
  const Mesh mesh = CGAL::lattice_mesh_3(fig8_cube(), field, CGAL::parameters::number_of_vertices(2500)
                                                               .lattice(lattice).number_of_threads(2));
  const LM::Mesh_validity_report v = LM::check_tetrahedral_mesh(mesh);
  EXPECT_TRUE(v.valid()) << v.message;
  const LM::Mesh_quality_3 q = LM::compute_mesh_quality(mesh, field, CGAL::parameters::lattice(LM::make_lattice(lattice)));
  std::cout << "  fig8 " << LM::make_lattice(lattice).name << ": " << q.vertices << " vertices, " << q.tets
            << " tets, theta_min mean " << q.theta_min.mean << " min " << q.theta_min.min << ", below 40: "
            << q.below40 << ", epsilon mean " << q.epsilon.mean << "\n";
  EXPECT_NEAR(double(q.vertices), 2500., 500.);
  return q;
}

// the paper's figures (Table 4)
TEST(Lattice_mesh_3, Fig8BccAlignment)
{
  const LM::Mesh_quality_3 q = fig8_pipeline(LM::Lattice_type::BCC);
  EXPECT_LT(q.epsilon.mean, 3.09);
  EXPECT_GT(q.theta_min.mean, 56.95);
  EXPECT_EQ(q.below40, 0u);
  EXPECT_GE(q.theta_min.min, 36.88);
}

TEST(Lattice_mesh_3, Fig8FccAlignment)
{
  const LM::Mesh_quality_3 q = fig8_pipeline(LM::Lattice_type::FCC);
  EXPECT_LT(q.epsilon.mean, .78);
  EXPECT_GT(q.theta_min.mean, 58.75);
  EXPECT_EQ(q.below40, 0u);
  EXPECT_GE(q.theta_min.min, 52.85);
}

// fig9 (the cube [1, 11]^3, radial stretch up to 20): the cells between an edge's two faces are
// wedges whose centroid lies within a tenth of their mean edge of the surface; dropped as flat,
// they left 4 edges chamfered at this count (8 boundary faces across two cube faces, 0.32 of the
// volume missing). The mesh fills the cube exactly.
TEST(Lattice_mesh_3, Fig9BccKeepsTheCubesEdges)
{
  const LM::Cylindrical_layer_frame_field_3<Traits> field;
  const Mesh mesh = CGAL::lattice_mesh_3(Domain(LM::make_cube_surface_3<K>(1., 11.)), field,
                                         CGAL::parameters::number_of_vertices(2500).number_of_threads(2));
  const LM::Mesh_validity_report v = LM::check_tetrahedral_mesh(mesh);
  ASSERT_TRUE(v.valid()) << v.message;
  double volume = 0.;
  for(const auto& t : mesh.tets) volume += CGAL::volume(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]);
  EXPECT_NEAR(volume, 1000., 1e-9);
  std::size_t across = 0;   // boundary faces whose vertices do not share a face of the cube
  for(const auto& f : mesh.boundary_faces) {
    bool shared = false;
    for(int a = 0; a < 3; ++a)
      for(double side : { 1., 11. }) {
        bool all = true;
        for(int v : f) all = all && std::abs(mesh.points[v][a] - side) < 1e-12;
        shared = shared || all;
      }
    across += !shared;
  }
  EXPECT_EQ(across, 0u);
}

} // namespace
