// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_PARTICLE_MESHER_3_H
#define CGAL_LATTICE_PARTICLE_MESHER_3_H

#include <CGAL/Lattice_mesher_traits_3.h>
#include <CGAL/Lattice_mesher_3/Lattice_3.h>
#include <CGAL/Lattice_mesher_3/Tetrahedral_mesh_3.h>
#include <CGAL/Lattice_mesher_3/collapse_edges.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/insert_delete_particles.h>
#include <CGAL/Lattice_mesher_3/internal/isotropic_embedding.h>
#include <CGAL/Lattice_mesher_3/optimize_particles.h>
#include <CGAL/Lattice_mesher_3/peel_slivers.h>
#include <CGAL/Lattice_mesher_3/flip_tetrahedra.h>
#include <CGAL/Lattice_mesher_3/smooth_vertices.h>
#include <CGAL/Lattice_mesher_3/tetrahedralize_particles.h>
#include <CGAL/Lattice_mesher_3/internal/field_sampling.h>
#include <CGAL/Lattice_mesher_3/internal/domain_indices.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>
#include <utility>

namespace CGAL {
namespace Lattice_mesher_3 {

/// What the optimizer reports after each round (see `LatticeMesherVisitor_3`).
struct Round_report
{
  int level = 0;            ///< coarse-to-fine level: 0 is the final edge length
  int round = 0;            ///< round within the level
  bool final_round = false; ///< the closing, tightly converged round
  std::size_t particles = 0; ///< number of particles after the round
  /*! \brief number of particles deleted before the round's optimization */
  std::size_t deleted = 0, inserted = 0; ///< number of particles inserted before the round's optimization
  int iterations = 0;       ///< number of L-BFGS iterations of the round
  double energy = 0.;       ///< total GHK energy
  double seconds = 0.;      ///< since the optimization started
  double deletion_seconds = 0.;     ///< seconds this round spent deleting particles
  double insertion_seconds = 0.;    ///< seconds this round spent inserting particles (at a level's round 0: the start, or the refinement from the coarser level)
  double optimization_seconds = 0.; ///< seconds of this round's L-BFGS iterations
};

/// The visitor that does nothing.
struct Null_lattice_mesher_visitor
{
  /// does nothing
  void round_done(const Round_report&) {}
};

/// A visitor that adds up the time of each stage (a model of `LatticeMesherVisitor_3`): the
/// L-BFGS iterations per coarse-to-fine level (`"optimization, level k"`), the insertions
/// (`"insertion"`, with the start and the refinements) and the deletions (`"deletion"`) of every
/// round, then each stage of the mesh improvement under its own name (flips, smoothing and
/// contractions summed over their repeats). Callers add stages of their own with `add()` (reading
/// the domain, writing the mesh), so that one table holds the whole run.
class Stage_times_visitor
{
public:
  /// the stages in the order they first ran, with their total seconds
  const std::vector<std::pair<std::string, double> >& stages() const { return stages_; }

  /// adds `seconds` to `stage`, a new stage at the end if there is none of that name yet
  void add(const std::string& stage, double seconds)
  {
    auto it = std::find_if(stages_.begin(), stages_.end(), [&](const std::pair<std::string, double>& s) { return s.first == stage; });
    if(it == stages_.end()) stages_.emplace_back(stage, seconds);
    else it->second += seconds;
  }

  /// the sum over the stages
  double total() const
  {
    double t = 0.;
    for(const auto& s : stages_) t += s.second;
    return t;
  }

  /// adds the round's deletion, insertion and optimization times
  void round_done(const Round_report& r)
  {
    add("insertion", r.insertion_seconds);
    add("optimization, level " + std::to_string(r.level), r.optimization_seconds);
    add("deletion", r.deletion_seconds);
    mesh_seconds_ = 0.;
  }

