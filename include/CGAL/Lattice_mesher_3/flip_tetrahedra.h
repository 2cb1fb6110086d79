// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_FLIP_TETRAHEDRA_H
#define CGAL_LATTICE_MESHER_3_FLIP_TETRAHEDRA_H

#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/// Settings of `flip_tetrahedra()`.
struct Flip_options
{
  /// Only faces and edges of tetrahedra whose smallest dihedral angle (isotropic space, degrees)
  /// is below this are tried: the lattice interior is left alone.
  double target_angle = 50.;
  int max_passes = 8;
  /// Edges with more incident tetrahedra than this are not removed (the ring's triangulations grow
  /// as the Catalan numbers; past 7 a removal almost never improves the worst tetrahedron).
  int max_ring_size = 7;
};

/// What `flip_tetrahedra()` did.
struct Flip_result
{
  std::size_t flips23 = 0, flips32 = 0, edge_removals = 0;   ///< edge_removals: rings of 4 and more
  std::size_t total() const { return flips23 + flips32 + edge_removals; }
};

namespace internal {

struct Face_key_hash
{
  std::size_t operator()(const std::array<int, 3>& k) const
  { return std::size_t(k[0]) * 73856093u ^ std::size_t(k[1]) * 19349663u ^ std::size_t(k[2]) * 83492791u; }
  std::size_t operator()(const std::array<int, 2>& k) const
  { return std::size_t(k[0]) * 73856093u ^ std::size_t(k[1]) * 19349663u; }
};

// A tetrahedral mesh under flips: tetrahedra with their faces and edges indexed by sorted vertex
// tuples, so that the tetrahedra around a face or an edge are found in constant time.
template <typename Point_3, typename FrameField>
class Flip_mesh
{
public:
  Flip_mesh(Tetrahedral_mesh_3<Point_3>& mesh, const FrameField& field) : mesh_(mesh), field_(field)
  {
    for(const std::array<int, 4>& t : mesh.tets) add(t, quality(t));
  }

  // smallest dihedral angle of (a, b, c, d) in the isotropic space at its centroid
  double quality(const std::array<int, 4>& t) const
  {
    std::array<Eigen::Vector3d, 4> p;
    for(int i = 0; i < 4; ++i) p[i] = to_eigen(mesh_.points[t[i]]);
    const Eigen::Vector3d c = .25 * (p[0] + p[1] + p[2] + p[3]);
    const Eigen::Matrix3d b = isotropic_map_at<Point_3>(field_, c);
    for(Eigen::Vector3d& q : p) q = b * (q - c);
    return dihedral_angle_range(p[0], p[1], p[2], p[3]).first;
  }

  CGAL::Orientation orientation(int a, int b, int c, int d) const
  { return CGAL::orientation(mesh_.points[a], mesh_.points[b], mesh_.points[c], mesh_.points[d]); }

  // (a, b, c, d) reordered to be positive, or false if flat
  bool positive(std::array<int, 4>& t) const
  {
    const CGAL::Orientation o = orientation(t[0], t[1], t[2], t[3]);
    if(o == CGAL::COPLANAR) return false;
    if(o == CGAL::NEGATIVE) std::swap(t[0], t[1]);
    return true;
  }

  // replaces the tetrahedra `old` by `created` if that raises the smallest angle among them
  bool try_replace(const std::vector<int>& old, std::vector<std::array<int, 4> >& created)
  {
    double before = 180., after = 180.;
    for(int t : old) before = (std::min)(before, quality_[t]);
    std::vector<double> q(created.size());
    for(std::size_t k = 0; k < created.size(); ++k) {
      if(!positive(created[k])) return false;
      q[k] = quality(created[k]);
      after = (std::min)(after, q[k]);
      if(after <= before + 1e-9) return false;
    }
    for(int t : old) remove(t);
    for(std::size_t k = 0; k < created.size(); ++k) add(created[k], q[k]);
    return true;
  }

  // 2-3 flip of the face (a, b, c) shared by two tetrahedra
  bool flip23(const std::array<int, 3>& f)
  {
    auto it = faces_.find(sorted(f));
    if(it == faces_.end() || it->second[1] < 0) return false;
    const int t0 = it->second[0], t1 = it->second[1];
    const int p = apex(t0, f), q = apex(t1, f);
    std::vector<std::array<int, 4> > created = { { f[0], f[1], p, q }, { f[1], f[2], p, q }, { f[2], f[0], p, q } };
    // the segment pq must cross the triangle: the three new tetrahedra have the same orientation
    const CGAL::Orientation o = orientation(f[0], f[1], p, q);
    if(o == CGAL::COPLANAR || orientation(f[1], f[2], p, q) != o || orientation(f[2], f[0], p, q) != o) return false;
    return try_replace({ t0, t1 }, created);
  }

