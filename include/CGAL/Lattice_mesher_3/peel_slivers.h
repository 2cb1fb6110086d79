// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_PEEL_SLIVERS_H
#define CGAL_LATTICE_MESHER_3_PEEL_SLIVERS_H

#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/check_mesh.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>
#include <CGAL/Lattice_mesher_3/internal/stage_parameters.h>

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

namespace internal {

// Settings of peel_boundary_slivers().
struct Peeling_options
{
  /// tetrahedra whose smallest dihedral angle (isotropic space, degrees) is below this are peeled
  double angle = 20.;
  /// ... if their smallest height is at most this fraction of their mean edge (isotropic
  /// space): the boundary moves by that height when they go. What the smoothing leaves below 20
  /// degrees with two boundary faces lies where a part is about one cell thick, at heights of
  /// 0.11 to 0.33 of the mean edge (3,000-vertex sweep: bull, dino, triceratops, fandisk_large)
  double flat_ratio = 0.4;
  /// ... and below this angle whatever their height: a sliver that all-fixed vertices hold (the
  /// corners of a coarse surface) is worse than the boundary moving by a fraction of an edge
  double sliver_angle = 10.;
  /// rounds of peeling: a peeled sliver may expose another
  int max_rounds = 10;
};

template <typename NamedParameters>
Peeling_options peeling_options(const NamedParameters& np)
{
  Peeling_options o;
  read_parameter(np, internal_np::peel_angle, o.angle);
  read_parameter(np, internal_np::flatness_ratio, o.flat_ratio);
  read_parameter(np, internal_np::sliver_angle, o.sliver_angle);
  read_parameter(np, internal_np::max_rounds, o.max_rounds);
  if(!(o.flat_ratio >= 0.) || o.max_rounds < 0)
    throw std::invalid_argument("peel_boundary_slivers(): flatness_ratio() and max_rounds() must be at least 0");
  return o;
}

} // namespace internal

namespace internal {

// The outward faces of the tetrahedra that are in no other tetrahedron, sorted.
inline std::vector<std::array<int, 3> > one_tet_faces(const std::vector<std::array<int, 4> >& tets)
{
  std::map<Triangle_indices, std::pair<int, Triangle_indices> > faces;   // sorted -> count, outward
  for(const std::array<int, 4>& t : tets)
    for(const Triangle_indices& f : outward_faces(t)) {
      auto& e = faces[sorted_triangle(f)];
      ++e.first;
      e.second = f;
    }
  std::vector<std::array<int, 3> > result;
  for(const auto& e : faces) if(e.second.first == 1) result.push_back(e.second.second);
  std::sort(result.begin(), result.end());
  return result;
}

} // namespace internal

