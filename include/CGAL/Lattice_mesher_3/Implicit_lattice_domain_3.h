// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_IMPLICIT_LATTICE_DOMAIN_3_H
#define CGAL_LATTICE_MESHER_3_IMPLICIT_LATTICE_DOMAIN_3_H

#include <CGAL/Lattice_mesher_3/Boundary_projection_3.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/number_utils.h>
#include <CGAL/Origin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3Domains

A model of `LatticeMeshDomain_3`: the volume {p : f(p) < 0} of a function `f`, inside a
user-given bounding box. The domain is smooth: it has no feature curves and no corners.

<b>Projection.</b> Newton steps x <- x - f(x) grad f(x) / |grad f(x)|^2, with a central-difference
gradient of step 1e-6 times the bounding-box diagonal, until |f| / |grad f| is below 1e-12 times
the diagonal. If a step does not decrease |f|, leaves the (enlarged) box, or the gradient
vanishes, the projection marches instead along the gradient line and the axis directions
(for an outside point, also toward a known inside point, which always brackets the surface),
keeps the nearest sign change and bisects it. Every loop is bounded. For a signed distance
function the first Newton step already gives the closest point. The normal is the normalized
gradient.

<b>Measures.</b> The constructor samples `f` at the centers of a grid of cubic cells of side
H = (longest box side) / `grid_resolution`, covering the box plus 3 cells on each side. With
the first-order signed distance d = f / |grad f| (grid central differences), the volume is
sum H^3 Heaviside_e(-d) and the area sum H^3 delta_e(d) (the smeared-delta form of the coarea
formula), with the cosine-smoothed Heaviside and delta of half-width e = 1.5 H. The error is
O(e^2 curvature^2): well below 1% for features a few cells wide.

<b>Validation.</b> The constructor throws `std::invalid_argument` if the box is empty, if `f` is
nowhere negative on the grid, or if it is negative at a grid point outside the box (the box does
not contain the domain). Every evaluation throws `std::domain_error` if `f` returns NaN.

\tparam K a CGAL kernel with `double`-convertible coordinates, e.g. `Epick`.
\tparam Function a callable `double f(const K::Point_3&) const`, negative inside the domain. It
must be safe to call concurrently for the queries to be thread-safe.

\cgalModels `LatticeMeshDomain_3`
*/
template <typename K, typename Function>
class Implicit_lattice_domain_3
{
public:
  typedef K                                Geom_traits; ///< the kernel
  typedef typename K::Point_3              Point_3;     ///< the point type
  typedef typename K::Vector_3             Vector_3;    ///< the vector type
  typedef Boundary_projection_3<K>         Projection;  ///< the result of a projection on the boundary (`Boundary_projection_3`)

  /// \param f the function, negative inside the domain
  /// \param bbox a box that contains the domain
  /// \param grid_resolution the number of grid cells along the longest side of `bbox`
  Implicit_lattice_domain_3(const Function& f, const CGAL::Bbox_3& bbox,
                            int grid_resolution = 128)
    : m_function(f), m_bbox(bbox)
  {
    if(!(bbox.xmin() < bbox.xmax() && bbox.ymin() < bbox.ymax() && bbox.zmin() < bbox.zmax())
       || !std::isfinite(bbox.xmin() + bbox.xmax() + bbox.ymin() + bbox.ymax() + bbox.zmin()
                         + bbox.zmax()))
      throw std::invalid_argument("Implicit_lattice_domain_3: the bounding box is empty or not finite");
    if(grid_resolution < 8)
      throw std::invalid_argument("Implicit_lattice_domain_3: the grid resolution must be at least 8");
    m_diagonal = std::sqrt(CGAL::square(bbox.xmax() - bbox.xmin()) + CGAL::square(bbox.ymax() - bbox.ymin())
                           + CGAL::square(bbox.zmax() - bbox.zmin()));
    m_cell = (std::max)({bbox.xmax() - bbox.xmin(), bbox.ymax() - bbox.ymin(),
                         bbox.zmax() - bbox.zmin()}) / grid_resolution;
    integrate_on_grid();
  }

  /// \name LatticeMeshDomain_3
  /// @{
  CGAL::Bbox_3 bbox() const { return m_bbox; } ///< the box given to the constructor

  /// `true` if f(p) < 0
  bool is_inside(const Point_3& p) const { return value(p) < 0.; }

