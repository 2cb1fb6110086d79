// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers
//
// Runs the stages of the lattice mesher one by one on the cube [0.1, 1.1]^3, as
// CGAL::Lattice_particle_mesher_3 chains them: initial particles at a coarse edge length;
// at each level, rounds of L-BFGS optimization, deletion and insertion, then refinement to
// the next level; a closing tight round; the tetrahedralization; flips, smoothing and edge
// contractions at the worst tetrahedra. Calling the stages directly lets a program replace one (here the start:
// the program places the particles itself) and look at the particles between stages (here:
// how many ended up at a corner, on a sharp edge, on the boundary and inside).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lattice_mesher_traits_3.h>
#include <CGAL/Lattice_mesher_3/Lattice_3.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/optimize_particles.h>
#include <CGAL/Lattice_mesher_3/insert_delete_particles.h>
#include <CGAL/Lattice_mesher_3/tetrahedralize_particles.h>
#include <CGAL/Lattice_mesher_3/collapse_edges.h>
#include <CGAL/Lattice_mesher_3/flip_tetrahedra.h>
#include <CGAL/Lattice_mesher_3/smooth_vertices.h>
#include <CGAL/Lattice_mesher_3/check_mesh.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <random>

namespace LM = CGAL::Lattice_mesher_3;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point_3;
typedef CGAL::Lattice_mesher_traits_3<K>                    Traits;
typedef LM::Polyhedral_lattice_domain_3<K>                  Domain;
typedef LM::Constant_frame_field_3<Traits>                  Field;

int main()
{
  try {
    // The cube: its 12 edges are feature curves and its 8 vertices corners.
    const Domain domain(LM::make_cube_surface_3<K>(0.1, 1.1));
    const Field field;                                  // T = I: axis-aligned lattice cubes
    const LM::Lattice_3 lattice = LM::bcc_lattice();    // its one-ring is the kernel's hole set

    const double edge_length = 1. / 8.;                 // l*: 8 lattice cubes along a side
    const int coarse_levels = 2;                        // start at 4 l*, then 2 l*, then l*

    // 1. Start (our own): a fixed particle at each corner, and as many random particles inside
    //    as the coarsest lattice has points in the volume.
    const auto start = std::chrono::steady_clock::now();
    LM::Particle_set_3<Point_3> particles;
    for(std::size_t c = 0; c < domain.corners().size(); ++c)
      particles.push_back(domain.corners()[c], LM::Particle_kind::FIXED, int(c));
    const double coarse_length = std::ldexp(edge_length, coarse_levels);
    const std::size_t n = std::size_t(lattice.density * domain.volume() / std::pow(coarse_length, 3));
    std::mt19937 random(1);
    std::uniform_real_distribution<double> coordinate(0.1, 1.1);
    while(particles.size() < domain.corners().size() + n) {
      const Point_3 p(coordinate(random), coordinate(random), coordinate(random));
      if(domain.is_inside(p)) particles.push_back(p, LM::Particle_kind::FREE);
    }

    // 2. Levels 4 l*, 2 l*, l*. At each level, rounds: L-BFGS on the Gaussian Hole Kernel
    //    energy (each round ends by snapping particles to the boundary and the sharp edges),
    //    then deletion and insertion, until neither changes anything. Every other setting is
    //    the paper's default.
    for(int level = coarse_levels; level >= 0; --level) {
      const auto np = CGAL::parameters::edge_length(std::ldexp(edge_length, level)).lattice(LM::Lattice_type::BCC);
      // Refinement: every particle adds its lattice one-ring at the finer edge length.
      if(level < coarse_levels)
        LM::refine_particles(particles, domain, field, np);

      LM::optimize_particles(particles, domain, field, np.number_of_iterations(13));
      for(int round = 1; round <= 8; ++round) {
        const std::size_t deleted = LM::delete_particles(particles, domain, field, np);
        const std::size_t inserted = LM::insert_particles(particles, domain, field, np);
        std::printf("level %d round %d: -%zu +%zu -> %zu particles\n", level, round, deleted, inserted,
                    particles.size());
        if(deleted + inserted == 0) break;
        LM::optimize_particles(particles, domain, field, np.number_of_iterations(round < 5 ? 13 : 8));
      }
    }

    // 3. The closing round: no iteration limit, a tighter gradient tolerance.
    const auto np = CGAL::parameters::edge_length(edge_length).lattice(LM::Lattice_type::BCC);
    const LM::Optimization_result last =
      LM::optimize_particles(particles, domain, field, np.number_of_iterations(0).gradient_tolerance(3e-3));
    std::printf("closing round: %d iterations, energy %.4f\n", last.iterations, last.energy);
    const auto optimized = std::chrono::steady_clock::now();

    // Inspection between stages: the particle kinds. A perfect BCC lattice of the cube has its
    // 8 corners, 12 x 7 points inside the edges, 6 x 7 x 7 inside the faces and 7^3 + 8^3 inside.
    std::array<std::size_t, 4> kinds = {{0, 0, 0, 0}};
    for(LM::Particle_kind k : particles.kinds)
      ++kinds[std::size_t(k)];
    std::printf("particles: %zu fixed, %zu sharp-edge, %zu boundary, %zu free\n",
                kinds[0], kinds[1], kinds[2], kinds[3]);

    // 4. Tetrahedralization: the Delaunay tetrahedralization restricted to the domain.
    LM::Tetrahedral_mesh_3<Point_3> mesh = LM::tetrahedralize_particles(particles, domain, field, np);

    // 5. Improvement of the worst tetrahedra in the isotropic space: flips, vertex moves, then
    // the removal of extra vertices where moves could not help.
    //    With l* and the lattice, flips and moves leave the lattice tetrahedra as they are.
    const LM::Flip_result flips = LM::flip_tetrahedra(mesh, field, np);
    const std::size_t moves = LM::smooth_vertices(mesh, domain, field, np);
    const std::size_t removed = LM::collapse_edges(mesh, field);
    std::printf("%zu flips, %zu vertex moves, %zu vertices removed\n", flips.total(), moves, removed);
    const auto meshed = std::chrono::steady_clock::now();

    const LM::Mesh_validity_report validity = LM::check_tetrahedral_mesh(mesh);
    std::cout << validity.message << "\n";
    LM::Mesh_quality_3 quality = LM::compute_mesh_quality(mesh, field, np);
    quality.seconds.optimize = std::chrono::duration<double>(optimized - start).count();
    quality.seconds.mesh = std::chrono::duration<double>(meshed - optimized).count();
    quality.seconds.total = quality.seconds.optimize + quality.seconds.mesh;
    LM::print_quality_table(std::cout, quality);

    // From the random start, coarse-to-fine reaches the perfect lattice: check the kinds, and
    // that the tetrahedra are the BCC ones (smallest dihedral angle 60 degrees inside, 45 at
    // the boundary) with edges along the lattice directions.
    const std::size_t fixed = kinds[std::size_t(LM::Particle_kind::FIXED)];
    const std::size_t sharp = kinds[std::size_t(LM::Particle_kind::SHARP_EDGE)];
    const std::size_t boundary = kinds[std::size_t(LM::Particle_kind::BOUNDARY)];
    const std::size_t interior = kinds[std::size_t(LM::Particle_kind::FREE)];
    const bool ok = validity.valid()
                 && fixed == 8
                 && sharp >= 80 && sharp <= 88                  // 84
                 && boundary >= 280 && boundary <= 310          // 294
                 && interior >= 830 && interior <= 880          // 855
                 && quality.theta_min.mean > 55.
                 && quality.below20 == 0
                 && quality.epsilon.mean < 5.;
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
