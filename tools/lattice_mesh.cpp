// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// lattice-mesh: meshes a closed surface file or a built-in shape with a field-aligned BCC/FCC
// lattice, prints progress and the quality table, and writes Medit, VTU and JSON statistics.

#include "command_line.h"
#include "render_png.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lattice_particle_mesher_3.h>
#include <CGAL/lattice_mesh_3.h>
#include <CGAL/Lattice_mesher_3/Discrete_frame_field_3.h>
#include <CGAL/Lattice_mesher_3/IO/frame_field.h>
#include <CGAL/Lattice_mesher_3/IO/gmsh.h>
#include <CGAL/Lattice_mesher_3/IO/medit.h>
#include <CGAL/Lattice_mesher_3/IO/sizing_field.h>
#include <CGAL/Lattice_mesher_3/IO/vtu.h>
#include <CGAL/Lattice_mesher_3/Implicit_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/check_mesh.h>
#include <CGAL/Lattice_mesher_3/compute_cross_field_3.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>
#include <CGAL/Lattice_mesher_3/sizing_fields.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace LM = CGAL::Lattice_mesher_3;
typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Lattice_mesher_traits_3<K> Traits;
typedef Traits::Matrix_3 Matrix_3;
typedef LM::Function_frame_field_3<Traits, std::function<Matrix_3(const Point_3&)> > Field;
typedef LM::Discrete_frame_field_3<Traits> Discrete_field;
typedef LM::Polyhedral_lattice_domain_3<K> Surface_domain;
typedef LM::Implicit_lattice_domain_3<K, std::function<double(const Point_3&)> > Implicit_domain;