  /// 0: `f` gives no bound of the distance to its zero set
  double inside_distance_bound(const Point_3&) const { return 0.; }

  /// the closest point of the zero set of `f` to `p`, with the unit outward normal (the normalized
  /// gradient) there
  Projection project_on_surface(const Point_3& p) const
  {
    const double fp = value(p);
    Point_3 x = p;
    double fx = fp;
    for(int step = 0; step < max_newton_steps; ++step) {
      const Vector_3 g = gradient(x);
      const double gg = CGAL::to_double(g.squared_length());
      if(std::abs(fx) <= convergence * m_diagonal * std::sqrt(gg))
        return projection(p, x, g);
      if(!(gg > 0.))
        break;
      const Point_3 y = x - (fx / gg) * g;
      const double fy = value(y);
      // Newton misbehaves far from the surface or near critical points of f: bisect instead.
      if(!(std::abs(fy) < std::abs(fx)) || !in_grid(y))
        break;
      x = y;
      fx = fy;
    }
    x = bracket_and_bisect(p, fp);
    return projection(p, x, gradient(x));
  }

  /// 0: the domain has no feature curve
  std::size_t number_of_curves() const { return 0; }

  /// always throws `std::out_of_range`: the domain has no feature curve
  Projection project_on_curve(const Point_3&, std::size_t curve) const
  {
    throw std::out_of_range("Implicit_lattice_domain_3::project_on_curve(): curve "
                            + std::to_string(curve) + " does not exist (the domain has no curves)");
  }

  /// returns `p` with index -1 and an infinite squared distance: the domain has no curves
  Projection project_on_features(const Point_3& p) const
  {
    return Projection{p, CGAL::NULL_VECTOR, -1, std::numeric_limits<double>::infinity()};
  }

  /// an empty vector: the domain has no corner
  const std::vector<Point_3>& corners() const { return m_corners; }
  /// the volume of the domain, estimated on the grid
  double volume() const { return m_volume; }
  /// the area of the boundary surface, estimated on the grid
  double area() const { return m_area; }
  /// 0: the domain has no feature curve
  double curves_length() const { return 0.; }

  /// writes the projections of the centers of the sample cells, of side h <= spacing / sqrt(3),
  /// that may meet the surface (|f| / |grad f| <= 1.5 h sqrt(3) / 2). A surface point is within
  /// h sqrt(3) / 2 of the center of its sample cell, and the projection of that center is at
  /// most as far again: every surface point is within `spacing` of a sample. The sample cells
  /// are blocks of grid cells or subdivisions of one, so only those in grid cells near the
  /// surface are tested. Throws `std::invalid_argument` if `spacing` is not positive.
  template <typename OutputIterator>
  OutputIterator sample_surface(double spacing, OutputIterator out) const
  {
    if(!(spacing > 0.))
      throw std::invalid_argument("Implicit_lattice_domain_3::sample_surface(): spacing "
                                  + std::to_string(spacing) + " is not positive");
    const double ratio = (std::min)(spacing / (std::sqrt(3.) * m_cell), 1e6);
    const int block = (std::max)(1, int(std::floor(ratio)));     // grid cells per sample cell
    const int split = (std::max)(1, int(std::ceil(1. / ratio))); // sample cells per grid cell
    const double h = m_cell * block / split;
    auto sample = [&](const Cell& key) {
      const Point_3 c(m_grid_corner[0] + (key[0] + .5) * h, m_grid_corner[1] + (key[1] + .5) * h,
                      m_grid_corner[2] + (key[2] + .5) * h);
      // 1.5: margin for the error of the first-order distance f / |grad f|
      if(std::abs(value(c)) <= 1.5 * h * std::sqrt(3.) / 2.
                               * std::sqrt(CGAL::to_double(gradient(c).squared_length())))
        *out++ = project_on_surface(c).point;
    };
    if(block == 1) {
      for(const Cell& cell : m_surface_cells)
        for(int i = 0; i < split; ++i)
          for(int j = 0; j < split; ++j)
            for(int k = 0; k < split; ++k)
              sample(Cell{{cell[0] * split + i, cell[1] * split + j, cell[2] * split + k}});
    }
    else {
      std::vector<Cell> blocks;
      for(const Cell& cell : m_surface_cells)
        blocks.push_back(Cell{{cell[0] / block, cell[1] / block, cell[2] / block}});
      std::sort(blocks.begin(), blocks.end());
      blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
      for(const Cell& b : blocks)
        sample(b);
    }
    return out;
  }
  /// @}

