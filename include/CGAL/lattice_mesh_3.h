// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESH_3_H
#define CGAL_LATTICE_MESH_3_H

#include <CGAL/Named_function_parameters.h>
#ifndef CGAL_LATTICE_MESHER_3_NP_HOOK
#error "Lattice_mesher_3: the np_hook/ include directory must come before CGAL's (see CMakeLists.txt)"
#endif

#include <CGAL/Lattice_particle_mesher_3.h>
#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/make_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/convert_to_c3t3.h>
#include <CGAL/Lattice_mesher_3/sizing_fields.h>

#include <cmath>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

namespace CGAL {

namespace Lattice_mesher_3 {
namespace internal {
// Visitors come by value (copied into the parameter pack) or as std::ref(v).
template <class T> T& unwrap(T& t) { return t; }
template <class T> T& unwrap(std::reference_wrapper<T>& t) { return t.get(); }

template <typename Traits, typename MeshDomain, typename FrameField, typename Visitor>
Tetrahedral_mesh_3<typename Traits::Point_3>
run_lattice_mesher(const MeshDomain& domain, const FrameField& field, const internal::Lattice_mesher_parameters& p,
                   const Traits& gt, Visitor& visitor)
{
  Lattice_particle_mesher_3<Traits, MeshDomain, FrameField> mesher(domain, field, p, gt);
  mesher.optimize(visitor);
  return mesher.tetrahedralize(visitor);
}

// The answer to number_of_vertices(n): `run(count)` meshes for a count (0: the edge length as
// given) and `vertices(result)` counts the mesh's vertices. The count model holds for a lattice
// that fills the domain; where it cannot (parts thinner than the smallest size, whose flat cells
// go; a box that takes a whole number of layers), a mesh of m vertices falls short of n. If m is
// off n by more than 15 %, the mesh is made again for n sqrt(n / m) (between n / 2 and 2 n), and
// the one closer to n is kept. Half the correction, in logarithm: the finer lattice resolves
// more of the thin parts, and n^2 / m overshoots (3,000 asked: boeing 1,367 vertices, for 6,584
// 5,111, for 4,443 3,115; cheese 1,315, 5,803, 3,331). A count that sizes given in lengths
// cannot meet (std::invalid_argument) leaves the first mesh.
template <typename Run, typename Vertices>
auto run_for_vertex_count(double n, Run run, Vertices vertices) -> decltype(run(n))
{
  auto result = run(n);
  const double m = double(vertices(result));
  if(!(n > 0.) || !(m > 0.) || std::abs(m - n) <= .15 * n) return result;
  try {
    auto again = run(n * (std::min)(2., (std::max)(.5, std::sqrt(n / m))));
    if(std::abs(double(vertices(again)) - n) < std::abs(m - n)) return again;
  } catch(const std::invalid_argument&) {}
  return result;
}

// No size of the user's.
struct Unbounded_size
{
  template <typename Point_3> double operator()(const Point_3&) const { return HUGE_VAL; }
};

// The size lattice_mesh_3() meshes with: the user's, and the size that follows the shape (never
// below `floor`) where it asks for one, the smaller of the two.
template <typename K, typename UserSize>
struct Combined_size_3
{
  std::shared_ptr<const UserSize> user;
  std::shared_ptr<const Graded_sizing_field_3<K> > shape;   // none: no part is thin
  double floor = 0.;

  double operator()(const typename K::Point_3& p) const
  {
    const double u = (*user)(p);
    return shape ? (std::min)(u, (std::max)((*shape)(p), floor)) : u;
  }
};

// The size that follows the shape: `cells_across` C (0: none), `surface_tolerance` (0: none),
// `grading` G, `min_edge_length` H (0: l*/4).
struct Shape_sizing_parameters
{
  double cells_across = 1.25, surface_tolerance = 0., grading = .3, min_edge_length = 0.;

