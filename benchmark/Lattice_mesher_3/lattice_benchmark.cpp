// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// lattice-benchmark: meshes one closed surface with one method (ours or a baseline) at about N
// vertices and measures the result with the package's quality function, plus wall time and
// peak memory. One method per run of the program: the peak RSS is that method's. Gmsh runs as its
// command-line program (Debian ships no libgmsh-dev headers), in a process of its own.

#include "../../tools/command_line.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/lattice_mesh_3.h>
#include <CGAL/Lattice_mesher_3/IO/medit.h>
#include <CGAL/Lattice_mesher_3/Polyhedral_lattice_domain_3.h>
#include <CGAL/Lattice_mesher_3/check_mesh.h>
#include <CGAL/Lattice_mesher_3/frame_fields.h>
#include <CGAL/Lattice_mesher_3/mesh_quality.h>

#include <CGAL/Handle_hash_function.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/make_mesh_3.h>

#ifdef CGAL_LATTICE_MESHER_3_USE_TETGEN
#include <tetgen.h>
#endif

#include <fcntl.h>
#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace LM = CGAL::Lattice_mesher_3;
typedef CGAL::Epick K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Surface;
typedef LM::Tetrahedral_mesh_3<Point_3> Tet_mesh;
typedef LM::Polyhedral_lattice_domain_3<K> Lattice_domain;
typedef LM::Constant_frame_field_3<CGAL::Lattice_mesher_traits_3<K> > Identity_field;

typedef CGAL::Polyhedral_mesh_domain_with_features_3<K, Surface> Mesh_domain;
typedef CGAL::Mesh_triangulation_3<Mesh_domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr, Mesh_domain::Corner_index, Mesh_domain::Curve_index> C3t3;
typedef CGAL::Mesh_criteria_3<Tr> Mesh_criteria;

static const double feature_angle = 60.;   // degrees, for ours and for Mesh_3
static const double tolerance = .05;       // on the vertex count
static const int max_attempts = 6;

static const char* usage =
  "usage: lattice-benchmark (INPUT | --domain cube) --method METHOD --vertices N [--threads T]\n"
  "                         [--seed S] [--no-tuning] [-o OUT.mesh] [--stats OUT.json]\n"
  "                         [--histograms OUT.csv]\n"
  "  INPUT         closed triangle surface (OFF, OBJ, STL, PLY); --domain cube is [0.1,1.1]^3\n"
  "  --method      bcc, fcc: ours; gaussian: Particle2013 (hole-less kernel, fixed count);\n"
  "                cvt, odt: CGAL Mesh_3 with Lloyd or ODT, no perturbation, no exudation;\n"
  "                cvt-pe, odt-pe: the same followed by CGAL's default perturbation and exudation;\n"
  "                tetgen: TetGen -pq with a maximum volume;\n"
  "                gmsh: Gmsh (the gmsh program, or $GMSH) remeshing the surface at one size with\n"
  "                its 60-degree features, then HXT with its optimizer (Mesh.Optimize 1), 1 thread\n"
  "  --vertices    the size parameter of the method (ours: the requested count, Mesh_3: one cell,\n"
  "                facet and edge size, TetGen: the maximum volume, Gmsh: Mesh.MeshSizeMin and\n"
  "                Max) is tuned by secant steps on log N until the mesh has N vertices within 5%\n"
  "                (at most 6 attempts, each in a child process; the last one reruns the\n"
  "                closest); only the final run is timed (Gmsh: its 1D, 2D and 3D meshing)\n"
  "  --no-tuning   one run with the method's own estimate of the size for N\n"
  "  --threads     OpenMP threads of ours (Mesh_3, TetGen and Gmsh run sequentially)\n"
  "  --seed        random start of ours (the baselines are deterministic)\n"
  "  --stats       quality (measured with the identity field; epsilon against the BCC one-ring\n"
  "                for every method), seconds, peak_rss_mb and the tuning attempts, as JSON\n"
  "  --histograms  dihedral angles, rho, kappa and epsilon as CSV histograms\n";

struct Options
{
  std::string input, domain, method, out, stats, histograms;
  double vertices = 0.;
  int threads = 1;
  unsigned int seed = 0;
  bool tune = true;
};

enum class Family { LATTICE, MESH_3, TETGEN, GMSH };

struct Method
{
  std::string name;
  Family family;
  LM::Lattice_type lattice;   // LATTICE
  bool lloyd;                 // MESH_3: Lloyd (CVT), else ODT
  bool perturb_and_exude;     // MESH_3
};

