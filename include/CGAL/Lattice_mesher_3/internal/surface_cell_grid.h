// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_INTERNAL_SURFACE_CELL_GRID_H
#define CGAL_LATTICE_MESHER_3_INTERNAL_SURFACE_CELL_GRID_H

#include <CGAL/Bbox_3.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {
namespace internal {

// Cubic cells over the box of a closed surface, each classified once: touched (its closed box
// meets a triangle: exact test), outside or inside (two untouched cells sharing a face lie on
// the same side: each region of untouched cells takes the side of one of its cell centres, and
// the region of the padding is outside; a cavity or a part enclosed by another is a region of
// its own), and for inside cells the Chebyshev distance k, in cells, to the nearest touched cell. A point in an untouched cell needs no ray cast to be
// classified, and one in an inside cell is at least (k - 1) h from the surface: the mesher
// skips the projections of particles deep inside (most of them) with it. Each untouched cell
// also keeps its region's winding number, so that a point in a touched cell is classified by a
// segment to a nearby untouched cell's centre rather than by a ray across the whole surface.
class Surface_cell_grid_3
{
public:
  Surface_cell_grid_3() = default;

  // `triangles`: a range of K::Triangle_3; `winding(x, y, z)`: the winding number of the surface
  // about a point off it (inside: at least 1)
  template <typename TriangleRange, typename WindingNumber>
  Surface_cell_grid_3(const CGAL::Bbox_3& box, const TriangleRange& triangles, const WindingNumber& winding,
                      int resolution = 128)
  {
    const std::array<double, 3> size = { box.x_span(), box.y_span(), box.z_span() };
    const double extent = (std::max)({ size[0], size[1], size[2] });
    if(!(extent > 0.) || !std::isfinite(extent)) return;   // no grid: every query answers "unknown"
    h_ = extent / resolution;
    // two cells of padding on each side: the outer layer of cells is at least h from the box,
    // untouched even where the surface lies on the box (a cube's faces and corners touch the
    // first layer), and the flood fill starts from it
    for(int a = 0; a < 3; ++a) {
      origin_[a] = box.min_coord(a) - 2. * h_;
      n_[a] = int(std::ceil(size[a] / h_)) + 5;
    }
    state_.assign(std::size_t(n_[0]) * n_[1] * n_[2], UNKNOWN);
    depth_.assign(state_.size(), 0);
    winding_.assign(state_.size(), 0);

    // touched cells: a margin of 1e-6 h on each box keeps the test valid for a point rounded
    // into a neighbouring cell by cell_of()
    for(const auto& t : triangles) {
      const CGAL::Bbox_3 tb = t.bbox();
      std::array<int, 3> lo = cell_of(tb.xmin(), tb.ymin(), tb.zmin()), hi = cell_of(tb.xmax(), tb.ymax(), tb.zmax());
      for(int a = 0; a < 3; ++a) { lo[a] = (std::max)(lo[a] - 1, 0); hi[a] = (std::min)(hi[a] + 1, n_[a] - 1); }
      for(int i = lo[0]; i <= hi[0]; ++i)
        for(int j = lo[1]; j <= hi[1]; ++j)
          for(int k = lo[2]; k <= hi[2]; ++k) {
            unsigned char& s = state_[index(i, j, k)];
            if(s == TOUCHED) continue;
            const double m = 1e-6 * h_;
            const CGAL::Bbox_3 cell(origin_[0] + i * h_ - m, origin_[1] + j * h_ - m, origin_[2] + k * h_ - m,
                                    origin_[0] + (i + 1) * h_ + m, origin_[1] + (j + 1) * h_ + m, origin_[2] + (k + 1) * h_ + m);
            if(CGAL::do_intersect(t, cell)) s = TOUCHED;
          }
    }
    // outside: untouched cells face-connected to the outer layer; then every other region of
    // untouched cells takes the side of its first cell's centre
    std::deque<std::array<int, 3> > queue;
    unsigned char side = OUTSIDE;
    int region_winding = 0;
    auto visit = [&](int i, int j, int k) {
      if(!on_grid(i, j, k)) return;
      unsigned char& s = state_[index(i, j, k)];
      if(s == UNKNOWN) { s = side; winding_[index(i, j, k)] = region_winding; queue.push_back({ i, j, k }); }
    };
    auto fill = [&] {
      while(!queue.empty()) {
        const std::array<int, 3> c = queue.front();
        queue.pop_front();
        for(int a = 0; a < 3; ++a)
          for(int d : { -1, 1 }) {
            std::array<int, 3> q = c;
            q[a] += d;
            visit(q[0], q[1], q[2]);
          }
      }
    };
    for(int i = 0; i < n_[0]; ++i)
      for(int j = 0; j < n_[1]; ++j)
        for(int k = 0; k < n_[2]; ++k)
          if(i == 0 || j == 0 || k == 0 || i == n_[0] - 1 || j == n_[1] - 1 || k == n_[2] - 1)
            visit(i, j, k);
    fill();
    for(int i = 0; i < n_[0]; ++i)
      for(int j = 0; j < n_[1]; ++j)
        for(int k = 0; k < n_[2]; ++k)
          if(state_[index(i, j, k)] == UNKNOWN) {
            region_winding = winding(origin_[0] + (i + .5) * h_, origin_[1] + (j + .5) * h_, origin_[2] + (k + .5) * h_);
            side = region_winding >= 1 ? INSIDE : OUTSIDE;
            visit(i, j, k);
            fill();
          }
    // depth by a breadth-first search from the touched cells over the 26 neighbours (Chebyshev
    // distance), saturated at 255; an inside cell of depth 0 is unvisited
    for(int i = 0; i < n_[0]; ++i)
      for(int j = 0; j < n_[1]; ++j)
        for(int k = 0; k < n_[2]; ++k)
          if(state_[index(i, j, k)] == TOUCHED) queue.push_back({ i, j, k });
    while(!queue.empty()) {
      const std::array<int, 3> c = queue.front();
      queue.pop_front();
      const unsigned char next = (unsigned char)((std::min)(int(depth_[index(c[0], c[1], c[2])]) + 1, 255));
      for(int di = -1; di <= 1; ++di)
        for(int dj = -1; dj <= 1; ++dj)
          for(int dk = -1; dk <= 1; ++dk) {
            const int i = c[0] + di, j = c[1] + dj, k = c[2] + dk;
            if(!on_grid(i, j, k)) continue;
            const std::size_t q = index(i, j, k);
            if(state_[q] != INSIDE || depth_[q] != 0) continue;
            depth_[q] = next;
            queue.push_back({ i, j, k });
          }
    }
  }