  /// adds the time since the previous stage of the mesh improvement
  void stage_done(const char* stage, double seconds)
  {
    if(seconds < mesh_seconds_) mesh_seconds_ = 0.;   // another tetrahedralization
    add(stage, seconds - mesh_seconds_);
    mesh_seconds_ = seconds;
  }

private:
  std::vector<std::pair<std::string, double> > stages_;
  double mesh_seconds_ = 0.;   // the mesh improvement's clock at its last stage
};

namespace internal {

// work(), its duration in seconds added to `seconds`
template <typename Work>
auto timed(double& seconds, Work&& work)
{
  const auto start = std::chrono::steady_clock::now();
  auto result = work();
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// A visitor's round_done() returns void (go on) or bool (false: stop the optimization).
template <typename Visitor>
bool continue_after(Visitor& visitor, const Round_report& report)
{
  if constexpr(std::is_same<decltype(visitor.round_done(report)), bool>::value) return visitor.round_done(report);
  else { visitor.round_done(report); return true; }
}

// stage_done(name, seconds) is optional.
template <typename Visitor, typename = void> struct Has_stage_done : std::false_type {};
template <typename Visitor>
struct Has_stage_done<Visitor, std::void_t<decltype(std::declval<Visitor&>().stage_done("", 0.))> > : std::true_type {};

template <typename Visitor>
void report_stage(Visitor& visitor, const char* stage, double seconds)
{
  if constexpr(Has_stage_done<Visitor>::value) visitor.stage_done(stage, seconds);
}

} // namespace internal

namespace internal {

// The parameters of Lattice_particle_mesher_3, read once from the named parameters of
// lattice_mesh_3() or of its constructor; the defaults are the paper's values.
struct Lattice_mesher_parameters
{
  double edge_length = 0.;             ///< l*, in the isotropic space of the field
  double number_of_vertices = 0.;      ///< instead of `edge_length`: l* for about this many vertices
  Lattice_3 lattice = bcc_lattice();
  unsigned int seed = 0;               ///< random points of the start; same seed and threads, same mesh
  int threads = 1;
  int max_rounds = -1;                 ///< MaxRoundNum; -1: 16 without a coarse level, 8 with, 30 without holes
  int coarse_levels = -1;              ///< k: start at 2^k l*; -1: the coarsest level with >= 16 vertices
  double sigma_ratio = 0.3;            ///< sigma / l_closest
  double neighbor_radius = 1.3;        ///< R / l*
  double gradient_tolerance = 1e-2;    ///< EpsG of the rounds
  /// EpsG of the last round. The paper's 1e-4 took 142 to 250 iterations (fandisk, knot1) for
  /// what 3e-3 reaches in 33: the same quality (fandisk mean 57.51 both, fig8, fig9, elephant,
  /// knot1 within 0.05 degree), a quarter of the optimization time.
  double final_gradient_tolerance = 3e-3;
  bool flip = true;                    ///< improve the connectivity by flips (`flip_tetrahedra()`)
  /// Rounds of `smooth_vertices()` and flips on the worst tetrahedra, edge contractions
  /// (`collapse_edges()`) before the second, and a last smoothing of those below 40 degrees
  /// followed by contractions; 0: none of these.
  int smoothing_rounds = 2;
};


template <typename NamedParameters>
Lattice_mesher_parameters mesher_parameters(const NamedParameters& np, const char* caller)
{
  using parameters::is_default_parameter;
  Lattice_mesher_parameters p;
  p.lattice = stage_lattice(np);
  p.sigma_ratio = p.lattice.sigma_ratio;
  read_parameter(np, internal_np::random_seed, p.seed);
  read_parameter(np, internal_np::number_of_threads, p.threads);
  read_parameter(np, internal_np::max_rounds, p.max_rounds);
  read_parameter(np, internal_np::coarse_levels, p.coarse_levels);
  read_parameter(np, internal_np::neighbor_radius_ratio, p.neighbor_radius);
  read_parameter(np, internal_np::gradient_tolerance, p.gradient_tolerance);
  read_parameter(np, internal_np::final_gradient_tolerance, p.final_gradient_tolerance);
  read_parameter(np, internal_np::do_flip, p.flip);
  read_parameter(np, internal_np::number_of_smoothing_rounds, p.smoothing_rounds);
  const bool has_length = !is_default_parameter<NamedParameters, internal_np::edge_length_t>::value;
  const bool has_count = !is_default_parameter<NamedParameters, internal_np::number_of_vertices_t>::value;
  if(has_length == has_count)
    throw std::invalid_argument(std::string(caller) + ": give exactly one of edge_length() and number_of_vertices()");
  read_parameter(np, internal_np::edge_length, p.edge_length);
  if(has_length && (!(p.edge_length > 0.) || !std::isfinite(p.edge_length)))
    throw std::invalid_argument(std::string(caller) + ": edge_length() must be positive and finite");
  read_parameter(np, internal_np::number_of_vertices, p.number_of_vertices);
  return p;
}

} // namespace internal
} // namespace Lattice_mesher_3

/*!
\ingroup PkgLatticeMesher3Ref

The particle-based lattice mesher: optimizes particles carrying a Gaussian Hole Kernel until
they form the chosen lattice aligned with the frame field (Alg. 1 and 2 of the paper, with
coarse-to-fine), then connects them into a tetrahedral mesh. Each stage is also a free function
(`optimize_particles()`, `delete_particles()`, `insert_particles()`,
`tetrahedralize_particles()`); this class chains them.

\tparam Traits a model of `LatticeMesherTraits_3`, e.g. `Lattice_mesher_traits_3<Epick>`
\tparam MeshDomain a model of `LatticeMeshDomain_3`
\tparam FrameField a model of `FrameField_3`
*/
template <typename Traits, typename MeshDomain, typename FrameField>
class Lattice_particle_mesher_3
{
public:
  typedef typename Traits::Point_3 Point_3; ///< the point type
  typedef Lattice_mesher_3::Particle_set_3<Point_3> Particle_set; ///< the particle system
  typedef Lattice_mesher_3::Tetrahedral_mesh_3<Point_3> Mesh; ///< the output mesh type

