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

#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/internal/particle_neighbors.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/squared_distance_3.h>

#include <Eigen/Dense>

#include <algorithm>
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
  if(!to_eigen(p).allFinite() || !t.allFinite()) {
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
A frame field known at samples (points with a frame each, e.g. the vertices of a tetrahedral
mesh): `frame(p)` is the frame of the sample nearest to `p`, found in a k-d tree. This is the
paper's discrete field.

The samples are validated on construction. The k-d tree is built then too, so that `frame()` can
be called concurrently; copies share the (immutable) samples and tree.

`IO/frame_field.h` reads such fields from files (`read_frame_field_samples()`,
`read_frame_field_from_medit()`). Before meshing, check that the samples cover the domain with
`check_coverage()`: outside the samples' box the field is extrapolated from the nearest sample.

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
    if(points.empty() || points.size() != frames.size()) {
      std::ostringstream os;
      os << "Discrete_frame_field_3: expected as many frames as points, at least one, got "
         << points.size() << " points and " << frames.size() << " frames";
      throw std::invalid_argument(os.str());
    }
    for(std::size_t i = 0; i < points.size(); ++i)
      internal::check_frame_sample("Discrete_frame_field_3: sample " + std::to_string(i), points[i], frames[i]);
    data_ = std::make_shared<const Data>(std::move(points), std::move(frames));
  }

  /// returns the frame of the sample nearest to `p`
  const Matrix_3& frame(const Point_3& p) const { return data_->frames[nearest_sample(p)]; }

  /// returns the index of the sample nearest to `p`
  std::size_t nearest_sample(const Point_3& p) const { return data_->search.nearest(p).first; }

  /// the number of samples
  std::size_t number_of_samples() const { return data_->points.size(); }
  /// the sample points
  const std::vector<Point_3>& points() const { return data_->points; }
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
    std::vector<Point_3> points;
    std::vector<Matrix_3> frames;
    internal::Point_search_3<GT> search;
    CGAL::Bbox_3 bbox;
    double spacing = 0.;

    Data(std::vector<Point_3>&& p, std::vector<Matrix_3>&& f)
      : points(std::move(p)), frames(std::move(f)), search(points)
    {
      for(const Point_3& q : points) bbox += q.bbox();
      spacing = median_nearest_distance();
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