static Method method_from_name(const std::string& name)
{
  typedef LM::Lattice_type L;
  static const std::array<Method, 9> methods = { {
    { "bcc", Family::LATTICE, L::BCC, false, false },
    { "fcc", Family::LATTICE, L::FCC, false, false },
    { "gaussian", Family::LATTICE, L::GAUSSIAN, false, false },
    { "cvt", Family::MESH_3, L::BCC, true, false },
    { "odt", Family::MESH_3, L::BCC, false, false },
    { "cvt-pe", Family::MESH_3, L::BCC, true, true },
    { "odt-pe", Family::MESH_3, L::BCC, false, true },
    { "tetgen", Family::TETGEN, L::BCC, false, false },
    { "gmsh", Family::GMSH, L::BCC, false, false } } };
  for(const Method& m : methods) {
    if(m.name != name) continue;
#ifndef CGAL_LATTICE_MESHER_3_USE_TETGEN
    if(m.family == Family::TETGEN)
      throw std::invalid_argument("this build has no TetGen: configure with -DLATTICE_MESHER_3_WITH_TETGEN=ON");
#endif
    return m;
  }
  throw std::invalid_argument("unknown method '" + name + "' (expected bcc, fcc, gaussian, cvt, odt, "
                              "cvt-pe, odt-pe, tetgen or gmsh)");
}

// The parameter tuned to hit the vertex count, and the exponent of the count in it.
struct Size_parameter
{
  const char* name;
  double exponent;
};

static Size_parameter size_parameter(Family f)
{
  switch(f) {
    case Family::LATTICE: return { "requested_vertices", 1. };
    case Family::MESH_3: return { "cell_size", -3. };
    case Family::TETGEN: return { "max_volume", -1. };
    case Family::GMSH: return { "mesh_size", -3. };
  }
  throw std::logic_error("size_parameter(): unknown family");
}

// The validated input that every method meshes.
struct Input
{
  std::string name;
  Surface surface;   // closed, not self-intersecting, triangulated, outward oriented
  double volume;
};

// First guesses, which the tuning corrects: on fandisk at a few thousand vertices, Mesh_3 gives
// about 2 V / s^3 vertices for the size s (as BCC for its lattice edge), TetGen about V / a for
// the volume bound a, Gmsh about V / h^3 for the mesh size h.
static double initial_size(Family f, const Input& in, double n)
{
  switch(f) {
    case Family::LATTICE: return n;
    case Family::MESH_3: return std::cbrt(2. * in.volume / n);
    case Family::TETGEN: return in.volume / n;
    case Family::GMSH: return std::cbrt(in.volume / n);
  }
  throw std::logic_error("initial_size(): unknown family");
}

struct Run
{
  Tet_mesh mesh;
  double seconds = 0.;       // wall time of the meshing call
  double peak_rss_mb = 0.;   // of the process, when the meshing call returned
  std::string details;       // more JSON keys ("key": value, ...), or empty
  std::vector<std::pair<std::string, double> > stages;   // ours: where the time went
};

static double peak_rss_mb()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.;   // Linux: kilobytes
}

// Times `mesher` (a call returning the method's own mesh structure) into `run`.
template <typename Mesher>
static auto timed(Run& run, const Mesher& mesher)
{
  const auto start = std::chrono::steady_clock::now();
  auto result = mesher();
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.peak_rss_mb = peak_rss_mb();
  return result;
}

template <typename Writer>
static void write_file(const std::string& name, const Writer& writer)
{
  if(name.empty()) return;
  std::ofstream os(name);
  if(!os) throw std::runtime_error("cannot write '" + name + "'");
  writer(os);
  if(!os) throw std::runtime_error("writing '" + name + "' failed");
}

