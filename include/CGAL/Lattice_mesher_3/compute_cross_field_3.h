// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_COMPUTE_CROSS_FIELD_3_H
#define CGAL_LATTICE_MESHER_3_COMPUTE_CROSS_FIELD_3_H

#include <CGAL/lattice_mesh_3.h>
#include <CGAL/Lattice_mesher_3/Discrete_frame_field_3.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/internal/cross_field_solver.h>
#include <CGAL/Lattice_mesher_3/internal/octahedral_frames.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3FrameFields
What `compute_frame_field_diagnostics()` measures on a frame field built on a tetrahedral mesh.
*/
struct Frame_field_diagnostics
{
  /// the smoothness energy 1/2 sum_ij w_ij |q_i - q_j|^2 over the mesh's edges ij, q the
  /// frames' degree-4 spherical harmonic coefficients (the frame's rotation; |q| = 1) and w_ij
  /// the number of tetrahedra around the edge
  double energy = 0.;
  /// the mean, weighted by area, over the boundary faces, of the angle (degrees) between the
  /// face's normal and the nearest direction of the frame at the face's centroid that the
  /// lattice's boundary holds (see `compute_cross_field_3()`: a face diagonal for BCC, an axis
  /// otherwise)
  double mean_boundary_alignment = 0.;
  /// the largest of these angles (degrees)
  double max_boundary_alignment = 0.;
  /// the singular edges: the inner edges of the mesh around which the frames of the tetrahedra
  /// (at their centroids) do not close up, matched from each tetrahedron to the next by the
  /// rotation of the cube that brings their axes nearest; pairs of vertex indices
  std::vector<std::array<int, 2> > singular_edges;
};