static const char* usage =
  "usage: lattice-mesh [INPUT | --domain cube|cube11|sphere|torus] [--lattice bcc|fcc|gaussian]\n"
  "                    [--edge-length L | --vertices N]\n"
  "                    [--field identity|rotation-y|fig8|fig9|cross|FILE [--field-data FILE]]\n"
  "                    [--field-vertices N] [--singularities OUT.vtu]\n"
  "                    [--feature-angle DEG] [--seed S] [--threads N] [--coarse-levels K]\n"
  "                    [--max-rounds R] [--no-flips] [--smoothing-rounds N] [--time-limit S]\n"
  "                    [--quiet | --verbose]\n"
  "                    [--size-field FILE] [--cells-across C] [--surface-tolerance E]\n"
  "                    [--grading G] [--min-edge-length H]\n"
  "                    -o OUT.mesh|OUT.vtu|OUT.msh [-o ...] [--stats OUT.json] [--png OUT.png]\n"
  "       lattice-mesh [INPUT | --domain ...] [--field ...] --write-field OUT.txt|OUT.mesh\n"
  "                    [--field-spacing H]\n"
  "  INPUT            closed triangle surface (OFF, OBJ, STL, PLY)\n"
  "  --domain         built-in shape: cube [0.1,1.1]^3, cube11 [1,11]^3, unit sphere,\n"
  "                   torus (axis y, radii 1 and 0.4)\n"
  "  --lattice        bcc (default), fcc, or gaussian (hole-less kernel of Particle2013)\n"
  "  --edge-length    lattice cube edge l* in the isotropic space of the field\n"
  "  --vertices       pick l* so that the mesh has about N vertices; a mesh more than 15% off N\n"
  "                   (thin parts lost, a box of whole lattice layers) is made again for\n"
  "                   N sqrt(N/M) (M its count), and the one closer to N is written\n"
  "  --field          identity (default); rotation-y (the paper's torus field Ry); fig8, fig9 (the\n"
  "                   paper's Fig. 8 and 9 fields, for the domains cube and cube11); cross (a\n"
  "                   smooth cross field of the domain, aligned with its boundary, feature curves\n"
  "                   and corners, for --lattice (the normal along a face diagonal of the frame\n"
  "                   for bcc, along an axis for fcc), computed on a background mesh; it prints\n"
  "                   its time, smoothness energy, boundary alignment and singular edges); or a\n"
  "                   discrete field, whose samples must cover the domain's bounding box (a field\n"
  "                   on a mesh is interpolated in its tetrahedra, one of samples alone is the\n"
  "                   nearest sample's):\n"
  "                   X.mesh  a Medit mesh whose vertices carry the frames of --field-data FILE\n"
  "                           (default X.sol): a Medit .sol of frames (9 values, T row by row) or\n"
  "                           of metrics M (6 values, T = M^-1/2), or a file of 9 numbers a line,\n"
  "                           the frame vectors t1 t2 t3 one after the other\n"
  "                   FILE    any other file: one sample a line, x y z t11 t12 t13 t21 ... t33\n"
  "                           (T row by row)\n"
  "  --field-vertices the background mesh's vertices for --field cross (default 4000)\n"
  "  --singularities  write the singular edges of --field cross (VTU line cells, for ParaView)\n"
  "  --write-field    write the field and exit: a discrete field (cross or a file) as its samples\n"
  "                   (OUT.txt, one sample a line) or with its mesh (OUT.mesh and OUT.sol, frames T\n"
  "                   row by row); any field sampled on a grid of spacing H (--field-spacing) over\n"
  "                   the domain's bounding box, as a text file of samples\n"
  "  --feature-angle  sharp-edge threshold in degrees (default 60)\n"
  "  --threads        OpenMP threads of every stage, the check and the measures included\n"
  "                   (default 1); the same seed and number of threads give the same mesh\n"
  "  --size-field     sizes (the largest edge) given at points: a file of lines 'x y z h', or a\n"
  "                   Medit X.mesh whose vertices carry the sizes of X.sol (one scalar a vertex,\n"
  "                   as MMG writes them); the size is the largest function below them that\n"
  "                   changes by at most G per unit length (--grading), and where the size that\n"
  "                   follows the shape is smaller, that one\n"
  "  --cells-across   the size follows the shape: where the domain is thinner than C l* (default\n"
  "                   C = 1.25; 0: l* everywhere), the edge shrinks so that C cells fit across it,\n"
  "                   and where a gap is narrower than l*, to the gap; the size changes by at most\n"
  "                   G per unit length (--grading, default 0.3) and is never below H\n"
  "                   (--min-edge-length, default l*/4); --edge-length and --vertices give l*,\n"
  "                   the largest edge\n"
  "  --surface-tolerance\n"
  "                   the boundary facets keep within E of the surface (as Mesh_3's facet_distance):\n"
  "                   where it curves or creases so much that facets of size l* would leave it by\n"
  "                   more, the size shrinks (never below H); default 0: none\n"
  "  --no-flips, --smoothing-rounds N\n"
  "                   connectivity flips and rounds of worst-element smoothing and edge\n"
  "                   contractions after the tetrahedralization (default: flips on, 2 rounds;\n"
  "                   0 keeps the particles as they are)\n"
  "  -o               the mesh, in the format of the extension: .mesh (Medit), .vtu (VTK, with\n"
  "                   theta_min, rho and kappa per tetrahedron), .msh (Gmsh 4.1); several allowed\n"
  "  --stats          the quality figures as JSON, with the seconds of every stage\n"
  "  --time-limit     stop the particle optimization after the round that ends past S seconds\n"
  "                   (from the start of the meshing) and mesh the particles as they are (and\n"
  "                   do not mesh again for a missed --vertices)\n"
  "  --quiet          print only warnings and errors\n"
  "  --verbose        print every optimization round and every stage of the mesh improvement\n"
  "                   with its time, and last the seconds by stage (default: a progress bar on a\n"
  "                   terminal, the rounds otherwise)\n"
  "  --png            a picture (PNG, 1600x800; needs VTK): the boundary, and the tetrahedra on one\n"
  "                   side of the plane z = the bounding box's centre, coloured by theta_min, those\n"
  "                   below 40 degrees red; without -o, the only output\n";

struct Options
{
  std::string input, domain, lattice = "bcc", field = "identity", field_data, write_field, stats, size_field, singularities;
  std::vector<std::string> outputs;
  std::string png;   // --png
  double edge_length = 0., vertices = 0., feature_angle = 60., field_spacing = 0., field_vertices = 4000.;
  bool has_edge_length = false, has_vertices = false;
  double cells_across = LM::internal::Shape_sizing_parameters().cells_across;
  double surface_tolerance = LM::internal::Shape_sizing_parameters().surface_tolerance;
  double grading = LM::internal::Shape_sizing_parameters().grading, min_edge_length = 0.;
  unsigned int seed = 0;
  int threads = 1, coarse_levels = -1, max_rounds = -1;
  bool quiet = false, verbose = false, flip = true;
  double time_limit = 0.;
  int smoothing_rounds = 2;
};

