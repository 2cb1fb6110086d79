// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_MESH_QUALITY_H
#define CGAL_LATTICE_MESHER_3_MESH_QUALITY_H

#include <CGAL/Lattice_mesher_3/Lattice_3.h>
#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/internal/stage_parameters.h>
#include <CGAL/Lattice_mesher_3/internal/triangle_sampling.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <exception>
#include <initializer_list>
#include <iomanip>
#include <iterator>
#include <ostream>
#include <stdexcept>
#include <tuple>
#include <string>
#include <utility>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3Quality
Summary of one quality figure over a mesh. `std` is the population standard deviation.
Only the fields meaningful for a figure are reported in the JSON output (e.g. no `min` for
the largest dihedral angle).
*/
struct Quality_statistics
{
  double min = 0.;   ///< the smallest value
  double max = 0.;   ///< the largest value
  double mean = 0.;  ///< the mean value
  double std = 0.;   ///< the population standard deviation
};

/*!
\ingroup PkgLatticeMesher3Quality
Quality of one tetrahedron, measured in the isotropic space. Angles are in degrees.
*/
struct Tetrahedron_quality_3
{
  double theta_min = 0.;  ///< smallest dihedral angle (70.53 for a regular tetrahedron)
  double theta_max = 0.;  ///< largest dihedral angle
  double rho = 0.;        ///< edge-radius ratio sqrt(6) e_min / (4 r_circ), 1 when regular
  double kappa = 0.;      ///< 3 sqrt(6) V / (2 l_rms A_rms), 1 when regular
};

/*!
\ingroup PkgLatticeMesher3Quality
The figures of the paper's quality tables, measured in the isotropic space of a frame field
(see `compute_mesh_quality()`). Angles are in degrees. `hausdorff` is negative when it was not
measured; `seconds` is filled by the caller.
*/
struct Mesh_quality_3
{
  std::size_t vertices = 0;      ///< number of vertices of the mesh
  std::size_t tets = 0;          ///< number of tetrahedra of the mesh
  Quality_statistics theta_min;  ///< of the per-tetrahedron smallest dihedral angle
  Quality_statistics theta_max;  ///< of the per-tetrahedron largest dihedral angle
  Quality_statistics rho;        ///< of the per-tetrahedron edge-radius ratio (`Tetrahedron_quality_3::rho`)
  Quality_statistics kappa;      ///< of the per-tetrahedron volume-area ratio (`Tetrahedron_quality_3::kappa`)
  Quality_statistics epsilon;    ///< edge alignment error, over the unique edges
  std::size_t below20 = 0;       ///< tetrahedra with theta_min < 20 degrees
  std::size_t below40 = 0;       ///< tetrahedra with theta_min < 40 degrees
  double hausdorff = -1.;        ///< symmetric Hausdorff distance between the mesh boundary and the domain surface (`boundary_distances()`), in the domain's length unit; negative when not measured
  double hausdorff_over_size = -1.;  ///< `Boundary_distances_3::over_size`, negative when not measured
  double edge_length = 0.;       ///< the l* the mesh was made for; 0 when not known (filled by the caller)
  struct Timings
  {
    double optimize = 0.;
    double mesh = 0.;
    double total = 0.;
    std::vector<std::pair<std::string, double> > stages;
  } seconds;  ///< running times in seconds of the particle optimization (`optimize`), the tetrahedralization and its improvement (`mesh`), the whole run (`total`) and each stage in the order they ran (`stages`, see `Stage_times_visitor`); filled by the caller, 0 and empty otherwise
};