// Every method's output in our arrays, the same way: points no tetrahedron uses are dropped, every
// tetrahedron is made positively oriented, and the boundary faces (in one tetrahedron) are
// oriented outward.
static Tet_mesh make_tetrahedral_mesh(const std::vector<Point_3>& points, std::vector<std::array<int, 4> > tets)
{
  Tet_mesh mesh;
  std::vector<int> index(points.size(), -1);
  for(std::array<int, 4>& t : tets) {
    for(int& v : t) {
      if(index[v] < 0) {
        index[v] = int(mesh.points.size());
        mesh.points.push_back(points[v]);
      }
      v = index[v];
    }
    if(CGAL::orientation(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]], mesh.points[t[3]]) == CGAL::NEGATIVE)
      std::swap(t[0], t[1]);
  }
  mesh.tets = std::move(tets);

  std::vector<std::pair<std::array<int, 3>, std::array<int, 3> > > faces;   // (sorted, oriented)
  faces.reserve(4 * mesh.tets.size());
  for(const std::array<int, 4>& t : mesh.tets)
    for(const std::array<int, 3>& f : LM::internal::outward_faces(t))
      faces.emplace_back(LM::internal::sorted_triangle(f), f);
  std::sort(faces.begin(), faces.end());
  for(std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while(j < faces.size() && faces[j].first == faces[i].first) ++j;
    if(j == i + 1) mesh.boundary_faces.push_back(faces[i].second);
    i = j;
  }
  return mesh;
}

static Run mesh_with_lattice(const Method& m, const Input& in, double requested_vertices, const Options& o)
{
  const Lattice_domain domain(in.surface, feature_angle);
  Run run;
  LM::Stage_times_visitor times;
  const Tet_mesh mesh = timed(run, [&] {
    return CGAL::lattice_mesh_3(domain, Identity_field(),
                                CGAL::parameters::number_of_vertices(requested_vertices)
                                  .lattice(m.lattice).number_of_threads(o.threads).random_seed(o.seed).visitor(std::ref(times)));
  });
  run.mesh = make_tetrahedral_mesh(mesh.points, mesh.tets);
  run.stages = times.stages();
  return run;
}

// Mesh_3 as its manual shows it, on a domain with the same 60-degree features as ours; one size s
// for cells, facets and feature edges. `refine_only` skips the optimizers, which move vertices but
// neither insert nor remove any: the tuning counts on refinement alone.
static Run mesh_with_mesh_3(const Method& m, const Input& in, double s, bool refine_only)
{
  namespace P = CGAL::parameters;
  Mesh_domain domain(in.surface);
  domain.detect_features(feature_angle);
  const Mesh_criteria criteria(P::edge_size = s, P::facet_angle = 25, P::facet_size = s,
                               P::facet_distance = s / 10, P::cell_radius_edge_ratio = 3, P::cell_size = s);
  const bool optimize = !refine_only;
  const auto lloyd = optimize && m.lloyd ? P::lloyd() : P::no_lloyd();
  const auto odt = optimize && !m.lloyd ? P::odt() : P::no_odt();
  const auto perturb = optimize && m.perturb_and_exude ? P::perturb() : P::no_perturb();
  const auto exude = optimize && m.perturb_and_exude ? P::exude() : P::no_exude();
  Run run;
  const C3t3 c3t3 = timed(run, [&] {
    return CGAL::make_mesh_3<C3t3>(domain, criteria, P::features(domain), lloyd, odt, perturb, exude);
  });

  // Mesh_3's points are weighted: convert them
  const Tr& tr = c3t3.triangulation();
  const auto point = tr.geom_traits().construct_point_3_object();
  std::unordered_map<Tr::Vertex_handle, int, CGAL::Handle_hash_function> index;
  std::vector<Point_3> points;
  std::vector<std::array<int, 4> > tets;
  for(C3t3::Cells_in_complex_iterator c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<int, 4> t;
    for(int i = 0; i < 4; ++i) {
      const auto inserted = index.emplace(c->vertex(i), int(points.size()));
      if(inserted.second) points.push_back(point(tr.point(c, i)));
      t[i] = inserted.first->second;
    }
    tets.push_back(t);
  }
  run.mesh = make_tetrahedral_mesh(points, std::move(tets));
  return run;
}