// The options of the size that follows the shape.
static LM::internal::Shape_sizing_parameters shape_sizing(const Options& o)
{
  LM::internal::Shape_sizing_parameters s;
  s.cells_across = o.cells_across;
  s.surface_tolerance = o.surface_tolerance;
  s.grading = o.grading;
  s.min_edge_length = o.min_edge_length;
  return s;
}

enum class Format { MEDIT, VTU, GMSH };

// The format of an output file, by its extension.
static Format output_format(const std::string& name)
{
  const std::string extension = std::filesystem::path(name).extension().string();
  if(extension == ".mesh") return Format::MEDIT;
  if(extension == ".vtu") return Format::VTU;
  if(extension == ".msh") return Format::GMSH;
  throw std::invalid_argument("-o " + name + ": unknown format '" + extension + "' (expected .mesh, .vtu or .msh)");
}

static Options parse(int argc, char** argv)
{
  Options o;
  command_line::Arguments args(argc, argv);
  for(std::string a; args.next(a);) {
    if(a == "-h" || a == "--help") { std::cout << usage; std::exit(0); }
    else if(a == "--domain") o.domain = args.value(a);
    else if(a == "--lattice") o.lattice = args.value(a);
    else if(a == "--edge-length") { o.edge_length = args.number(a); o.has_edge_length = true; }
    else if(a == "--vertices") { o.vertices = args.number(a); o.has_vertices = true; }
    else if(a == "--field") o.field = args.value(a);
    else if(a == "--field-data") o.field_data = args.value(a);
    else if(a == "--write-field") o.write_field = args.value(a);
    else if(a == "--field-spacing") o.field_spacing = args.number(a);
    else if(a == "--field-vertices") o.field_vertices = args.number(a);
    else if(a == "--singularities") o.singularities = args.value(a);
    else if(a == "--feature-angle") o.feature_angle = args.number(a);
    else if(a == "--seed") o.seed = (unsigned int)args.integer(a, 0, std::numeric_limits<unsigned int>::max());
    else if(a == "--threads") o.threads = int(args.integer(a, 1, 1024));
    else if(a == "--coarse-levels") o.coarse_levels = int(args.integer(a, -1, std::numeric_limits<int>::max()));   // the mesher checks the range
    else if(a == "--max-rounds") o.max_rounds = int(args.integer(a, -1, std::numeric_limits<int>::max()));
    else if(a == "-o" || a == "--output") o.outputs.push_back(args.value(a));
    else if(a == "--stats") o.stats = args.value(a);
    else if(a == "--png") o.png = args.value(a);
    else if(a == "--quiet") o.quiet = true;
    else if(a == "--verbose") o.verbose = true;
    else if(a == "--time-limit") o.time_limit = args.number(a);
    else if(a == "--no-flips") o.flip = false;
    else if(a == "--size-field") o.size_field = args.value(a);
    else if(a == "--cells-across") o.cells_across = args.number(a);
    else if(a == "--surface-tolerance") o.surface_tolerance = args.number(a);
    else if(a == "--grading") o.grading = args.number(a);
    else if(a == "--min-edge-length") o.min_edge_length = args.number(a);
    else if(a == "--smoothing-rounds") o.smoothing_rounds = int(args.integer(a, 0, std::numeric_limits<int>::max()));
    else command_line::Arguments::positional(a, o.input);
  }
  if(o.quiet && o.verbose) throw std::invalid_argument("--quiet and --verbose exclude each other");
  if(!(o.time_limit >= 0.) || !std::isfinite(o.time_limit))
    throw std::invalid_argument("--time-limit must be a positive number of seconds, got " + std::to_string(o.time_limit));
  if(o.input.empty() == o.domain.empty())
    throw std::invalid_argument("give either an input surface file or --domain cube|cube11|sphere|torus");
  if(!(o.field_vertices >= 4.)) throw std::invalid_argument("--field-vertices must be at least 4, got " + std::to_string(o.field_vertices));
  if(o.field != "cross" && (!o.singularities.empty() || o.field_vertices != 4000.))
    throw std::invalid_argument("--singularities and --field-vertices go with --field cross");
  if(o.write_field.empty() && o.field_spacing != 0.) throw std::invalid_argument("--field-spacing goes with --write-field");
  if(!o.write_field.empty()) {
    const bool analytic = o.field == "identity" || o.field == "rotation-y" || o.field == "fig8" || o.field == "fig9";
    if(analytic && o.field_spacing == 0.)
      throw std::invalid_argument("--write-field with the analytic field '" + o.field + "' needs --field-spacing H, the grid's spacing");
    if(o.field_spacing != 0. && !(o.field_spacing > 0.)) throw std::invalid_argument("--field-spacing must be positive");
    return o;   // no mesh: the other options do not apply
  }
  if(o.outputs.empty() && o.png.empty())
    throw std::invalid_argument("an output file is required: -o OUT.mesh (or .vtu, .msh) or --png OUT.png");
  if(!o.png.empty()) render_png::check_available();   // built with VTK
  for(const std::string& out : o.outputs) output_format(out);   // an unknown extension fails before any work
  if(o.has_edge_length == o.has_vertices)
    throw std::invalid_argument("give exactly one of --edge-length L and --vertices N");
  if(o.has_edge_length && !(o.edge_length > 0.))
    throw std::invalid_argument("--edge-length must be positive, got " + std::to_string(o.edge_length));
  if(o.has_vertices && !(o.vertices >= 4.))
    throw std::invalid_argument("--vertices must be at least 4, got " + std::to_string(o.vertices));
  LM::lattice_type_from_name(o.lattice);   // validates the name
  shape_sizing(o).check([](const char* parameter) {   // cells_across -> --cells-across
    std::string option = std::string("--") + parameter;
    std::replace(option.begin(), option.end(), '_', '-');
    return option;
  });
  return o;
}

