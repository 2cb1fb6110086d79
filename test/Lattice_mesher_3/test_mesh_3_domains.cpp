// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh_3 domains as users have them, passed to lattice_mesh_3() as they are: a polyhedral
// domain with its detected features, an implicit Labeled_mesh_domain_3, and one with a feature
// curve added by the user.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/lattice_mesh_3.h>
#include <CGAL/Lattice_mesher_3/Implicit_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/check_mesh.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>
#include <CGAL/IO/File_medit.h>
#include <CGAL/IO/output_to_vtu.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/odt_optimize_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>
#include <CGAL/tetrahedral_remeshing.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>
#include <vector>

namespace {

namespace LM = CGAL::Lattice_mesher_3;
typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef K::FT FT;
typedef CGAL::Lattice_mesher_traits_3<K> Traits;
typedef LM::Constant_frame_field_3<Traits> Field;

bool has_vertex_at(const LM::Tetrahedral_mesh_3<Point_3>& mesh, const Point_3& p, double tolerance)
{
  for(const Point_3& q : mesh.points)
    if(CGAL::squared_distance(p, q) <= tolerance * tolerance) return true;
  return false;
}

// The cube [0, 1]^3 as a Polyhedral_mesh_domain_with_features_3: its 12 edges are detected,
// and the mesh keeps the 8 corners and stays within the cube.
TEST(Mesh_3_domains, PolyhedralDomainWithFeatures)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Mesh> Domain;
  Domain domain(LM::make_cube_surface_3<K>(0., 1.));
  domain.detect_features();
  const LM::Polyhedral_lattice_domain_3<K> converted = LM::make_lattice_domain_3(domain, CGAL::parameters::edge_length(.2));
  EXPECT_EQ(converted.corners().size(), 8u);
  EXPECT_NEAR(converted.curves_length(), 12., 1e-9);
  EXPECT_NEAR(converted.volume(), 1., 1e-9);

  const auto mesh = CGAL::lattice_mesh_3(domain, Field(), CGAL::parameters::edge_length(.2).number_of_threads(2));
  const LM::Mesh_validity_report r = LM::check_tetrahedral_mesh(mesh);
  EXPECT_TRUE(r.valid()) << r.message;
  for(int i = 0; i < 8; ++i)
    EXPECT_TRUE(has_vertex_at(mesh, Point_3(i & 1, (i >> 1) & 1, (i >> 2) & 1), 1e-9)) << "corner " << i;
  double volume = 0.;
  for(const auto& t : mesh.tets)
    volume += CGAL::volume(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]);
  EXPECT_NEAR(volume, 1., 1e-6);
  EXPECT_GE(LM::compute_mesh_quality(mesh, Field(), CGAL::parameters::lattice(LM::make_lattice(LM::Lattice_type::BCC))).theta_min.min, 30.);
  // the domain's own indices: its subdomain, and one of its patches for each side of the cube
  EXPECT_EQ(std::set<int>(mesh.subdomains.begin(), mesh.subdomains.end()), std::set<int>{ 1 });
  ASSERT_EQ(mesh.boundary_patches.size(), mesh.boundary_faces.size());
  EXPECT_EQ(std::set<int>(mesh.boundary_patches.begin(), mesh.boundary_patches.end()).size(), 6u);
}

FT unit_sphere(const Point_3& p) { return p.x() * p.x() + p.y() * p.y() + p.z() * p.z() - 1.; }