  static_assert(Lattice_mesher_3::internal::Is_frame_field_3<FrameField, Traits>::value,
                "FrameField must be a model of FrameField_3: Matrix_3 frame(const Point_3&) const");

  /// Checks the parameters and, for `number_of_vertices`, solves for l*. The named parameters
  /// are those of `lattice_mesh_3()` but for the sizing (`size_field`, `cells_across`,
  /// `surface_tolerance`, `grading`, `min_edge_length`) and `visitor`, which `optimize()` takes,
  /// plus `final_gradient_tolerance` (EpsG of the closing round, default 3e-3).
  /// \throws std::invalid_argument naming the parameter that is missing or out of range
  template <typename NamedParameters = parameters::Default_named_parameters,
            typename = std::enable_if_t<!std::is_same<NamedParameters, Lattice_mesher_3::internal::Lattice_mesher_parameters>::value> >
  Lattice_particle_mesher_3(const MeshDomain& domain, const FrameField& field,
                            const NamedParameters& np = parameters::default_values())
    : Lattice_particle_mesher_3(domain, field, Lattice_mesher_3::internal::mesher_parameters(np, "Lattice_particle_mesher_3"),
                                parameters::choose_parameter<Traits>(parameters::get_parameter(np, internal_np::geom_traits)))
  {}

  /// \cond SKIP_IN_MANUAL
  // The parameters as lattice_mesh_3() reads them from its named parameters, checked as above.
  Lattice_particle_mesher_3(const MeshDomain& domain, const FrameField& field,
                            const Lattice_mesher_3::internal::Lattice_mesher_parameters& p, const Traits& gt = Traits())
    : domain_(domain), field_(field), p_(p), traits_(gt), lattice_(p.lattice)
  {
    lattice_.sigma_ratio = p.sigma_ratio;
    if((p.edge_length != 0.) == (p.number_of_vertices != 0.))
      throw std::invalid_argument("Lattice_particle_mesher_3: give exactly one of the edge length and the number of vertices");
    if(p.number_of_vertices != 0.) p_.edge_length = edge_length_for_vertices(p.number_of_vertices);
    auto require_positive = [](double x, const std::string& what) {
      if(!(x > 0.) || !std::isfinite(x))
        throw std::invalid_argument("Lattice_particle_mesher_3: " + what + " must be positive and finite");
    };
    require_positive(p_.edge_length, "the edge length");
    require_positive(p.sigma_ratio, "sigma_ratio");
    require_positive(p.neighbor_radius, "neighbor_radius");
    require_positive(p.gradient_tolerance, "the gradient tolerances");
    require_positive(p.final_gradient_tolerance, "the gradient tolerances");
    if(p.threads < 1) throw std::invalid_argument("Lattice_particle_mesher_3: the number of threads must be at least 1");
    if(p.coarse_levels < -1 || p.coarse_levels > max_coarse_levels)
      throw std::invalid_argument("Lattice_particle_mesher_3: coarse_levels must be -1 (automatic) or in [0, 4]");
    // negative counts would silently mean the defaults (max_rounds) or nothing (smoothing)
    if(p.max_rounds < -1) throw std::invalid_argument("Lattice_particle_mesher_3: max_rounds must be -1 (automatic) or at least 0");
    if(p.smoothing_rounds < 0) throw std::invalid_argument("Lattice_particle_mesher_3: smoothing_rounds must be at least 0");
    const double estimate = lattice_.density * isotropic_volume() / std::pow(p_.edge_length, 3);
    if(!(estimate < max_particles))
    {
      std::ostringstream os;
      os << "Lattice_particle_mesher_3: edge length " << p_.edge_length << " would need about " << estimate
         << " particles (more than " << max_particles << "); choose a larger edge length";
      throw std::invalid_argument(os.str());
    }
  }
  /// \endcond

