// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers
//
// Mesh_3 and the lattice mesher side by side on the same Polyhedral_mesh_domain_with_features_3
// (fandisk, or the file given): both return a C3T3 of the same type, compared by their dihedral
// angles; then the lattice mesh goes on to CGAL's tetrahedral remeshing and is written in the
// Medit format, as a Mesh_3 user would do with Mesh_3's.
//
//   lattice_mesh_and_mesh_3 [surface.off] [edge length]

#include <CGAL/lattice_mesh_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/File_medit.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/tetrahedral_remeshing.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Epick K;
typedef CGAL::Surface_mesh<K::Point_3> Surface;
typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface> Mesh_domain;
typedef CGAL::Mesh_triangulation_3<Mesh_domain>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Mesh_domain::Corner_index, Mesh_domain::Curve_index> C3t3;

// smallest dihedral angle of each tetrahedron: the smallest, the mean, the count below 40 degrees
template <typename Tetrahedra, typename Point_of>
void print_angles(const char* name, std::size_t vertices, const Tetrahedra& tets, Point_of point, double seconds)
{
  double smallest = 180., sum = 0.;
  std::size_t n = 0, below40 = 0;
  for(const auto& c : tets) {
    K::Point_3 p[4];
    for(int i = 0; i < 4; ++i) p[i] = point(c, i);
    double m = 180.;
    static const int e[6][4] = { {0,1,2,3}, {0,2,1,3}, {0,3,1,2}, {1,2,0,3}, {1,3,0,2}, {2,3,0,1} };
    for(const auto& ed : e)
      m = (std::min)(m, std::abs(CGAL::to_double(CGAL::approximate_dihedral_angle(p[ed[0]], p[ed[1]], p[ed[2]], p[ed[3]]))));
    smallest = (std::min)(smallest, m);
    sum += m;
    below40 += m < 40. ? 1 : 0;
    ++n;
  }
  std::cout << name << ": " << vertices << " vertices, " << n << " tetrahedra, smallest dihedral angle "
            << smallest << ", mean of the smallest " << sum / double(n) << ", " << below40 << " below 40 degrees, "
            << seconds << " s\n";
}

template <typename C>
void print_c3t3(const char* name, const C& c3t3, double seconds)
{
  auto point = c3t3.triangulation().geom_traits().construct_point_3_object();
  std::vector<typename C::Cell_handle> cells;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) cells.push_back(c);
  print_angles(name, c3t3.triangulation().number_of_vertices(), cells,
               [&](const typename C::Cell_handle& c, int i) { return point(c->vertex(i)->point()); }, seconds);
}

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : CGAL::data_file_path("meshes/fandisk.off");
  const double h = argc > 2 ? std::atof(argv[2]) : 0.04;
  Surface surface;
  if(!CGAL::IO::read_polygon_mesh(file, surface) || !CGAL::is_triangle_mesh(surface)) {
    std::cerr << "cannot read a triangle mesh from " << file << "\n";
    return EXIT_FAILURE;
  }
  Mesh_domain domain(surface);
  domain.detect_features();
  auto seconds_since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };

  // Mesh_3 with its defaults: refinement, then sliver perturbation and exudation
  namespace P = CGAL::parameters;
  const CGAL::Mesh_criteria_3<Tr> criteria(P::edge_size = h, P::facet_angle = 25, P::facet_size = h,
                                           P::facet_distance = h / 10, P::cell_radius_edge_ratio = 3, P::cell_size = h);
  auto start = std::chrono::steady_clock::now();
  const C3t3 refined = CGAL::make_mesh_3<C3t3>(domain, criteria);
  print_c3t3("Mesh_3          ", refined, seconds_since(start));

  // the lattice mesher on the same domain, with the same number of vertices: as arrays (its own
  // connectivity) and as a C3T3 (the Delaunay triangulation of its vertices, exuded)
  CGAL::Lattice_mesher_3::Constant_frame_field_3<CGAL::Lattice_mesher_traits_3<K> > field;
  const auto np = P::number_of_vertices(double(refined.triangulation().number_of_vertices())).number_of_threads(2);
  start = std::chrono::steady_clock::now();
  const auto arrays = CGAL::lattice_mesh_3(domain, field, np);
  print_angles("lattice arrays  ", arrays.points.size(), arrays.tets,
               [&](const std::array<int, 4>& t, int i) { return arrays.points[t[i]]; }, seconds_since(start));
  start = std::chrono::steady_clock::now();
  C3t3 lattice = CGAL::lattice_mesh_3<C3t3>(domain, field, np);
  print_c3t3("lattice C3T3    ", lattice, seconds_since(start));
  std::ofstream medit("lattice_mesh_and_mesh_3.mesh");
  CGAL::IO::output_to_medit(medit, lattice);

  // then CGAL's tetrahedral remeshing, as on any C3T3
  start = std::chrono::steady_clock::now();
  auto tr = CGAL::convert_to_triangulation_3(std::move(lattice));
  CGAL::tetrahedral_isotropic_remeshing(tr, h, P::number_of_iterations(2));
  auto point = tr.geom_traits().construct_point_3_object();
  std::vector<decltype(tr.finite_cells_begin())> cells;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    if(c->subdomain_index() != 0) cells.push_back(c);
  print_angles("remeshed lattice", tr.number_of_vertices(), cells,
               [&](decltype(tr.finite_cells_begin()) c, int i) { return point(c->vertex(i)->point()); }, seconds_since(start));
  return tr.is_valid() ? EXIT_SUCCESS : EXIT_FAILURE;
}