  // throws std::invalid_argument for a value out of range, naming the parameter as `name`
  // spells it (`name("cells_across")`: a named parameter, a command-line option)
  template <typename Name>
  void check(const Name& name) const
  {
    auto require = [&](bool ok, const char* parameter, const char* what) {
      if(!ok) throw std::invalid_argument(name(parameter) + " must be " + what);
    };
    require((cells_across == 0. || cells_across >= 1.) && std::isfinite(cells_across), "cells_across",
            "0 (no size that follows the shape) or at least 1");
    require(surface_tolerance >= 0. && std::isfinite(surface_tolerance), "surface_tolerance", "0 (none) or positive and finite");
    require(grading > 0. && std::isfinite(grading), "grading", "positive and finite");
    require(min_edge_length >= 0. && std::isfinite(min_edge_length), "min_edge_length", "0 (l*/4) or positive and finite");
  }
};

// What the sizing did: the samples of the shape's size, the cells across, the smallest size, and
// the floor below which it shrinks no size (min_edge_length, l*/4 by default; 0 without a size
// that follows the shape).
struct Shape_sizing_report
{
  std::size_t samples = 0;
  double cells_across = 0., surface_tolerance = 0., smallest_size = 0., floor = 0.;
};

// `field` scaled by the user's size and the size that follows the shape of `domain`, and
// p.edge_length (l*, the largest edge): given, or for p.number_of_vertices the l* and the cells
// across that give about that count. The thin parts' vertices are paid for by the rest: l* may
// grow by a quarter over its estimate without the shape's size; past that, fewer cells fit
// across the thin parts (C down to the default, 1.25), and only then does l* grow further.
template <typename Traits, typename MeshDomain, typename FrameField, typename UserSize>
Sized_frame_field_3<FrameField, Combined_size_3<typename MeshDomain::Geom_traits, UserSize> >
sized_field(const MeshDomain& domain, const FrameField& field, const UserSize& user, internal::Lattice_mesher_parameters& p,
            const Shape_sizing_parameters& s, Shape_sizing_report* report = nullptr)
{
  typedef typename MeshDomain::Geom_traits K;
  typedef Combined_size_3<K, UserSize> Size;
  typedef Sized_frame_field_3<FrameField, Size> Sized;
  typedef Graded_sizing_field_3<K> Shape;
  const double n = p.number_of_vertices;
  p.number_of_vertices = 0.;
  auto floor = [&](double l) { return s.min_edge_length > 0. ? s.min_edge_length : .25 * l; };
  auto sized = [&](Size h, double l) { h.floor = floor(l); return Sized(field, h, l); };
  // the count of the field scaled by h at l, from |det B| at fixed inside points: drawn once, they
  // spare the fit's hundred counts their inside tests; not drawn without a count to fit. The
  // mesher also checks the parameters before the sizing's work.
  typedef Lattice_particle_mesher_3<Traits, MeshDomain, FrameField> Mesher;
  internal::Lattice_mesher_parameters q = p;
  q.number_of_vertices = n;
  const Mesher mesher(domain, field, q);
  const std::vector<typename K::Point_3> inside = n > 0. ? internal::inside_samples(domain, 4096) : std::vector<typename K::Point_3>();
  auto count = [&](const Size& h, double l) { return mesher.expected_vertices(l, internal::det_b_at(inside, sized(h, l)).mean); };
  // the largest l from lo on with count(h, l) <= n: the count falls as l grows
  auto solve = [&](const Size& h, double lo, double hi) {
    const double start = lo;
    while(count(h, hi) > n && hi < 1e6 * start) { lo = hi; hi *= 2.; }
    // sizes given in lengths (a size field, min_edge_length, surface_tolerance) that alone
    // need more than the count at any l*
    if(count(h, hi) > n) {
      std::ostringstream os;
      os << "number_of_vertices(" << n << "): the sizes below l* alone need about " << count(h, hi)
         << " vertices at any l*; ask for more vertices, or for larger sizes (size_field, min_edge_length, surface_tolerance)";
      throw std::invalid_argument(os.str());
    }
    for(int it = 0; it < 40; ++it) { const double mid = .5 * (lo + hi); (count(h, mid) > n ? lo : hi) = mid; }
    return hi;
  };
  const std::shared_ptr<const UserSize> user_size = std::make_shared<const UserSize>(user);
  Size size{ user_size, nullptr, 0. };
  double l = p.edge_length;
  if(n > 0.) {
    l = mesher.edge_length();
    // a user's size above l at every sample leaves l as the mesher solved it, bit for bit
    if(internal::det_b_at(inside, sized(size, l)).mean != internal::det_b_at(inside, field).mean) l = solve(size, l, l);
  }
  double cells = s.cells_across;
  const double estimate = l, tolerance = s.surface_tolerance;
  if(cells > 0. || tolerance > 0.) {
    // sizes up to twice the estimate, so that they also serve the l* of the fit: thicknesses up
    // to C times that and gaps up to that, in steps of l*/4 (a thinner part measures a step,
    // whose size is below the smallest, l*/4); deviations at scales down to l*/4
    std::vector<Thickness_sample_3<K> > measures;
    if(cells > 0.) measures = thickness_samples(domain, .5 * estimate, .25 * estimate, 2. * cells * estimate, 2. * estimate, p.threads);
    std::vector<Deviation_sample_3<K> > deviations;
    if(tolerance > 0.) deviations = deviation_samples(domain, .5 * estimate, 2. * estimate, p.threads);
    auto shape = [&](double c) -> std::shared_ptr<const Shape> {
      std::vector<std::pair<typename K::Point_3, double> > samples;
      if(c > 0.) size_samples(measures, c, 2. * estimate, std::back_inserter(samples));
      if(tolerance > 0.) tolerance_size_samples(deviations, tolerance, 2. * estimate, std::back_inserter(samples));
      if(samples.empty()) return nullptr;
      return std::make_shared<const Shape>(samples, s.grading, 2. * estimate);
    };
    auto with = [&](double c) { return Size{ user_size, shape(c), 0. }; };
    size = with(cells);
    if(n > 0. && size.shape) {
      const double most = 1.25 * estimate;
      if(count(size, most) <= n) l = solve(size, estimate, most);
      else {
        l = most;
        const double fewest = (std::min)(Shape_sizing_parameters().cells_across, cells);
        if(cells > fewest && count(with(fewest), most) <= n) {   // the count grows with the cells across
          double lo = fewest, hi = cells;
          for(int it = 0; it < 6; ++it) { const double mid = .5 * (lo + hi); (count(with(mid), most) > n ? hi : lo) = mid; }
          cells = lo;
          size = with(cells);
        }
        else {
          if(cells > fewest) { cells = fewest; size = with(cells); }
          l = solve(size, most, most);
        }
      }
    }
  }
  p.edge_length = l;
  if(report) {
    report->samples = size.shape ? size.shape->number_of_samples() : 0;
    report->cells_across = cells;
    report->surface_tolerance = tolerance;
    report->smallest_size = size.shape ? (std::max)(size.shape->min_size(), floor(l)) : l;
    report->floor = size.shape ? floor(l) : 0.;
  }
  return sized(size, l);
}
// The lattice domain of a Mesh_3 domain, sampled for the l* of `np`: edge_length(), or for
// number_of_vertices() the l* of that count in the bounding box, then, if the domain's volume
// asks for a finer one, in that volume.
template <typename MeshDomain, typename NamedParameters>
Polyhedral_lattice_domain_3<Mesh_domain_kernel<MeshDomain> > lattice_domain_for(const MeshDomain& domain, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const double length = choose_parameter(get_parameter(np, internal_np::edge_length), 0.);
  if(length > 0. && std::isfinite(length))
    return make_lattice_domain_3(domain, parameters::edge_length(length));
  const double n = choose_parameter(get_parameter(np, internal_np::number_of_vertices), 0.);
  const Lattice_type lattice = choose_parameter(get_parameter(np, internal_np::lattice_param), Lattice_type::BCC);
  const double per_cube = lattice == Lattice_type::FCC ? 4. : 2.;
  const Bbox_3 b = domain.bbox();
  const double box = (b.xmax() - b.xmin()) * (b.ymax() - b.ymin()) * (b.zmax() - b.zmin());
  if(!(n >= 1.) || !std::isfinite(n) || !(box > 0.))
    return make_lattice_domain_3(domain);   // the mesher names what is wrong with the parameters
  const double l = std::cbrt(per_cube * box / n);
  Polyhedral_lattice_domain_3<Mesh_domain_kernel<MeshDomain> > result = make_lattice_domain_3(domain, parameters::edge_length(l));
  const double finer = std::cbrt(per_cube * result.volume() / n);
  if(finer < l / 1.5) return make_lattice_domain_3(domain, parameters::edge_length(finer));
  return result;
}

} // namespace internal
} // namespace Lattice_mesher_3

/*!
\ingroup PkgLatticeMesher3Ref

Meshes `domain` with tetrahedra whose vertices form a BCC or FCC lattice aligned with `field`:
optimizes particles carrying a Gaussian Hole Kernel (`Lattice_particle_mesher_3`) and connects
them (`tetrahedralize_particles()`).

\tparam MeshDomain a model of `LatticeMeshDomain_3`, or of Mesh_3's `MeshDomain_3` (`Polyhedral_mesh_domain_with_features_3`, `Labeled_mesh_domain_3`, ...), which it meshes through `Lattice_mesher_3::make_lattice_domain_3()`
\tparam FrameField a model of `FrameField_3`

\cgalNamedParamsBegin
  \cgalParamNBegin{edge_length}
    \cgalParamDescription{the lattice cube edge l* in the isotropic space of the field}
    \cgalParamType{double}
    \cgalParamExtra{exactly one of `edge_length` and `number_of_vertices` is required}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_vertices}
    \cgalParamDescription{picks l* so that the mesh has about this many vertices, n; if the mesh's
      count m is off n by more than 15 % (where parts thinner than `min_edge_length` lose their flat
      cells, or a box takes a whole number of lattice layers), meshes again for n sqrt(n / m)
      (between n / 2 and 2 n) and returns the mesh closer to n (the visitor sees both runs)}
    \cgalParamType{double}
  \cgalParamNEnd
  \cgalParamNBegin{lattice}
    \cgalParamDescription{the lattice; `Lattice_type::GAUSSIAN` is the hole-less kernel of Particle2013
      (a random start at the final count, no insertion or deletion: the baseline)}
    \cgalParamType{`CGAL::Lattice_mesher_3::Lattice_type`}
    \cgalParamDefault{`Lattice_type::BCC`}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{seed of the random points of the start: the same seed and number of threads give the same mesh}
    \cgalParamType{unsigned int}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_threads}
    \cgalParamDescription{OpenMP threads}
    \cgalParamType{int}
    \cgalParamDefault{1}
  \cgalParamNEnd
  \cgalParamNBegin{max_rounds}
    \cgalParamDescription{MaxRoundNum: rounds of deletion, insertion and optimization per level}
    \cgalParamType{int}
    \cgalParamDefault{16 without a coarse level, 8 with}
  \cgalParamNEnd
  \cgalParamNBegin{coarse_levels}
    \cgalParamDescription{k: the optimization starts at 2^k l* and refines}
    \cgalParamType{int}
    \cgalParamDefault{-1: the largest k <= 4 at which the coarse lattice has at least 16 vertices}
  \cgalParamNEnd
  \cgalParamNBegin{sigma_ratio}
    \cgalParamDescription{sigma / l_closest of the kernel}
    \cgalParamType{double}
    \cgalParamDefault{0.3}
  \cgalParamNEnd
  \cgalParamNBegin{neighbor_radius_ratio}
    \cgalParamDescription{R / l*: the isotropic radius within which particles interact}
    \cgalParamType{double}
    \cgalParamDefault{1.3}
  \cgalParamNEnd
  \cgalParamNBegin{gradient_tolerance}
    \cgalParamDescription{EpsG: a round stops when the RMS particle gradient (units of 1/l*) is below it}
    \cgalParamType{double}
    \cgalParamDefault{0.01 (the last round: 3e-3)}
  \cgalParamNEnd
  \cgalParamNBegin{do_flip}
    \cgalParamDescription{improve the connectivity by flips in the isotropic space (`flip_tetrahedra()`)}
    \cgalParamType{bool}
    \cgalParamDefault{true}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_smoothing_rounds}
    \cgalParamDescription{rounds of worst-element smoothing and flips after the tetrahedralization
                          (`smooth_vertices()`), with edge contractions (`collapse_edges()`) before
                          the second and a last round on the tetrahedra below 40 degrees; 0 keeps
                          the particles as they are}
    \cgalParamType{int}
    \cgalParamDefault{2}
  \cgalParamNEnd
  \cgalParamNBegin{size_field}
    \cgalParamDescription{the largest edge length h(x) at each point, a graded function (slope well below 1, e.g.
      0.3; a `Lattice_mesher_3::Graded_sizing_field_3` is); the lattice cube shrinks to h(x) where h(x) is
      below l*, keeping the directions of the field (`Lattice_mesher_3::Sized_frame_field_3`), and l* is the
      largest edge; with `number_of_vertices`, l* is chosen so that the sized mesh has about that many;
      where the size that follows the shape (`cells_across`) is smaller, that one}
    \cgalParamType{a callable `double(const Point_3&)`, thread-safe}
    \cgalParamDefault{none: the edge is l* everywhere}
  \cgalParamNEnd
  \cgalParamNBegin{cells_across}
    \cgalParamDescription{the size that follows the shape: where a part of the domain is thinner than
      C l*, the edge shrinks so that C cells fit across it, and where a gap between two parts is
      narrower than l*, to the gap (`Lattice_mesher_3::thickness_samples()`, `Lattice_mesher_3::size_samples()`);
      with `number_of_vertices`, l* may grow by a quarter over its estimate to pay for the thin parts'
      vertices, and past that C comes down to 1.25 (if it is above) before l* grows further; 0 keeps l*
      everywhere}
    \cgalParamType{double, 0 or at least 1}
    \cgalParamDefault{1.25}
  \cgalParamNEnd
  \cgalParamNBegin{surface_tolerance}
    \cgalParamDescription{the distance epsilon from the surface that boundary facets should keep, as
      Mesh_3's `facet_distance`: where the surface curves (or creases below the feature angle) so
      much that facets of size l* would leave it by more, the size shrinks to what keeps them within
      epsilon (`Lattice_mesher_3::deviation_samples()`, `Lattice_mesher_3::tolerance_size_samples()`),
      never below `min_edge_length`; with `number_of_vertices`, l* grows to pay for these vertices}
    \cgalParamType{double, at least 0}
    \cgalParamDefault{0: none}
  \cgalParamNEnd
  \cgalParamNBegin{grading}
    \cgalParamDescription{the largest slope of the size that follows the shape (`Lattice_mesher_3::Graded_sizing_field_3`)}
    \cgalParamType{double}
    \cgalParamDefault{0.3}
  \cgalParamNEnd
  \cgalParamNBegin{min_edge_length}
    \cgalParamDescription{the size that follows the shape is never below it}
    \cgalParamType{double}
    \cgalParamDefault{l* / 4}
  \cgalParamNEnd
  \cgalParamNBegin{visitor}
    \cgalParamDescription{progress: `round_done(const Lattice_mesher_3::Round_report&)` after each round;
                          pass `std::ref(v)` to keep the state in `v`}
    \cgalParamType{a model of `LatticeMesherVisitor_3`}
    \cgalParamDefault{`Lattice_mesher_3::Null_lattice_mesher_visitor`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{the traits object; its predicates decide the Delaunay tetrahedralization}
    \cgalParamType{a model of `LatticeMesherTraits_3`}
    \cgalParamDefault{`Lattice_mesher_traits_3<MeshDomain::Geom_traits>`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the mesh as vertex and tetrahedron arrays (`Lattice_mesher_3::Tetrahedral_mesh_3`),
with the subdomain index of each tetrahedron and the surface patch index of each boundary face:
a Mesh_3 domain's own (pairs of subdomain indices numbered 1, 2, ...), or those of a
`LatticeMeshDomain_3`.
\throws std::invalid_argument naming the parameter if one is out of range: a length, ratio or
tolerance that is not positive and finite, fewer than 1 thread, `coarse_levels` outside [-1, 4],
`max_rounds` below -1, `number_of_smoothing_rounds` below 0, or an edge length that needs more
than 5e7 particles
*/
template <typename MeshDomain, typename FrameField,
          typename NamedParameters = parameters::Default_named_parameters>
Lattice_mesher_3::Tetrahedral_mesh_3<typename Lattice_mesher_3::internal::Domain_point_3<MeshDomain>::type>
lattice_mesh_3(const MeshDomain& domain, const FrameField& field,
               const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  namespace LM = Lattice_mesher_3;
  if constexpr(!LM::internal::Is_lattice_mesh_domain_3<MeshDomain>::value) {
    auto mesh = lattice_mesh_3(LM::internal::lattice_domain_for(domain, np), field, np);
    typedef LM::internal::Mesh_domain_index_types<MeshDomain> Indices;
    LM::internal::label_mesh(mesh, LM::internal::Mesh_domain_indices<Indices, MeshDomain>(domain, typename Indices::Subdomain_index(1)));
    return mesh;
  }
  else {

  static_assert(is_default_parameter<NamedParameters, internal_np::feature_angle_t>::value,
                "lattice_mesh_3(domain, ...): feature_angle() applies when meshing a surface mesh; "
                "a domain already has its features");
  typedef typename internal_np::Lookup_named_param_def<
    internal_np::geom_traits_t, NamedParameters,
    Lattice_mesher_traits_3<typename MeshDomain::Geom_traits> >::type Traits;

  LM::internal::Lattice_mesher_parameters p = LM::internal::mesher_parameters(np, "lattice_mesh_3()");

  typedef typename internal_np::Lookup_named_param_def<
    internal_np::visitor_t, NamedParameters, LM::Null_lattice_mesher_visitor>::type Visitor;
  Visitor visitor = choose_parameter<Visitor>(get_parameter(np, internal_np::visitor));

  typedef typename internal_np::Lookup_named_param_def<
    internal_np::size_field_t, NamedParameters, LM::internal::Unbounded_size>::type Size;
  const Size size = choose_parameter<Size>(get_parameter(np, internal_np::size_field));
  const LM::internal::Shape_sizing_parameters defaults;
  LM::internal::Shape_sizing_parameters s;
  s.cells_across = choose_parameter(get_parameter(np, internal_np::cells_across), defaults.cells_across);
  s.surface_tolerance = choose_parameter(get_parameter(np, internal_np::surface_tolerance), defaults.surface_tolerance);
  s.grading = choose_parameter(get_parameter(np, internal_np::grading), defaults.grading);
  s.min_edge_length = choose_parameter(get_parameter(np, internal_np::min_edge_length), defaults.min_edge_length);
  s.check([](const char* parameter) { return "lattice_mesh_3(): " + std::string(parameter) + "()"; });
  const Traits traits = choose_parameter<Traits>(get_parameter(np, internal_np::geom_traits));
  auto run = [&](double count) {
    LM::internal::Lattice_mesher_parameters q = p;
    q.number_of_vertices = count;
    const auto sized = LM::internal::sized_field<Traits>(domain, field, size, q, s);
    return LM::internal::run_lattice_mesher(domain, sized, q, traits, LM::internal::unwrap(visitor));
  };
  return LM::internal::run_for_vertex_count(p.number_of_vertices, run,
                                            [](const LM::Tetrahedral_mesh_3<typename Traits::Point_3>& m) { return m.points.size(); });
  }
}

namespace Lattice_mesher_3 {
namespace internal {
template <typename C, typename = void> struct Is_c3t3 : std::false_type {};
template <typename C>
struct Is_c3t3<C, std::void_t<typename C::Triangulation, typename C::Cells_in_complex_iterator> > : std::true_type {};
} // namespace internal
} // namespace Lattice_mesher_3

/*!
\ingroup PkgLatticeMesher3Ref

Meshes `domain` as `lattice_mesh_3(domain, field, np)` does and returns the mesh as a
`Mesh_complex_3_in_triangulation_3` (`Lattice_mesher_3::convert_to_c3t3()`), which Mesh_3's
optimizers and writers and `CGAL::tetrahedral_isotropic_remeshing()` (through
`CGAL::convert_to_triangulation_3()`) take. For a Mesh_3 domain, the cells carry the
subdomain index the domain gives at their centroid, the boundary facets the surface patch index
where the segment across them meets the surface, and the feature edges and corners the domain's
curve and corner indices.

\tparam C3t3 a `Mesh_complex_3_in_triangulation_3` whose triangulation is
`Mesh_triangulation_3<MeshDomain>::type` for a Mesh_3 domain, e.g.
`Lattice_mesher_3::Mesh_complex_3<K>` for a `LatticeMeshDomain_3`
*/
template <typename C3t3, typename MeshDomain, typename FrameField,
          typename NamedParameters = parameters::Default_named_parameters>
std::enable_if_t<Lattice_mesher_3::internal::Is_c3t3<C3t3>::value, C3t3>
lattice_mesh_3(const MeshDomain& domain, const FrameField& field,
               const NamedParameters& np = parameters::default_values())
{
  namespace LM = Lattice_mesher_3;
  C3t3 c3t3;
  if constexpr(LM::internal::Is_lattice_mesh_domain_3<MeshDomain>::value)
    LM::convert_to_c3t3(lattice_mesh_3(domain, field, np), domain, c3t3);
  else {
    const auto lattice_domain = LM::internal::lattice_domain_for(domain, np);
    const LM::internal::Mesh_domain_indices<C3t3, MeshDomain> indices(domain, typename C3t3::Subdomain_index(1));
    LM::internal::convert_to_c3t3(lattice_mesh_3(lattice_domain, field, np), lattice_domain, indices, c3t3);
  }
  return c3t3;
}

/*!
\ingroup PkgLatticeMesher3Ref

Meshes the volume bounded by the closed triangle mesh `surface`: builds a
`Polyhedral_lattice_domain_3` whose sharp edges are those with a dihedral angle sharper than the
named parameter `feature_angle` (degrees, default 60), then calls the domain overload with the
other named parameters.
*/
template <typename Point_3, typename FrameField, typename NamedParameters = parameters::Default_named_parameters>
Lattice_mesher_3::Tetrahedral_mesh_3<Point_3>
lattice_mesh_3(const Surface_mesh<Point_3>& surface, const FrameField& field,
               const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename Kernel_traits<Point_3>::Kernel K;
  const double angle = choose_parameter(get_parameter(np, internal_np::feature_angle), 60.);
  const Lattice_mesher_3::Polyhedral_lattice_domain_3<K> domain(surface, angle);
  // the angle is used up: hide it from the domain overload, which rejects it
  return lattice_mesh_3(domain, field, np.feature_angle(internal_np::Param_not_found()));
}

} // namespace CGAL

#endif // CGAL_LATTICE_MESH_3_H
