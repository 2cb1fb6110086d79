// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers
//
// Meshes a solid torus, given by an implicit function, with an FCC lattice that follows a
// varying frame field: the paper's field Ry, which turns the lattice cubes about the y axis so
// that they stay radial, vertical and tangential around the ring. The quality, and in
// particular the alignment error of the edges, is measured in the isotropic space of the field.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/lattice_mesh_3.h>
#include <CGAL/Lattice_mesher_3/Implicit_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/check_mesh.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>

#include <chrono>
#include <exception>
#include <iostream>

namespace LM = CGAL::Lattice_mesher_3;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point_3;
typedef CGAL::Lattice_mesher_traits_3<K>                    Traits;

int main()
{
  try {
    // The torus of axis y, major radius 1 and minor radius 0.4 (a smooth domain: no feature
    // curve, no corner), and the field Ry: T(p) is the rotation about y by atan2(p_z, p_x).
    const auto domain = LM::make_torus_domain_3<K>(1., .4);
    const LM::Rotation_y_frame_field_3<Traits> field;

    const auto start = std::chrono::steady_clock::now();
    const LM::Tetrahedral_mesh_3<Point_3> mesh =
      CGAL::lattice_mesh_3(domain, field,
                           CGAL::parameters::number_of_vertices(2000)
                                            .lattice(LM::Lattice_type::FCC)
                                            .random_seed(1u));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const LM::Mesh_validity_report validity = LM::check_tetrahedral_mesh(mesh);
    std::cout << validity.message << "\n";

    // Each tetrahedron is mapped by B = T^-1 at its centroid, each edge by B at its midpoint,
    // and the edge directions are compared with the FCC one-ring.
    LM::Mesh_quality_3 quality = LM::compute_mesh_quality(mesh, field, CGAL::parameters::lattice(LM::fcc_lattice()));
    quality.hausdorff = LM::boundary_hausdorff_distance(mesh, domain, 0.05);
    quality.seconds.total = seconds;
    LM::print_quality_table(std::cout, quality);

    // A field-aligned FCC mesh: valid, close to the boundary, with well-shaped tetrahedra
    // whose edges follow the rotating lattice directions.
    const bool ok = validity.valid()
                 && quality.vertices > 1500 && quality.vertices < 2500
                 && quality.theta_min.mean > 45.
                 && quality.epsilon.mean < 15.
                 && quality.hausdorff < 0.1;
    if(!ok) {
      std::cerr << "error: unexpected result (see above)\n";
      return 1;
    }
  }
  catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