  // removal of the interior edge (a, b): its ring of n vertices is triangulated (the best of
  // all triangulations for the smallest angle, by dynamic programming), each triangle joined to
  // a and to b. n = 3 is the 3-2 flip, n = 4 the 4-4 flip.
  int remove_edge(int a, int b, int max_ring)
  {
    auto it = edges_.find(sorted(std::array<int, 2>{ a, b }));
    if(it == edges_.end()) return 0;
    const std::vector<int> around = it->second;
    const int n = int(around.size());
    if(n < 3 || n > max_ring) return 0;
    std::vector<int> ring;
    if(!order_ring(a, b, around, ring)) return 0;   // a boundary edge: its ring is open

    // best[i][j]: best smallest angle triangulating ring[i..j]; choice[i][j] the apex
    std::vector<std::vector<double> > best(n, std::vector<double>(n, 180.));
    std::vector<std::vector<int> > choice(n, std::vector<int>(n, -1));
    for(int len = 2; len < n; ++len)
      for(int i = 0; i + len < n; ++i) {
        const int j = i + len;
        best[i][j] = -1.;
        for(int k = i + 1; k < j; ++k) {
          const double q = (std::min)((std::min)(best[i][k], best[k][j]), pair_quality(ring[i], ring[k], ring[j], a, b));
          if(q > best[i][j]) { best[i][j] = q; choice[i][j] = k; }
        }
      }
    if(best[0][n - 1] <= 0.) return 0;
    std::vector<std::array<int, 4> > created;
    collect(ring, choice, 0, n - 1, a, b, created);
    return try_replace(around, created) ? n : 0;
  }

  // writes the current tetrahedra back to the mesh
  void commit()
  {
    mesh_.tets.clear();
    for(std::size_t t = 0; t < tets_.size(); ++t)
      if(alive_[t]) mesh_.tets.push_back(tets_[t]);
  }

  std::vector<int> tetrahedra_below(double angle) const
  {
    std::vector<int> out;
    for(std::size_t t = 0; t < tets_.size(); ++t)
      if(alive_[t] && quality_[t] < angle) out.push_back(int(t));
    return out;
  }
  bool alive(int t) const { return alive_[t] != 0; }
  const std::array<int, 4>& tet(int t) const { return tets_[t]; }

private:
  static std::array<int, 3> sorted(std::array<int, 3> k) { std::sort(k.begin(), k.end()); return k; }
  static std::array<int, 2> sorted(std::array<int, 2> k) { if(k[0] > k[1]) std::swap(k[0], k[1]); return k; }

  int apex(int t, const std::array<int, 3>& f) const
  {
    for(int v : tets_[t]) if(v != f[0] && v != f[1] && v != f[2]) return v;
    return -1;
  }

  // both tetrahedra (ring triangle + a, + b) valid, their smaller angle; -1 if a or b is on the
  // wrong side
  double pair_quality(int i, int j, int k, int a, int b) const
  {
    const CGAL::Orientation oa = orientation(i, j, k, a), ob = orientation(i, j, k, b);
    if(oa == CGAL::COPLANAR || ob == CGAL::COPLANAR || oa == ob) return -1.;
    return (std::min)(quality({ i, j, k, a }), quality({ i, j, k, b }));
  }

  void collect(const std::vector<int>& ring, const std::vector<std::vector<int> >& choice, int i, int j,
               int a, int b, std::vector<std::array<int, 4> >& out) const
  {
    if(j - i < 2) return;
    const int k = choice[i][j];
    out.push_back({ ring[i], ring[k], ring[j], a });
    out.push_back({ ring[i], ring[k], ring[j], b });
    collect(ring, choice, i, k, a, b, out);
    collect(ring, choice, k, j, a, b, out);
  }