namespace internal {

constexpr double degrees_per_radian = 57.295779513082320876798154814105;

// Angle between two vectors in [0, 180] degrees; atan2 keeps full precision near 0 and 180,
// where acos of a dot product loses half the digits (slivers live there).
inline double angle_degrees(const Eigen::Vector3d& u, const Eigen::Vector3d& v)
{ return degrees_per_radian * std::atan2(u.cross(v).norm(), u.dot(v)); }


// OpenMP's default number of threads (1 without OpenMP)
inline int default_number_of_threads()
{
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

// The threads of a measure: the named parameter number_of_threads, or OpenMP's default.
template <typename NamedParameters>
int measure_threads(const NamedParameters& np)
{
  const int threads = parameters::choose_parameter(parameters::get_parameter(np, internal_np::number_of_threads),
                                                   default_number_of_threads());
  if(threads < 1) throw std::invalid_argument("number_of_threads() must be at least 1");
  return threads;
}

// Runs f(i) for i in [0, n) on `threads` threads (OpenMP's default: all). OpenMP forbids
// exceptions from leaving the loop, so the one of the lowest index is rethrown afterwards: the
// same error for any thread count. A thread takes `chunk` consecutive items at a time (0: an
// equal share of them): small chunks balance items of unequal cost.
template <typename F>
void parallel_for_rethrow(std::size_t n, const F& f, int threads = default_number_of_threads(), std::size_t chunk = 0)
{
  std::exception_ptr error;
  std::ptrdiff_t error_index = std::ptrdiff_t(n);
  if(chunk == 0) chunk = (std::max)(std::size_t(1), (n + std::size_t(threads) - 1) / std::size_t(threads));
#pragma omp parallel for num_threads(threads) schedule(dynamic, chunk)
  for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(n); ++i) {
    try {
      f(std::size_t(i));
    } catch(...) {
#pragma omp critical(lattice_mesher_3_quality_error)
      if(i < error_index) { error_index = i; error = std::current_exception(); }
    }
  }
  if(error) std::rethrow_exception(error);
}

// Serial, in index order: the sums, hence the figures, do not depend on the thread count.
inline Quality_statistics summarize(const std::vector<double>& values)
{
  Quality_statistics s;
  if(values.empty()) return s;
  s.min = *std::min_element(values.begin(), values.end());
  s.max = *std::max_element(values.begin(), values.end());
  double sum = 0.;
  for(double v : values) sum += v;
  s.mean = sum / double(values.size());
  double squares = 0.;
  for(double v : values) squares += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(squares / double(values.size()));
  return s;
}

// The sorted list of unique edges (i < j) of the tetrahedra.
inline std::vector<std::pair<int, int> > unique_edges(const std::vector<std::array<int, 4> >& tets)
{
  std::vector<std::pair<int, int> > edges;
  edges.reserve(6 * tets.size());
  for(const std::array<int, 4>& t : tets)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        edges.emplace_back((std::min)(t[i], t[j]), (std::max)(t[i], t[j]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

// B at p, the isotropic map of the field.
template <typename Point_3, typename FrameField>
Eigen::Matrix3d isotropic_map_at(const FrameField& field, const Eigen::Vector3d& p)
{
  const Point_3 where(p[0], p[1], p[2]);
  const Eigen::Matrix3d t = field.frame(where);
  return isotropic_map(t, where);
}

// The tetrahedron with these corners in the isotropic space: mapped by B at its centroid, about it.
template <typename Point_3, typename FrameField>
std::array<Eigen::Vector3d, 4> isotropic_tetrahedron(const FrameField& field, const std::array<Point_3, 4>& corners)
{
  std::array<Eigen::Vector3d, 4> p;
  for(int i = 0; i < 4; ++i) p[i] = to_eigen(corners[i]);
  const Eigen::Vector3d centroid = .25 * (p[0] + p[1] + p[2] + p[3]);
  const Eigen::Matrix3d b = isotropic_map_at<Point_3>(field, centroid);
  for(Eigen::Vector3d& q : p) q = b * (q - centroid);
  return p;
}

// The tetrahedron t of `mesh` in the isotropic space.
template <typename Point_3, typename FrameField>
std::array<Eigen::Vector3d, 4> isotropic_tetrahedron(const Tetrahedral_mesh_3<Point_3>& mesh,
                                                     const FrameField& field, std::size_t t)
{
  const std::array<int, 4>& v = mesh.tets[t];
  return isotropic_tetrahedron(field, std::array<Point_3, 4>{ mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]] });
}

// Area vectors (twice the area) of the faces opposite a, b, c, d, all outward for a positive
// tetrahedron and all inward for a negative one: the dihedral angles are the same either way.
inline std::array<Eigen::Vector3d, 4> face_area_vectors(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                        const Eigen::Vector3d& c, const Eigen::Vector3d& d)
{ return { (c - b).cross(d - b), (d - a).cross(c - a), (b - a).cross(d - a), (c - a).cross(b - a) }; }

// The faces i and j meet at the edge opposite both, with interior angle pi - angle(n_i, n_j).
inline double dihedral_angle(const std::array<Eigen::Vector3d, 4>& n, int i, int j)
{ return angle_degrees(n[i], -n[j]); }

// The smallest dihedral angle from the face area vectors, found by its cosine. acos is precise
// enough above 1 degree (a relative error of about 1e-14 / angle); below, atan2 (slivers).
inline double smallest_angle_of_faces(const std::array<Eigen::Vector3d, 4>& n)
{
  std::array<double, 4> norm;
  for(int i = 0; i < 4; ++i) norm[i] = n[i].norm();
  int lo_i = 0, lo_j = 1;
  double cos_lo = -2.;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j) {
      const double cosine = -n[i].dot(n[j]) / (norm[i] * norm[j]);
      if(cosine > cos_lo) { cos_lo = cosine; lo_i = i; lo_j = j; }
    }
  return cos_lo < 0.9998 ? degrees_per_radian * std::acos(cos_lo) : dihedral_angle(n, lo_i, lo_j);
}

// Radius ratio from the face area vectors n1 = w x v, n2 = u x w, n3 = v x u (u = b - a,
// v = c - a, w = d - a) and the squared length of the shortest edge:
// r_circ = | |u|^2 v x w + |v|^2 w x u + |w|^2 u x v | / (2 |u.(v x w)|).
inline double radius_ratio_of_faces(const std::array<Eigen::Vector3d, 4>& n, const Eigen::Vector3d& u,
                                   const Eigen::Vector3d& v, const Eigen::Vector3d& w, double e_min2)
{
  const double six_volume = std::abs(u.dot(n[1]));
  if(!(six_volume > 0.)) return 0.;
  const double r_circ = (u.squaredNorm() * n[1] + v.squaredNorm() * n[2] + w.squaredNorm() * n[3]).norm() / (2. * six_volume);
  return std::sqrt(6.) * std::sqrt(e_min2) / (4. * r_circ);
}

inline double shortest_squared_edge(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                    const Eigen::Vector3d& d)
{
  return (std::min)({ (b - a).squaredNorm(), (c - a).squaredNorm(), (d - a).squaredNorm(), (c - b).squaredNorm(),
                      (d - b).squaredNorm(), (d - c).squaredNorm() });
}

// The smallest height of the tetrahedron (a, b, c, d) (three times its volume over its largest
// face) over its mean edge: 0.816 for the regular one, 0 for a flat one. Removing a tetrahedron
// with two faces on the boundary moves the boundary by that height.
inline double height_over_mean_edge(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                    const Eigen::Vector3d& d)
{
  const std::array<Eigen::Vector3d, 4> p{ a, b, c, d };
  double mean_edge = 0., largest_face = 0.;
  for(int i = 0; i < 4; ++i) for(int j = i + 1; j < 4; ++j) mean_edge += (p[i] - p[j]).norm();
  mean_edge /= 6.;
  for(int i = 0; i < 4; ++i)
    largest_face = (std::max)(largest_face, .5 * (p[(i + 2) % 4] - p[(i + 1) % 4]).cross(p[(i + 3) % 4] - p[(i + 1) % 4]).norm());
  const double volume = std::abs((b - a).cross(c - a).dot(d - a)) / 6.;
  return mean_edge > 0. && largest_face > 0. ? 3. * volume / (mean_edge * largest_face) : 0.;
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Quality
Smallest and largest interior dihedral angle (degrees) of the tetrahedron (a, b, c, d), whatever
its orientation.
*/
inline std::pair<double, double> dihedral_angle_range(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                      const Eigen::Vector3d& c, const Eigen::Vector3d& d)
{
  const std::array<Eigen::Vector3d, 4> n = internal::face_area_vectors(a, b, c, d);
  // The extreme angles are found by their cosines; only those two go through atan2, which is
  // precise near 0 and 180 degrees.
  std::array<double, 4> norm;
  for(int i = 0; i < 4; ++i) norm[i] = n[i].norm();
  int lo_i = 0, lo_j = 1, hi_i = 0, hi_j = 1;
  double cos_lo = -2., cos_hi = 2.;   // cosine of the smallest and of the largest angle
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j) {
      const double cosine = -n[i].dot(n[j]) / (norm[i] * norm[j]);
      if(cosine > cos_lo) { cos_lo = cosine; lo_i = i; lo_j = j; }
      if(cosine < cos_hi) { cos_hi = cosine; hi_i = i; hi_j = j; }
    }
  return { internal::dihedral_angle(n, lo_i, lo_j), internal::dihedral_angle(n, hi_i, hi_j) };
}

/*!
\ingroup PkgLatticeMesher3Quality
Smallest interior dihedral angle (degrees) of the tetrahedron (a, b, c, d): the first of
`dihedral_angle_range()`, by acos of its cosine above 1 degree (the hot loops of flips and smoothing).
*/
inline double smallest_dihedral_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                      const Eigen::Vector3d& c, const Eigen::Vector3d& d)
{ return internal::smallest_angle_of_faces(internal::face_area_vectors(a, b, c, d)); }

