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

// The faces of `tets` that are in no other tetrahedron, oriented outward (as `outward_faces()`
// gives them), sorted; only those that `keep` accepts.
template <typename Keep>
std::vector<std::array<int, 3> > one_tet_faces(const std::vector<std::array<int, 4> >& tets, Keep keep)
{
  std::vector<std::pair<Triangle_indices, Triangle_indices> > faces;   // sorted, outward
  for(const std::array<int, 4>& t : tets)
    for(const Triangle_indices& f : outward_faces(t))
      if(keep(f)) faces.emplace_back(sorted_triangle(f), f);
  std::sort(faces.begin(), faces.end());
  std::vector<std::array<int, 3> > result;
  for(std::size_t i = 0, j; i < faces.size(); i = j) {
    for(j = i + 1; j < faces.size() && faces[j].first == faces[i].first; ++j) {}
    if(j - i == 1) result.push_back(faces[i].second);
  }
  std::sort(result.begin(), result.end());
  return result;
}

inline std::vector<std::array<int, 3> > one_tet_faces(const std::vector<std::array<int, 4> >& tets)
{
  return one_tet_faces(tets, [](const Triangle_indices&) { return true; });
}

// Which of the tetrahedra `batch` (indices into mesh.tets, no two sharing a vertex) may go: those
// whose removal leaves the boundary a 2-manifold. A removal changes the boundary only at the
// tetrahedron's own vertices and edges, where the faces are all in the tetrahedra around its
// vertices, and those of the batch share none: each is judged alone, from these faces. Returns
// the flags of the batch, and sets `boundary` to the new boundary faces around the vertices of
// those that may go.
template <typename Point_3>
std::vector<char> removable_tets(const Tetrahedral_mesh_3<Point_3>& mesh, const std::vector<std::size_t>& batch,
                                 std::vector<Triangle_indices>& boundary)
{
  std::vector<int> owner(mesh.points.size(), -1);   // the batch's tetrahedron of each vertex
  std::vector<char> gone(mesh.tets.size(), 0);
  for(std::size_t k = 0; k < batch.size(); ++k) {
    gone[batch[k]] = 1;
    for(int v : mesh.tets[batch[k]]) owner[std::size_t(v)] = int(k);
  }
  auto owned = [&](const auto& f) { return std::any_of(f.begin(), f.end(), [&](int v) { return owner[std::size_t(v)] >= 0; }); };
  std::vector<std::array<int, 4> > around;
  for(std::size_t t = 0; t < mesh.tets.size(); ++t)
    if(!gone[t] && owned(mesh.tets[t])) around.push_back(mesh.tets[t]);
  boundary = one_tet_faces(around, owned);
  std::vector<char> removable(batch.size(), 1);
  const Boundary_manifold_problems problems = boundary_manifold_problems(boundary);
  for(const std::array<int, 2>& e : problems.edges)
    for(int v : e) if(owner[std::size_t(v)] >= 0) removable[std::size_t(owner[std::size_t(v)])] = 0;
  for(int v : problems.vertices)
    if(owner[std::size_t(v)] >= 0) removable[std::size_t(owner[std::size_t(v)])] = 0;
  boundary.erase(std::remove_if(boundary.begin(), boundary.end(), [&](const Triangle_indices& f) {
                   return std::none_of(f.begin(), f.end(), [&](int v) { return owner[std::size_t(v)] >= 0 && removable[std::size_t(owner[std::size_t(v)])]; });
                 }), boundary.end());
  return removable;
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
    std::vector<Face> boundary;   // the faces' sorted indices, sorted
    std::vector<char> on_boundary(mesh.points.size(), 0);
    for(const Face& f : mesh.boundary_faces) {
      boundary.push_back(internal::sorted_triangle(f));
      for(int v : f) on_boundary[std::size_t(v)] = 1;
    }
    std::sort(boundary.begin(), boundary.end());
    // candidates: (angle, tet)
    std::vector<std::pair<double, std::size_t> > candidates;
    for(std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const std::array<int, 4>& v = mesh.tets[t];
      if(!(on_boundary[v[0]] && on_boundary[v[1]] && on_boundary[v[2]] && on_boundary[v[3]])) continue;
      int faces = 0;
      for(const Face& f : internal::outward_faces(v))
        faces += std::binary_search(boundary.begin(), boundary.end(), internal::sorted_triangle(f)) ? 1 : 0;
      if(faces < 2) continue;
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
    // a batch of slivers that share no vertex, of which those that keep the boundary manifold go
    std::vector<char> used(mesh.points.size(), 0);
    std::vector<std::size_t> batch;
    for(const auto& c : candidates) {
      const std::array<int, 4>& v = mesh.tets[c.second];
      if(used[v[0]] || used[v[1]] || used[v[2]] || used[v[3]]) continue;
      for(int i : v) used[i] = 1;
      batch.push_back(c.second);
    }
    std::vector<Face> new_faces;
    const std::vector<char> removable = internal::removable_tets(mesh, batch, new_faces);
    std::vector<char> drop(mesh.points.size(), 0), gone(mesh.tets.size(), 0);   // drop: faces around these are new
    std::size_t taken = 0;
    for(std::size_t k = 0; k < batch.size(); ++k)
      if(removable[k]) {
        ++taken;
        gone[batch[k]] = 1;
        for(int v : mesh.tets[batch[k]]) drop[std::size_t(v)] = 1;
      }
    if(taken == 0) break;
    std::size_t kept = 0;
    for(std::size_t t = 0; t < mesh.tets.size(); ++t) if(!gone[t]) mesh.tets[kept++] = mesh.tets[t];
    mesh.tets.resize(kept);
    mesh.boundary_faces.erase(std::remove_if(mesh.boundary_faces.begin(), mesh.boundary_faces.end(), [&](const Face& f) {
                                return drop[std::size_t(f[0])] || drop[std::size_t(f[1])] || drop[std::size_t(f[2])];
                              }), mesh.boundary_faces.end());
    mesh.boundary_faces.insert(mesh.boundary_faces.end(), new_faces.begin(), new_faces.end());
    removed += taken;
  }
  if(removed > 0) {   // the rounds kept the boundary faces up to date: sorted; the vertices in no tetrahedron go
    std::sort(mesh.boundary_faces.begin(), mesh.boundary_faces.end());
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
does, and the boundary moves by its height. Removals that would leave the boundary non-manifold
are not made: a round takes a set of slivers that share no vertex and removes each unless the
boundary around its vertices would then not be a 2-manifold (as `check_tetrahedral_mesh()` defines
it). Vertices that end up in no tetrahedron are removed.

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