// work(), its time added to `stage` of `times`
template <typename Work>
static auto timed(LM::Stage_times_visitor& times, const char* stage, Work&& work)
{
  double seconds = 0.;
  auto result = LM::internal::timed(seconds, work);
  times.add(stage, seconds);
  return result;
}

// The field, and its samples if it is discrete (to check that they cover the domain).
struct Field_choice
{
  Field field;
  std::shared_ptr<const Discrete_field> samples;
};

template <typename AnalyticField>
static Field_choice analytic(const AnalyticField& f)
{ return { Field([f](const Point_3& p) { return Matrix_3(f.frame(p)); }), nullptr }; }

// The cross field of the domain, with its figures; its singular edges to --singularities.
template <typename Domain>
static Field_choice cross_field(const Domain& domain, const Options& o, LM::Stage_times_visitor& times)
{
  double seconds = 0.;
  const auto field = LM::internal::timed(seconds, [&] {
    return std::make_shared<const Discrete_field>(LM::compute_cross_field_3(domain,
        CGAL::parameters::number_of_vertices(o.field_vertices).random_seed(o.seed).number_of_threads(o.threads)
                         .lattice(LM::lattice_type_from_name(o.lattice))));
  });
  times.add("field", seconds);
  const LM::Frame_field_diagnostics d = timed(times, "field", [&] {
    return LM::compute_frame_field_diagnostics(*field, CGAL::parameters::lattice(LM::lattice_type_from_name(o.lattice)));
  });
  if(!o.quiet)
    std::printf("lattice-mesh: cross field: %zu vertices, %zu tetrahedra, %.2f s; smoothness energy %.6g; boundary alignment "
                "%.3f degrees mean, %.3f max; %zu singular edges\n", field->number_of_samples(), field->mesh().tets.size(), seconds,
                d.energy, d.mean_boundary_alignment, d.max_boundary_alignment, d.singular_edges.size());
  if(!o.singularities.empty()) {
    std::ofstream os(o.singularities);
    if(!os) throw std::runtime_error("cannot write '" + o.singularities + "'");
    LM::write_vtu_segments(os, field->points(), d.singular_edges);
  }
  return { Field([field](const Point_3& p) { return field->frame(p); }), field };
}