/*!
\ingroup PkgLatticeMesher3Quality
Radius ratio rho = sqrt(6) e_min / (4 r_circ) of the tetrahedron (a, b, c, d) (1 for the regular
one, 0 for a degenerate one).
*/
inline double radius_ratio(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                           const Eigen::Vector3d& d)
{
  return internal::radius_ratio_of_faces(internal::face_area_vectors(a, b, c, d), b - a, c - a, d - a,
                                        internal::shortest_squared_edge(a, b, c, d));
}

/*!
\ingroup PkgLatticeMesher3Quality
Quality of the tetrahedron (a, b, c, d), given in the space where it is measured (the isotropic
space). The result does not depend on the orientation of the tetrahedron; a degenerate one has
`rho` = `kappa` = 0.
*/
inline Tetrahedron_quality_3 tetrahedron_quality(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                                 const Eigen::Vector3d& c, const Eigen::Vector3d& d)
{
  Tetrahedron_quality_3 q;
  std::tie(q.theta_min, q.theta_max) = dihedral_angle_range(a, b, c, d);
  double squared_areas = 0.;
  for(const Eigen::Vector3d& n : internal::face_area_vectors(a, b, c, d))
    squared_areas += .25 * n.squaredNorm();

  const Eigen::Vector3d u = b - a, v = c - a, w = d - a;
  const std::array<Eigen::Vector3d, 6> edges = { u, v, w, c - b, d - b, d - c };
  double squared_lengths = 0.;
  for(const Eigen::Vector3d& e : edges) squared_lengths += e.squaredNorm();
  const double six_volume = std::abs(u.dot(v.cross(w)));
  if(six_volume > 0.) {
    q.rho = radius_ratio(a, b, c, d);
    const double l_rms = std::sqrt(squared_lengths / 6.), a_rms = std::sqrt(squared_areas / 4.);
    q.kappa = 3. * std::sqrt(6.) * (six_volume / 6.) / (2. * l_rms * a_rms);
  }
  return q;
}