  /// the function `f`
  const Function& function() const { return m_function; }

private:
  static constexpr int max_newton_steps = 50;
  static constexpr int bisection_steps = 100;
  static constexpr double convergence = 1e-12;    // |f| / |grad f|, relative to the diagonal
  static constexpr double gradient_step = 1e-6;   // relative to the diagonal
  static constexpr int padding = 3;               // grid cells around the box

  typedef std::array<int, 3> Cell;                // integer coordinates in a grid

  double value(const Point_3& p) const
  {
    const double v = m_function(p);
    if(std::isnan(v)) {
      std::ostringstream msg;
      msg.precision(17);
      msg << "Implicit_lattice_domain_3: the implicit function returned NaN at (" << p << ")";
      throw std::domain_error(msg.str());
    }
    return v;
  }

  Vector_3 gradient(const Point_3& p) const
  {
    const double d = gradient_step * m_diagonal;
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    return Vector_3(value(Point_3(x + d, y, z)) - value(Point_3(x - d, y, z)),
                    value(Point_3(x, y + d, z)) - value(Point_3(x, y - d, z)),
                    value(Point_3(x, y, z + d)) - value(Point_3(x, y, z - d))) / (2. * d);
  }

  // the box enlarged by the grid padding
  CGAL::Bbox_3 grid_box() const
  {
    const double m = padding * m_cell;
    return CGAL::Bbox_3(m_bbox.xmin() - m, m_bbox.ymin() - m, m_bbox.zmin() - m,
                        m_bbox.xmax() + m, m_bbox.ymax() + m, m_bbox.zmax() + m);
  }

  bool in_grid(const Point_3& p) const { return CGAL::do_overlap(grid_box(), p.bbox()); }

  // The part [t0, t1] of the ray p + t d (t >= 0) inside the padded box; empty if t0 > t1.
  void clip_to_grid(const Point_3& p, const Vector_3& d, double& t0, double& t1) const
  {
    const CGAL::Bbox_3 box = grid_box();
    t0 = 0.;
    t1 = std::numeric_limits<double>::infinity();
    for(int a = 0; a < 3; ++a) {
      const double pa = CGAL::to_double(p.cartesian(a)), da = CGAL::to_double(d.cartesian(a));
      if(da != 0.) {
        const double u = (box.min(a) - pa) / da, v = (box.max(a) - pa) / da;
        t0 = (std::max)(t0, (std::min)(u, v));
        t1 = (std::min)(t1, (std::max)(u, v));
      }
      else if(pa < box.min(a) || pa > box.max(a))
        t0 = std::numeric_limits<double>::infinity();
    }
  }

  Projection projection(const Point_3& p, const Point_3& x, const Vector_3& g) const
  {
    const double gg = CGAL::to_double(g.squared_length());
    // A critical point of f on the surface has no normal: fall back to the direction away
    // from a known inside point.
    const Vector_3 n = gg > 0. ? g / std::sqrt(gg) : unit(x - m_inside_point);
    return Projection{x, n, -1, CGAL::to_double(CGAL::squared_distance(p, x))};
  }

  static Vector_3 unit(const Vector_3& v)
  {
    return v / std::sqrt(CGAL::to_double(v.squared_length()));
  }