#ifdef CGAL_LATTICE_MESHER_3_USE_TETGEN
static Run mesh_with_tetgen(const Input& in, double max_volume)
{
  tetgenio input, output;   // their destructors free the arrays below (new[])
  input.firstnumber = 0;
  input.numberofpoints = int(in.surface.number_of_vertices());
  input.pointlist = new REAL[3 * input.numberofpoints];
  for(Surface::Vertex_index v : in.surface.vertices())
    for(int i = 0; i < 3; ++i) input.pointlist[3 * v.idx() + i] = in.surface.point(v)[i];
  input.numberoffacets = int(in.surface.number_of_faces());
  input.facetlist = new tetgenio::facet[input.numberoffacets];
  for(Surface::Face_index f : in.surface.faces()) {
    tetgenio::facet& facet = input.facetlist[f.idx()];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    int i = 0;
    for(Surface::Vertex_index v : CGAL::vertices_around_face(in.surface.halfedge(f), in.surface))
      facet.polygonlist[0].vertexlist[i++] = int(v.idx());
  }
  // p: the surface as a PLC, q: quality (radius-edge 2), z: 0-based, Q: quiet, a: the volume bound
  std::ostringstream switches;
  switches << "pqzQa" << std::fixed << std::setprecision(15) << max_volume;
  std::string s = switches.str();

  Run run;
  const int number_of_tets = timed(run, [&] {
    try {
      tetrahedralize(&s[0], &input, &output);
    } catch(int code) {   // TetGen's library build reports errors by throwing its exit code
      throw std::runtime_error("TetGen failed with error code " + std::to_string(code));
    }
    return output.numberoftetrahedra;
  });

  std::vector<Point_3> points;
  for(int i = 0; i < output.numberofpoints; ++i)
    points.emplace_back(output.pointlist[3 * i], output.pointlist[3 * i + 1], output.pointlist[3 * i + 2]);
  std::vector<std::array<int, 4> > tets(number_of_tets);
  for(int t = 0; t < number_of_tets; ++t)
    for(int i = 0; i < 4; ++i) tets[t][i] = output.tetrahedronlist[output.numberofcorners * t + i] - output.firstnumber;
  return Run{ make_tetrahedral_mesh(points, std::move(tets)), run.seconds, run.peak_rss_mb };
}
#endif

// Gmsh as its user meshes a triangulated surface with it: the surface merged as a discrete mesh,
// ClassifySurfaces with the same 60-degree features as ours (curves and parametrizable patches)
// and CreateGeometry, so that Gmsh remeshes curves and surfaces at the size h (Frontal-Delaunay)
// before HXT fills the volume; Mesh.Optimize 1 is HXT's own optimizer (smoothing, edge removal,
// growing sphere cavities on the tetrahedra of quality below Mesh.OptimizeThreshold, 0.3 by
// default: Gmsh 4.8 runs its other optimizers after HXT only when asked in the script). One size
// everywhere (Mesh.MeshSizeMin = Mesh.MeshSizeMax = h, no size from curvature), one thread (-nt 1).
// `reparam_max_triangles` > 0 splits the patches further, to at most that many triangles (Gmsh's
// default is 250000: patches are split only where their topology asks for it).
static std::string gmsh_script(double h, int reparam_max_triangles)
{
  std::ostringstream geo;
  geo << std::setprecision(17) << "Merge \"surface.msh\";\n";
  if(reparam_max_triangles > 0) geo << "Mesh.ReparamMaxTriangles = " << reparam_max_triangles << ";\n";
  geo << "ClassifySurfaces{" << feature_angle << " * Pi / 180, 1, 1, Pi};\n"
      << "CreateGeometry;\n"
      << "Surface Loop(1) = Surface{:};\n"
      << "Volume(1) = {1};\n"
      << "Mesh.Algorithm3D = 10;\n"
      << "Mesh.Optimize = 1;\n"
      << "Mesh.MeshSizeFromCurvature = 0;\n"
      << "Mesh.MeshSizeMin = " << h << ";\n"
      << "Mesh.MeshSizeMax = " << h << ";\n";
  return geo.str();
}

// The surface as a Gmsh 2.2 mesh of triangles, with the coordinates as they are (STL would round
// them to floats).
static void write_gmsh_surface(std::ostream& os, const Surface& surface)
{
  os << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << surface.number_of_vertices() << "\n"
     << std::setprecision(17);
  for(Surface::Vertex_index v : surface.vertices()) {
    const Point_3& p = surface.point(v);
    os << v.idx() + 1 << " " << p.x() << " " << p.y() << " " << p.z() << "\n";
  }
  os << "$EndNodes\n$Elements\n" << surface.number_of_faces() << "\n";
  for(Surface::Face_index f : surface.faces()) {
    os << f.idx() + 1 << " 2 2 1 1";   // triangle, tags: physical 1, elementary 1
    for(Surface::Vertex_index v : CGAL::vertices_around_face(surface.halfedge(f), surface)) os << " " << v.idx() + 1;
    os << "\n";
  }
  os << "$EndElements\n";
}

