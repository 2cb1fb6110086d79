// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Meshes shared by the test files of the mesh-improvement stages.

#ifndef CGAL_LATTICE_MESHER_3_TEST_MESHES_H
#define CGAL_LATTICE_MESHER_3_TEST_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lattice_mesher_traits_3.h>
#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/tetrahedralize_particles.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>

namespace test_meshes {

typedef CGAL::Epick K;
typedef CGAL::Lattice_mesher_3::Polyhedral_lattice_domain_3<K> Domain;

inline const Domain& unit_cube()
{
  static const Domain d(CGAL::Lattice_mesher_3::make_cube_surface_3<K>(0., 1.));
  return d;
}

// The kind of a particle on `on` of a box's three pairs of faces: 3 a corner, 2 an edge, 1 a face.
inline CGAL::Lattice_mesher_3::Particle_kind box_particle_kind(int on)
{
  namespace LM = CGAL::Lattice_mesher_3;
  return on == 3 ? LM::Particle_kind::FIXED : on == 2 ? LM::Particle_kind::SHARP_EDGE
       : on == 1 ? LM::Particle_kind::BOUNDARY : LM::Particle_kind::FREE;
}

// A jittered (n+1)^3 grid on the unit cube: corners fixed, edge and face points on the surface,
// the rest free. Its Delaunay mesh has many poor tetrahedra for the improvement stages to work on.
inline CGAL::Lattice_mesher_3::Tetrahedral_mesh_3<K::Point_3> jittered_mesh(unsigned int seed, int n = 6)
{
  namespace LM = CGAL::Lattice_mesher_3;
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> jitter(-0.12, 0.12);
  LM::Particle_set_3<K::Point_3> ps;
  for(int i = 0; i <= n; ++i) for(int j = 0; j <= n; ++j) for(int k = 0; k <= n; ++k) {
    const int on = (i == 0 || i == n) + (j == 0 || j == n) + (k == 0 || k == n);
    auto c = [&](int a, bool fixed) { return fixed ? double(a) / n : (a + jitter(g)) / n; };
    const K::Point_3 p(c(i, i == 0 || i == n), c(j, j == 0 || j == n), c(k, k == 0 || k == n));
    ps.push_back(p, box_particle_kind(on));
  }
  return LM::tetrahedralize_particles(ps, unit_cube(), LM::Constant_frame_field_3<CGAL::Lattice_mesher_traits_3<K> >());
}

// The boundary faces of a mesh as sorted vertex triples, whatever their orientation.
template <typename Point_3>
std::set<std::array<int, 3> > sorted_faces(const CGAL::Lattice_mesher_3::Tetrahedral_mesh_3<Point_3>& mesh)
{
  std::set<std::array<int, 3> > faces;
  for(auto f : mesh.boundary_faces) { std::sort(f.begin(), f.end()); faces.insert(f); }
  return faces;
}

} // namespace test_meshes

#endif // CGAL_LATTICE_MESHER_3_TEST_MESHES_H