/*!
\ingroup PkgLatticeMesher3Quality
Alignment error of an isotropic-space edge vector `e`: the smallest angle, in degrees, between
`e` and the vectors of the lattice's one-ring (which holds both signs of every direction).
*/
inline double edge_alignment_error(const Eigen::Vector3d& e, const Lattice_3& lattice)
{
  if(lattice.one_ring.empty())
    throw std::invalid_argument("edge_alignment_error(): the lattice has an empty one-ring");
  double best = 180.;
  for(const Eigen::Vector3d& o : lattice.one_ring) best = (std::min)(best, internal::angle_degrees(e, o));
  return best;
}

/*!
\ingroup PkgLatticeMesher3Quality
Quality of every tetrahedron of `mesh`, mapped to the isotropic space by B = T^-1 at its
centroid, T = `field.frame(centroid)`. Computed in parallel (OpenMP), the same for any number of
threads.

\tparam FrameField a model of `FrameField_3` for points of type `Point_3`

\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{OpenMP threads}
    \cgalParamType{int}
    \cgalParamDefault{OpenMP's default (all cores)}
  \cgalParamNEnd
\cgalNamedParamsEnd
\throws std::domain_error if the frame at a centroid is singular
\throws std::invalid_argument if `number_of_threads` is below 1
*/
template <typename Point_3, typename FrameField,
          typename NamedParameters = parameters::Default_named_parameters>
std::vector<Tetrahedron_quality_3> compute_tetrahedra_quality(const Tetrahedral_mesh_3<Point_3>& mesh,
                                                              const FrameField& field,
                                                              const NamedParameters& np = parameters::default_values())
{
  std::vector<Tetrahedron_quality_3> quality(mesh.tets.size());
  internal::parallel_for_rethrow(mesh.tets.size(), [&](std::size_t t) {
    const std::array<Eigen::Vector3d, 4> p = internal::isotropic_tetrahedron(mesh, field, t);
    quality[t] = tetrahedron_quality(p[0], p[1], p[2], p[3]);
  }, internal::measure_threads(np));
  return quality;
}

/*!
\ingroup PkgLatticeMesher3Quality
Alignment error (degrees) of every unique edge of `mesh`, mapped to the isotropic space by B at
its midpoint. The edges are taken in lexicographic order of their sorted vertex pairs. The named
parameter `number_of_threads` is as for `compute_tetrahedra_quality()`.

\throws std::domain_error if the frame at a midpoint is singular
*/
template <typename Point_3, typename FrameField,
          typename NamedParameters = parameters::Default_named_parameters>
std::vector<double> compute_edge_alignment_errors(const Tetrahedral_mesh_3<Point_3>& mesh,
                                                  const FrameField& field, const Lattice_3& lattice,
                                                  const NamedParameters& np = parameters::default_values())
{
  const std::vector<std::pair<int, int> > edges = internal::unique_edges(mesh.tets);
  std::vector<double> errors(edges.size());
  internal::parallel_for_rethrow(edges.size(), [&](std::size_t e) {
    const Eigen::Vector3d p = internal::to_eigen(mesh.points[edges[e].first]);
    const Eigen::Vector3d q = internal::to_eigen(mesh.points[edges[e].second]);
    const Eigen::Matrix3d b = internal::isotropic_map_at<Point_3>(field, .5 * (p + q));
    errors[e] = edge_alignment_error(b * (q - p), lattice);
  }, internal::measure_threads(np));
  return errors;
}

