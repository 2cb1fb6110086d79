// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_DISCRETE_FRAME_FIELD_3_H
#define CGAL_LATTICE_MESHER_3_DISCRETE_FRAME_FIELD_3_H

#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/internal/octahedral_frames.h>
#include <CGAL/Lattice_mesher_3/internal/particle_neighbors.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/squared_distance_3.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

namespace internal {

// Throws, prefixed by `sample` (which names the sample), if the point or the frame is not finite
// (std::invalid_argument), or if the frame is near-singular (std::domain_error, with its condition
// number): the test is isotropic_map()'s, so that a frame accepted here is accepted by every stage.
template <typename Point_3>
void check_frame_sample(const std::string& sample, const Point_3& p, const Eigen::Matrix3d& t)
{
  std::ostringstream os;
  os << sample << ": ";
  if(!internal::to_eigen(p).allFinite() || !t.allFinite()) {
    os << (t.allFinite() ? "non-finite point (" : "non-finite frame at point (") << p << ")";
    throw std::invalid_argument(os.str());
  }
  try {
    isotropic_map(t, p);
  } catch(const std::domain_error& e) {
    os << e.what();
    throw std::domain_error(os.str());
  }
}

inline std::ostream& print_box(std::ostream& os, const CGAL::Bbox_3& b)
{
  return os << '[' << b.xmin() << ", " << b.xmax() << "] x [" << b.ymin() << ", " << b.ymax() << "] x ["
            << b.zmin() << ", " << b.zmax() << ']';
}

} // namespace internal

/*!
\ingroup PkgLatticeMesher3FrameFields
A frame field known at samples: points with a frame each, or the vertices of a tetrahedral mesh.

- Samples alone: `frame(p)` is the frame of the sample nearest to `p` (the lowest index among
  equally near ones), found in a grid of cells (the paper's discrete field).
- The vertices of a tetrahedral mesh: `frame(p)` interpolates the frames of the tetrahedron that
  contains `p` (the nearest one for a point outside the mesh) and stays a frame of the same kind
  between the samples: each frame T = R S is split into a rotation R and a stretch S (polar
  decomposition; -T for a left-handed T, the same lattice); the four frames are matched to the
  frame of largest weight by the rotation of the cube that brings their axes nearest to it; the
  matched rotations are averaged with the barycentric weights and brought back to the nearest
  rotation, the stretches averaged. A field of rotations times sizes thus gives a rotation times
  the interpolated size at every point.

The samples are validated on construction. The search structures are built then too, so that
`frame()` can be called concurrently; copies share the (immutable) samples.

`IO/frame_field.h` reads such fields from files (`read_frame_field_samples()`,
`read_frame_field_from_medit()`) and writes them; `compute_cross_field_3()` computes one. Before
meshing, check that the samples cover the domain with `check_coverage()`: outside the samples'
box the field is extrapolated from the nearest samples.

\tparam GT a model of `LatticeMesherTraits_3`, e.g. `Lattice_mesher_traits_3<Epick>`
\cgalModels `FrameField_3`
*/
template <typename GT>
class Discrete_frame_field_3
{
public:
  typedef typename GT::Point_3  Point_3;  ///< the point type
  typedef typename GT::Matrix_3 Matrix_3; ///< the frame type, a 3x3 matrix

  /*!
  builds the field of the samples (`points[i]`, `frames[i]`).
  \throws std::invalid_argument if there is no sample, the sizes differ, or a point or frame is
  not finite, naming the sample
  \throws std::domain_error if a frame is near-singular (condition number above 1e8, the bound of
  every stage), naming the sample, its point and the condition number
  */
  Discrete_frame_field_3(std::vector<Point_3> points, std::vector<Matrix_3> frames)
  {
    Tetrahedral_mesh_3<Point_3> samples;
    samples.points = std::move(points);
    data_ = std::make_shared<const Data>(std::move(samples), std::move(frames));
  }

  /*!
  builds the field of the vertices of `mesh`, `frames[i]` at `mesh.points[i]`, interpolated in
  its tetrahedra (a mesh without tetrahedra gives the field of its vertices alone). The mesh's
  boundary faces are kept (see `mesh()`).
  \throws std::invalid_argument as the other constructor, and if a tetrahedron has a vertex
  index out of range
  \throws std::domain_error as the other constructor
  */
  Discrete_frame_field_3(Tetrahedral_mesh_3<Point_3> mesh, std::vector<Matrix_3> frames)
  {
    data_ = std::make_shared<const Data>(std::move(mesh), std::move(frames));
  }