  /// Runs the whole particle optimization: the start (`initialize_particles()`) at the coarsest
  /// level, rounds of L-BFGS with deletion and insertion, refinement to the next level, and a
  /// last tight round.
  /// The hole-less kernel (Particle2013) has no lattice to insert along: its particles start at
  /// the final count (`scatter_particles()`) and only move, in 30 rounds of 5 iterations (or
  /// `max_rounds`), free particles kept inside and boundary ones on the boundary after each.
  template <typename Visitor>
  void optimize(Visitor& visitor)
  {
    using namespace Lattice_mesher_3;
    const auto start = std::chrono::steady_clock::now();
    auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const Schedule sc = schedule();
    const int levels = coarse_levels();
    const int max_rounds = p_.max_rounds >= 0 ? p_.max_rounds : levels > 0 ? sc.rounds_after_coarse : sc.rounds;
    auto remove = [&](const Lattice_mesher_3::internal::Optimization_options& o) {
      return sc.grow ? Lattice_mesher_3::internal::delete_particles(particles_, domain_, field_, lattice_, o) : std::size_t(0);
    };
    auto insert = [&](const Lattice_mesher_3::internal::Optimization_options& o) {
      if(!sc.grow) return std::size_t(0);
      // the one-ring candidates, then the gaps left along the curves
      const std::size_t inserted = Lattice_mesher_3::internal::insert_particles(particles_, domain_, field_, lattice_, o);
      return inserted + Lattice_mesher_3::internal::insert_feature_particles(particles_, domain_, field_, lattice_, o);
    };

    // what the next report counts: the time of each part of the round
    double deletion = 0., insertion = 0., optimization = 0.;
    using Lattice_mesher_3::internal::timed;
    auto report = [&](int level, int round, const Optimization_result& r, std::size_t del, std::size_t ins, bool final_round) {
      Round_report rep;
      rep.level = level; rep.round = round; rep.final_round = final_round;
      rep.particles = particles_.size(); rep.deleted = del; rep.inserted = ins;
      rep.iterations = r.iterations; rep.energy = r.energy; rep.seconds = seconds();
      rep.deletion_seconds = deletion; rep.insertion_seconds = insertion; rep.optimization_seconds = optimization;
      deletion = insertion = optimization = 0.;
      return Lattice_mesher_3::internal::continue_after(visitor, rep);
    };
    auto optimize_round = [&](const Lattice_mesher_3::internal::Optimization_options& o) {
      return timed(optimization, [&] { return Lattice_mesher_3::internal::optimize_particles_round(particles_, domain_, field_, lattice_, o); });
    };

    for(int level = levels; level >= 0; --level) {
      Lattice_mesher_3::internal::Optimization_options o = options(std::ldexp(p_.edge_length, level));
      timed(insertion, [&] {
        if(level < levels) return Lattice_mesher_3::internal::insert_particles(particles_, domain_, field_, lattice_, o);   // refinement
        if(sc.grow) initialize_particles(o.edge_length);
        else scatter_particles(o.edge_length);
        return std::size_t(0);
      });
      o.max_iterations = sc.early_iterations;
      Optimization_result r = optimize_round(o);
      if(!report(level, 0, r, 0, 0, false)) return;
      for(int round = 1; round <= max_rounds; ++round) {
        const std::size_t del = timed(deletion, [&] { return remove(o); });
        const std::size_t ins = timed(insertion, [&] { return insert(o); });
        if(sc.grow && del + ins == 0) break;
        o.max_iterations = round < 5 ? sc.early_iterations : sc.late_iterations;
        const double previous = r.energy;
        r = optimize_round(o);
        if(!report(level, round, r, del, ins, false)) return;
        // Near a boundary that cuts the lattice obliquely, a few particles may be deleted and
        // re-inserted forever; once a round no longer lowers the energy, more rounds only churn.
        if(sc.grow && round >= 4 && r.energy > previous - 1e-4 * std::abs(previous)) break;
      }
    }
    // Rounds end with an optimization, so the last insertions are never checked against the
    // deletion tests: particles squeezed in next to a corner would stay (FCC cube: 29 of them, 4
    // tetrahedra below 40 degrees). A last deletion, insertion into the holes it leaves, and
    // deletion of what still does not fit close the loop.
    Lattice_mesher_3::internal::Optimization_options o = options(p_.edge_length);
    std::size_t deleted = timed(deletion, [&] { return remove(o); });
    const std::size_t inserted = timed(insertion, [&] { return insert(o); });
    deleted += timed(deletion, [&] { return remove(o); });
    o.max_iterations = sc.final_iterations;
    o.gradient_tolerance = p_.final_gradient_tolerance;
    report(0, 0, optimize_round(o), deleted, inserted, true);
  }

  /// runs `optimize(visitor)` with a `Null_lattice_mesher_visitor`
  void optimize() { Lattice_mesher_3::Null_lattice_mesher_visitor v; optimize(v); }

