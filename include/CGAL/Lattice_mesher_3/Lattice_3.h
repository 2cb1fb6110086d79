// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_LATTICE_3_H
#define CGAL_LATTICE_MESHER_3_LATTICE_3_H

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/// The lattices and kernels the package knows by name.
enum class Lattice_type { BCC, FCC, GAUSSIAN };

/*!
\ingroup PkgLatticeMesher3Ref

A lattice and its particle kernel, as data. All offsets are for a unit lattice cube in the
isotropic space; the stages scale them by the target edge length l*.

- `one_ring` is the lattice's one-ring O_1..O_Nor: insertion candidates are p + T l* O_k,
  and the alignment error of an edge is its angle to the closest O_k.
- `holes` are the centres of the kernel's negative Gaussians (the Gaussian Hole Kernel).
  For BCC and FCC they are the one-ring; the hole-less isotropic Gaussian kernel of
  Particle2013 has none: it keeps BCC's density for the vertex count and BCC's one-ring for
  the alignment error, and the mesher neither inserts nor deletes its particles.
- `closest_distance` is l_closest / l*, `density` the number of lattice points per unit cube.

A new lattice (A15, ...) is one more hole set: no stage depends on which lattice it runs.
*/
struct Lattice_3
{
  typedef Eigen::Vector3d Vector; ///< an offset in the isotropic space, in units of l*

  std::string name;               ///< name of the lattice: `"bcc"`, `"fcc"` or `"gaussian"`
  std::vector<Vector> one_ring;   ///< the one-ring offsets O_1..O_Nor
  std::vector<Vector> holes;      ///< centres of the kernel's negative Gaussians (empty: no holes)
  double closest_distance = 1.;   ///< l_closest / l*, the distance between closest lattice points
  double density = 1.;            ///< number of lattice points per unit cube
  double sigma_ratio = 0.3;       ///< sigma / l_closest, the width of the kernel's Gaussians
  // Number of points of a lattice patch that fills a body of volume V, boundary area A and
  // feature length L at edge length l: density V/l^3 + area_factor A/l^2 + length_factor L/l
  // (exact for a lattice-aligned cube; used to pick l* from a vertex count).
  double area_factor = 0.;        ///< points per unit boundary area A / l^2 of a lattice patch
  double length_factor = 0.;      ///< points per unit feature length L / l of a lattice patch

  /// sigma / l*
  double sigma() const { return sigma_ratio * closest_distance; }
  /// largest |O_k|
  double ring_radius() const
  {
    double r = 0.;
    for(const Vector& o : one_ring) r = (std::max)(r, o.norm());
    return r;
  }
  /// `true` if the kernel has holes (false for the hole-less Gaussian kernel)
  bool has_holes() const { return !holes.empty(); }
};

namespace internal {
/// min over `set` of |v - u|^2 (HUGE_VAL for an empty set)
inline double squared_distance_to_closest(const Eigen::Vector3d& v, const std::vector<Eigen::Vector3d>& set)
{
  double best = HUGE_VAL;
  for(const Eigen::Vector3d& u : set) best = (std::min)(best, (v - u).squaredNorm());
  return best;
}

/// The lattice's short vectors: its one-ring offsets and the nonzero sums of two (BCC: 64,
/// up to 2 l*), the edges of its own tetrahedra and of those a wall on a lattice plane leaves.
inline std::vector<Eigen::Vector3d> lattice_vectors(const std::vector<Eigen::Vector3d>& one_ring)
{
  std::vector<Eigen::Vector3d> v(one_ring);
  for(const Eigen::Vector3d& a : one_ring)
    for(const Eigen::Vector3d& b : one_ring) if((a + b).norm() > .5) v.push_back(a + b);
  auto lexicographic = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(v.begin(), v.end(), lexicographic);
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

inline void add_axis_offsets(std::vector<Eigen::Vector3d>& ring)
{
  for(int a = 0; a < 3; ++a)
    for(int s = -1; s <= 1; s += 2) {
      Eigen::Vector3d v = Eigen::Vector3d::Zero();
      v[a] = s;
      ring.push_back(v);
    }
}
} // namespace internal

/// BCC: 8 offsets (±1/2, ±1/2, ±1/2) and 6 axis offsets; l_closest = sqrt(3)/2 l*.
inline Lattice_3 bcc_lattice()
{
  Lattice_3 l;
  l.name = "bcc";
  for(int i = 0; i < 8; ++i)
    l.one_ring.emplace_back((i & 1) ? .5 : -.5, (i & 2) ? .5 : -.5, (i & 4) ? .5 : -.5);
  internal::add_axis_offsets(l.one_ring);
  l.holes = l.one_ring;
  l.closest_distance = std::sqrt(3.) / 2.;
  l.density = 2.;
  l.area_factor = .5;
  l.length_factor = .25;
  return l;
}

/// FCC: 12 offsets (±1/2, ±1/2, 0) and permutations, and 6 axis offsets; l_closest = sqrt(2)/2 l*.
inline Lattice_3 fcc_lattice()
{
  Lattice_3 l;
  l.name = "fcc";
  for(int zero = 0; zero < 3; ++zero)
    for(int i = 0; i < 4; ++i) {
      Eigen::Vector3d v;
      const double a = (i & 1) ? .5 : -.5, b = (i & 2) ? .5 : -.5;
      v[zero] = 0.;
      v[(zero + 1) % 3] = a;
      v[(zero + 2) % 3] = b;
      l.one_ring.push_back(v);
    }
  internal::add_axis_offsets(l.one_ring);
  l.holes = l.one_ring;
  l.closest_distance = std::sqrt(2.) / 2.;
  l.density = 4.;
  l.area_factor = 1.;
  l.length_factor = .25;
  return l;
}

/// The isotropic Gaussian kernel of Particle2013 (no holes), sampled at the BCC density.
inline Lattice_3 gaussian_kernel_lattice()
{
  Lattice_3 l = bcc_lattice();
  l.name = "gaussian";
  l.holes.clear();
  return l;
}

inline Lattice_3 make_lattice(Lattice_type t)
{
  switch(t) {
    case Lattice_type::BCC: return bcc_lattice();
    case Lattice_type::FCC: return fcc_lattice();
    case Lattice_type::GAUSSIAN: return gaussian_kernel_lattice();
  }
  throw std::invalid_argument("make_lattice(): unknown lattice type");
}

inline Lattice_type lattice_type_from_name(const std::string& name)
{
  if(name == "bcc") return Lattice_type::BCC;
  if(name == "fcc") return Lattice_type::FCC;
  if(name == "gaussian") return Lattice_type::GAUSSIAN;
  throw std::invalid_argument("unknown lattice '" + name + "' (expected bcc, fcc or gaussian)");
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_LATTICE_3_H