/*!
\ingroup PkgLatticeMesher3Quality
Measures `mesh` in the isotropic space of `field`: the dihedral angles, rho and kappa of every
tetrahedron (mapped by B at its centroid) and the alignment error epsilon of every edge with
respect to the one-ring of the named parameter `lattice` (a `Lattice_type` or a `Lattice_3`,
default BCC; mapped by B at its midpoint), on `number_of_threads` OpenMP threads (as for
`compute_tetrahedra_quality()`). The result is the same for any number of threads. `hausdorff` is left negative (see `boundary_hausdorff_distance()`) and `seconds` at 0.

\tparam FrameField a model of `FrameField_3` for points of type `Point_3`
\throws std::domain_error if the frame is singular at a centroid or a midpoint
*/
template <typename Point_3, typename FrameField,
          typename NamedParameters = parameters::Default_named_parameters>
Mesh_quality_3 compute_mesh_quality(const Tetrahedral_mesh_3<Point_3>& mesh, const FrameField& field,
                                    const NamedParameters& np = parameters::default_values())
{
  const Lattice_3 lattice = internal::stage_lattice(np);
  Mesh_quality_3 result;
  result.vertices = mesh.points.size();
  result.tets = mesh.tets.size();

  const std::vector<Tetrahedron_quality_3> quality = compute_tetrahedra_quality(mesh, field, np);
  std::vector<double> values(quality.size());
  auto summarize_member = [&](double Tetrahedron_quality_3::*member) {
    for(std::size_t t = 0; t < quality.size(); ++t) values[t] = quality[t].*member;
    return internal::summarize(values);
  };
  result.theta_min = summarize_member(&Tetrahedron_quality_3::theta_min);
  result.theta_max = summarize_member(&Tetrahedron_quality_3::theta_max);
  result.rho = summarize_member(&Tetrahedron_quality_3::rho);
  result.kappa = summarize_member(&Tetrahedron_quality_3::kappa);
  for(const Tetrahedron_quality_3& q : quality) {
    if(q.theta_min < 20.) ++result.below20;
    if(q.theta_min < 40.) ++result.below40;
  }
  result.epsilon = internal::summarize(compute_edge_alignment_errors(mesh, field, lattice, np));
  return result;
}

/*!
\ingroup PkgLatticeMesher3Quality
Distances between the boundary of a mesh and the surface of its domain
(`boundary_distances()`).
*/
template <typename Point_3>
struct Boundary_distances_3
{
  double hausdorff = 0.;       ///< the symmetric Hausdorff distance
  double over_size = 0.;       ///< the largest of the same distances, each over the size at its sample
  Point_3 worst_sample;        ///< the sample of `over_size`
  /// whether `worst_sample` is a sample of the surface, far from the mesh (a part of the domain
  /// that the mesh lacks), or of the mesh's boundary, far from the surface
  bool worst_on_surface = false;
};

/*!
\ingroup PkgLatticeMesher3Quality
Symmetric Hausdorff distance between the boundary triangles of `mesh` and the boundary surface
of `domain`, both sampled at `spacing`, and the same relative to the size the mesh was made
for, on `number_of_threads` OpenMP threads (a named parameter, as for
`compute_tetrahedra_quality()`): the largest of
- the distance to the surface (`domain.project_on_surface()`) of the boundary vertices and of
  points at most `spacing` apart on every boundary triangle, and
- the distance to the boundary triangles of the points of `domain.sample_surface(spacing)`;
each divided, for `Boundary_distances_3::over_size`, by `size` at the sample (the local edge
length: a graded mesh is held to its own size, a thin part to the size it was given), whose
largest names its sample (`Boundary_distances_3::worst_sample`).

\tparam Domain a model of `LatticeMeshDomain_3` whose points are of type `Point_3`
\tparam Size a callable `double(const Point_3&)`, positive, thread-safe
\throws std::invalid_argument if `spacing` is not positive or the mesh has no boundary face
*/
template <typename Point_3, typename Domain, typename Size,
          typename NamedParameters = parameters::Default_named_parameters>