  /// The start at edge length `l`: a fixed particle at every corner of the domain, grown by
  /// `grow_particles()` into the lattice, which then registers with the walls that meet there.
  /// A domain without corners grows from a free particle at a deep point (of 256 random points
  /// inside, the farthest from the boundary in the isotropic space). A deep seed is not added to
  /// the corners: its grain has a phase of its own, and where it meets theirs it leaves a grain
  /// boundary (fig8 BCC: 44 to 161 tetrahedra below 40 degrees, depending on the seed; none
  /// without it). Where the growth cannot reach (another component, a passage narrower than
  /// the lattice), a random point (uniform in the isotropic space) farther than 2 l from every
  /// particle seeds another grain. Random points come from the seed of the parameters.
  /// Replaces the current particles.
  void initialize_particles(double l)
  {
    using namespace Lattice_mesher_3;
    typedef typename MeshDomain::Geom_traits K;
    start_at_corners();
    const std::size_t n = std::size_t(std::llround(lattice_.density * isotropic_volume() / (l * l * l)));
    Uniform u(p_.seed);
    auto sample = [&](Point_3& p) { return random_inside(u, p); };
    Point_3 p;
    if(particles_.size() == 0) {
      Point_3 deep;
      double depth = -1.;
      for(int k = 0; k < 256 && sample(p); ++k) {
        const Eigen::Matrix3d b = Lattice_mesher_3::internal::isotropic_map(field_.frame(p), p);
        const double d = (b * (Lattice_mesher_3::internal::to_eigen(p) - Lattice_mesher_3::internal::to_eigen(domain_.project_on_surface(p).point))).norm();
        if(d > depth) { depth = d; deep = p; }
      }
      if(depth < 0.) cannot_place_particles();
      particles_.push_back(deep, Particle_kind::FREE);
    }
    Lattice_mesher_3::internal::Optimization_options o = options(l);
    o.max_iterations = 5;
    for(;;) {
      Lattice_mesher_3::internal::grow_particles(particles_, domain_, field_, lattice_, o);
      // the first random point that no particle covers seeds the next grain
      const std::vector<Lattice_mesher_3::internal::Vec3> x = Lattice_mesher_3::internal::to_vectors(particles_.points);
      const Lattice_mesher_3::internal::Particle_frames frames = Lattice_mesher_3::internal::compute_particle_frames<K>(x, field_, p_.threads);
      const Lattice_mesher_3::internal::Point_search_3<K> search(x);
      std::vector<std::size_t> near;
      bool seeded = false;
      for(std::size_t k = 0; k < 2 * n + 64 && !seeded && sample(p); ++k) {
        const Lattice_mesher_3::internal::Vec3 q = Lattice_mesher_3::internal::to_eigen(p);
        const Eigen::Matrix3d t = field_.frame(p), b = Lattice_mesher_3::internal::isotropic_map(t, p);
        near.clear();
        Lattice_mesher_3::internal::search_isotropic_ball(search, q, t, 2. * l, frames.max_stretch, near);
        bool covered = false;
        for(std::size_t j : near) covered = covered || (b * (q - x[j])).norm() < 2. * l;
        if(!covered) { particles_.push_back(p, Particle_kind::FREE); seeded = true; }
      }
      if(!seeded) break;
    }
    if(particles_.size() < 4) cannot_place_particles();
  }

  /// The start of Particle2013 at edge length `l`: a fixed particle at every corner of the
  /// domain, boundary particles at the density of a lattice face (area / l^2 in the isotropic
  /// space), each a random inside point projected on the surface, and free ones up to the vertex
  /// count of the lattice (`expected_vertices()`), uniform in the isotropic space. Replaces the
  /// current particles.
  void scatter_particles(double l)
  {
    using namespace Lattice_mesher_3;
    start_at_corners();
    const double n = expected_vertices(l) - double(domain_.corners().size());
    const double scale = std::cbrt(det_b_samples().mean);   // isotropic length per unit length
    const double on_surface = (std::min)(n, domain_.area() * scale * scale / (l * l));
    Uniform u(p_.seed);
    Point_3 p;
    for(double k = 0.; k < n && random_inside(u, p); ++k) {
      if(k < on_surface) particles_.push_back(domain_.project_on_surface(p).point, Particle_kind::BOUNDARY);
      else particles_.push_back(p, Particle_kind::FREE);
    }
    if(particles_.size() < 4) cannot_place_particles();
  }