  // +1: strictly inside, -1: outside (off the grid too), 0: unknown (a touched cell, no grid,
  // a non-finite point)
  int side(double x, double y, double z) const
  {
    const std::ptrdiff_t c = locate(x, y, z);
    if(c < 0) return c == OFF_GRID ? -1 : 0;
    return state_[c] == INSIDE ? 1 : state_[c] == OUTSIDE ? -1 : 0;
  }

  // Calls f(x, y, z, w) with the centres (x, y, z) of at most `count` untouched cells within
  // `radius` cells (Chebyshev) of the cell of the point, nearest first, and their winding numbers
  // w, until f returns true; returns whether one did.
  template <typename F>
  bool find_untouched_cell_near(double x, double y, double z, int radius, int count, F f) const
  {
    if(locate(x, y, z) < 0) return false;
    const std::array<int, 3> c = cell_of(x, y, z);
    for(int r = 1; r <= radius; ++r)
      for(int i = c[0] - r; i <= c[0] + r; ++i)
        for(int j = c[1] - r; j <= c[1] + r; ++j)
          for(int k = c[2] - r; k <= c[2] + r; ++k) {
            if((std::max)({ std::abs(i - c[0]), std::abs(j - c[1]), std::abs(k - c[2]) }) != r || !on_grid(i, j, k)) continue;
            const std::size_t q = index(i, j, k);
            if(state_[q] != INSIDE && state_[q] != OUTSIDE) continue;
            if(count-- == 0) return false;
            if(f(origin_[0] + (i + .5) * h_, origin_[1] + (j + .5) * h_, origin_[2] + (k + .5) * h_, int(winding_[q])))
              return true;
          }
    return false;
  }

  // a lower bound of the distance to the surface of a point inside; 0 if not known inside
  double inside_distance_bound(double x, double y, double z) const
  {
    const std::ptrdiff_t c = locate(x, y, z);
    if(c < 0 || state_[c] != INSIDE) return 0.;
    return (std::max)(int(depth_[c]) - 1, 0) * h_;
  }

private:
  enum : unsigned char { UNKNOWN = 0, TOUCHED, OUTSIDE, INSIDE };
  static constexpr std::ptrdiff_t OFF_GRID = -1, NO_CELL = -2;

  // the index of the cell of (x, y, z): OFF_GRID (outside the padded box), NO_CELL (no grid,
  // a non-finite point)
  std::ptrdiff_t locate(double x, double y, double z) const
  {
    if(state_.empty() || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return NO_CELL;
    const std::array<int, 3> c = cell_of(x, y, z);
    return on_grid(c[0], c[1], c[2]) ? std::ptrdiff_t(index(c[0], c[1], c[2])) : OFF_GRID;
  }
  bool on_grid(int i, int j, int k) const
  { return i >= 0 && j >= 0 && k >= 0 && i < n_[0] && j < n_[1] && k < n_[2]; }

  std::array<int, 3> cell_of(double x, double y, double z) const
  {
    const std::array<double, 3> p = { x, y, z };
    std::array<int, 3> c;
    for(int a = 0; a < 3; ++a) {
      const double f = std::floor((p[a] - origin_[a]) / h_);
      c[a] = f < 0. ? -1 : f >= double(n_[a]) ? n_[a] : int(f);   // -1 and n_[a]: off the grid
    }
    return c;
  }
  std::size_t index(int i, int j, int k) const { return (std::size_t(i) * n_[1] + j) * n_[2] + k; }

  double h_ = 0.;
  std::array<double, 3> origin_ = { 0., 0., 0. };
  std::array<int, 3> n_ = { 0, 0, 0 };
  std::vector<unsigned char> state_, depth_;
  std::vector<int> winding_;
};

} // namespace internal
} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_INTERNAL_SURFACE_CELL_GRID_H
