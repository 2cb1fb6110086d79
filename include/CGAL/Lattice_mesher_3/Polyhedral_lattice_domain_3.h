// Copyright (c) 2026 Lattice_mesher_3 developers.
// All rights reserved.
//
// This file is part of Lattice_mesher_3 (a CGAL-style package).
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : Lattice_mesher_3 developers

#ifndef CGAL_LATTICE_MESHER_3_POLYHEDRAL_LATTICE_DOMAIN_3_H
#define CGAL_LATTICE_MESHER_3_POLYHEDRAL_LATTICE_DOMAIN_3_H

#include <CGAL/Lattice_mesher_3/Boundary_projection_3.h>
#include <CGAL/Lattice_mesher_3/internal/surface_cell_grid.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/split_graph_into_polylines.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <boost/graph/adjacency_list.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Lattice_mesher_3 {

/*!
\ingroup PkgLatticeMesher3Domains

A model of `LatticeMeshDomain_3`: the volume bounded by a closed triangle surface, with the
sharp edges of the surface as feature curves.

The constructor copies the surface, removes its isolated vertices, triangulates polygonal
faces, checks that the surface bounds a volume (closed, not self-intersecting, positive and
finite volume) and orients it outward.
Edges whose dihedral angle differs from flat by more than `feature_angle` degrees are sharp
(`Polygon_mesh_processing::detect_sharp_edges()`). The sharp-edge graph is split into
polylines with the rule of `Polyhedral_mesh_domain_with_features_3`: a vertex ends a polyline
if it is on one or more than two sharp edges, or if the polyline turns there by 90 degrees or
more. These end vertices are the corners. A closed loop without such a vertex is one curve,
whose first point is repeated at its end, and has no corner.

Projections use AABB trees built in the constructor: one over the triangles, one over all
feature segments and one per curve. The domain shares its immutable data between copies, so
copying is cheap and all queries are `const` and thread-safe.

\tparam K a CGAL kernel with `double`-convertible coordinates, e.g. `Epick`.

\cgalModels `LatticeMeshDomain_3`
*/
template <typename K = CGAL::Epick>
class Polyhedral_lattice_domain_3
{
public:
  typedef K                                Geom_traits;
  typedef typename K::Point_3              Point_3;
  typedef typename K::Vector_3             Vector_3;
  typedef Boundary_projection_3<K>         Projection;
  typedef CGAL::Surface_mesh<Point_3>      Surface_mesh;
  typedef std::vector<Point_3>             Polyline;

  /// builds the domain bounded by `surface`. Throws `std::invalid_argument` (the message names
  /// the problem) if `feature_angle` is not in (0, 180] or if `surface` does not bound a volume.
  explicit Polyhedral_lattice_domain_3(const Surface_mesh& surface, double feature_angle = 60.)
    : m_data(std::make_shared<const Data>(surface, feature_angle))
  {}

  /// \name LatticeMeshDomain_3
  /// @{
  CGAL::Bbox_3 bbox() const { return m_data->bbox; }