  // the vertices around edge ab in cyclic order; false if the tetrahedra do not close a ring
  bool order_ring(int a, int b, const std::vector<int>& around, std::vector<int>& ring) const
  {
    std::vector<std::array<int, 2> > links;
    for(int t : around) {
      std::array<int, 2> l{ -1, -1 };
      int k = 0;
      for(int v : tets_[t]) if(v != a && v != b) l[k++] = v;
      links.push_back(l);
    }
    ring.assign(1, links[0][0]);
    int next = links[0][1];
    std::vector<char> used(links.size(), 0);
    used[0] = 1;
    for(std::size_t step = 1; step < links.size(); ++step) {
      ring.push_back(next);
      bool found = false;
      for(std::size_t e = 0; e < links.size() && !found; ++e) {
        if(used[e]) continue;
        if(links[e][0] == next) { next = links[e][1]; used[e] = 1; found = true; }
        else if(links[e][1] == next) { next = links[e][0]; used[e] = 1; found = true; }
      }
      if(!found) return false;
    }
    return next == ring[0];
  }

  void add(const std::array<int, 4>& t, double quality)
  {
    const int id = int(tets_.size());
    tets_.push_back(t);
    quality_.push_back(quality);
    alive_.push_back(1);
    for(int i = 0; i < 4; ++i) {
      auto& slot = faces_.emplace(sorted(std::array<int, 3>{ t[(i + 1) % 4], t[(i + 2) % 4], t[(i + 3) % 4] }),
                                  std::array<int, 2>{ -1, -1 }).first->second;
      (slot[0] < 0 ? slot[0] : slot[1]) = id;
      for(int j = i + 1; j < 4; ++j) edges_[sorted(std::array<int, 2>{ t[i], t[j] })].push_back(id);
    }
  }

  void remove(int id)
  {
    const std::array<int, 4>& t = tets_[id];
    alive_[id] = 0;
    for(int i = 0; i < 4; ++i) {
      auto it = faces_.find(sorted(std::array<int, 3>{ t[(i + 1) % 4], t[(i + 2) % 4], t[(i + 3) % 4] }));
      if(it->second[0] == id) { it->second[0] = it->second[1]; }
      it->second[1] = -1;
      if(it->second[0] < 0) faces_.erase(it);
      for(int j = i + 1; j < 4; ++j) {
        auto e = edges_.find(sorted(std::array<int, 2>{ t[i], t[j] }));
        e->second.erase(std::find(e->second.begin(), e->second.end(), id));
        if(e->second.empty()) edges_.erase(e);
      }
    }
  }

  Tetrahedral_mesh_3<Point_3>& mesh_;
  const FrameField& field_;
  std::vector<std::array<int, 4> > tets_;
  std::vector<double> quality_;   // smallest dihedral angle of each tetrahedron, isotropic space
  std::vector<char> alive_;
  std::unordered_map<std::array<int, 3>, std::array<int, 2>, Face_key_hash> faces_;
  std::unordered_map<std::array<int, 2>, std::vector<int>, Face_key_hash> edges_;
};

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Flips

Improves the connectivity of a tetrahedral mesh by topological flips: 2-3 flips of interior faces
and removals of interior edges (3-2 and 4-4 flips, and the general edge removal with the best
triangulation of the edge's ring), each done only when it raises the smallest dihedral angle of
the tetrahedra it replaces, measured in the isotropic space of `field` (B at each tetrahedron's
centroid). Only the faces and edges of tetrahedra below `target_angle` are tried. Flips never
create an inverted tetrahedron (exact orientation tests) and never touch the boundary: boundary
faces belong to one tetrahedron and boundary edges have an open ring, so neither is flipped.
*/
template <typename Point_3, typename FrameField>
Flip_result flip_tetrahedra(Tetrahedral_mesh_3<Point_3>& mesh, const FrameField& field,
                            const Flip_options& o = Flip_options())
{
  internal::Flip_mesh<Point_3, FrameField> fm(mesh, field);
  Flip_result result;
  for(int pass = 0; pass < o.max_passes; ++pass) {
    const std::size_t before = result.total();
    for(int t : fm.tetrahedra_below(o.target_angle)) {
      if(!fm.alive(t)) continue;
      const std::array<int, 4> v = fm.tet(t);
      bool done = false;
      for(int i = 0; i < 4 && !done; ++i)
        for(int j = i + 1; j < 4 && !done; ++j) {
          const int n = fm.remove_edge(v[i], v[j], o.max_ring_size);
          if(n == 3) ++result.flips32;
          else if(n > 3) ++result.edge_removals;
          done = n > 0;
        }
      for(int i = 0; i < 4 && !done; ++i)
        if(fm.flip23({ v[(i + 1) % 4], v[(i + 2) % 4], v[(i + 3) % 4] })) { ++result.flips23; done = true; }
    }
    if(result.total() == before) break;
  }
  fm.commit();
  return result;
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_FLIP_TETRAHEDRA_H
