// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers
//
// Meshes fandisk with an axis-aligned BCC lattice through the front function
// CGAL::lattice_mesh_3(): reads the surface into a domain (its sharp edges become feature
// curves), follows the optimization round by round with a visitor, checks the output mesh,
// prints its quality measured in the isotropic space and writes it in the Medit format.

// first, as in the README's listing: the front function's header includes all it needs
#include <CGAL/lattice_mesh_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/check_mesh.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>
#include <CGAL/Lattice_mesher_3/IO/medit.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>

namespace LM = CGAL::Lattice_mesher_3;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point_3;
typedef CGAL::Lattice_mesher_traits_3<K>                    Traits;
typedef LM::Polyhedral_lattice_domain_3<K>                  Domain;
typedef LM::Constant_frame_field_3<Traits>                  Field;

// A model of LatticeMesherVisitor_3: prints one line per optimization round, and keeps the
// number of rounds and the time the optimization took.
struct Progress_printer
{
  std::size_t rounds = 0;
  bool saw_final_round = false;
  double seconds = 0.;

  void round_done(const LM::Round_report& r)
  {
    ++rounds;
    saw_final_round = saw_final_round || r.final_round;
    seconds = r.seconds;
    std::printf("%s level %d round %2d: %6zu particles  -%-4zu +%-4zu  energy %10.3f  (%.2f s)\n",
                r.final_round ? "[final]" : "       ", r.level, r.round, r.particles, r.deleted,
                r.inserted, r.energy, r.seconds);
  }
};

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : CGAL::data_file_path("meshes/fandisk.off");
  const std::size_t target_vertices = 3000;

  try {
    // Edges sharper than 60 degrees are feature curves; their end points are corners.
    const Domain domain = LM::read_polyhedral_lattice_domain_3<K>(filename, 60.);
    std::cout << filename << ": " << domain.number_of_curves() << " feature curves, "
              << domain.corners().size() << " corners\n";

    // T(p) = identity: unit cubes aligned with the axes, i.e. an isotropic mesh.
    const Field field;

    // The visitor is passed by reference so that `progress` keeps its state.
    Progress_printer progress;
    const auto start = std::chrono::steady_clock::now();
    const LM::Tetrahedral_mesh_3<Point_3> mesh =
      CGAL::lattice_mesh_3(domain, field,
                           CGAL::parameters::number_of_vertices(double(target_vertices))
                                            .lattice(LM::Lattice_type::BCC)
                                            .number_of_threads(2)
                                            .visitor(std::ref(progress)));
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // Validity: positive tetrahedra, boundary faces oriented outward, closed manifold boundary.
    const LM::Mesh_validity_report validity = LM::check_tetrahedral_mesh(mesh);
    std::cout << validity.message << "\n";

    // Quality in the isotropic space of the field (here, the physical space).
    LM::Mesh_quality_3 quality = LM::compute_mesh_quality(mesh, field, CGAL::parameters::lattice(LM::bcc_lattice()));
    quality.seconds.optimize = progress.seconds;
    quality.seconds.mesh = total - progress.seconds;
    quality.seconds.total = total;
    LM::print_quality_table(std::cout, quality);

    std::ofstream out("fandisk_bcc.mesh");
    LM::write_medit(out, mesh);
    std::cout << "wrote fandisk_bcc.mesh\n";

    // What a BCC mesh of fandisk at this size looks like: valid, about the asked number of
    // vertices, a mean smallest dihedral angle above 50 degrees and almost no sliver.
    bool ok = validity.valid();
    ok = ok && progress.rounds > 1 && progress.saw_final_round;
    ok = ok && quality.vertices > 0.8 * target_vertices && quality.vertices < 1.2 * target_vertices;
    ok = ok && quality.theta_min.mean > 50.;
    ok = ok && quality.below20 < quality.tets / 100;
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
