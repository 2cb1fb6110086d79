// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_CHECK_MESH_H
#define CGAL_LATTICE_MESHER_3_CHECK_MESH_H

#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <ostream>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3Quality
What `check_tetrahedral_mesh()` found. Every `number_of_*` field counts an error; the mesh is
valid when they are all 0. `connected_components` and `unused_vertices` are information: a
domain may have several bodies, a particle set may keep particles that no tetrahedron uses.
*/
struct Mesh_validity_report
{
  std::size_t vertices = 0;                               ///< number of vertices of the mesh
  std::size_t tets = 0;                                   ///< number of tetrahedra of the mesh
  std::size_t boundary_faces = 0;                         ///< number of boundary faces of the mesh
  std::size_t number_of_bad_indices = 0;                  ///< tets and boundary faces with an index out of range
  std::size_t number_of_bad_vertex_kinds = 0;             ///< 1 if `vertex_kinds` is neither empty nor one per point
  std::size_t number_of_degenerate_tets = 0;              ///< tets with a repeated vertex
  std::size_t number_of_non_positive_tets = 0;            ///< tets whose orientation is not `POSITIVE`
  std::size_t number_of_duplicate_tets = 0;               ///< further copies of a tet (same vertex set)
  std::size_t number_of_non_manifold_faces = 0;           ///< triangles in more than two tets
  std::size_t number_of_missing_boundary_faces = 0;       ///< one-tet faces absent from `boundary_faces`
  std::size_t number_of_extra_boundary_faces = 0;         ///< `boundary_faces` entries that are no one-tet face, or repeated
  std::size_t number_of_misoriented_boundary_faces = 0;   ///< boundary faces not oriented outward
  std::size_t number_of_non_manifold_boundary_edges = 0;  ///< not in exactly two boundary faces of opposite directions
  std::size_t number_of_pinched_vertices = 0;             ///< boundary faces around the vertex do not form one cycle
  std::size_t connected_components = 0;                   ///< of the tets, adjacent through a face
  std::size_t unused_vertices = 0;                        ///< points in no tet
  /// one line per error found (with its first example), then a one-line summary
  std::string message;

  /// `true` if no error was found
  bool valid() const;
};

namespace internal {

typedef std::array<int, 3> Triangle_indices;

// The faces of a positive tet (a0, a1, a2, a3), oriented outward; face i is opposite a_i.
inline std::array<Triangle_indices, 4> outward_faces(const std::array<int, 4>& t)
{
  return { { { t[1], t[2], t[3] }, { t[0], t[3], t[2] }, { t[0], t[1], t[3] }, { t[0], t[2], t[1] } } };
}

// The same oriented triangle written from its smallest index: equal iff same orientation.
inline Triangle_indices canonical_rotation(const Triangle_indices& f)
{
  const int i = int(std::min_element(f.begin(), f.end()) - f.begin());
  return { f[i], f[(i + 1) % 3], f[(i + 2) % 3] };
}

inline Triangle_indices sorted_triangle(Triangle_indices f)
{
  std::sort(f.begin(), f.end());
  return f;
}

// The errors a report counts, with how the message names them.
struct Validity_problem
{
  std::size_t Mesh_validity_report::*count;
  const char* description;
};

inline const std::array<Validity_problem, 11>& validity_problems()
{
  typedef Mesh_validity_report R;
  static const std::array<Validity_problem, 11> problems = { {
    { &R::number_of_bad_indices, "tets or boundary faces with an index out of range" },
    { &R::number_of_bad_vertex_kinds, "vertex_kinds of the wrong size" },
    { &R::number_of_degenerate_tets, "tets with a repeated vertex" },
    { &R::number_of_non_positive_tets, "tets not positively oriented" },
    { &R::number_of_duplicate_tets, "duplicate tets" },
    { &R::number_of_non_manifold_faces, "faces in more than two tets" },
    { &R::number_of_missing_boundary_faces, "one-tet faces missing from boundary_faces" },
    { &R::number_of_extra_boundary_faces, "boundary_faces entries that are no one-tet face, or repeated" },
    { &R::number_of_misoriented_boundary_faces, "boundary faces not oriented outward" },
    { &R::number_of_non_manifold_boundary_edges,
      "boundary edges not in exactly two boundary faces of opposite directions" },
    { &R::number_of_pinched_vertices, "boundary vertices whose boundary faces do not form one cycle" } } };
  return problems;
}

// Counts the problems of a report and keeps the first example of each for its message.
class Problem_log
{
public:
  explicit Problem_log(Mesh_validity_report& r) : r_(r) {}

  void add(std::size_t Mesh_validity_report::*count, const std::string& example)
  {
    if((r_.*count)++ == 0) first_.emplace_back(&(r_.*count), example);
  }