  /// returns the frame at `p`
  Matrix_3 frame(const Point_3& p) const
  {
    if(data_->tets.empty()) return data_->frames[nearest_sample(p)];
    const Eigen::Vector3d x = internal::to_eigen(p);
    // from the tetrahedron of p's grid cell; if the walk leaves the mesh far from p (a cell
    // across a gap of a non-convex mesh), from a tetrahedron of the nearest sample
    int t = data_->cell_tet(x);
    Eigen::Vector4d w;
    if(t < 0 || !data_->walk(x, t, w)) {
      t = data_->vertex_tet[nearest_sample(p)];
      if(t < 0) return data_->frames[nearest_sample(p)];
      data_->walk(x, t, w);
    }
    return data_->interpolate(t, w);
  }

  /// returns the index of the sample nearest to `p`
  std::size_t nearest_sample(const Point_3& p) const { return data_->search.nearest(p).first; }

  /// the number of samples
  std::size_t number_of_samples() const { return data_->points.size(); }
  /// the sample points
  const std::vector<Point_3>& points() const { return data_->mesh.points; }
  /// the samples' mesh: the sample points, and the tetrahedra and boundary faces if the field
  /// was built on a tetrahedral mesh
  const Tetrahedral_mesh_3<Point_3>& mesh() const { return data_->mesh; }
  /// the frames of the samples, in the order of `points()`
  const std::vector<Matrix_3>& frames() const { return data_->frames; }

  /// the bounding box of the sample points
  const CGAL::Bbox_3& bbox() const { return data_->bbox; }

  /// the median distance from a sample to its nearest other sample (estimated on at most 2000
  /// samples); 0 for a single sample
  double typical_spacing() const { return data_->spacing; }

  /*!
  checks that the samples cover `box` (typically the domain's bounding box): on each side, the
  samples' box may fall short of `box` by at most half the typical spacing, as a sample's frame
  stands for the points up to about that distance.
  \throws std::invalid_argument saying on which sides and by how much the samples fall short
  */
  void check_coverage(const CGAL::Bbox_3& box) const
  {
    const CGAL::Bbox_3& s = bbox();
    const double tolerance = 0.5 * typical_spacing();
    static const char* const axes = "xyz";
    std::ostringstream shortfalls;
    for(int a = 0; a < 3; ++a) {
      const double below = s.min_coord(a) - box.min_coord(a), above = box.max_coord(a) - s.max_coord(a);
      if(below > tolerance) shortfalls << (shortfalls.tellp() > 0 ? ", " : "") << below << " at " << axes[a] << " min";
      if(above > tolerance) shortfalls << (shortfalls.tellp() > 0 ? ", " : "") << above << " at " << axes[a] << " max";
    }
    if(shortfalls.tellp() == 0) return;
    std::ostringstream os;
    os << "frame field: the samples do not cover the box ";
    internal::print_box(os, box) << ": they span ";
    internal::print_box(os, s) << " and fall short by " << shortfalls.str() << " (tolerance " << tolerance
                               << ", half the typical sample spacing)";
    throw std::invalid_argument(os.str());
  }

private:
  struct Data
  {
    Tetrahedral_mesh_3<Point_3> mesh;
    const std::vector<Point_3>& points;
    const std::vector<std::array<int, 4> >& tets;
    std::vector<Matrix_3> frames;
    internal::Point_search_3<GT> search;
    CGAL::Bbox_3 bbox;
    double spacing = 0.;
    // with tetrahedra: each frame's rotation and stretch, a tetrahedron of each vertex (-1 for
    // none), the tetrahedra's neighbours (-1 across the boundary; neighbor k is opposite vertex
    // k) and the inverses of their edge matrices, for the barycentric coordinates
    std::vector<Eigen::Matrix3d> rotations, stretches;
    bool scalar_stretches = true;   // every stretch a multiple of the identity (its (0, 0) entry)
    std::vector<int> vertex_tet;
    std::vector<std::array<int, 4> > neighbors;
    std::vector<Eigen::Matrix3d> inverses;
    // per tetrahedron, reference vertex r and vertex k, the rotation of the cube that matches k's
    // frame to r's (R_k G nearest to R_r); computed once, not at every query
    typedef internal::Cube_rotation_code Cube_rotation_code;
    std::vector<std::array<std::array<Cube_rotation_code, 4>, 4> > matches;
    // a grid over the box, with a tetrahedron near each cell's centre (-1 where there is none)
    std::array<int, 3> cells = { 0, 0, 0 };
    Eigen::Vector3d origin, cell_size;
    std::vector<int> grid;

    Data(Tetrahedral_mesh_3<Point_3>&& m, std::vector<Matrix_3>&& f)
      : mesh(checked(std::move(m), f)), points(mesh.points), tets(mesh.tets), frames(std::move(f)), search(points)
    {
      for(const Point_3& q : points) bbox += q.bbox();
      spacing = median_nearest_distance();
      if(!tets.empty()) build_interpolation();
    }