namespace internal {

// see peel_boundary_slivers()
template <typename Point_3, typename FrameField>
std::size_t peel_boundary_slivers(Tetrahedral_mesh_3<Point_3>& mesh, const FrameField& field,
                                  const Peeling_options& o)
{
  typedef internal::Triangle_indices Face;
  std::size_t removed = 0;
  for(int round = 0; round < o.max_rounds; ++round) {
    std::map<Face, int> boundary;   // sorted boundary face -> 1
    for(const auto& f : mesh.boundary_faces) boundary[internal::sorted_triangle(f)] = 1;
    // candidates: (angle, tet)
    std::vector<std::pair<double, std::size_t> > candidates;
    for(std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const std::array<int, 4>& v = mesh.tets[t];
      const std::array<Face, 4> faces = internal::outward_faces(v);
      int on_boundary = 0;
      for(const Face& f : faces) on_boundary += boundary.count(internal::sorted_triangle(f)) ? 1 : 0;
      if(on_boundary < 2) continue;
      const std::array<Eigen::Vector3d, 4> q = internal::isotropic_tetrahedron(mesh, field, t);
      const double angle = smallest_dihedral_angle(q[0], q[1], q[2], q[3]);
      if(!(angle < o.angle)) continue;
      // flat: its smallest height, by which the boundary moves when it goes, is a fraction of
      // its mean edge
      const bool flat = internal::height_over_mean_edge(q[0], q[1], q[2], q[3]) <= o.flat_ratio;
      if(flat || angle < o.sliver_angle) candidates.emplace_back(angle, t);
    }
    if(candidates.empty()) break;
    std::sort(candidates.begin(), candidates.end());
    // a first batch of slivers that share no vertex
    std::vector<char> used(mesh.points.size(), 0);
    std::vector<std::size_t> batch;
    for(const auto& c : candidates) {
      const std::array<int, 4>& v = mesh.tets[c.second];
      if(used[v[0]] || used[v[1]] || used[v[2]] || used[v[3]]) continue;
      for(int i : v) used[i] = 1;
      batch.push_back(c.second);
    }
    auto without = [&](const std::vector<std::size_t>& gone) {
      std::vector<char> drop(mesh.tets.size(), 0);
      for(std::size_t t : gone) drop[t] = 1;
      Tetrahedral_mesh_3<Point_3> m;
      m.points = mesh.points;
      m.vertex_kinds = mesh.vertex_kinds;
      for(std::size_t t = 0; t < mesh.tets.size(); ++t) if(!drop[t]) m.tets.push_back(mesh.tets[t]);
      m.boundary_faces = internal::one_tet_faces(m.tets);
      return m;
    };
    Tetrahedral_mesh_3<Point_3> next = without(batch);
    std::size_t taken = batch.size();
    if(!check_tetrahedral_mesh(next).valid()) {
      taken = 0;
      std::vector<std::size_t> kept;
      for(std::size_t k = 0; k < batch.size() && k < 64; ++k) {
        std::vector<std::size_t> trial(kept);
        trial.push_back(batch[k]);
        Tetrahedral_mesh_3<Point_3> m = without(trial);
        if(check_tetrahedral_mesh(m).valid()) { kept = trial; next = std::move(m); }
      }
      taken = kept.size();
      if(taken == 0) break;
    }
    mesh = std::move(next);
    removed += taken;
  }
  if(removed > 0) {   // drop the vertices in no tetrahedron
    std::vector<char> unused(mesh.points.size(), 1);
    for(const std::array<int, 4>& t : mesh.tets)
      for(int i : t) unused[i] = 0;
    internal::remove_vertices(mesh, unused);
  }
  return removed;
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Flips

Removes the slivers that lie flat on the boundary: a tetrahedron with two to four faces on the
boundary (four: alone, where a part of the domain is thinner than the lattice), a smallest dihedral angle below `peel_angle` and a smallest height at most `flatness_ratio`
times its mean edge (both in the isotropic space of `field`), or whatever its height, below
`sliver_angle`. Such a tetrahedron adds almost no
volume; what no flip or move of a vertex raises (its vertices held on the surface), removing it
does, and the boundary moves by its height. Removals that would leave the boundary non-manifold are not made: a round
removes a set of slivers that share no vertex, and if the mesh is then invalid
(`check_tetrahedral_mesh()`), tries them one at a time. Vertices that end up in no tetrahedron
are removed.

\tparam FrameField a model of `FrameField_3`

\cgalNamedParamsBegin
  \cgalParamNBegin{peel_angle}
    \cgalParamDescription{tetrahedra whose smallest dihedral angle (isotropic space, degrees) is below this are peeled ...}
    \cgalParamType{double}
    \cgalParamDefault{20}
  \cgalParamNEnd
  \cgalParamNBegin{flatness_ratio}
    \cgalParamDescription{... if their smallest height is at most this fraction of their mean edge (isotropic space): the boundary moves by that height when they go ...}
    \cgalParamType{double}
    \cgalParamDefault{0.4}
  \cgalParamNEnd
  \cgalParamNBegin{sliver_angle}
    \cgalParamDescription{... and below this angle whatever their height: a sliver that all-fixed vertices hold (the corners of a coarse surface) is worse than the boundary moving by a fraction of an edge}
    \cgalParamType{double}
    \cgalParamDefault{10}
  \cgalParamNEnd
  \cgalParamNBegin{max_rounds}
    \cgalParamDescription{rounds of peeling: a peeled sliver may expose another}
    \cgalParamType{int}
    \cgalParamDefault{10}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number of tetrahedra removed
\throws std::invalid_argument for a named parameter out of range
*/
template <typename Point_3, typename FrameField,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t peel_boundary_slivers(Tetrahedral_mesh_3<Point_3>& mesh, const FrameField& field,
                                  const NamedParameters& np = parameters::default_values())
{
  return internal::peel_boundary_slivers(mesh, field, internal::peeling_options(np));
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_PEEL_SLIVERS_H