  /// Connects the current particles into a tetrahedral mesh, then improves its worst tetrahedra
  /// (`flip_tetrahedra()`, `smooth_vertices()`, `collapse_edges()`), as the parameters say, and
  /// removes the slivers that lie flat on the boundary (`peel_boundary_slivers()`); last, labels
  /// the tetrahedra and boundary faces with the domain's subdomain and surface patch indices. The
  /// visitor's `stage_done()`, if it has one, follows the stages.
  template <typename Visitor>
  Mesh tetrahedralize(Visitor& visitor) const
  {
    Lattice_mesher_3::internal::Tetrahedralization_options o;
    o.threads = p_.threads;
    o.edge_length = p_.edge_length;
    const auto start = std::chrono::steady_clock::now();
    auto stage = [&](const char* name) {
      Lattice_mesher_3::internal::report_stage(visitor, name, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    };
    Mesh mesh = Lattice_mesher_3::internal::tetrahedralize_particles(particles_, domain_, field_, o, traits_);
    stage("tetrahedralization");
    Lattice_mesher_3::internal::Flip_options fo;
    fo.threads = p_.threads;
    Lattice_mesher_3::internal::set_lattice_to_keep(fo, lattice_, p_.edge_length);
    if(p_.flip) Lattice_mesher_3::internal::flip_tetrahedra(mesh, field_, fo);
    stage("flips");
    // smoothing moves vertices by a fraction of an edge: the connectivity already follows the
    // field, only the worst tetrahedra are flipped again
    Lattice_mesher_3::internal::Smoothing_options so;
    so.threads = p_.threads;
    Lattice_mesher_3::internal::set_lattice_to_keep(so, lattice_, p_.edge_length);
    // Whether the mesh is as the last flips left it but for the vertices moved since: then the
    // next flips try only the tetrahedra around these, the others would fail again (the same
    // flips as over the whole mesh: Design chapter, Speed).
    bool flipped = p_.flip;
    // returns which vertices moved
    auto smooth_and_flip = [&](const Lattice_mesher_3::internal::Smoothing_options& options) {
      const std::vector<Point_3> before = mesh.points;
      const std::size_t moves = Lattice_mesher_3::internal::smooth_vertices(mesh, domain_, field_, options);
      stage("smoothing");
      std::vector<bool> moved(before.size());
      for(std::size_t v = 0; v < before.size(); ++v) moved[v] = before[v] != mesh.points[v];
      if(moves > 0 && p_.flip) {
        Lattice_mesher_3::internal::Flip_options angle;
        angle.threads = p_.threads;
        if(flipped) angle.around = moved;
        Lattice_mesher_3::internal::flip_tetrahedra(mesh, field_, angle);
        flipped = true;
        stage("flips");
      }
      return moved;
    };
    auto any = [](const std::vector<bool>& flags) { return std::find(flags.begin(), flags.end(), true) != flags.end(); };
    // The extra vertices of lattice defects are removed once the first round has done what
    // moves could (before it, contractions take vertices the smoothing would have placed well).
    for(int round = 0; round < p_.smoothing_rounds; ++round) {
      if(round > 0) {
        Lattice_mesher_3::internal::collapse_edges(mesh, field_, Lattice_mesher_3::internal::Collapse_options());
        flipped = false;
        stage("contractions");
      }
      if(!any(smooth_and_flip(so))) break;
    }
    if(p_.smoothing_rounds > 0) {
      // Last, the tetrahedra below the floor alone, their shortfall below 41 degrees weighing 200
      // times more, which costs a little of the mean; then a round as before around the vertices
      // this moved gives most of it back (elephant 10k: 55.71 -> 55.78, Design chapter) ...
      Lattice_mesher_3::internal::Smoothing_options worst = so;
      worst.select_angle = worst.floor_angle;
      worst.worst_angle = 41.;
      worst.worst_weight = 200.;
      Lattice_mesher_3::internal::Smoothing_options around = so;
      around.around = smooth_and_flip(worst);
      smooth_and_flip(around);
      // ... and the slivers of short boundary edges, which the surface holds
      Lattice_mesher_3::internal::Collapse_options co;
      co.boundary_angle = 20.;
      Lattice_mesher_3::internal::collapse_edges(mesh, field_, co);
      stage("contractions");
    }
    // what is left below 20 degrees on the boundary is mostly slivers whose four vertices the
    // surface holds: the flat ones go
    Lattice_mesher_3::internal::peel_boundary_slivers(mesh, field_, Lattice_mesher_3::internal::Peeling_options());
    stage("peeling");
    Lattice_mesher_3::internal::label_mesh(
        mesh, Lattice_mesher_3::internal::Lattice_domain_indices<Lattice_mesher_3::internal::Int_indices, MeshDomain>{ domain_ });
    stage("labels");
    return mesh;
  }

  /// runs `tetrahedralize(visitor)` with a `Null_lattice_mesher_visitor`
  Mesh tetrahedralize() const { Lattice_mesher_3::Null_lattice_mesher_visitor v; return tetrahedralize(v); }

  /// The traits object, as given by the named parameter `geom_traits`; its predicates decide the
  /// Delaunay tetrahedralization.
  const Traits& geom_traits() const { return traits_; }

  /// the current particles
  const Particle_set& particles() const { return particles_; }
  /// the current particles, which may be changed before the next stage
  Particle_set& particles() { return particles_; }
  /// the lattice of the particles' Gaussian Hole Kernel, with the `sigma_ratio` of the parameters
  const Lattice_mesher_3::Lattice_3& lattice() const { return lattice_; }

  /// Isotropic volume of the domain, the integral of |det B| over it (Monte Carlo for a
  /// varying field, with a fixed seed).
  double isotropic_volume() const
  {
    const Lattice_mesher_3::internal::Det_b_samples s = det_b_samples();
    return domain_.volume() * s.mean;
  }

  /// Number of vertices expected at edge length `l`: the lattice density times the
  /// isotropic volume, plus the boundary and feature layers (exact for a lattice-aligned cube).
  double expected_vertices(double l) const { return expected_vertices(l, det_b_samples().mean); }

  /// The same for another field of the same domain, whose |det B| has mean `mean_det_b` over it.
  double expected_vertices(double l, double mean_det_b) const
  {
    const double scale = std::cbrt(mean_det_b);   // isotropic length per unit length
    return lattice_.density * domain_.volume() * mean_det_b / (l * l * l)
         + lattice_.area_factor * domain_.area() * scale * scale / (l * l)
         + lattice_.length_factor * domain_.curves_length() * scale / l
         + double(domain_.corners().size());
  }

  /// The edge length in use (given, or solved from the number of vertices).
  double edge_length() const { return p_.edge_length; }

  /// The edge length at which the mesh has about `n` vertices (solves expected_vertices(l) = n).
  double edge_length_for_vertices(double n) const
  {
    if(!(n >= 4.)) throw std::invalid_argument("the target number of vertices must be at least 4");
    double lo = 1e-12, hi = 1e12;
    for(int it = 0; it < 200; ++it) {
      const double mid = std::sqrt(lo * hi);
      (expected_vertices(mid) > n ? lo : hi) = mid;
    }
    return std::sqrt(lo * hi);
  }

  /// The number k of coarse levels (none for the hole-less kernel): as given, or the largest
  /// k <= 4 at which the coarse lattice still has 16 vertices and can follow the field: its
  /// stretch changes by at most 25% along a coarse cube edge (`field_variation()`). Few particles at the start form one lattice grain
  /// instead of many with mismatched offsets, which refinement then propagates to the final edge
  /// length; but a coarse lattice across which the field varies (fig8: B doubles along a cube
  /// edge at k = 2) is no lattice of the fine field, and refinement propagates its defects.
  int coarse_levels() const
  {
    if(!schedule().grow) return 0;   // no lattice to refine
    if(p_.coarse_levels >= 0) return p_.coarse_levels;
    int k = 0;
    while(k < max_coarse_levels && expected_vertices(std::ldexp(p_.edge_length, k + 1)) >= 16. &&
          field_variation(std::ldexp(p_.edge_length, k + 1)) <= 0.25) ++k;
    return k;
  }

  /// How much the field's stretch changes over an isotropic length `l`: at 256 random points p
  /// inside the domain, the largest relative change |S(p + l T(p) e_m) - S(p)| / |S(p)|
  /// (Frobenius) along the three frame axes, S = (B^T B)^1/2 the metric part of B; the 90th
  /// percentile of these. 0 for a constant field and for any cross field, whose rotations a
  /// coarse lattice follows as well as a fine one.
  double field_variation(double l) const
  {
    using Lattice_mesher_3::internal::isotropic_map;
    using Lattice_mesher_3::internal::metric_root;
    using Lattice_mesher_3::internal::to_eigen;
    const CGAL::Bbox_3 bb = domain_.bbox();
    Uniform u(0x5eed);
    std::vector<double> change;
    for(int tries = 0; tries < 100000 && change.size() < 256; ++tries) {
      const Point_3 p = Lattice_mesher_3::internal::random_point<Point_3>(bb, u);
      if(!domain_.is_inside(p)) continue;
      try {
        const Eigen::Matrix3d t = field_.frame(p), b = metric_root(isotropic_map(t, p));
        double c = 0.;
        for(int m = 0; m < 3; ++m) {
          const Eigen::Vector3d q = to_eigen(p) + l * t.col(m);
          const Point_3 pq(q[0], q[1], q[2]);
          c = (std::max)(c, (metric_root(isotropic_map(field_.frame(pq), pq)) - b).norm() / b.norm());
        }
        change.push_back(c);
      } catch(const std::exception&) {}   // a frame outside the field's domain tells nothing
    }
    if(change.empty()) return 0.;
    std::sort(change.begin(), change.end());
    return change[std::size_t(0.9 * double(change.size() - 1))];
  }

private:
  static constexpr double max_particles = 5e7;
  static constexpr int max_coarse_levels = 4;

  // How the rounds run. The lattice kernel grows its grain by deletion and insertion and stops
  // once nothing changes or the energy no longer falls; its closing round runs to the tight
  // tolerance. The hole-less kernel (Particle2013) has no lattice to insert along: it only moves
  // its fixed count, in short rounds, because repulsion alone pushes free particles out of the
  // domain within a long one; between rounds they are put back inside instead of joining the
  // boundary, and the energy goes up and down as they are, so all rounds run.
  struct Schedule
  {
    bool grow;                  // deletion, insertion, stop when settled; free particles may join the boundary
    int early_iterations, late_iterations;   // L-BFGS iterations of rounds 0-4 and of later ones
    int rounds, rounds_after_coarse;         // MaxRoundNum without and with a coarse level
    int final_iterations;       // of the closing round; 0: until the tight tolerance
  };

  Schedule schedule() const
  {
    if(lattice_.has_holes()) return Schedule{true, 13, 8, 16, 8, 0};
    return Schedule{false, 5, 5, 30, 30, 5};
  }

  // Replaces the particles by a fixed one at every corner of the domain but those closer than
  // l*/2 (isotropic) to one already taken: fixed particles that close (the corners of a coarse
  // or noisy surface, bull: 703 of 1838 vertices) only make short edges and slivers that nothing
  // can lengthen.
  void start_at_corners()
  {
    using Lattice_mesher_3::internal::to_eigen;
    particles_.clear();
    for(std::size_t c = 0; c < domain_.corners().size(); ++c) {
      const Point_3& p = domain_.corners()[c];
      const Eigen::Matrix3d b = Lattice_mesher_3::internal::isotropic_map(field_.frame(p), p);
      bool crowded = false;
      for(std::size_t k = 0; k < particles_.size() && !crowded; ++k)
        crowded = (b * (to_eigen(particles_.points[k]) - to_eigen(p))).norm() < .5 * p_.edge_length;
      if(!crowded) particles_.push_back(p, Lattice_mesher_3::Particle_kind::FIXED, int(c));
    }
  }

  [[noreturn]] static void cannot_place_particles()
  {
    throw std::invalid_argument("Lattice_particle_mesher_3: could not place particles inside the domain "
                                "(is it empty, or the edge length larger than the domain?)");
  }

  Lattice_mesher_3::internal::Optimization_options options(double l) const
  {
    Lattice_mesher_3::internal::Optimization_options o;
    o.edge_length = l;
    o.neighbor_radius = p_.neighbor_radius;
    o.gradient_tolerance = p_.gradient_tolerance;
    o.threads = p_.threads;
    o.free_particles_join_boundary = schedule().grow;
    return o;
  }

  // Uniform random numbers in [0,1) from a fixed generator, identical on every platform.
  struct Uniform
  {
    std::mt19937_64 g;
    explicit Uniform(unsigned int seed) : g(seed) {}
    double operator()() { return double(g() >> 11) * 0x1.0p-53; }
  };

  // A random point inside, uniform in the isotropic space (rejection by |det B|); false after
  // many misses.
  bool random_inside(Uniform& u, Point_3& p) const
  {
    const CGAL::Bbox_3 bb = domain_.bbox();
    const double max_det = det_b_samples().max * 1.25;
    for(int tries = 0; tries < 100000; ++tries) {
      p = Lattice_mesher_3::internal::random_point<Point_3>(bb, u);
      const double accept = u();
      if(domain_.is_inside(p) &&
         accept * max_det <= std::abs(Lattice_mesher_3::internal::isotropic_map(field_.frame(p), p).determinant())) return true;
    }
    return false;
  }

  Lattice_mesher_3::internal::Det_b_samples det_b_samples() const
  {
    if(!samples_computed_) {
      samples_ = Lattice_mesher_3::internal::sample_det_b(domain_, field_, 4096);
      samples_computed_ = true;
    }
    return samples_;
  }

  const MeshDomain& domain_;
  const FrameField& field_;
  Lattice_mesher_3::internal::Lattice_mesher_parameters p_;
  Traits traits_;
  Lattice_mesher_3::Lattice_3 lattice_;
  Particle_set particles_;
  mutable bool samples_computed_ = false;
  mutable Lattice_mesher_3::internal::Det_b_samples samples_;
};

} // namespace CGAL

#endif // CGAL_LATTICE_PARTICLE_MESHER_3_H