    static Tetrahedral_mesh_3<Point_3>&& checked(Tetrahedral_mesh_3<Point_3>&& m, const std::vector<Matrix_3>& f)
    {
      if(m.points.empty() || m.points.size() != f.size()) {
        std::ostringstream os;
        os << "Discrete_frame_field_3: expected as many frames as points, at least one, got "
           << m.points.size() << " points and " << f.size() << " frames";
        throw std::invalid_argument(os.str());
      }
      for(std::size_t i = 0; i < m.points.size(); ++i)
        internal::check_frame_sample("Discrete_frame_field_3: sample " + std::to_string(i), m.points[i], f[i]);
      for(std::size_t t = 0; t < m.tets.size(); ++t)
        for(int v : m.tets[t])
          if(v < 0 || std::size_t(v) >= m.points.size())
            throw std::invalid_argument("Discrete_frame_field_3: tetrahedron " + std::to_string(t) + " has vertex index "
                                        + std::to_string(v) + ", out of [0, " + std::to_string(m.points.size()) + ")");
      return std::move(m);
    }

    void build_interpolation()
    {
      for(const Matrix_3& t : frames) {
        const Eigen::Matrix3d right = t.determinant() < 0. ? Eigen::Matrix3d(-t) : Eigen::Matrix3d(t);
        rotations.push_back(internal::rotation_factor(right));
        stretches.push_back(rotations.back().transpose() * right);
        const Eigen::Matrix3d& st = stretches.back();
        scalar_stretches = scalar_stretches && (st - st(0, 0) * Eigen::Matrix3d::Identity()).norm() <= 1e-12 * std::abs(st(0, 0));
      }
      vertex_tet.assign(points.size(), -1);
      std::vector<std::pair<std::array<int, 3>, int> > faces;   // sorted face, 4 t + k
      for(std::size_t t = 0; t < tets.size(); ++t) {
        const std::array<int, 4>& c = tets[t];
        for(int k = 0; k < 4; ++k) {
          vertex_tet[std::size_t(c[std::size_t(k)])] = int(t);
          std::array<int, 3> f = { c[std::size_t((k + 1) % 4)], c[std::size_t((k + 2) % 4)], c[std::size_t((k + 3) % 4)] };
          std::sort(f.begin(), f.end());
          faces.emplace_back(f, int(4 * t) + k);
        }
        Eigen::Matrix3d e;
        const Eigen::Vector3d a = internal::to_eigen(points[std::size_t(c[0])]);
        for(int k = 1; k < 4; ++k) e.col(k - 1) = internal::to_eigen(points[std::size_t(c[std::size_t(k)])]) - a;
        const Eigen::Matrix3d inverse = e.inverse();
        // a flat tetrahedron: the weights of its first vertex, 1 (it then holds every point)
        inverses.push_back(inverse.allFinite() ? inverse : Eigen::Matrix3d::Zero());
        std::array<std::array<Cube_rotation_code, 4>, 4> codes;
        for(int r = 0; r < 4; ++r)
          for(int k = 0; k < 4; ++k)
            codes[std::size_t(r)][std::size_t(k)] = internal::best_cube_rotation_code(
                rotations[std::size_t(c[std::size_t(r)])].transpose() * rotations[std::size_t(c[std::size_t(k)])]);
        matches.push_back(codes);
      }
      std::sort(faces.begin(), faces.end());
      neighbors.assign(tets.size(), { -1, -1, -1, -1 });
      for(std::size_t i = 0; i + 1 < faces.size(); ++i)
        if(faces[i].first == faces[i + 1].first) {
          const int a = faces[i].second, b = faces[i + 1].second;
          neighbors[std::size_t(a / 4)][std::size_t(a % 4)] = b / 4;
          neighbors[std::size_t(b / 4)][std::size_t(b % 4)] = a / 4;
        }
      build_grid();
    }

    // About one cell per tetrahedron; each cell's tetrahedron found by a walk from the nearest
    // sample to its centre.
    void build_grid()
    {
      const Eigen::Vector3d lo(bbox.xmin(), bbox.ymin(), bbox.zmin()), hi(bbox.xmax(), bbox.ymax(), bbox.zmax());
      const Eigen::Vector3d span = (hi - lo).cwiseMax(1e-12 * (1. + (hi - lo).maxCoeff()));
      const double cell = std::cbrt(span.prod() / double(tets.size()));
      for(int a = 0; a < 3; ++a) cells[std::size_t(a)] = (std::max)(1, (std::min)(1000, int(std::ceil(span[a] / cell))));
      origin = lo;
      cell_size = span.cwiseQuotient(Eigen::Vector3d(cells[0], cells[1], cells[2]));
      grid.assign(std::size_t(cells[0]) * std::size_t(cells[1]) * std::size_t(cells[2]), -1);
      for(int i = 0; i < cells[0]; ++i)
        for(int j = 0; j < cells[1]; ++j)
          for(int k = 0; k < cells[2]; ++k) {
            const Eigen::Vector3d c = origin + cell_size.cwiseProduct(Eigen::Vector3d(i + .5, j + .5, k + .5));
            int t = vertex_tet[search.nearest(Point_3(c[0], c[1], c[2])).first];
            Eigen::Vector4d w;
            if(t >= 0) walk(c, t, w);
            grid[(std::size_t(i) * std::size_t(cells[1]) + std::size_t(j)) * std::size_t(cells[2]) + std::size_t(k)] = t;
          }
    }