// A directory of its own for Gmsh's files, removed with everything in it.
struct Temporary_directory
{
  std::filesystem::path path;
  Temporary_directory()
  {
    std::string name = (std::filesystem::temp_directory_path() / "lattice-benchmark-gmsh-XXXXXX").string();
    if(!mkdtemp(&name[0])) throw std::runtime_error(std::string("mkdtemp() failed: ") + std::strerror(errno));
    path = name;
  }
  ~Temporary_directory()
  {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  Temporary_directory(const Temporary_directory&) = delete;
  Temporary_directory& operator=(const Temporary_directory&) = delete;
};

// Runs `argv` in `directory` with its output to `log`; returns its exit status and resource usage.
static int run_program(const std::vector<std::string>& argv, const std::filesystem::path& directory,
                       const std::filesystem::path& log, rusage& usage)
{
  std::vector<char*> args;
  for(const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::cout.flush();
  const pid_t pid = fork();
  if(pid < 0) throw std::runtime_error(std::string("fork() failed: ") + std::strerror(errno));
  if(pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if(fd < 0 || chdir(directory.c_str()) != 0 || dup2(fd, STDOUT_FILENO) < 0 || dup2(fd, STDERR_FILENO) < 0) _exit(127);
    execvp(args[0], args.data());
    std::fprintf(stderr, "cannot run %s: %s\n", args[0], std::strerror(errno));
    _exit(127);
  }
  int status = 0;
  if(wait4(pid, &status, 0, &usage) < 0) throw std::runtime_error(std::string("wait4() failed: ") + std::strerror(errno));
  return status;
}

static std::string read_text(const std::filesystem::path& path)
{
  std::ifstream is(path);
  std::ostringstream text;
  text << is.rdbuf();
  return text.str();
}

// The last n lines of `text`.
static std::string last_lines(const std::string& text, int n)
{
  std::size_t start = text.size();
  while(n-- >= 0 && start > 0) {
    const std::size_t newline = text.rfind('\n', start - 1);
    start = newline == std::string::npos ? 0 : newline;
  }
  return text.substr(start);
}

// Smaller patches for a surface whose classified patches Gmsh cannot parametrize at its defaults
// (couplingdown: "Wrong topology of boundary mesh for parametrization", then HXT fails; 3000, 2000
// and 1000 triangles fail too).
static const int gmsh_fallback_reparam_max_triangles = 500;

static Run mesh_with_gmsh(const Input& in, double h)
{
  const char* program = std::getenv("GMSH");
  const std::string gmsh = program && *program ? program : "gmsh";
  const Temporary_directory dir;
  write_file((dir.path / "surface.msh").string(), [&](std::ostream& os) { write_gmsh_surface(os, in.surface); });

  int reparam_max_triangles = 0;   // Gmsh's default
  rusage usage;
  int status = 0;
  double process_seconds = 0.;
  std::string log;
  for(;;) {
    write_file((dir.path / "mesh.geo").string(), [&](std::ostream& os) { os << gmsh_script(h, reparam_max_triangles); });
    const auto start = std::chrono::steady_clock::now();
    status = run_program({ gmsh, "mesh.geo", "-3", "-nt", "1", "-format", "mesh", "-o", "tets.mesh" }, dir.path,
                         dir.path / "gmsh.log", usage);
    process_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    log = read_text(dir.path / "gmsh.log");
    if(reparam_max_triangles != 0 || log.find("Wrong topology of boundary mesh for parametrization") == std::string::npos)
      break;
    reparam_max_triangles = gmsh_fallback_reparam_max_triangles;
    std::cout << "  gmsh cannot parametrize a patch (Wrong topology of boundary mesh for parametrization): again "
                 "with Mesh.ReparamMaxTriangles = " << reparam_max_triangles << std::endl;
  }
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0 || log.find("Error   :") != std::string::npos)
    throw std::runtime_error(gmsh + " failed (" +
                             (WIFSIGNALED(status) ? std::string("signal ") + strsignal(WTERMSIG(status))
                                                  : "exit status " + std::to_string(WEXITSTATUS(status))) +
                             "); the end of its output:\n" + last_lines(log, 15));

  // Gmsh's own wall times of each meshing stage ("Done meshing 3D (Wall 0.21s, CPU 0.19s)")
  std::array<double, 3> stage_seconds = { { -1., -1., -1. } };
  const std::regex done(R"(Done meshing ([123])D \(Wall ([0-9.eE+-]+)s)");
  for(std::sregex_iterator m(log.begin(), log.end(), done), end; m != end; ++m)
    stage_seconds[std::stoi((*m)[1]) - 1] = std::stod((*m)[2]);
  for(double s : stage_seconds)
    if(s < 0.) throw std::runtime_error("no 'Done meshing 1D/2D/3D (Wall ...)' in Gmsh's output:\n" + last_lines(log, 15));

  Tet_mesh tets;
  std::ifstream is(dir.path / "tets.mesh");
  if(!is) throw std::runtime_error(gmsh + " wrote no tets.mesh; the end of its output:\n" + last_lines(log, 15));
  LM::read_medit(is, tets);

  Run run;
  run.mesh = make_tetrahedral_mesh(tets.points, std::move(tets.tets));
  run.seconds = stage_seconds[0] + stage_seconds[1] + stage_seconds[2];
  run.peak_rss_mb = double(usage.ru_maxrss) / 1024.;
  std::ostringstream details;
  details << std::setprecision(6) << "\"gmsh_wall_seconds\": {\"mesh_1d\": " << stage_seconds[0]
          << ", \"mesh_2d\": " << stage_seconds[1] << ", \"mesh_3d\": " << stage_seconds[2]
          << ", \"process\": " << process_seconds << "}";
  if(reparam_max_triangles > 0) details << ", \"gmsh_reparam_max_triangles\": " << reparam_max_triangles;
  run.details = details.str();
  std::cout << "  gmsh h = " << h << ": meshing 1D " << stage_seconds[0] << " s, 2D " << stage_seconds[1] << " s, 3D "
            << stage_seconds[2] << " s (Gmsh's wall times), the whole process " << process_seconds << " s" << std::endl;
  return run;
}

static Run mesh_once(const Method& m, const Input& in, double size, bool count_only, const Options& o)
{
  switch(m.family) {
    case Family::LATTICE: return mesh_with_lattice(m, in, size, o);
    case Family::MESH_3: return mesh_with_mesh_3(m, in, size, count_only);
    case Family::TETGEN:
#ifdef CGAL_LATTICE_MESHER_3_USE_TETGEN
      return mesh_with_tetgen(in, size);
#endif
      break;   // method_from_name() rejected it
    case Family::GMSH: return mesh_with_gmsh(in, size);
  }
  throw std::logic_error("mesh_once(): the method is not in this build");
}

struct Attempt
{
  double size;
  std::size_t vertices;
};

static bool within_tolerance(std::size_t n, double target) { return std::abs(double(n) / target - 1.) <= tolerance; }

// A secant step on log N against log size from the last two attempts; the model exponent while
// there is one attempt, or when the measured slope is unusable (a flat, quantized count).
static double next_size(const std::vector<Attempt>& tried, double exponent, double target)
{
  const Attempt& b = tried.back();
  const auto log_count = [](std::size_t n) { return std::log(double((std::max)(n, std::size_t(1)))); };
  double slope = exponent;
  if(tried.size() >= 2) {
    const Attempt& a = tried[tried.size() - 2];
    const double measured = (log_count(b.vertices) - log_count(a.vertices)) / (std::log(b.size) - std::log(a.size));
    if(measured / exponent > .25 && measured / exponent < 4.) slope = measured;
  }
  const double step = std::clamp((std::log(target) - log_count(b.vertices)) / slope, -std::log(4.), std::log(4.));
  return b.size * std::exp(step);
}

static std::string json_string(const std::string& s)
{
  std::string quoted = "\"";
  for(char c : s) {
    if(c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + '"';
}

static void write_json(std::ostream& os, const LM::Mesh_quality_3& q, const Method& m, const Input& in,
                       const Run& run, bool valid, const std::vector<Attempt>& tried, const Options& o)
{
  std::ostringstream quality;
  LM::write_quality_json(quality, q);
  std::string json = quality.str();
  json.erase(json.find_last_of('}'));   // reopen the object for our keys
  json.erase(json.find_last_not_of('\n') + 1);
  os << json << ",\n" << std::setprecision(10)
     << "  \"method\": " << json_string(m.name) << ",\n"
     << "  \"input\": " << json_string(in.name) << ",\n"
     << "  \"target_vertices\": " << o.vertices << ",\n"
     << "  \"threads\": " << (m.family == Family::LATTICE ? o.threads : 1) << ",\n"
     << "  \"peak_rss_mb\": " << run.peak_rss_mb << ",\n"
     << "  \"valid\": " << (valid ? "true" : "false") << ",\n"
     << "  \"epsilon_lattice\": " << json_string(LM::make_lattice(m.lattice).name) << ",\n"
     << "  \"size_parameter\": " << json_string(size_parameter(m.family).name) << ",\n"
     << (run.details.empty() ? "" : "  " + run.details + ",\n")
     << "  \"tuning\": [";
  for(std::size_t i = 0; i < tried.size(); ++i)
    os << (i ? ", " : "") << "{\"size\": " << tried[i].size << ", \"vertices\": " << tried[i].vertices << "}";
  os << "],\n"
     << "  \"notes\": \""
     << (m.family == Family::GMSH
           ? "seconds.total is the sum of the wall times Gmsh reports for meshing 1D, 2D and 3D in the "
             "final run (surface remeshing at the size, HXT and its optimizer; not reading the surface, "
             "classifying it, writing the mesh, nor the tuning or measurement), gmsh_wall_seconds has "
             "them apart and the whole gmsh process's; peak_rss_mb is the peak RSS of the gmsh process"
           : "seconds.total is the wall time of the final meshing call only (no tuning, domain set-up or "
             "measurement; optimize and mesh are not measured apart); peak_rss_mb is the peak RSS of the "
             "process that ran it")
     << (m.family == Family::MESH_3 ? "; the tuning counts come from refinement-only runs" : "") << "\"\n}\n";
}

static void report(const Method& m, const Input& in, const Run& run, const std::vector<Attempt>& tried, const Options& o)
{
  const Identity_field field;
  // epsilon against the method's own lattice: FCC for ours with FCC, the BCC one-ring otherwise
  // (Particle2013's hole-less kernel keeps BCC's)
  const LM::Lattice_3 lattice = LM::make_lattice(m.lattice);
  const LM::Mesh_validity_report validity = LM::check_tetrahedral_mesh(run.mesh);
  LM::Mesh_quality_3 q = LM::compute_mesh_quality(run.mesh, field, CGAL::parameters::lattice(lattice));
  q.seconds.total = run.seconds;
  q.seconds.stages = run.stages;

  std::cout << "lattice-benchmark: " << m.name << " on " << in.name << ": " << run.mesh.points.size()
            << " vertices (target " << o.vertices << "), " << run.seconds << " s (final run only), peak RSS "
            << run.peak_rss_mb << " MB\n"
            << "  measured with the identity field; epsilon against the " << lattice.name << " one-ring\n";
  LM::print_quality_table(std::cout, q);
  if(!validity.valid())
    std::cout << "lattice-benchmark: warning: the " << m.name << " mesh is not valid:\n" << validity.message << "\n";

  write_file(o.out, [&](std::ostream& os) { LM::write_medit(os, run.mesh); });
  write_file(o.stats, [&](std::ostream& os) { write_json(os, q, m, in, run, validity.valid(), tried, o); });
  write_file(o.histograms, [&](std::ostream& os) { LM::write_quality_histograms_csv(os, run.mesh, field, CGAL::parameters::lattice(lattice)); });
}

// One attempt, in a child process: meshes at `size`; if the count is within the tolerance or the
// attempt is `final`, reruns Mesh_3 with its optimizers, then measures and writes the outputs.
static std::size_t attempt(const Method& m, const Input& in, double size, bool final, std::vector<Attempt> tried,
                           const Options& o)
{
  Run run = mesh_once(m, in, size, true, o);
  const std::size_t n = run.mesh.points.size();
  tried.push_back({ size, n });
  std::cout << "  attempt " << tried.size() << ": " << size_parameter(m.family).name << " " << size << " -> " << n
            << " vertices" << (m.family == Family::MESH_3 ? " (refinement only)" : "") << std::endl;
  if(final || within_tolerance(n, o.vertices)) {
    if(m.family == Family::MESH_3) {
      run = Run();   // free it first: the peak RSS is the full run's
      run = mesh_once(m, in, size, false, o);
    }
    report(m, in, run, tried, o);
  }
  return n;
}

// Runs f() in a child process and returns the count it returns. A fresh process per attempt
// keeps ru_maxrss to one run, and turns a crash of a baseline into an error message.
template <typename F>
static std::size_t in_child_process(const F& f)
{
  int fd[2];
  if(pipe(fd) != 0) throw std::runtime_error(std::string("pipe() failed: ") + std::strerror(errno));
  std::cout.flush();
  const pid_t pid = fork();
  if(pid < 0) throw std::runtime_error(std::string("fork() failed: ") + std::strerror(errno));
  if(pid == 0) {
    close(fd[0]);
    int status = EXIT_SUCCESS;
    try {
      const std::size_t n = f();
      if(write(fd[1], &n, sizeof n) != ssize_t(sizeof n)) status = EXIT_FAILURE;
    } catch(const std::exception& e) {
      std::cerr << "lattice-benchmark: error: " << e.what() << "\n";
      status = EXIT_FAILURE;
    }
    std::cout.flush();
    _exit(status);
  }
  close(fd[1]);
  std::size_t n = 0;
  const bool received = read(fd[0], &n, sizeof n) == ssize_t(sizeof n);
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if(WIFSIGNALED(status))
    throw std::runtime_error(std::string("the meshing process was killed by signal ") + strsignal(WTERMSIG(status)));
  if(!received || !WIFEXITED(status) || WEXITSTATUS(status) != EXIT_SUCCESS)
    throw std::runtime_error("the meshing process failed");
  return n;
}

static Options parse(int argc, char** argv)
{
  Options o;
  command_line::Arguments args(argc, argv);
  for(std::string a; args.next(a);) {
    if(a == "-h" || a == "--help") { std::cout << usage; std::exit(EXIT_SUCCESS); }
    else if(a == "--domain") o.domain = args.value(a);
    else if(a == "--method") o.method = args.value(a);
    else if(a == "--vertices") o.vertices = args.number(a);
    else if(a == "--threads") o.threads = int(args.integer(a, 1, 1024));
    else if(a == "--seed") o.seed = (unsigned int)args.integer(a, 0, std::numeric_limits<unsigned int>::max());
    else if(a == "--no-tuning") o.tune = false;
    else if(a == "-o" || a == "--output") o.out = args.value(a);
    else if(a == "--stats") o.stats = args.value(a);
    else if(a == "--histograms") o.histograms = args.value(a);
    else command_line::Arguments::positional(a, o.input);
  }
  if(o.input.empty() == o.domain.empty()) throw std::invalid_argument("give either an input surface file or --domain cube");
  if(!o.domain.empty() && o.domain != "cube") throw std::invalid_argument("unknown domain '" + o.domain + "' (expected cube)");
  if(o.method.empty()) throw std::invalid_argument("a method is required: --method bcc|fcc|gaussian|cvt|odt|cvt-pe|odt-pe|tetgen|gmsh");
  if(!(o.vertices >= 16. && o.vertices <= 1e7)) throw std::invalid_argument("--vertices N is required, with 16 <= N <= 10^7");
  return o;
}

// Validating through our domain rejects open or self-intersecting surfaces with a clear message
// (TetGen would crash on them); its triangulated, outward-oriented surface is what every method meshes.
static Input read_input(const Options& o)
{
  const Lattice_domain domain = o.input.empty()
    ? Lattice_domain(LM::make_cube_surface_3<K>(0.1, 1.1), feature_angle)
    : LM::read_polyhedral_lattice_domain_3<K>(o.input, feature_angle);
  return Input{ o.input.empty() ? "cube" : o.input, domain.surface(), domain.volume() };
}

int main(int argc, char** argv)
{
  try {
    const Options o = parse(argc, argv);
    const Method m = method_from_name(o.method);
    const Input in = read_input(o);
    malloc_trim(0);   // the validation's freed memory would count in every child's RSS

    // The parent only steers: every attempt runs in a child, which measures and writes the
    // outputs when its count is accepted (the same test as below).
    const Size_parameter parameter = size_parameter(m.family);
    std::vector<Attempt> tried;
    double size = initial_size(m.family, in, o.vertices);
    bool final = !o.tune;
    for(;;) {
      const std::size_t n = in_child_process([&] { return attempt(m, in, size, final, tried, o); });
      tried.push_back({ size, n });
      if(final || within_tolerance(n, o.vertices)) break;
      size = next_size(tried, parameter.exponent, o.vertices);
      // out of attempts, or a size already tried (its count would repeat): rerun the closest
      final = int(tried.size()) + 1 == max_attempts
              || std::any_of(tried.begin(), tried.end(), [&](const Attempt& a) { return std::abs(a.size / size - 1.) < 1e-9; });
      if(final)
        size = std::min_element(tried.begin(), tried.end(), [&](const Attempt& a, const Attempt& b) {
                 return std::abs(std::log(double(a.vertices) / o.vertices)) < std::abs(std::log(double(b.vertices) / o.vertices));
               })->size;
    }
    return EXIT_SUCCESS;
  } catch(const std::exception& e) {
    std::cerr << "lattice-benchmark: error: " << e.what() << "\n" << (argc <= 1 ? usage : "");
    return EXIT_FAILURE;
  }
}