  // Marches from p along a few rays, clipped to the padded box, with steps of one grid cell;
  // keeps the nearest sign change of f and bisects it. The domain lies in the box, so f >= 0
  // where a ray enters it from outside.
  Point_3 bracket_and_bisect(const Point_3& p, double fp) const
  {
    if(fp == 0.)
      return p;
    const bool inside = fp < 0.;
    std::vector<Vector_3> rays;
    const Vector_3 g = gradient(p);
    if(CGAL::to_double(g.squared_length()) > 0.)
      rays.push_back(unit(inside ? g : -g));
    for(int a = 0; a < 3; ++a)
      for(int s = -1; s <= 1; s += 2) {
        std::array<double, 3> e = {{0., 0., 0.}};
        e[a] = s;
        rays.emplace_back(e[0], e[1], e[2]);
      }
    if(!inside) // this ray always brackets the surface
      rays.push_back(unit(m_inside_point - p));

    double best_lo = std::numeric_limits<double>::infinity(), best_hi = best_lo;
    Vector_3 best_ray = CGAL::NULL_VECTOR;
    for(const Vector_3& d : rays) {
      double t_lo, t_end;
      clip_to_grid(p, d, t_lo, t_end);
      while(t_lo < (std::min)(t_end, best_lo)) {
        const double t_hi = (std::min)(t_lo + m_cell, t_end);
        if((value(p + t_hi * d) < 0.) != inside) {
          best_lo = t_lo;
          best_hi = t_hi;
          best_ray = d;
          break;
        }
        t_lo = t_hi;
      }
    }
    if(best_lo == std::numeric_limits<double>::infinity()) // p inside, every ray ends inside
      throw std::runtime_error("Implicit_lattice_domain_3: no boundary found around an inside "
                               "point: the function is negative outside the bounding box");
    for(int step = 0; step < bisection_steps && best_hi - best_lo > 1e-16 * m_diagonal; ++step) {
      const double t = (best_lo + best_hi) / 2.;
      ((value(p + t * best_ray) < 0.) == inside ? best_lo : best_hi) = t;
    }
    return p + ((best_lo + best_hi) / 2.) * best_ray;
  }

  // Samples f on the padded grid, validates it, integrates volume and area, and keeps the
  // cells that may meet the surface (for sample_surface()).
  void integrate_on_grid()
  {
    m_grid_corner = {{m_bbox.xmin() - padding * m_cell, m_bbox.ymin() - padding * m_cell,
                      m_bbox.zmin() - padding * m_cell}};
    const std::array<int, 3> n = {{int(std::ceil((m_bbox.xmax() - m_bbox.xmin()) / m_cell)) + 2 * padding,
                                   int(std::ceil((m_bbox.ymax() - m_bbox.ymin()) / m_cell)) + 2 * padding,
                                   int(std::ceil((m_bbox.zmax() - m_bbox.zmin()) / m_cell)) + 2 * padding}};
    auto index = [&](int i, int j, int k) { return (std::size_t(i) * n[1] + j) * n[2] + k; };
    auto cell_center = [&](int i, int j, int k) {
      return Point_3(m_grid_corner[0] + (i + .5) * m_cell, m_grid_corner[1] + (j + .5) * m_cell,
                     m_grid_corner[2] + (k + .5) * m_cell);
    };
    const std::size_t cells = std::size_t(n[0]) * n[1] * n[2];
    std::vector<double> f(cells);
    double f_min = std::numeric_limits<double>::infinity();
    for(int i = 0; i < n[0]; ++i)
      for(int j = 0; j < n[1]; ++j)
        for(int k = 0; k < n[2]; ++k) {
          const Point_3 c = cell_center(i, j, k);
          const double v = f[index(i, j, k)] = value(c);
          if(v < 0. && !CGAL::do_overlap(m_bbox, c.bbox())) {
            std::ostringstream msg;
            msg << "Implicit_lattice_domain_3: the bounding box does not contain the domain "
                   "(the function is negative at (" << c << "))";
            throw std::invalid_argument(msg.str());
          }
          if(v < f_min) {
            f_min = v;
            m_inside_point = c;
          }
        }
    if(!(f_min < 0.))
      throw std::invalid_argument("Implicit_lattice_domain_3: the implicit function is nowhere "
                                  "negative in the bounding box (sampled on a grid of cell size "
                                  + std::to_string(m_cell) + ")");

    const double eps = 1.5 * m_cell;
    const double cell_volume = m_cell * m_cell * m_cell;
    const double pi = 3.14159265358979323846;
    const double near_surface = 1.5 * m_cell * std::sqrt(3.) / 2.; // 1.5: as in sample_surface()
    m_volume = m_area = 0.;
    for(int i = 1; i + 1 < n[0]; ++i)
      for(int j = 1; j + 1 < n[1]; ++j)
        for(int k = 1; k + 1 < n[2]; ++k) {
          const double v = f[index(i, j, k)];
          const double gx = f[index(i + 1, j, k)] - f[index(i - 1, j, k)];
          const double gy = f[index(i, j + 1, k)] - f[index(i, j - 1, k)];
          const double gz = f[index(i, j, k + 1)] - f[index(i, j, k - 1)];
          const double g = std::sqrt(gx * gx + gy * gy + gz * gz) / (2. * m_cell);
          const double d = g > 0. ? v / g : (v < 0. ? -1. : 1.) * std::numeric_limits<double>::infinity();
          if(std::abs(d) < eps) {
            m_volume += cell_volume * .5 * (1. - d / eps - std::sin(pi * d / eps) / pi);
            m_area += cell_volume * (1. + std::cos(pi * d / eps)) / (2. * eps);
          }
          else if(d < 0.)
            m_volume += cell_volume;
          if(std::abs(d) <= near_surface)
            m_surface_cells.push_back(Cell{{i, j, k}});
        }
  }