    int cell_tet(const Eigen::Vector3d& x) const
    {
      std::size_t index = 0;
      for(int a = 0; a < 3; ++a) {
        const int i = (std::max)(0, (std::min)(cells[std::size_t(a)] - 1, int(std::floor((x[a] - origin[a]) / cell_size[a]))));
        index = index * std::size_t(cells[std::size_t(a)]) + std::size_t(i);
      }
      return grid[index];
    }

    Eigen::Vector4d barycentric(int t, const Eigen::Vector3d& x) const
    {
      const Eigen::Vector3d l = inverses[std::size_t(t)] * (x - internal::to_eigen(points[std::size_t(tets[std::size_t(t)][0])]));
      return Eigen::Vector4d(1. - l.sum(), l[0], l[1], l[2]);
    }

    // From tetrahedron t, steps to the neighbour opposite the most negative weight until the
    // weights are all positive or the walk would leave the mesh; then t is the last tetrahedron
    // and w its weights, clamped to [0, 1]. False if the walk stopped at the boundary with x more
    // than a tenth of the tetrahedron outside it (by its weights).
    bool walk(const Eigen::Vector3d& x, int& t, Eigen::Vector4d& w) const
    {
      w = barycentric(t, x);
      for(int step = 0; step < 200; ++step) {
        int k = 0;
        if(w.minCoeff(&k) >= -1e-12) break;
        const int next = neighbors[std::size_t(t)][std::size_t(k)];
        if(next < 0) break;
        t = next;
        w = barycentric(t, x);
      }
      const bool near = w.minCoeff() >= -0.1;
      w = w.cwiseMax(0.);
      w /= w.sum();
      return near;
    }

    // The frames of tetrahedron t matched to that of largest weight, blended with the weights w.
    Matrix_3 interpolate(int t, const Eigen::Vector4d& w) const
    {
      const std::array<int, 4>& c = tets[std::size_t(t)];
      int reference = 0;
      w.maxCoeff(&reference);
      const std::array<Cube_rotation_code, 4>& code = matches[std::size_t(t)][std::size_t(reference)];
      Eigen::Matrix3d r = Eigen::Matrix3d::Zero(), s = Eigen::Matrix3d::Zero();
      double size = 0.;
      for(int k = 0; k < 4; ++k) {
        if(w[k] == 0.) continue;
        const std::size_t v = std::size_t(c[std::size_t(k)]);
        r.noalias() += w[k] * internal::times_cube_rotation(rotations[v], code[std::size_t(k)]);
        if(scalar_stretches) size += w[k] * stretches[v](0, 0);
        else {
          const Eigen::Matrix3d g = internal::cube_rotation_matrix(code[std::size_t(k)]);
          s += w[k] * g.transpose() * stretches[v] * g;
        }
      }
      return scalar_stretches ? Matrix_3(size * internal::rotation_factor(r)) : Matrix_3(internal::rotation_factor(r) * s);
    }

    // Each probe's nearest other sample, by sphere queries that double from the spacing of
    // evenly spread samples until they find one.
    double median_nearest_distance() const
    {
      const std::size_t n = points.size();
      const double diagonal = std::sqrt(CGAL::square(bbox.x_span()) + CGAL::square(bbox.y_span()) + CGAL::square(bbox.z_span()));
      if(n < 2 || !(diagonal > 0.)) return 0.;
      std::vector<double> nearest;
      std::vector<std::size_t> found;
      for(std::size_t i = 0; i < n; i += (std::max)(std::size_t(1), n / 1000)) {
        double best = HUGE_VAL;
        for(double r = diagonal / std::cbrt(double(n)); best == HUGE_VAL; r *= 2.) {
          found.clear();
          search.in_sphere(points[i], r, found);
          for(std::size_t j : found)
            if(j != i) best = (std::min)(best, std::sqrt(CGAL::squared_distance(points[i], points[j])));
        }
        nearest.push_back(best);
      }
      std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
      return nearest[nearest.size() / 2];
    }
  };

  std::shared_ptr<const Data> data_;
};

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_DISCRETE_FRAME_FIELD_3_H