  /// a ray cast only where the cell grid (below) does not tell
  bool is_inside(const Point_3& p) const
  {
    const int side = m_data->cells.side(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    return side != 0 ? side > 0 : m_data->side_of(p) == CGAL::ON_BOUNDED_SIDE;
  }

  /// from a grid of 128 cubic cells along the longest side of the bounding box, classified in
  /// the constructor: (k - 1) h, with h the cell side and k the number of cells (Chebyshev
  /// distance) from the cell of `p` to the nearest cell that meets the surface
  double inside_distance_bound(const Point_3& p) const
  {
    return m_data->cells.inside_distance_bound(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }

  /// the normal is the closest face's unit outward normal
  Projection project_on_surface(const Point_3& p) const
  {
    const auto hit = m_data->triangle_tree.closest_point_and_primitive(p);
    return Projection{hit.first, m_data->face_normals[hit.second.idx()], -1,
                      CGAL::to_double(CGAL::squared_distance(p, hit.first))};
  }

  std::size_t number_of_curves() const { return m_data->curves.size(); }

  /// the tangent is the unit direction of the closest segment, in the order of `curves()[curve]`.
  /// Throws `std::out_of_range` if `curve >= number_of_curves()`.
  Projection project_on_curve(const Point_3& p, std::size_t curve) const
  {
    if(curve >= number_of_curves())
      throw std::out_of_range("Polyhedral_lattice_domain_3::project_on_curve(): curve "
                              + std::to_string(curve) + " does not exist ("
                              + std::to_string(number_of_curves()) + " curves)");
    return project(m_data->curve_trees[curve], p);
  }

  /// without feature curves, returns `p` with index -1 and an infinite squared distance
  Projection project_on_features(const Point_3& p) const
  {
    if(m_data->segments.empty())
      return Projection{p, CGAL::NULL_VECTOR, -1, std::numeric_limits<double>::infinity()};
    return project(m_data->segment_tree, p);
  }

  const std::vector<Point_3>& corners() const { return m_data->corners; }
  double volume() const { return m_data->volume; }
  double area() const { return m_data->area; }
  double curves_length() const { return m_data->curves_length; }

  /// writes the vertices and grid points of the edges and triangles (the grid sampling of
  /// `Polygon_mesh_processing::sample_triangle_mesh()` at `spacing / 2`, so that every point
  /// of the surface is closer than `spacing` to a sample). Throws `std::invalid_argument`
  /// if `spacing` is not positive.
  template <typename OutputIterator>
  OutputIterator sample_surface(double spacing, OutputIterator out) const
  {
    if(!(spacing > 0.))
      throw std::invalid_argument("Polyhedral_lattice_domain_3::sample_surface(): spacing "
                                  + std::to_string(spacing) + " is not positive");
    namespace PMP = CGAL::Polygon_mesh_processing;
    return PMP::sample_triangle_mesh(m_data->surface, out,
                                     CGAL::parameters::use_grid_sampling(true)
                                                      .grid_spacing(spacing / 2.));
  }
  /// @}

  /// the closed, triangulated, outward-oriented boundary surface
  const Surface_mesh& surface() const { return m_data->surface; }
  /// the feature polylines; a closed curve repeats its first point at its end
  const std::vector<Polyline>& curves() const { return m_data->curves; }
  /// the feature angle, in degrees, used to detect the sharp edges
  double feature_angle() const { return m_data->feature_angle; }

private:
  // the triangles are stored in the primitives (CacheDatum): rebuilding each from the mesh's
  // halfedges in every closest-point traversal cost more than the traversal's own tests
  typedef CGAL::AABB_face_graph_triangle_primitive<Surface_mesh, CGAL::Default, CGAL::Tag_true, CGAL::Tag_true>
                                                                             Triangle_primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Triangle_primitive> >         Triangle_tree;
  typedef CGAL::Side_of_triangle_mesh<Surface_mesh, K, CGAL::Default, Triangle_tree>
                                                                             Side_of_surface;
  typedef typename std::vector<typename K::Segment_3>::const_iterator        Segment_iterator;
  typedef CGAL::AABB_segment_primitive<K, Segment_iterator>                 Segment_primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Segment_primitive> >          Segment_tree;

  // Graph of the sharp edges; its vertices carry their points for the turning-angle test.
  typedef boost::adjacency_list<boost::setS, boost::vecS, boost::undirectedS, Point_3>
                                                                             Feature_graph;
  typedef typename boost::graph_traits<Feature_graph>::vertex_descriptor    Feature_vertex;

  // The corner rule of Polyhedral_mesh_domain_with_features_3. The BGL calls are qualified:
  // Point_3 makes CGAL an associated namespace, and ADL would pick CGAL's halfedge-graph
  // overloads.
  struct Is_corner
  {
    bool operator()(Feature_vertex v, const Feature_graph& g) const
    {
      if(boost::out_degree(v, g) != 2)
        return true;
      auto it = boost::adjacent_vertices(v, g).first;
      const Point_3& p1 = g[*it++];
      const Point_3& p2 = g[*it];
      return CGAL::angle(p1, g[v], p2) != CGAL::OBTUSE;
    }
  };

  struct Polyline_collector
  {
    const Feature_graph& graph;
    std::vector<Polyline>& polylines;
    void start_new_polyline() { polylines.emplace_back(); }
    void add_node(Feature_vertex v) { polylines.back().push_back(graph[v]); }
    void end_polyline() {}
  };

  static Vector_3 unit(const Vector_3& v)
  {
    return v / std::sqrt(CGAL::to_double(v.squared_length()));
  }

  // Validates and prepares a copy of the input: the trees below are built on the result.
  static Surface_mesh prepared_surface(const Surface_mesh& input, double feature_angle)
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    if(!(feature_angle > 0. && feature_angle <= 180.))
      throw std::invalid_argument("feature angle " + std::to_string(feature_angle)
                                  + " is outside (0, 180] degrees");
    for(typename Surface_mesh::Vertex_index v : input.vertices()) { // the indices of the input
      const Point_3& p = input.point(v);
      if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y()))
         || !std::isfinite(CGAL::to_double(p.z())))
        throw std::invalid_argument("vertex " + std::to_string(std::size_t(v))
                                    + " has a non-finite coordinate");
    }
    Surface_mesh mesh = input;
    // An isolated vertex has no halfedge, which orient_to_bound_a_volume() dereferences; OFF
    // files may list unused vertices.
    PMP::remove_isolated_vertices(mesh);
    mesh.collect_garbage(); // dense indices: face normals are stored by face index
    if(mesh.number_of_faces() == 0)
      throw std::invalid_argument("the surface has no faces");
    if(!CGAL::is_triangle_mesh(mesh) && !PMP::triangulate_faces(mesh))
      throw std::invalid_argument("some polygonal faces cannot be triangulated");
    std::size_t border_edges = 0;
    for(typename Surface_mesh::Halfedge_index h : mesh.halfedges())
      if(mesh.is_border(h))
        ++border_edges;
    if(border_edges > 0)
      throw std::invalid_argument("the surface is not closed (" + std::to_string(border_edges)
                                  + " border edges)");
    if(PMP::does_self_intersect(mesh))
      throw std::invalid_argument("the surface self-intersects (or has degenerate faces)");
    // Also handles nested components (cavities), unlike a single is_outward_oriented() test.
    PMP::orient_to_bound_a_volume(mesh);
    // Coordinates near the limits of double overflow the volume (and the squared distances).
    const double volume = CGAL::to_double(PMP::volume(mesh));
    if(!(volume > 0) || !std::isfinite(volume))
      throw std::invalid_argument("the surface bounds a zero, negative or non-finite volume");
    return mesh;
  }

  // Everything the queries read, built once and never moved: the primitives and the inside
  // test point into `surface`, `segments` and `triangle_tree`.
  struct Data
  {
    double feature_angle;
    Surface_mesh surface;
    Triangle_tree triangle_tree;
    Side_of_surface side_of;
    std::vector<Vector_3> face_normals;
    std::vector<Polyline> curves;
    std::vector<Point_3> corners;
    std::vector<typename K::Segment_3> segments; // curve by curve, in polyline order
    std::vector<int> segment_curve;              // the curve of each segment
    Segment_tree segment_tree;
    std::vector<Segment_tree> curve_trees;
    CGAL::Bbox_3 bbox;
    internal::Surface_cell_grid_3 cells;
    double volume, area, curves_length = 0.;

    Data(const Surface_mesh& input, double angle)
      : feature_angle(angle),
        surface(prepared_surface(input, angle)),
        triangle_tree(faces(surface).first, faces(surface).second, surface),
        side_of(triangle_tree)
    {
      namespace PMP = CGAL::Polygon_mesh_processing;
      triangle_tree.accelerate_distance_queries();
      face_normals.reserve(surface.number_of_faces());
      for(typename Surface_mesh::Face_index f : surface.faces())
        face_normals.push_back(PMP::compute_face_normal(f, surface));
      bbox = PMP::bbox(surface);
      std::vector<typename K::Triangle_3> triangles;
      triangles.reserve(surface.number_of_faces());
      for(typename Surface_mesh::Face_index f : surface.faces()) {
        const typename Surface_mesh::Halfedge_index h = surface.halfedge(f);
        triangles.emplace_back(surface.point(surface.source(h)), surface.point(surface.target(h)),
                               surface.point(surface.target(surface.next(h))));
      }
      cells = internal::Surface_cell_grid_3(bbox, triangles);
      volume = CGAL::to_double(PMP::volume(surface));
      area = CGAL::to_double(PMP::area(surface));
      build_curves();
      for(std::size_t c = 0; c < curves.size(); ++c)
        for(std::size_t i = 0; i + 1 < curves[c].size(); ++i) {
          segments.emplace_back(curves[c][i], curves[c][i + 1]);
          segment_curve.push_back(int(c));
          curves_length += std::sqrt(CGAL::to_double(segments.back().squared_length()));
        }
      segment_tree.insert(segments.cbegin(), segments.cend());
      segment_tree.accelerate_distance_queries();
      curve_trees.reserve(curves.size());
      Segment_iterator first = segments.cbegin();
      for(const Polyline& curve : curves) {
        curve_trees.emplace_back(first, first + (curve.size() - 1));
        curve_trees.back().accelerate_distance_queries();
        first += curve.size() - 1;
      }
    }

    void build_curves()
    {
      typedef typename Surface_mesh::Edge_index Edge_index;
      typedef typename Surface_mesh::Vertex_index Vertex_index;
      auto is_sharp = surface.template add_property_map<Edge_index, bool>("e:is_sharp", false).first;
      CGAL::Polygon_mesh_processing::detect_sharp_edges(surface, feature_angle, is_sharp);
      Feature_graph graph;
      std::vector<Feature_vertex> graph_vertex(surface.number_of_vertices(),
                                               boost::graph_traits<Feature_graph>::null_vertex());
      auto add_vertex = [&](Vertex_index v) {
        Feature_vertex& gv = graph_vertex[v.idx()];
        if(gv == boost::graph_traits<Feature_graph>::null_vertex())
          gv = boost::add_vertex(surface.point(v), graph);
        return gv;
      };
      for(Edge_index e : surface.edges())
        if(is_sharp[e])
          boost::add_edge(add_vertex(surface.vertex(e, 0)), add_vertex(surface.vertex(e, 1)), graph);
      surface.remove_property_map(is_sharp); // keep surface() free of our bookkeeping

      Polyline_collector collector{graph, curves};
      CGAL::split_graph_into_polylines(graph, collector, Is_corner());
      for(Feature_vertex v : CGAL::make_range(boost::vertices(graph)))
        if(Is_corner()(v, graph))
          corners.push_back(graph[v]);
    }
  };

  Projection project(const Segment_tree& tree, const Point_3& p) const
  {
    const auto hit = tree.closest_point_and_primitive(p);
    const std::size_t s = std::size_t(hit.second - m_data->segments.cbegin());
    return Projection{hit.first, unit(m_data->segments[s].to_vector()), m_data->segment_curve[s],
                      CGAL::to_double(CGAL::squared_distance(p, hit.first))};
  }

  std::shared_ptr<const Data> m_data;
};