static Field_choice make_field(const Options& o)
{
  const std::string& name = o.field;
  if(name == "cross") return analytic(LM::Constant_frame_field_3<Traits>());   // replaced in run(), with the domain's
  if(name == "identity") return analytic(LM::Constant_frame_field_3<Traits>());
  if(name == "rotation-y") return analytic(LM::Rotation_y_frame_field_3<Traits>());
  if(name == "fig8") return analytic(LM::Planar_layer_frame_field_3<Traits>());
  if(name == "fig9") return analytic(LM::Cylindrical_layer_frame_field_3<Traits>());
  if(!std::filesystem::exists(name))
    throw std::invalid_argument("--field " + name + ": " + (name.find_first_of("/.") != std::string::npos
      ? std::string("the field file does not exist") : std::string("unknown field"))
      + " (expected identity, rotation-y, fig8, fig9, cross or a field file)");
  const bool medit = std::filesystem::path(name).extension() == ".mesh";
  if(!medit && !o.field_data.empty())
    throw std::invalid_argument("--field-data goes with a Medit field mesh (--field X.mesh), not with '" + name + "'");
  const std::string data = o.field_data.empty() ? std::filesystem::path(name).replace_extension(".sol").string() : o.field_data;
  const auto samples = std::make_shared<const Discrete_field>(medit ? LM::read_frame_field_from_medit<Traits>(name, data)
                                                                    : LM::read_frame_field_samples<Traits>(name));
  if(!o.quiet)
    std::printf("lattice-mesh: field '%s': %zu samples, typical spacing %.6g\n", (medit ? name + "' with '" + data : name).c_str(),
                samples->number_of_samples(), samples->typical_spacing());
  return { Field([samples](const Point_3& p) { return samples->frame(p); }), samples };
}

// What the program shows while it meshes: nothing (--quiet), a bar rewritten in place on a
// terminal, or a line per round (and per improvement stage with --verbose). Asks the mesher to
// stop the optimization once the time limit has passed.
class Progress
{
public:
  Progress(const Options& o, int levels, LM::Stage_times_visitor& times)
    : bar_(!o.quiet && !o.verbose && isatty(fileno(stdout))), lines_(!o.quiet && !bar_), verbose_(o.verbose),
      levels_(levels), time_limit_(o.time_limit), times_(times) {}

  bool round_done(const LM::Round_report& r)
  {
    times_.round_done(r);
    if(lines_)
      std::printf("  %-7s level %d round %2d: %8zu particles, energy %12.4f, -%zu +%zu, %3d iterations, %7.2f s\n",
                  r.final_round ? "[final]" : "", r.level, r.round, r.particles, r.energy, r.deleted, r.inserted,
                  r.iterations, r.seconds);
    if(bar_) {
      // the levels count alike; within one, a round is an eighth of what is left of it
      const double level_done = r.final_round ? 1. : 1. - std::pow(7. / 8., r.round + 1);
      const double done = r.final_round ? 1. : (double(levels_ - r.level) + level_done) / double(levels_ + 1);
      const int width = 30, filled = int(done * width + .5);
      std::printf("\r  [%s%s] %3.0f%%  level %d round %2d  %zu particles  %.1f s ", std::string(std::size_t(filled), '#').c_str(),
                  std::string(std::size_t(width - filled), '.').c_str(), 100. * done, r.level, r.round, r.particles, r.seconds);
      if(r.final_round) std::printf("\n");
    }
    std::fflush(stdout);
    if(time_limit_ > 0. && r.seconds > time_limit_ && !r.final_round) {
      if(bar_) std::printf("\n");
      std::fprintf(stderr, "lattice-mesh: warning: --time-limit %g s reached at level %d round %d (%.2f s): the mesh is made of "
                   "the particles as they are\n", time_limit_, r.level, r.round, r.seconds);
      return false;
    }
    return true;
  }

  void stage_done(const char* stage, double seconds)
  {
    times_.stage_done(stage, seconds);
    if(verbose_) std::printf("  [mesh] %-18s done at %7.2f s\n", stage, seconds);
  }

private:
  bool bar_, lines_, verbose_;
  int levels_;
  double time_limit_;
  LM::Stage_times_visitor& times_;
};