Boundary_distances_3<Point_3> boundary_distances(const Tetrahedral_mesh_3<Point_3>& mesh, const Domain& domain, double spacing,
                                        const Size& size, const NamedParameters& np = parameters::default_values())
{
  // The boundary triangles in double arithmetic: the surface samples often lie in the plane of a
  // boundary face (CAD models), where the filtered sphere-box tests of the tree's traversal fell
  // back to exact arithmetic (anchor at 15,000 vertices: a quarter of the time of the check).
  typedef CGAL::Simple_cartesian<double> DK;
  typedef std::vector<typename DK::Triangle_3> Triangles;
  typedef CGAL::AABB_triangle_primitive<DK, typename Triangles::const_iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<DK, Primitive> > Tree;
  auto to_double = [](const Point_3& p) { return typename DK::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())); };

  if(!(spacing > 0.))
    throw std::invalid_argument("boundary_distances(): the sampling spacing must be positive");
  if(mesh.boundary_faces.empty())
    throw std::invalid_argument("boundary_distances(): the mesh has no boundary face");
  const int threads = internal::measure_threads(np);

  Triangles triangles;
  triangles.reserve(mesh.boundary_faces.size());
  for(const std::array<int, 3>& f : mesh.boundary_faces)
    triangles.emplace_back(to_double(mesh.points[f[0]]), to_double(mesh.points[f[1]]), to_double(mesh.points[f[2]]));
  // mesh -> surface: the boundary vertices, edges and faces, each once, sampled at `spacing`
  std::vector<int> vertices;
  std::vector<std::array<int, 2> > edges;
  for(const std::array<int, 3>& f : mesh.boundary_faces)
    for(int e = 0; e < 3; ++e) {
      vertices.push_back(f[e]);
      edges.push_back({ (std::min)(f[e], f[(e + 1) % 3]), (std::max)(f[e], f[(e + 1) % 3]) });
    }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<Point_3> points;
  for(int v : vertices) points.push_back(mesh.points[std::size_t(v)]);
  for(const std::array<int, 2>& e : edges)
    internal::sample_segment(mesh.points[std::size_t(e[0])], mesh.points[std::size_t(e[1])], spacing, std::back_inserter(points));
  for(const std::array<int, 3>& f : mesh.boundary_faces)
    internal::sample_triangle_inside(std::array<Point_3, 3>{ mesh.points[std::size_t(f[0])], mesh.points[std::size_t(f[1])], mesh.points[std::size_t(f[2])] },
                                     spacing, std::back_inserter(points));
  // (distance, distance over the size) at each sample
  std::vector<std::array<double, 2> > mesh_to_surface(points.size());
  internal::parallel_for_rethrow(points.size(), [&](std::size_t i) {
    const double d = std::sqrt(CGAL::to_double(domain.project_on_surface(points[i]).squared_distance));
    mesh_to_surface[i] = { d, d / size(points[i]) };
  }, threads);

  // surface -> mesh; the tree's search structures are built before the concurrent queries
  std::vector<Point_3> samples;
  domain.sample_surface(spacing, std::back_inserter(samples));
  Tree tree(triangles.cbegin(), triangles.cend());
  tree.build();
  tree.accelerate_distance_queries();
  std::vector<std::array<double, 2> > surface_to_mesh(samples.size());
  internal::parallel_for_rethrow(samples.size(), [&](std::size_t s) {
    const double d = std::sqrt(tree.squared_distance(to_double(samples[s])));
    surface_to_mesh[s] = { d, d / size(samples[s]) };
  }, threads);

  Boundary_distances_3<Point_3> result;
  result.worst_sample = points.front();
  for(int side = 0; side < 2; ++side) {
    const std::vector<std::array<double, 2> >& d = side ? surface_to_mesh : mesh_to_surface;
    for(std::size_t i = 0; i < d.size(); ++i) {
      result.hausdorff = (std::max)(result.hausdorff, d[i][0]);
      if(!(d[i][1] > result.over_size)) continue;
      result.over_size = d[i][1];
      result.worst_sample = side ? samples[i] : points[i];
      result.worst_on_surface = side == 1;
    }
  }
  return result;
}

/*!
\ingroup PkgLatticeMesher3Quality
The symmetric Hausdorff distance of `boundary_distances()` (with the same named parameters).
*/
template <typename Point_3, typename Domain,
          typename NamedParameters = parameters::Default_named_parameters>
double boundary_hausdorff_distance(const Tetrahedral_mesh_3<Point_3>& mesh, const Domain& domain,
                                   double spacing, const NamedParameters& np = parameters::default_values())
{
  return boundary_distances(mesh, domain, spacing, [](const Point_3&) { return 1.; }, np).hausdorff;
}