/*!
\ingroup PkgLatticeMesher3Domains

reads a closed surface from `filename` (OFF, OBJ, STL or PLY, by extension) with
`CGAL::IO::read_polygon_mesh()` and builds the domain it bounds. Throws `std::runtime_error`
if the file cannot be opened or read and `std::invalid_argument` if the surface does not bound a
volume or `feature_angle` is not in (0, 180]; the message starts with the file name.
*/
template <typename K = CGAL::Epick>
Polyhedral_lattice_domain_3<K>
read_polyhedral_lattice_domain_3(const std::string& filename, double feature_angle = 60.)
{
  typename Polyhedral_lattice_domain_3<K>::Surface_mesh mesh;
  std::ifstream file(filename, std::ios::binary | std::ios::ate);
  if(!file)
    throw std::runtime_error("'" + filename + "': cannot open the file");
  if(file.tellg() == 0)
    throw std::runtime_error("'" + filename + "': the file is empty");
  file.close();
  if(!CGAL::IO::read_polygon_mesh(filename, mesh))
    throw std::runtime_error("'" + filename + "': cannot read a polygon mesh (unsupported "
                             "extension, non-manifold or inconsistently oriented faces, or "
                             "malformed data, e.g. a coordinate such as nan)");
  try {
    return Polyhedral_lattice_domain_3<K>(mesh, feature_angle);
  }
  catch(const std::invalid_argument& e) {
    throw std::invalid_argument("'" + filename + "': " + e.what());
  }
}