// The field scaled by the size that follows the shape, and p's edge length (the largest edge).
template <typename Domain>
static Field shape_sized_field(const Domain& domain, const Field& field, LM::internal::Lattice_mesher_parameters& p, const Options& o,
                               LM::Stage_times_visitor& times, LM::internal::Shape_sizing_report& report)
{
  const auto start = std::chrono::steady_clock::now();
  const LM::internal::Shape_sizing_parameters s = shape_sizing(o);
  // the user's sizes: the envelope of the file's samples
  std::function<double(const Point_3&)> user = LM::internal::Unbounded_size();
  if(!o.size_field.empty()) {
    const LM::Graded_sizing_field_3<K> given(LM::read_size_samples<K>(o.size_field), o.grading, HUGE_VAL);
    if(!o.quiet)
      std::printf("lattice-mesh: size field '%s': %zu samples, smallest size %.6g\n", o.size_field.c_str(),
                  given.number_of_samples(), given.min_size());
    user = given;
  }
  const auto sized = LM::internal::sized_field<Traits>(domain, field, user, p, s, &report);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  times.add("sizing", seconds);
  if(!o.quiet && (o.cells_across > 0. || report.surface_tolerance > 0.))
    std::printf("lattice-mesh: shape sizing: %zu samples (%.3g cells across, surface tolerance %.4g) at l* %.4g, smallest size %.4g, %.2f s\n",
                report.samples, report.cells_across, report.surface_tolerance, p.edge_length, report.smallest_size, seconds);
  return Field([sized](const Point_3& x) { return sized.frame(x); });
}

// A boundary farther than 1.5 times the local size from the surface (the limit of the manual's
// sweep) is a part lost or a bulge, which the quality table alone would leave unnoticed: where,
// and why when a part is lost where the size is the smallest the sizing gives (it is thinner).
static void warn_if_part_lost(const LM::Boundary_distances_3<Point_3>& d, double size, double floor)
{
  if(!(d.over_size > 1.5)) return;
  const Point_3& w = d.worst_sample;
  if(d.worst_on_surface)
    std::fprintf(stderr, "lattice-mesh: warning: the mesh lacks a part of the domain: the surface at (%.6g, %.6g, %.6g) is %.4g "
                 "from its boundary, %.3g times the size there (%.4g)", w.x(), w.y(), w.z(), d.over_size * size, d.over_size, size);
  else
    std::fprintf(stderr, "lattice-mesh: warning: the mesh's boundary at (%.6g, %.6g, %.6g) is %.4g from the surface, %.3g times "
                 "the size there (%.4g)", w.x(), w.y(), w.z(), d.over_size * size, d.over_size, size);
  if(d.worst_on_surface && size <= 1.001 * floor)
    std::fprintf(stderr, ", the smallest size: a part thinner than that is lost there; a smaller --min-edge-length (default "
                 "l*/4), with more vertices, keeps it");
  std::fprintf(stderr, "\n");
}