namespace internal {

inline void write_table_row(std::ostream& os, const char* name, const Quality_statistics& s)
{
  os << "  " << std::left << std::setw(18) << name << std::right
     << std::setw(12) << s.min << std::setw(12) << s.mean << std::setw(12) << s.std
     << std::setw(12) << s.max << '\n';
}

inline void write_table_count(std::ostream& os, const char* name, std::size_t count, std::size_t total)
{
  os << "  " << std::left << std::setw(18) << name << std::right << std::setw(12) << count;
  if(total > 0) {
    const std::streamsize precision = os.precision(2);
    os << "  (" << 100. * double(count) / double(total) << " %)";
    os.precision(precision);
  }
  os << '\n';
}

// A field of Quality_statistics as written to JSON.
struct Json_statistic
{
  const char* name;
  double Quality_statistics::*value;
};

inline constexpr Json_statistic json_min = { "min", &Quality_statistics::min };
inline constexpr Json_statistic json_max = { "max", &Quality_statistics::max };
inline constexpr Json_statistic json_mean = { "mean", &Quality_statistics::mean };
inline constexpr Json_statistic json_std = { "std", &Quality_statistics::std };

// `  "name": {"field": value, ...},` with the listed fields of `s` only
inline void write_json_statistics(std::ostream& os, const char* name, const Quality_statistics& s,
                                  std::initializer_list<Json_statistic> fields)
{
  os << "  \"" << name << "\": {";
  const char* separator = "";
  for(const Json_statistic& f : fields) {
    os << separator << '"' << f.name << "\": " << s.*f.value;
    separator = ", ";
  }
  os << "},\n";
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Quality
Writes `q` as a fixed-width table (angles in degrees).
*/
inline void print_quality_table(std::ostream& os, const Mesh_quality_3& q)
{
  const std::ios_base::fmtflags flags = os.flags();
  const std::streamsize precision = os.precision();
  os << std::fixed << std::setprecision(4);
  os << "  " << std::left << std::setw(18) << "vertices" << std::right << std::setw(12) << q.vertices << '\n'
     << "  " << std::left << std::setw(18) << "tetrahedra" << std::right << std::setw(12) << q.tets << '\n'
     << "  " << std::left << std::setw(18) << "" << std::right << std::setw(12) << "min" << std::setw(12)
     << "mean" << std::setw(12) << "std" << std::setw(12) << "max" << '\n';
  internal::write_table_row(os, "theta_min (deg)", q.theta_min);
  internal::write_table_row(os, "theta_max (deg)", q.theta_max);
  internal::write_table_row(os, "rho", q.rho);
  internal::write_table_row(os, "kappa", q.kappa);
  internal::write_table_row(os, "epsilon (deg)", q.epsilon);
  internal::write_table_count(os, "theta_min < 20", q.below20, q.tets);
  internal::write_table_count(os, "theta_min < 40", q.below40, q.tets);
  os << "  " << std::left << std::setw(18) << "Hausdorff" << std::right;
  if(q.hausdorff < 0.) os << std::setw(12) << "-" << "  (not measured)\n";
  else os << std::setw(12) << q.hausdorff << "  (" << q.hausdorff_over_size << " times the local size, at most)\n";
  os << "  " << std::left << std::setw(18) << "seconds" << std::right
     << "optimize " << q.seconds.optimize << ", mesh " << q.seconds.mesh << ", total " << q.seconds.total << '\n';
  os.flags(flags);
  os.precision(precision);
}

/*!
\ingroup PkgLatticeMesher3Quality
Writes `q` as a JSON object with the keys `vertices`, `tets`, `theta_min` {`min`, `mean`, `std`},
`theta_max` {`max`, `mean`, `std`}, `rho` and `kappa` {`min`, `mean`, `std`}, `epsilon`
{`mean`, `std`}, `below20`, `below40`, `hausdorff` and `hausdorff_over_size` (-1 when not measured), `edge_length` and `seconds`
{`optimize`, `mesh`, `total`, and `stages` {name: seconds, in the order they ran} when there are
any}. Numbers have 10 significant digits.
*/
inline void write_quality_json(std::ostream& os, const Mesh_quality_3& q)
{
  const std::ios_base::fmtflags flags = os.flags();
  const std::streamsize precision = os.precision();
  os.unsetf(std::ios_base::floatfield);
  os << std::setprecision(10);
  os << "{\n"
     << "  \"vertices\": " << q.vertices << ",\n"
     << "  \"tets\": " << q.tets << ",\n";
  using internal::json_min;
  using internal::json_max;
  using internal::json_mean;
  using internal::json_std;
  internal::write_json_statistics(os, "theta_min", q.theta_min, { json_min, json_mean, json_std });
  internal::write_json_statistics(os, "theta_max", q.theta_max, { json_max, json_mean, json_std });
  internal::write_json_statistics(os, "rho", q.rho, { json_min, json_mean, json_std });
  internal::write_json_statistics(os, "kappa", q.kappa, { json_min, json_mean, json_std });
  internal::write_json_statistics(os, "epsilon", q.epsilon, { json_mean, json_std });
  os << "  \"below20\": " << q.below20 << ",\n"
     << "  \"below40\": " << q.below40 << ",\n"
     << "  \"hausdorff\": " << q.hausdorff << ",\n"
     << "  \"hausdorff_over_size\": " << q.hausdorff_over_size << ",\n"
     << "  \"edge_length\": " << q.edge_length << ",\n"
     << "  \"seconds\": {\"optimize\": " << q.seconds.optimize << ", \"mesh\": " << q.seconds.mesh
     << ", \"total\": " << q.seconds.total;
  if(!q.seconds.stages.empty()) {
    os << ", \"stages\": {";
    for(std::size_t i = 0; i < q.seconds.stages.size(); ++i)
      os << (i ? ", " : "") << '"' << q.seconds.stages[i].first << "\": " << q.seconds.stages[i].second;
    os << '}';
  }
  os << "}\n"
     << "}\n";
  os.flags(flags);
  os.precision(precision);
}

/*!
\ingroup PkgLatticeMesher3Quality
Returns the six interior dihedral angles (degrees) of the tetrahedron (a, b, c, d), whatever its
orientation, at the edges ab, ac, ad, bc, bd and cd; their extremes are `dihedral_angle_range()`.
*/
inline std::array<double, 6> dihedral_angles(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                             const Eigen::Vector3d& c, const Eigen::Vector3d& d)
{
  const std::array<Eigen::Vector3d, 4> n = internal::face_area_vectors(a, b, c, d);
  // the edge ab is opposite the faces 2 and 3 (those of d and c), and so on
  return { internal::dihedral_angle(n, 2, 3), internal::dihedral_angle(n, 1, 3), internal::dihedral_angle(n, 1, 2),
           internal::dihedral_angle(n, 0, 3), internal::dihedral_angle(n, 0, 2), internal::dihedral_angle(n, 0, 1) };
}

namespace internal {

// Counts in bins of width `step` centred on 0, step, 2 step, ..., last: the exact angles of a
// lattice (60 and 90 degrees) fall in the middle of a bin, not on a bin boundary.
class Quality_histogram
{
public:
  Quality_histogram(const char* name, double step, double last)
    : name_(name), step_(step), counts_(std::size_t(std::lround(last / step)) + 1, 0)
  {}

  void add(double value)
  {
    const long bin = std::lround(value / step_);
    ++counts_[std::size_t(std::clamp(bin, 0L, long(counts_.size()) - 1))];
  }

  void write(std::ostream& os) const
  {
    for(std::size_t k = 0; k < counts_.size(); ++k) os << name_ << ',' << double(k) * step_ << ',' << counts_[k] << '\n';
  }

private:
  const char* name_;
  double step_;
  std::vector<std::size_t> counts_;
};

} // namespace internal

/*!
\ingroup PkgLatticeMesher3Quality
Writes the distributions summarized by `compute_mesh_quality()`, with the same mapping to the
isotropic space and the same formulas, as CSV histograms with the header `quantity,value,count`:
`dihedral` counts the six dihedral angles of every tetrahedron (degrees, bins of 1 on [0, 180]),
`rho` and `kappa` every tetrahedron (bins of 0.01 on [0, 1]) and `epsilon` the alignment error of
every unique edge with respect to the named parameter `lattice` (as for `compute_mesh_quality()`; degrees, bins of 0.5 on [0, 90]). `value` is the
centre of a bin; values beyond the last bin are counted in it. Every bin is written, empty or not.
The named parameter `number_of_threads` is as for `compute_tetrahedra_quality()`.

\tparam FrameField a model of `FrameField_3` for points of type `Point_3`
\throws std::domain_error if the frame is singular at a centroid or a midpoint
\throws std::runtime_error if the stream fails
*/
template <typename Point_3, typename FrameField,
          typename NamedParameters = parameters::Default_named_parameters>
void write_quality_histograms_csv(std::ostream& os, const Tetrahedral_mesh_3<Point_3>& mesh,
                                  const FrameField& field, const NamedParameters& np = parameters::default_values())
{
  const Lattice_3 lattice = internal::stage_lattice(np);
  // per tetrahedron: its six dihedral angles, rho and kappa, computed in parallel and binned in order
  std::vector<std::array<double, 8> > values(mesh.tets.size());
  internal::parallel_for_rethrow(mesh.tets.size(), [&](std::size_t t) {
    const std::array<Eigen::Vector3d, 4> p = internal::isotropic_tetrahedron(mesh, field, t);
    const std::array<double, 6> angles = dihedral_angles(p[0], p[1], p[2], p[3]);
    const Tetrahedron_quality_3 q = tetrahedron_quality(p[0], p[1], p[2], p[3]);
    std::copy(angles.begin(), angles.end(), values[t].begin());
    values[t][6] = q.rho;
    values[t][7] = q.kappa;
  }, internal::measure_threads(np));
  internal::Quality_histogram dihedral("dihedral", 1., 180.), rho("rho", .01, 1.), kappa("kappa", .01, 1.),
                              epsilon("epsilon", .5, 90.);
  for(const std::array<double, 8>& v : values) {
    for(int i = 0; i < 6; ++i) dihedral.add(v[i]);
    rho.add(v[6]);
    kappa.add(v[7]);
  }
  for(double e : compute_edge_alignment_errors(mesh, field, lattice, np)) epsilon.add(e);

  os << "quantity,value,count\n";
  for(const internal::Quality_histogram* h : { &dihedral, &rho, &kappa, &epsilon }) h->write(os);
  if(!os) throw std::runtime_error("write_quality_histograms_csv(): the output stream failed");
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_MESH_QUALITY_H