/*!
\ingroup PkgLatticeMesher3Domains

returns the surface of the cube [lo, hi]^3: 8 vertices and 12 triangles, oriented outward.
*/
template <typename K = CGAL::Epick>
CGAL::Surface_mesh<typename K::Point_3> make_cube_surface_3(double lo, double hi)
{
  typedef CGAL::Surface_mesh<typename K::Point_3> Mesh;
  if(!(lo < hi))
    throw std::invalid_argument("make_cube_surface_3(): lo must be smaller than hi");
  Mesh mesh;
  std::vector<typename Mesh::Vertex_index> v;
  for(int i = 0; i < 8; ++i) // bit 0: x, bit 1: y, bit 2: z
    v.push_back(mesh.add_vertex(typename K::Point_3((i & 1) ? hi : lo, (i & 2) ? hi : lo,
                                                   (i & 4) ? hi : lo)));
  // each face counterclockwise seen from outside, as two triangles
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto& q : quads) {
    mesh.add_face(v[q[0]], v[q[1]], v[q[2]]);
    mesh.add_face(v[q[0]], v[q[2]], v[q[3]]);
  }
  return mesh;
}

} // namespace Lattice_mesher_3
} // namespace CGAL

#endif // CGAL_LATTICE_MESHER_3_POLYHEDRAL_LATTICE_DOMAIN_3_H