// The unit ball as an implicit Labeled_mesh_domain_3: Mesh_3 samples its surface, and the
// mesh's boundary vertices lie on the sphere.
TEST(Mesh_3_domains, ImplicitLabeledDomain)
{
  typedef CGAL::Labeled_mesh_domain_3<K> Domain;
  const Domain domain = Domain::create_implicit_mesh_domain(unit_sphere, K::Sphere_3(CGAL::ORIGIN, 4.));
  const double l = .25;
  const auto mesh = CGAL::lattice_mesh_3(domain, Field(), CGAL::parameters::edge_length(l).number_of_threads(2));
  const LM::Mesh_validity_report r = LM::check_tetrahedral_mesh(mesh);
  EXPECT_TRUE(r.valid()) << r.message;
  double volume = 0., farthest = 0.;
  for(const auto& t : mesh.tets)
    volume += CGAL::volume(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]);
  for(const auto& f : mesh.boundary_faces)
    for(int v : f) farthest = (std::max)(farthest, std::abs(std::sqrt(CGAL::to_double(unit_sphere(mesh.points[v]) + 1.)) - 1.));
  EXPECT_LE(farthest, l / 25.);
  // an inscribed polyhedron: inside the ball, and its facets (edges below 1.5 l) leave it by
  // less than the sagitta (1.5 l)^2 / 8
  EXPECT_LE(volume, 4. / 3. * CGAL_PI);
  EXPECT_GE(volume, 4. / 3. * CGAL_PI - 4. * CGAL_PI * (1.5 * l) * (1.5 * l) / 8.);
  // one patch (between subdomain 1 and the outside, numbered 1), one subdomain (label 1)
  EXPECT_EQ(mesh.boundary_patches, std::vector<int>(mesh.boundary_faces.size(), 1));
  EXPECT_EQ(mesh.subdomains, std::vector<int>(mesh.tets.size(), 1));
  EXPECT_GE(LM::compute_mesh_quality(mesh, Field(), CGAL::parameters::lattice(LM::make_lattice(LM::Lattice_type::BCC))).theta_min.min, 15.);

  // with number_of_vertices, the sampling follows the l* of the count
  const auto counted = CGAL::lattice_mesh_3(domain, Field(), CGAL::parameters::number_of_vertices(2000).number_of_threads(2));
  EXPECT_TRUE(LM::check_tetrahedral_mesh(counted).valid());
  EXPECT_NEAR(double(counted.points.size()), 2000., 400.);
}

// A cylinder (implicit) whose two rim circles the user adds as features: they become curves
// of the lattice domain, and the mesh keeps vertices on them.
FT cylinder(const Point_3& p) { return (std::max)(p.x() * p.x() + p.y() * p.y() - 1., std::abs(p.z()) - 1.); }

TEST(Mesh_3_domains, AddedFeatureCurves)
{
  typedef CGAL::Mesh_domain_with_polyline_features_3<CGAL::Labeled_mesh_domain_3<K> > Domain;
  Domain domain = Domain::create_implicit_mesh_domain(cylinder, K::Sphere_3(CGAL::ORIGIN, 9.));
  std::vector<std::vector<Point_3> > rims(2);
  for(int z = 0; z < 2; ++z) {
    for(int i = 0; i <= 360; ++i)
      rims[z].push_back(Point_3(std::cos(i * CGAL_PI / 180.), std::sin(i * CGAL_PI / 180.), z ? 1. : -1.));
    rims[z].back() = rims[z].front();
  }
  domain.add_features(rims.begin(), rims.end());
  const double l = .25;
  const LM::Polyhedral_lattice_domain_3<K> converted = LM::make_lattice_domain_3(domain, CGAL::parameters::edge_length(l));
  ASSERT_EQ(converted.number_of_curves(), 2u);
  EXPECT_NEAR(converted.curves_length(), 4. * CGAL_PI, .01);

  const auto mesh = CGAL::lattice_mesh_3(domain, Field(), CGAL::parameters::edge_length(l).number_of_threads(2));
  const LM::Mesh_validity_report r = LM::check_tetrahedral_mesh(mesh);
  EXPECT_TRUE(r.valid()) << r.message;
  // the rims are edges of the mesh: vertices on them about l apart
  std::size_t on_rims = 0;
  for(const Point_3& p : mesh.points)
    if(std::abs(std::abs(p.z()) - 1.) < 1e-3 && std::abs(std::hypot(p.x(), p.y()) - 1.) < 1e-3) ++on_rims;
  EXPECT_GE(double(on_rims), .7 * 4. * CGAL_PI / l);
}

// Sum of the volumes of the cells in the complex.
template <typename C3t3>
double complex_volume(const C3t3& c3t3)
{
  auto point = c3t3.triangulation().geom_traits().construct_point_3_object();
  double volume = 0.;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    volume += CGAL::volume(point(c->vertex(0)->point()), point(c->vertex(1)->point()),
                           point(c->vertex(2)->point()), point(c->vertex(3)->point()));
  return volume;
}