// Meshes `domain`; `times` holds the stages already run (reading the domain and the field).
template <typename Domain>
static int run(const Domain& domain, const Field_choice& given, const Options& o, LM::Stage_times_visitor times)
{
  typedef CGAL::Lattice_particle_mesher_3<Traits, Domain, Field> Mesher;
  const Field_choice choice = o.field == "cross" ? cross_field(domain, o, times) : given;
  if(choice.samples && o.field != "cross") {
    try { choice.samples->check_coverage(domain.bbox()); }
    catch(const std::invalid_argument& e) { throw std::invalid_argument("--field " + o.field + ": " + e.what()); }
  }
  if(!o.write_field.empty()) {
    const std::filesystem::path out(o.write_field);
    if(o.field_spacing > 0.) LM::write_frame_field_samples(o.write_field, choice.field, domain.bbox(), o.field_spacing);
    else if(out.extension() == ".mesh") LM::write_frame_field_to_medit(o.write_field, std::filesystem::path(out).replace_extension(".sol").string(), *choice.samples);
    else LM::write_frame_field_samples(o.write_field, *choice.samples);
    if(!o.quiet) std::printf("lattice-mesh: wrote the field '%s' to '%s'\n", o.field.c_str(), o.write_field.c_str());
    return 0;
  }
  LM::internal::Lattice_mesher_parameters p;
  p.lattice = LM::make_lattice(LM::lattice_type_from_name(o.lattice));
  p.seed = o.seed;
  p.threads = o.threads;
  p.coarse_levels = o.coarse_levels;
  p.max_rounds = o.max_rounds;
  p.flip = o.flip;
  p.smoothing_rounds = o.smoothing_rounds;
  p.edge_length = o.edge_length;
  p.number_of_vertices = o.vertices;
  // one run for a count (0: the edge length given), and the runs' seconds
  // floor: the smallest size where the size follows the thickness (0: it does not), below
  // which thinner parts are lost
  struct Meshed { LM::Tetrahedral_mesh_3<Point_3> mesh; Field field; double edge_length; LM::Lattice_3 lattice; double floor; };
  double optimize_seconds = 0., mesh_seconds = 0.;
  auto mesh_for = [&](double count) {
    LM::internal::Lattice_mesher_parameters q = p;
    q.number_of_vertices = count;
    if(!o.quiet && count != p.number_of_vertices)
      std::printf("lattice-mesh: the mesh is more than 15%% off %.0f vertices: meshing again for about %.0f\n", p.number_of_vertices, count);
    LM::internal::Shape_sizing_report sizing;
    const Field field = shape_sized_field(domain, choice.field, q, o, times, sizing);
    Mesher mesher(domain, field, q);
    if(!o.quiet)
      std::printf("lattice-mesh: %s lattice, l* = %.6g, about %.0f vertices expected, %d coarse level(s), %d thread(s)\n",
                  o.lattice.c_str(), mesher.edge_length(), mesher.expected_vertices(mesher.edge_length()), mesher.coarse_levels(), o.threads);
    const auto t0 = std::chrono::steady_clock::now();
    Progress progress(o, mesher.coarse_levels(), times);
    mesher.optimize(progress);
    const auto t1 = std::chrono::steady_clock::now();
    Meshed result{ mesher.tetrahedralize(progress), field, mesher.edge_length(), mesher.lattice(),
                   sizing.cells_across > 0. ? sizing.floor : 0. };
    optimize_seconds += std::chrono::duration<double>(t1 - t0).count();
    mesh_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    return result;
  };
  // a time limit is for one run
  const Meshed meshed = o.time_limit > 0. ? mesh_for(p.number_of_vertices)
                      : LM::internal::run_for_vertex_count(p.number_of_vertices, mesh_for, [](const Meshed& m) { return m.mesh.points.size(); });
  const LM::Tetrahedral_mesh_3<Point_3>& mesh = meshed.mesh;
  const Field& field = meshed.field;

  const auto checked = std::chrono::steady_clock::now();
  const LM::Mesh_validity_report validity = LM::check_tetrahedral_mesh(mesh);
  LM::Mesh_quality_3 q = LM::compute_mesh_quality(mesh, field, CGAL::parameters::lattice(meshed.lattice).number_of_threads(o.threads));
  // the local size: the longest edge of the lattice cube there, which the sizing shrinks
  auto local_size = [&](const Point_3& x) { return meshed.edge_length * field.frame(x).colwise().norm().maxCoeff(); };
  const LM::Boundary_distances_3<Point_3> distances = LM::boundary_distances(mesh, domain, 0.25 * meshed.edge_length,
      local_size, CGAL::parameters::number_of_threads(o.threads));
  times.add("check and quality", std::chrono::duration<double>(std::chrono::steady_clock::now() - checked).count());
  warn_if_part_lost(distances, local_size(distances.worst_sample), meshed.floor);
  q.hausdorff = distances.hausdorff;
  q.hausdorff_over_size = distances.over_size;
  q.edge_length = meshed.edge_length;
  q.seconds.optimize = optimize_seconds;
  q.seconds.mesh = mesh_seconds;
  q.seconds.total = q.seconds.optimize + q.seconds.mesh;
  if(!o.quiet) LM::print_quality_table(std::cout, q);

  // the quality in the isotropic space, per tetrahedron (.vtu and --png), computed once
  std::vector<LM::Tetrahedron_quality_3> tq;
  auto tetrahedra_quality = [&]() -> const std::vector<LM::Tetrahedron_quality_3>& {
    if(tq.size() != mesh.tets.size()) tq = LM::compute_tetrahedra_quality(mesh, field, CGAL::parameters::number_of_threads(o.threads));
    return tq;
  };
  auto open = [](const std::string& name) {
    std::ofstream os(name);
    if(!os) throw std::runtime_error("cannot write '" + name + "'");
    return os;
  };
  const auto written = std::chrono::steady_clock::now();
  for(const std::string& out : o.outputs) {
    std::ofstream os = open(out);
    switch(output_format(out)) {
    case Format::MEDIT: LM::write_medit(os, mesh); break;
    case Format::GMSH: LM::write_gmsh(os, mesh); break;
    case Format::VTU: {
      std::map<std::string, std::vector<double> > cells;
      for(const LM::Tetrahedron_quality_3& t : tetrahedra_quality()) {
        cells["theta_min"].push_back(t.theta_min);
        cells["rho"].push_back(t.rho);
        cells["kappa"].push_back(t.kappa);
      }
      LM::write_vtu(os, mesh, cells);
      break;
    }
    }
  }
  if(!o.png.empty()) {   // drawn by VTK in render_png.cpp
    std::vector<std::array<double, 3> > points;
    for(const Point_3& p : mesh.points) points.push_back({ p.x(), p.y(), p.z() });
    std::vector<double> theta_min;
    for(const LM::Tetrahedron_quality_3& t : tetrahedra_quality()) theta_min.push_back(t.theta_min);
    render_png::write_png(o.png, points, mesh.tets, theta_min);
  }
  times.add("output", std::chrono::duration<double>(std::chrono::steady_clock::now() - written).count());
  q.seconds.stages = times.stages();
  if(!o.stats.empty()) { std::ofstream os = open(o.stats); LM::write_quality_json(os, q); }
  if(o.verbose) {
    std::printf("  seconds by stage (%.2f in all)\n", times.total());
    for(const auto& s : times.stages()) std::printf("    %-24s %8.3f\n", s.first.c_str(), s.second);
  }
  if(!validity.valid()) {
    std::cerr << "lattice-mesh: error: the output mesh is not valid:\n" << validity.message << "\n";
    return 2;
  }
  return 0;
}