  // one line per problem found, then a summary line
  std::string message() const
  {
    std::ostringstream os;
    for(const Validity_problem& p : validity_problems()) {
      const std::size_t& count = r_.*p.count;
      if(count == 0) continue;
      os << count << ' ' << p.description;
      for(const auto& f : first_)
        if(f.first == &count) os << " (first: " << f.second << ')';
      os << '\n';
    }
    os << (r_.valid() ? "valid mesh: " : "invalid mesh: ") << r_.vertices << " vertices (" << r_.unused_vertices
       << " unused), " << r_.tets << " tets, " << r_.boundary_faces << " boundary faces, "
       << r_.connected_components << " connected component(s)";
    return os.str();
  }

private:
  Mesh_validity_report& r_;
  std::vector<std::pair<const std::size_t*, std::string> > first_;
};

// "what (i j k)"
template <typename Indices>
std::string describe(const std::string& what, const Indices& v)
{
  std::ostringstream os;
  os << what << " (";
  for(std::size_t i = 0; i < v.size(); ++i) os << (i ? " " : "") << v[i];
  os << ')';
  return os.str();
}

// Union-find with path halving.
inline std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i)
{
  while(parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// What makes a boundary (oriented faces, each once) not a 2-manifold: its edges that are not in
// exactly two faces of opposite directions (each once), and its vertices around which the faces
// do not form one cycle. An edge's faces all hold its ends, and a vertex's faces hold it: of the
// faces around a set of vertices alone, the answer is exact for the edges and vertices of the set.
struct Boundary_manifold_problems
{
  std::vector<std::array<int, 2> > edges;
  std::vector<int> vertices;
};

inline Boundary_manifold_problems boundary_manifold_problems(const std::vector<Triangle_indices>& faces)
{
  Boundary_manifold_problems p;
  std::vector<std::pair<int, int> > directed_edges;
  std::vector<std::array<int, 3> > links;  // (v, a, b): the face (v, a, b) turns from a to b around v
  for(const Triangle_indices& f : faces)
    for(int i = 0; i < 3; ++i) {
      directed_edges.emplace_back(f[i], f[(i + 1) % 3]);
      links.push_back({ f[i], f[(i + 1) % 3], f[(i + 2) % 3] });
    }
  std::sort(directed_edges.begin(), directed_edges.end());
  for(std::size_t i = 0, j; i < directed_edges.size(); i = j) {
    for(j = i + 1; j < directed_edges.size() && directed_edges[j] == directed_edges[i]; ++j) {}
    const std::pair<int, int> e = directed_edges[i], reverse(e.second, e.first);
    const auto range = std::equal_range(directed_edges.begin(), directed_edges.end(), reverse);
    // each undirected edge is judged once: from its smaller end, or from the only direction present
    if((j - i != 1 || range.second - range.first != 1) && (e.first < e.second || range.first == range.second))
      p.edges.push_back({ e.first, e.second });
  }
  std::sort(links.begin(), links.end());
  for(std::size_t i = 0, j; i < links.size(); i = j) {
    const int v = links[i][0];
    for(j = i + 1; j < links.size() && links[j][0] == v; ++j) {}
    // links[i, j) is sorted by a; a single cycle iff the a are distinct and the walk a -> b
    // from the first a comes back after exactly j - i steps
    bool distinct = true;
    for(std::size_t k = i + 1; k < j; ++k) distinct = distinct && links[k][1] != links[k - 1][1];
    auto next = [&](int a) {
      const auto it = std::lower_bound(links.begin() + i, links.begin() + j, std::array<int, 3>{ v, a, -1 });
      return (it != links.begin() + j && (*it)[1] == a) ? (*it)[2] : -1;
    };
    const int start = links[i][1];
    std::size_t steps = 0;
    int a = start;
    do { a = next(a); ++steps; } while(a != -1 && a != start && steps <= j - i);
    if(!distinct || a != start || steps != j - i) p.vertices.push_back(v);
  }
  return p;
}

} // namespace internal

inline bool Mesh_validity_report::valid() const
{
  for(const internal::Validity_problem& p : internal::validity_problems())
    if(this->*p.count != 0) return false;
  return true;
}

/*!
\ingroup PkgLatticeMesher3Quality
Checks that `mesh` is a valid tetrahedral mesh of a volume with a closed manifold boundary:
- indices in range, no repeated vertex in a tet, every tet positively oriented (exact
  predicates), no duplicate tet, every triangle in at most two tets;
- `boundary_faces` is exactly the set of triangles in one tet, each oriented outward;
- the boundary is a closed 2-manifold: every boundary edge is in exactly two boundary faces,
  in opposite directions, and the boundary faces around every boundary vertex form a single
  cycle (no pinched vertex).
It also counts the face-connected components of tets and the unused vertices. Tets with an index
out of range are left out of every further check.
*/
template <typename Point_3>
Mesh_validity_report check_tetrahedral_mesh(const Tetrahedral_mesh_3<Point_3>& mesh)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
  typedef Mesh_validity_report R;
  typedef std::array<int, 4> Tet;
  using internal::Triangle_indices;
  using internal::describe;

  R r;
  internal::Problem_log log(r);
  r.vertices = mesh.points.size();
  r.tets = mesh.tets.size();
  r.boundary_faces = mesh.boundary_faces.size();
  const int n = int(mesh.points.size());
  auto in_range = [n](int v) { return v >= 0 && v < n; };

  if(!mesh.vertex_kinds.empty() && mesh.vertex_kinds.size() != mesh.points.size())
    log.add(&R::number_of_bad_vertex_kinds,
            std::to_string(mesh.vertex_kinds.size()) + " kinds for " + std::to_string(mesh.points.size()) + " points");

  // per-tet checks; `checked` keeps the tets with distinct in-range indices
  std::vector<std::size_t> checked;
  std::vector<char> used(n, 0);
  std::vector<Tet> sorted_tets;
  for(std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const Tet& tet = mesh.tets[t];
    const std::string name = "tet " + std::to_string(t);
    if(!std::all_of(tet.begin(), tet.end(), in_range)) {
      log.add(&R::number_of_bad_indices, describe(name, tet));
      continue;
    }
    for(int v : tet) used[v] = 1;
    Tet s = tet;
    std::sort(s.begin(), s.end());
    if(std::adjacent_find(s.begin(), s.end()) != s.end()) {
      log.add(&R::number_of_degenerate_tets, describe(name, tet));
      continue;
    }
    checked.push_back(t);
    sorted_tets.push_back(s);
    auto point = [&](int i) {
      const Point_3& p = mesh.points[tet[i]];
      return Epick::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    };
    if(CGAL::orientation(point(0), point(1), point(2), point(3)) != CGAL::POSITIVE)
      log.add(&R::number_of_non_positive_tets, describe(name, tet));
  }
  std::sort(sorted_tets.begin(), sorted_tets.end());
  for(std::size_t i = 1; i < sorted_tets.size(); ++i)
    if(sorted_tets[i] == sorted_tets[i - 1])
      log.add(&R::number_of_duplicate_tets, describe("tet", sorted_tets[i]));
  r.unused_vertices = std::size_t(std::count(used.begin(), used.end(), 0));

  // every tet face, keyed by its sorted indices, with its tet and its outward orientation
  struct Face_incidence
  {
    Triangle_indices key;
    std::size_t tet;
    Triangle_indices outward;
    bool operator<(const Face_incidence& o) const { return std::tie(key, tet) < std::tie(o.key, o.tet); }
  };
  std::vector<Face_incidence> incidences;
  incidences.reserve(4 * checked.size());
  for(std::size_t t : checked)
    for(const Triangle_indices& f : internal::outward_faces(mesh.tets[t]))
      incidences.push_back({ internal::sorted_triangle(f), t, f });
  std::sort(incidences.begin(), incidences.end());

  // the one-tet faces (sorted by key), and the face adjacency of tets as a union-find
  std::vector<std::size_t> parent(mesh.tets.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  std::vector<std::pair<Triangle_indices, Triangle_indices> > boundary;  // (key, outward)
  for(std::size_t i = 0, j; i < incidences.size(); i = j) {
    for(j = i + 1; j < incidences.size() && incidences[j].key == incidences[i].key; ++j)
      parent[internal::find_root(parent, incidences[j].tet)] = internal::find_root(parent, incidences[i].tet);
    if(j - i == 1) boundary.emplace_back(incidences[i].key, incidences[i].outward);
    else if(j - i > 2) log.add(&R::number_of_non_manifold_faces, describe("face", incidences[i].key));
  }
  for(std::size_t t : checked)
    if(internal::find_root(parent, t) == t) ++r.connected_components;

  // boundary_faces against the one-tet faces, as sets
  std::vector<char> listed(boundary.size(), 0);
  for(std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    const Triangle_indices& face = mesh.boundary_faces[f];
    const std::string name = "boundary face " + std::to_string(f);
    if(!std::all_of(face.begin(), face.end(), in_range)) {
      log.add(&R::number_of_bad_indices, describe(name, face));
      continue;
    }
    const Triangle_indices key = internal::sorted_triangle(face);
    const auto it = std::lower_bound(boundary.begin(), boundary.end(), key,
                                     [](const std::pair<Triangle_indices, Triangle_indices>& b,
                                        const Triangle_indices& k) { return b.first < k; });
    const std::size_t b = std::size_t(it - boundary.begin());
    if(it == boundary.end() || it->first != key || listed[b]) {
      log.add(&R::number_of_extra_boundary_faces, describe(name, face));
      continue;
    }
    listed[b] = 1;
    if(internal::canonical_rotation(face) != internal::canonical_rotation(it->second))
      log.add(&R::number_of_misoriented_boundary_faces, describe(name, face));
  }
  for(std::size_t b = 0; b < boundary.size(); ++b)
    if(!listed[b]) log.add(&R::number_of_missing_boundary_faces, describe("face", boundary[b].second));

  // manifold boundary (the tets' own, whatever boundary_faces says)
  std::vector<Triangle_indices> outward;
  outward.reserve(boundary.size());
  for(const auto& b : boundary) outward.push_back(b.second);
  const internal::Boundary_manifold_problems manifold = internal::boundary_manifold_problems(outward);
  for(const std::array<int, 2>& e : manifold.edges) log.add(&R::number_of_non_manifold_boundary_edges, describe("edge", e));
  for(int v : manifold.vertices) log.add(&R::number_of_pinched_vertices, "vertex " + std::to_string(v));

  r.message = log.message();
  return r;
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_CHECK_MESH_H