  Function m_function;
  CGAL::Bbox_3 m_bbox;
  double m_diagonal, m_cell;
  double m_volume, m_area;
  Point_3 m_inside_point;                // the grid point where f is smallest
  std::array<double, 3> m_grid_corner;   // min corner of the padded grid
  std::vector<Cell> m_surface_cells;     // the grid cells that may meet the surface
  std::vector<Point_3> m_corners;        // always empty
};

/*!
\ingroup PkgLatticeMesher3Domains

The signed distance to the sphere of center `c` and radius `r`: |p - c| - r.
*/
template <typename K = CGAL::Epick>
struct Implicit_sphere_3
{
  typename K::Point_3 center;  ///< the center c
  double radius;               ///< the radius r

  /// the signed distance from `p` to the sphere, negative inside
  double operator()(const typename K::Point_3& p) const
  {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(p, center))) - radius;
  }
};

/*!
\ingroup PkgLatticeMesher3Domains

The signed distance to the torus centered at the origin whose axis is the y axis (its tube
circles around y, in the xz plane): sqrt((sqrt(x^2 + z^2) - R)^2 + y^2) - r.
*/
template <typename K = CGAL::Epick>
struct Implicit_torus_3
{
  double major_radius;  ///< R, the distance from the y axis to the center of the tube
  double minor_radius;  ///< r, the radius of the tube

  /// the signed distance from `p` to the torus, negative inside
  double operator()(const typename K::Point_3& p) const
  {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    return std::sqrt(CGAL::square(std::sqrt(x * x + z * z) - major_radius) + y * y) - minor_radius;
  }
};

/*!
\ingroup PkgLatticeMesher3Domains

returns the ball of center `center` and radius `radius`, in its tight bounding box. Throws
`std::invalid_argument` if `radius` is not positive.
*/
template <typename K = CGAL::Epick>
Implicit_lattice_domain_3<K, Implicit_sphere_3<K> >
make_sphere_domain_3(const typename K::Point_3& center = typename K::Point_3(CGAL::ORIGIN),
                     double radius = 1.)
{
  if(!(radius > 0. && std::isfinite(radius)))
    throw std::invalid_argument("make_sphere_domain_3(): the radius must be positive");
  const double x = CGAL::to_double(center.x()), y = CGAL::to_double(center.y()),
               z = CGAL::to_double(center.z());
  return Implicit_lattice_domain_3<K, Implicit_sphere_3<K> >(
      Implicit_sphere_3<K>{center, radius},
      CGAL::Bbox_3(x - radius, y - radius, z - radius, x + radius, y + radius, z + radius));
}

/*!
\ingroup PkgLatticeMesher3Domains

returns the solid torus centered at the origin with axis y (see `Implicit_torus_3`), in its
tight bounding box. Throws `std::invalid_argument` unless 0 < `minor_radius` < `major_radius`.
*/
template <typename K = CGAL::Epick>
Implicit_lattice_domain_3<K, Implicit_torus_3<K> >
make_torus_domain_3(double major_radius = 1., double minor_radius = .4)
{
  if(!(minor_radius > 0. && minor_radius < major_radius && std::isfinite(major_radius)))
    throw std::invalid_argument("make_torus_domain_3(): the radii must satisfy "
                                "0 < minor_radius < major_radius");
  const double e = major_radius + minor_radius;
  return Implicit_lattice_domain_3<K, Implicit_torus_3<K> >(
      Implicit_torus_3<K>{major_radius, minor_radius},
      CGAL::Bbox_3(-e, -minor_radius, -e, e, minor_radius, e));
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_IMPLICIT_LATTICE_DOMAIN_3_H