// A C3T3 out of a polyhedral domain with features: valid as a regular triangulation, its
// complex the cube with its 6 surface patches, 12 curves and 8 corners, and Mesh_3's writers,
// optimizers and the tetrahedral remeshing take it.
TEST(Mesh_3_domains, C3t3OfAPolyhedralDomainWithFeatures)
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Mesh> Domain;
  typedef CGAL::Mesh_triangulation_3<Domain>::type Tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index> C3t3;
  Domain domain(LM::make_cube_surface_3<K>(0., 1.));
  domain.detect_features();
  C3t3 c3t3 = CGAL::lattice_mesh_3<C3t3>(domain, Field(), CGAL::parameters::edge_length(.2).number_of_threads(2));
  EXPECT_TRUE(c3t3.triangulation().is_valid());
  EXPECT_NEAR(complex_volume(c3t3), 1., 1e-6);
  std::set<Domain::Surface_patch_index> patches;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    patches.insert(c3t3.surface_patch_index(*f));
  EXPECT_EQ(patches.size(), 6u);
  std::set<Domain::Curve_index> curves;
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e)
    curves.insert(c3t3.curve_index(*e));
  EXPECT_EQ(curves.size(), 12u);
  EXPECT_EQ(c3t3.number_of_vertices_in_complex(), 8u);
  std::size_t by_dimension[4] = { 0, 0, 0, 0 };
  for(auto v = c3t3.triangulation().finite_vertices_begin(); v != c3t3.triangulation().finite_vertices_end(); ++v)
    ++by_dimension[c3t3.in_dimension(v)];
  EXPECT_EQ(by_dimension[0], 8u);
  EXPECT_GT(by_dimension[1], 0u);
  EXPECT_GT(by_dimension[2], 0u);
  EXPECT_GT(by_dimension[3], 0u);

  std::ostringstream medit, vtu;
  CGAL::IO::output_to_medit(medit, c3t3);
  CGAL::IO::output_to_vtu(vtu, c3t3, CGAL::IO::ASCII);
  EXPECT_NE(medit.str().find("Tetrahedra"), std::string::npos);
  EXPECT_NE(vtu.str().find("UnstructuredGrid"), std::string::npos);

  C3t3 copy(c3t3);
  EXPECT_EQ(copy.number_of_cells_in_complex(), c3t3.number_of_cells_in_complex());
  namespace P = CGAL::parameters;
  CGAL::odt_optimize_mesh_3(c3t3, domain, P::max_iteration_number = 2);
  CGAL::perturb_mesh_3(c3t3, domain, P::time_limit = 2);
  CGAL::exude_mesh_3(c3t3, P::time_limit = 2);
  EXPECT_TRUE(c3t3.triangulation().is_valid());
  // the optimizers decide again which cells are in the complex by their circumcenters, without
  // the protecting balls make_mesh_3() puts on the features: a few cells along the edges leave
  EXPECT_NEAR(complex_volume(c3t3), 1., 1e-2);

  auto tr = CGAL::convert_to_triangulation_3(std::move(copy));
  CGAL::tetrahedral_isotropic_remeshing(tr, .2, CGAL::parameters::number_of_iterations(1));
  EXPECT_TRUE(tr.is_valid());
}

// A C3T3 out of an implicit Labeled_mesh_domain_3: subdomain 1 and one surface patch.
TEST(Mesh_3_domains, C3t3OfAnImplicitDomain)
{
  typedef CGAL::Labeled_mesh_domain_3<K> Domain;
  typedef CGAL::Mesh_triangulation_3<Domain>::type Tr;
  typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3t3;
  const Domain domain = Domain::create_implicit_mesh_domain(unit_sphere, K::Sphere_3(CGAL::ORIGIN, 4.));
  const C3t3 c3t3 = CGAL::lattice_mesh_3<C3t3>(domain, Field(), CGAL::parameters::edge_length(.25).number_of_threads(2));
  EXPECT_TRUE(c3t3.triangulation().is_valid());
  std::set<Domain::Subdomain_index> subdomains;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    subdomains.insert(c3t3.subdomain_index(c));
  EXPECT_EQ(subdomains, std::set<Domain::Subdomain_index>{ 1 });
  std::set<Domain::Surface_patch_index> patches;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    patches.insert(c3t3.surface_patch_index(*f));
  EXPECT_EQ(patches, (std::set<Domain::Surface_patch_index>{ { 0, 1 } }));   // as the domain names it
  EXPECT_NEAR(complex_volume(c3t3), 4. / 3. * CGAL_PI, 4. * CGAL_PI * .375 * .375 / 8.);

  // and of our own domain, in Lattice_mesher_3::Mesh_complex_3
  const auto ball = LM::make_sphere_domain_3<K>(Point_3(0., 0., 0.), 1.);
  const LM::Mesh_complex_3<K> ours = CGAL::lattice_mesh_3<LM::Mesh_complex_3<K> >(ball, Field(), CGAL::parameters::edge_length(.25));
  EXPECT_TRUE(ours.triangulation().is_valid());
  EXPECT_NEAR(complex_volume(ours), 4. / 3. * CGAL_PI, 4. * CGAL_PI * .375 * .375 / 8.);
}

} // namespace
