// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_INTERNAL_WINDING_NUMBER_H
#define CGAL_LATTICE_MESHER_3_INTERNAL_WINDING_NUMBER_H

#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/boost/iterator/counting_iterator.hpp>
#include <CGAL/Bbox_3.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {
namespace internal {

// The winding number of a closed, oriented triangle surface about a point: the number of times
// a ray from the point leaves the enclosed volume minus the number of times it enters it
// (exact orientation tests, the ray shot again in another direction when it meets an edge or a
// vertex). For a surface that does not self-intersect it is 1 inside and 0 outside, a cavity
// (an inward shell) taking its 1 back; where closed parts overlap or a surface folds through
// itself it counts the layers, so `winding >= 1` is the union of what the surface encloses,
// which a ray-parity test gets wrong (parity says "outside" where two parts overlap).
// Collinear triangles are left out: they bound nothing and would make every ray degenerate.
// Queries are const and thread-safe; the object is neither copied nor moved (the tree points
// into its triangles).
template <typename K>
class Winding_number_3
{
public:
  typedef typename K::Point_3 Point_3;
  typedef typename K::Triangle_3 Triangle_3;

  template <typename TriangleRange>
  explicit Winding_number_3(const TriangleRange& triangles)
  {
    for(const Triangle_3& t : triangles)
      if(!K().collinear_3_object()(t[0], t[1], t[2])) triangles_.push_back(t);
    for(const Triangle_3& t : triangles_) box_ += t.bbox();
    tree_.insert(triangles_.cbegin(), triangles_.cend());
    tree_.build();
  }
  Winding_number_3(const Winding_number_3&) = delete;
  Winding_number_3& operator=(const Winding_number_3&) = delete;

  // 0 also for a point on the surface and off the surface's box
  int operator()(const Point_3& p) const
  {
    if(triangles_.empty() || !CGAL::do_overlap(box_, p.bbox())) return 0;
    // generic directions: a ray along an axis or a diagonal would meet the edges of
    // axis-aligned models (cubes, CAD parts) every time
    static const double directions[][3] = { { .3216, .5874, .7427 }, { -.6311, .2137, .7456 },
                                            { .5120, -.8323, .2126 }, { -.2785, -.3917, -.8769 },
                                            { .8042, .3361, -.4903 }, { -.1429, .9302, -.3380 },
                                            { .6657, -.2971, .6845 }, { -.7793, -.5412, .3159 } };
    const double reach = 2. * (std::sqrt(CGAL::square(box_.x_span()) + CGAL::square(box_.y_span())
                                         + CGAL::square(box_.z_span())) + 1.);
    for(const auto& d : directions) {   // to a point off the box, where the winding number is 0
      int winding;
      if(from(p, Point_3(p.x() + reach * d[0], p.y() + reach * d[1], p.z() + reach * d[2]), 0, winding)) return winding;
    }
    return 0;
  }

  // The winding number about p from that about q, `winding_at_q`, and the triangles that the
  // segment pq crosses: false if it touches an edge, a vertex or a plane at q, or lies in a
  // triangle's plane. A point on the surface, which every segment from it touches, has 0 (as
  // for operator()), found by the first segment.
  bool from(const Point_3& p, const Point_3& q, int winding_at_q, int& winding) const
  {
    winding = winding_at_q;
    int stop = 0;   // degenerate_crossing or p_on_triangle, once a triangle says so
    tree_.all_intersected_primitives(typename K::Segment_3(p, q), boost::make_function_output_iterator([&](typename Triangles::const_iterator t) {
      if(stop != 0) return;
      const int c = crossing(*t, p, q);
      if(c == degenerate_crossing || c == p_on_triangle) stop = c;
      else winding += c;
    }));
    if(stop == p_on_triangle) winding = 0;
    return stop != degenerate_crossing;
  }

private:
  typedef std::vector<Triangle_3> Triangles;
  typedef CGAL::AABB_triangle_primitive<K, typename Triangles::const_iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;
  static constexpr int degenerate_crossing = 2, p_on_triangle = 3;

  // For a triangle that the segment pq meets: +1 if pq leaves through it (p on its inner side),
  // -1 if it enters, 0 if it misses it, p_on_triangle if p lies on it (in its plane,
  // q not: they meet at p), degenerate_crossing if pq touches an edge, a vertex or the plane at q
  static int crossing(const Triangle_3& t, const Point_3& p, const Point_3& q)
  {
    const typename K::Orientation_3 orientation = K().orientation_3_object();
    const CGAL::Orientation sp = orientation(t[0], t[1], t[2], p);
    const CGAL::Orientation sq = orientation(t[0], t[1], t[2], q);
    if(sq == CGAL::COPLANAR) return degenerate_crossing;
    if(sp == CGAL::COPLANAR) return p_on_triangle;   // pq meets the plane at p only, so p is on t
    if(sp == sq) return 0;
    const CGAL::Orientation e0 = orientation(p, q, t[0], t[1]);
    const CGAL::Orientation e1 = orientation(p, q, t[1], t[2]);
    const CGAL::Orientation e2 = orientation(p, q, t[2], t[0]);
    if(e0 == CGAL::COPLANAR || e1 == CGAL::COPLANAR || e2 == CGAL::COPLANAR) return degenerate_crossing;
    if(e0 != e1 || e1 != e2) return 0;
    return sp == CGAL::NEGATIVE ? 1 : -1;
  }

  Triangles triangles_;
  Tree tree_;
  CGAL::Bbox_3 box_;
};

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_WINDING_NUMBER_H