namespace internal {

// The direction of the frames that the boundary's normal holds, for the lattice of the named
// parameter `lattice` (BCC if absent): a face diagonal for BCC, whose {110} planes are made of
// faces of its tetrahedra (its {100} planes cut them into half octahedra, theta_min 45
// degrees), a cube axis for FCC (its {100} planes halve its octahedra: theta_min 54.7 degrees)
// and the hole-less kernel.
template <typename NamedParameters>
Frame_direction boundary_frame_direction(const NamedParameters& np)
{
  return stage_lattice(np).name == "bcc" ? Frame_direction::FACE_DIAGONAL : Frame_direction::AXIS;
}

// The tetrahedra around each inner edge (a, b), a < b, in the order of the ring (consecutive
// ones share a face); boundary edges are left out.
template <typename Point_3>
std::vector<std::pair<std::array<int, 2>, std::vector<int> > > inner_edge_rings(const Tetrahedral_mesh_3<Point_3>& mesh)
{
  // the two tetrahedra of each inner face, and one tetrahedron of each edge
  std::map<std::array<int, 3>, std::array<int, 2> > face_tets;
  std::map<std::array<int, 2>, int> edge_tet;
  for(std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const std::array<int, 4>& c = mesh.tets[t];
    for(int k = 0; k < 4; ++k) {
      std::array<int, 3> f = { c[std::size_t((k + 1) % 4)], c[std::size_t((k + 2) % 4)], c[std::size_t((k + 3) % 4)] };
      std::sort(f.begin(), f.end());
      auto it = face_tets.emplace(f, std::array<int, 2>{ int(t), -1 });
      if(!it.second) it.first->second[1] = int(t);
      for(int j = k + 1; j < 4; ++j)
        edge_tet.emplace(std::array<int, 2>{ (std::min)(c[std::size_t(k)], c[std::size_t(j)]), (std::max)(c[std::size_t(k)], c[std::size_t(j)]) }, int(t));
    }
  }
  auto other = [&](int t, int a, int b, int not_this) {   // t's vertex that is none of a, b, not_this
    for(int v : mesh.tets[std::size_t(t)]) if(v != a && v != b && v != not_this) return v;
    return -1;
  };
  std::vector<std::pair<std::array<int, 2>, std::vector<int> > > rings;
  for(const auto& e : edge_tet) {
    const int a = e.first[0], b = e.first[1];
    std::vector<int> ring(1, e.second);
    int previous = -1;   // the vertex of the face crossed last, to go on forward
    for(int c = other(e.second, a, b, -1);;) {
      std::array<int, 3> f = { a, b, c };
      std::sort(f.begin(), f.end());
      const std::array<int, 2>& two = face_tets.at(f);
      const int t = ring.back(), next = two[0] == t ? two[1] : two[0];
      if(next < 0) { ring.clear(); break; }   // a boundary face: a boundary edge
      if(next == ring.front()) break;
      ring.push_back(next);
      previous = c;
      c = other(next, a, b, previous);
      if(ring.size() > mesh.tets.size()) { ring.clear(); break; }   // not a manifold ring
    }
    if(ring.size() >= 3) rings.emplace_back(e.first, std::move(ring));
  }
  return rings;
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3FrameFields
Measures the smoothness, the boundary alignment and the singular edges of a frame field built on
a tetrahedral mesh (e.g. by `compute_cross_field_3()` or `read_frame_field_from_medit()`): see
`Frame_field_diagnostics`. A field without tetrahedra has no edges (energy 0, no singular edge),
and one without boundary faces no alignment figures (0).

\cgalNamedParamsBegin
  \cgalParamNBegin{lattice}
    \cgalParamDescription{the lattice whose boundary direction the alignment is measured against,
    as in `compute_cross_field_3()`: the nearest face diagonal of the frame for BCC, the nearest
    axis otherwise}
    \cgalParamType{`Lattice_type` or `Lattice_3`}
    \cgalParamDefault{`Lattice_type::BCC`}
  \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <typename GT, typename NamedParameters = parameters::Default_named_parameters>
Frame_field_diagnostics compute_frame_field_diagnostics(const Discrete_frame_field_3<GT>& field,
                                                        const NamedParameters& np = parameters::default_values())
{
  typedef typename GT::Point_3 Point_3;
  const Tetrahedral_mesh_3<Point_3>& mesh = field.mesh();
  auto rotation = [](Eigen::Matrix3d t) { return internal::frame_rotation_of_axes(t); };
  const internal::Frame_direction direction = internal::boundary_frame_direction(np);
  Frame_field_diagnostics d;
  std::vector<Eigen::Matrix3d> rotations;
  for(const auto& t : field.frames()) rotations.push_back(rotation(t));
  d.energy = internal::frame_field_energy(internal::weighted_edges(mesh), rotations);

  double area_sum = 0., weighted = 0.;
  for(const std::array<int, 3>& f : mesh.boundary_faces) {
    const Eigen::Vector3d a = internal::to_eigen(mesh.points[std::size_t(f[0])]), b = internal::to_eigen(mesh.points[std::size_t(f[1])]),
                          c = internal::to_eigen(mesh.points[std::size_t(f[2])]);
    const Eigen::Vector3d n = (b - a).cross(c - a), g = (a + b + c) / 3.;
    if(!(n.norm() > 0.)) continue;
    const double angle = internal::angle_to_nearest_direction(rotation(field.frame(Point_3(g[0], g[1], g[2]))), n.normalized(), direction);
    area_sum += n.norm();
    weighted += n.norm() * angle;
    d.max_boundary_alignment = (std::max)(d.max_boundary_alignment, angle);
  }
  if(area_sum > 0.) d.mean_boundary_alignment = weighted / area_sum;

  std::vector<Eigen::Matrix3d> tet_rotations;
  for(const std::array<int, 4>& t : mesh.tets) {
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for(int v : t) g += .25 * internal::to_eigen(mesh.points[std::size_t(v)]);
    tet_rotations.push_back(rotation(field.frame(Point_3(g[0], g[1], g[2]))));
  }
  for(const auto& ring : internal::inner_edge_rings(mesh)) {
    // carry the first frame around the ring, matching each next frame to it
    Eigen::Matrix3d carried = tet_rotations[std::size_t(ring.second.front())];
    for(std::size_t i = 1; i < ring.second.size(); ++i) {
      const Eigen::Matrix3d& r = tet_rotations[std::size_t(ring.second[i])];
      carried = r * internal::best_cube_rotation(carried.transpose() * r);
    }
    const Eigen::Matrix3d& first = tet_rotations[std::size_t(ring.second.front())];
    if(!internal::best_cube_rotation(carried.transpose() * first).isIdentity(1e-9)) d.singular_edges.push_back(ring.first);
  }
  return d;
}

/*!
\ingroup PkgLatticeMesher3FrameFields

Computes a smooth octahedral frame field ("cross field") of `domain` whose frames hold the
boundary's normal along a lattice direction: on a background tetrahedral mesh of the domain
(`lattice_mesh_3()` with the identity field, at the size of the named parameters), the frames of
the vertices minimize the smoothness energy 1/2 sum_ij w_ij |q_i - q_j|^2 of their degree-4
spherical harmonic coefficients q (w_ij: the number of tetrahedra around the edge ij), as
follows.

- The direction along the normal follows the lattice's boundary layer: a face diagonal of the
  frame for BCC, whose {110} planes are made of faces of its tetrahedra (its {100} planes cut
  them into half octahedra of theta_min 45 degrees), a cube axis for FCC, whose {100} planes cut
  its octahedra into halves of theta_min 54.7 degrees, and for the hole-less kernel.
- Boundary constraints, surface patch by surface patch: on a patch, that direction along the
  domain's normal (two free coefficients a vertex for an axis, as Palmer et al. 2020, four for a
  face diagonal); on a feature curve (two patches), the frame with an axis along the curve whose
  two directions across it are nearest to both normals (axes at 45 degrees from their bisector,
  or face diagonals: axes along the bisector and across it); at a corner (three patches), the
  frame nearest to the corner's three edges, for BCC too (no three face diagonals are
  orthogonal, and whole {100} layers fill a box corner).
- Initialization: the harmonic field under these constraints (a sparse linear solve, Eigen's
  conjugate gradient), projected onto the frames (Ray et al. 2016).
- Palmer et al.'s modified MBO iterations: a step of diffusion (M + tau_k L) q = M p under the
  constraints, then the projection onto the frames; tau_k = 50 / (lambda_1 k^3). The iterate of
  least energy is kept.

This variant (MBO rather than Ray et al.'s nonlinear optimization of rotation angles) is simple
and robust: each step is a sparse linear solve and a projection per vertex, with no line search.

The returned field holds a rotation per vertex of the background mesh and interpolates them in
its tetrahedra (see `Discrete_frame_field_3`): it is a rotation at every point. Give it to
`lattice_mesh_3()` like any `FrameField_3`; its size composes there with the sizing field
(T = h(x) R(x)) and the `edge_length` scales it. `write_frame_field_to_medit()` saves it and
`compute_frame_field_diagnostics()` measures it.

\tparam MeshDomain a model of `LatticeMeshDomain_3` or of Mesh_3's `MeshDomain_3` (meshed through
`Lattice_mesher_3::make_lattice_domain_3()`)

\cgalNamedParamsBegin
  \cgalParamNBegin{lattice}
    \cgalParamDescription{the lattice that the field is for, which sets the direction along the
    normal (see above); the background mesh is BCC whatever it is}
    \cgalParamType{`Lattice_type` or `Lattice_3`}
    \cgalParamDefault{`Lattice_type::BCC`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_vertices}
    \cgalParamDescription{about how many vertices the background mesh has}
    \cgalParamType{double}
    \cgalParamDefault{4000}
  \cgalParamNEnd
  \cgalParamNBegin{edge_length}
    \cgalParamDescription{the background mesh's lattice cube edge, instead of `number_of_vertices`}
    \cgalParamType{double}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the largest number of MBO iterations (fewer when the energy stops
    changing: by less than 1e-5 of itself once tau_k lambda_1 is below 1 / 100)}
    \cgalParamType{int}
    \cgalParamDefault{40}
  \cgalParamNEnd
  \cgalParamNBegin{align_to_features}
    \cgalParamDescription{whether feature curves and corners fix the frame (see above); if
    `false`, only the normal constrains the frames, averaged over the faces at a feature}
    \cgalParamType{bool}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the background mesh}
    \cgalParamType{unsigned int}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{the threads of the background mesh and of the solver's sparse products (Eigen's OpenMP threads, set for the call)}
    \cgalParamType{int}
    \cgalParamDefault{1}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the field, of type `Discrete_frame_field_3<Lattice_mesher_traits_3<K>>`, K the
domain's kernel
\throws std::invalid_argument if `number_of_iterations` is negative, or as `lattice_mesh_3()`
for the background mesh's size
*/
template <typename MeshDomain, typename NamedParameters = parameters::Default_named_parameters>
auto compute_cross_field_3(const MeshDomain& domain, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  if constexpr(!internal::Is_lattice_mesh_domain_3<MeshDomain>::value) {
    const double n = choose_parameter(get_parameter(np, internal_np::number_of_vertices), 4000.);
    return compute_cross_field_3(internal::lattice_domain_for(domain, np.number_of_vertices(n)), np);
  }
  else {
    typedef Lattice_mesher_traits_3<typename MeshDomain::Geom_traits> Traits;
    const int iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 40);
    if(iterations < 0)
      throw std::invalid_argument("compute_cross_field_3(): number_of_iterations() must not be negative, got " + std::to_string(iterations));
    const double length = choose_parameter(get_parameter(np, internal_np::edge_length), 0.);
    const auto common = parameters::random_seed(choose_parameter(get_parameter(np, internal_np::random_seed), 0u))
                          .number_of_threads(choose_parameter(get_parameter(np, internal_np::number_of_threads), 1));
    const Constant_frame_field_3<Traits> identity;
    Tetrahedral_mesh_3<typename Traits::Point_3> mesh = length > 0.
        ? lattice_mesh_3(domain, identity, common.edge_length(length))
        : lattice_mesh_3(domain, identity, common.number_of_vertices(choose_parameter(get_parameter(np, internal_np::number_of_vertices), 4000.)));
    const bool features = choose_parameter(get_parameter(np, internal_np::align_to_features), true);
    const internal::Eigen_threads_scope eigen_threads(choose_parameter(get_parameter(np, internal_np::number_of_threads), 1));
    internal::Cross_field_solver solver(mesh, internal::boundary_frame_constraints(mesh, domain, features, internal::boundary_frame_direction(np)));
    internal::Cross_field_result result = solver.solve(iterations);
    std::vector<typename Traits::Matrix_3> frames(result.rotations.begin(), result.rotations.end());
    return Discrete_frame_field_3<Traits>(std::move(mesh), std::move(frames));
  }
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_COMPUTE_CROSS_FIELD_3_H