int main(int argc, char** argv)
{
  try {
    const Options o = parse(argc, argv);
    // every output can be written, before the work
    std::vector<std::string> files = o.outputs;
    for(const std::string& f : { o.stats, o.write_field, o.png, o.singularities }) if(!f.empty()) files.push_back(f);
    for(const std::string& f : files)
      if(!std::ofstream(f, std::ios::app)) throw std::runtime_error("cannot write '" + f + "'");
    LM::Stage_times_visitor times;
    const Field_choice field = timed(times, "field", [&] { return make_field(o); });
    if(!o.input.empty()) {
      const Surface_domain domain = timed(times, "domain", [&] { return LM::read_polyhedral_lattice_domain_3<K>(o.input, o.feature_angle); });
      for(const std::string& w : domain.warnings()) std::cerr << "lattice-mesh: warning: '" << o.input << "': " << w << "\n";
      return run(domain, field, o, times);
    }
    if(o.domain == "cube")
      return run(Surface_domain(LM::make_cube_surface_3<K>(0.1, 1.1), o.feature_angle), field, o, times);
    if(o.domain == "cube11")
      return run(Surface_domain(LM::make_cube_surface_3<K>(1., 11.), o.feature_angle), field, o, times);
    if(o.domain == "sphere")
      return run(Implicit_domain(LM::Implicit_sphere_3<K>{Point_3(0., 0., 0.), 1.}, CGAL::Bbox_3(-1, -1, -1, 1, 1, 1)), field, o, times);
    if(o.domain == "torus")
      return run(Implicit_domain(LM::Implicit_torus_3<K>{1., .4}, CGAL::Bbox_3(-1.4, -.4, -1.4, 1.4, .4, 1.4)), field, o, times);
    throw std::invalid_argument("unknown domain '" + o.domain + "' (expected cube, cube11, sphere or torus)");
  } catch(const std::exception& e) {
    std::cerr << "lattice-mesh: error: " << e.what() << "\n" << (argc <= 1 ? usage : "");
    return 1;
  }
}
