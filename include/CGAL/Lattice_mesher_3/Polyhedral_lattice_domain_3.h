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
#include <CGAL/Lattice_mesher_3/internal/triangle_sampling.h>
#include <CGAL/Lattice_mesher_3/internal/winding_number.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/split_graph_into_polylines.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/property_map.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>

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

The constructor copies the surface and makes it bound a volume as Mesh_3 users expect: it
removes isolated vertices, triangulates polygonal faces, stitches border edges that coincide,
removes degenerate faces, and orients every component outward, a component enclosed by
another bounding a cavity. A self-intersecting surface is meshed too: the volume is where
the winding number of the surface is at least 1 (the union of overlapping parts), its boundary
the faces between such points and the outside; buried faces are left out of the projections,
the features and the samples, and `warnings()` says how many face pairs intersect. Only a
surface that stays open (border edges), has no faces, non-finite coordinates, or encloses no
volume is refused.
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
  typedef K                                Geom_traits;  ///< the kernel
  typedef typename K::Point_3              Point_3;      ///< the point type
  typedef typename K::Vector_3             Vector_3;     ///< the vector type
  typedef Boundary_projection_3<K>         Projection;   ///< the result of a projection on the boundary or a feature curve (`Boundary_projection_3`)
  typedef CGAL::Surface_mesh<Point_3>      Surface_mesh; ///< the type of the input surface
  typedef std::vector<Point_3>             Polyline;     ///< a feature curve, as a sequence of points

  /// builds the domain bounded by `surface`. Throws `std::invalid_argument` (the message names
  /// the problem) if `feature_angle` is not in (0, 180] or if `surface` does not bound a volume.
  explicit Polyhedral_lattice_domain_3(const Surface_mesh& surface, double feature_angle = 60.)
    : m_data(std::make_shared<const Data>(surface, feature_angle, nullptr))
  {}

  /// builds the domain bounded by `surface` with the feature curves `curves` instead of its
  /// sharp edges (as Mesh_3's `add_features()`): polylines on the surface, a closed one
  /// repeating its first point at its end. The corners are `corners` and the end points of the
  /// open curves. Throws `std::invalid_argument` if `surface` does not bound a volume.
  Polyhedral_lattice_domain_3(const Surface_mesh& surface, const std::vector<Polyline>& curves,
                              const std::vector<Point_3>& corners = std::vector<Point_3>())
    : m_data(std::make_shared<const Data>(surface, 0., &curves, &corners))
  {}

  /// \name LatticeMeshDomain_3
  /// @{
  CGAL::Bbox_3 bbox() const { return m_data->bbox; } ///< the bounding box of the surface

  /// the winding number of the surface about `p` is at least 1; computed only where the cell
  /// grid (below) does not tell, from a nearby cell of the grid that does (by a ray cast
  /// through the whole surface if none of the 8 nearest within 4 cells gives a segment clear of its edges)
  bool is_inside(const Point_3& p) const
  {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    const int side = m_data->cells.side(x, y, z);
    if(side != 0) return side > 0;
    int winding = 0;
    const bool found = m_data->cells.find_untouched_cell_near(x, y, z, 4, 8, [&](double qx, double qy, double qz, int at_q) {
      return m_data->winding.from(p, Point_3(qx, qy, qz), at_q, winding);
    });
    return (found ? winding : m_data->winding(p)) >= 1;
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

  /// the surface patch (from 1) of the boundary point closest to `p`: the patches are the parts
  /// of the surface between its sharp edges (with given feature curves, its connected components)
  int surface_patch_index(const Point_3& p) const
  {
    return m_data->face_patches[m_data->triangle_tree.closest_point_and_primitive(p).second.idx()];
  }

  /// the number of surface patches
  int number_of_surface_patches() const { return m_data->number_of_patches; }

  /// the number of feature curves
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

  /// the corners: the end vertices of the feature curves (and, with given curves, the given corners)
  const std::vector<Point_3>& corners() const { return m_data->corners; }
  /// the volume enclosed by the surface (where parts of a self-intersecting surface overlap,
  /// they count twice: an upper bound)
  double volume() const { return m_data->volume; }
  /// the area of the boundary (without buried faces)
  double area() const { return m_data->area; }
  /// the total length of the feature curves
  double curves_length() const { return m_data->curves_length; }

  /// writes the vertices, points at most `spacing / 2` apart on the edges, and inside each
  /// triangle rows of points at most `spacing / 2` apart, parallel to its longest edge and at
  /// most `spacing / 2` from one another, so that every point of the surface is closer than
  /// `spacing` to a sample: about 4 area / spacing^2 points, however thin the triangles (CAD
  /// models' long ones included). Throws `std::invalid_argument` if `spacing` is not positive.
  template <typename OutputIterator>
  OutputIterator sample_surface(double spacing, OutputIterator out) const
  {
    if(!(spacing > 0.))
      throw std::invalid_argument("Polyhedral_lattice_domain_3::sample_surface(): spacing "
                                  + std::to_string(spacing) + " is not positive");
    const Surface_mesh& m = m_data->boundary;
    const double g = .5 * spacing;
    for(typename Surface_mesh::Vertex_index v : m.vertices()) *out++ = m.point(v);
    for(typename Surface_mesh::Edge_index e : m.edges())
      out = internal::sample_segment(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1)), g, out);
    for(typename Surface_mesh::Face_index f : m.faces()) {
      std::array<Point_3, 3> p;
      std::size_t i = 0;
      for(typename Surface_mesh::Vertex_index v : vertices_around_face(m.halfedge(f), m)) p[i++] = m.point(v);
      out = internal::sample_triangle_inside(p, g, out);
    }
    return out;
  }
  /// @}

  /// the closed, triangulated surface, each component oriented outward (or inward around a
  /// cavity)
  const Surface_mesh& surface() const { return m_data->surface; }
  /// the faces of `surface()` that bound the volume: all of them unless the surface
  /// self-intersects, when the buried ones are left out
  const Surface_mesh& boundary() const { return m_data->boundary; }
  /// what the constructor repaired or found in the input, a sentence each; empty for a closed,
  /// outward-oriented surface without self-intersections or degenerate faces
  const std::vector<std::string>& warnings() const { return m_data->warnings; }
  /// the number of pairs of faces of the surface that intersect
  std::size_t number_of_self_intersections() const { return m_data->self_intersections; }
  /// the feature polylines; a closed curve repeats its first point at its end
  const std::vector<Polyline>& curves() const { return m_data->curves; }
  /// the feature angle, in degrees, used to detect the sharp edges (0: the curves were given)
  double feature_angle() const { return m_data->feature_angle; }

private:
  // the triangles are stored in the primitives (CacheDatum): rebuilding each from the mesh's
  // halfedges in every closest-point traversal cost more than the traversal's own tests
  typedef CGAL::AABB_face_graph_triangle_primitive<Surface_mesh, CGAL::Default, CGAL::Tag_true, CGAL::Tag_true>
                                                                             Triangle_primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Triangle_primitive> >         Triangle_tree;
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

  typedef typename Surface_mesh::Face_index Face_index;
  typedef std::vector<std::pair<Face_index, Face_index> > Face_pairs;
  typedef internal::Winding_number_3<K> Winding_number;

  static typename K::Triangle_3 triangle(const Surface_mesh& mesh, Face_index f)
  {
    const typename Surface_mesh::Halfedge_index h = mesh.halfedge(f);
    return typename K::Triangle_3(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                  mesh.point(mesh.target(mesh.next(h))));
  }

  // points just behind and just in front of the centroid of face f (1e-6 of its size along its
  // normal), where the winding number tells the sides of the face apart; twice the centroid for
  // a degenerate face
  static std::pair<Point_3, Point_3> face_sides(const Surface_mesh& mesh, Face_index f)
  {
    const typename K::Triangle_3 t = triangle(mesh, f);
    const Vector_3 normal = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    const double length = std::sqrt(CGAL::to_double(normal.squared_length()));
    const Point_3 c = CGAL::centroid(t);
    if(!(length > 0.)) return { c, c };
    const Vector_3 step = normal * (1e-6 / std::sqrt(length));
    return { c - step, c + step };
  }

  static std::vector<typename K::Triangle_3> triangles(const Surface_mesh& mesh)
  {
    std::vector<typename K::Triangle_3> result;
    result.reserve(mesh.number_of_faces());
    for(Face_index f : mesh.faces()) result.push_back(triangle(mesh, f));
    return result;
  }

  static std::size_t number_of_border_edges(const Surface_mesh& mesh)
  {
    std::size_t n = 0;
    for(typename Surface_mesh::Halfedge_index h : mesh.halfedges())
      if(mesh.is_border(h)) ++n;
    return n;
  }

  // Orients each component of a self-intersecting surface, which orient_to_bound_a_volume()
  // does not take: outward (positive signed volume), then, largest first, a component that
  // meets no other and lies where the others wind at least once turns inward (a cavity; an
  // island in it stays outward, as the cavity already took its 1 back).
  static void orient_overlapping_components(Surface_mesh& mesh, const Face_pairs& pairs)
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    auto component = mesh.template add_property_map<Face_index, std::size_t>("f:lm_component").first;
    const std::size_t n = PMP::connected_components(mesh, component);
    std::vector<std::vector<Face_index> > faces_of(n);
    std::vector<double> volume(n, 0.);
    const Point_3 origin = mesh.point(*mesh.vertices().begin());   // near the mesh: fewer digits lost
    for(Face_index f : mesh.faces()) {
      faces_of[component[f]].push_back(f);
      const typename K::Triangle_3 t = triangle(mesh, f);
      volume[component[f]] += CGAL::to_double(CGAL::volume(origin, t[0], t[1], t[2]));
    }
    std::vector<bool> meets_another(n, false);
    for(const auto& fp : pairs)
      if(component[fp.first] != component[fp.second])
        meets_another[component[fp.first]] = meets_another[component[fp.second]] = true;
    for(std::size_t c = 0; c < n; ++c)
      if(volume[c] < 0.) PMP::reverse_face_orientations(faces_of[c], mesh);
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return std::abs(volume[a]) > std::abs(volume[b]) || (std::abs(volume[a]) == std::abs(volume[b]) && a < b);
    });
    std::unique_ptr<Winding_number> winding(new Winding_number(triangles(mesh)));
    for(std::size_t c : order) {
      if(meets_another[c] || n == 1) continue;
      // a point just outside one of its faces, where the component itself winds 0 times
      const std::pair<Point_3, Point_3> sides = face_sides(mesh, faces_of[c].front());
      if(sides.first == sides.second || (*winding)(sides.second) < 1) continue;
      PMP::reverse_face_orientations(faces_of[c], mesh);
      winding.reset(new Winding_number(triangles(mesh)));
    }
    mesh.remove_property_map(component);
  }

  // Everything the queries read, built once and never moved: the primitives and the inside
  // test point into `boundary`, `segments` and the winding number's triangles.
  struct Data
  {
    double feature_angle;
    std::vector<std::string> warnings;
    std::size_t self_intersections = 0;
    Surface_mesh surface;
    Winding_number winding;
    Surface_mesh boundary;
    Triangle_tree triangle_tree;
    std::vector<Vector_3> face_normals; // of `boundary`, toward the outside
    std::vector<int> face_patches;      // of `boundary`, from 1
    int number_of_patches = 0;
    std::vector<Polyline> curves;
    std::vector<Point_3> corners;
    std::vector<typename K::Segment_3> segments; // curve by curve, in polyline order
    std::vector<int> segment_curve;              // the curve of each segment
    Segment_tree segment_tree;
    std::vector<Segment_tree> curve_trees;
    CGAL::Bbox_3 bbox;
    internal::Surface_cell_grid_3 cells;
    double volume, area, curves_length = 0.;

    // `curves` and `corners` null: the features are the sharp edges at `angle`
    Data(const Surface_mesh& input, double angle, const std::vector<Polyline>* given_curves,
         const std::vector<Point_3>* given_corners = nullptr)
      : feature_angle(angle),
        surface(prepare(input, given_curves == nullptr)),
        winding(triangles(surface)),
        boundary(bounding_part())
    {
      namespace PMP = CGAL::Polygon_mesh_processing;
      triangle_tree.insert(faces(boundary).first, faces(boundary).second, boundary);
      triangle_tree.build();
      triangle_tree.accelerate_distance_queries();
      auto flipped = boundary.template property_map<Face_index, bool>("f:lm_flipped").first;
      face_normals.reserve(boundary.number_of_faces());
      for(Face_index f : boundary.faces())
        face_normals.push_back(PMP::compute_face_normal(f, boundary) * (flipped[f] ? -1. : 1.));
      boundary.remove_property_map(flipped);
      bbox = PMP::bbox(surface);
      cells = internal::Surface_cell_grid_3(bbox, triangles(surface), [this](double x, double y, double z) {
        return winding(Point_3(x, y, z));
      });
      volume = CGAL::to_double(PMP::volume(surface));   // overlaps count twice: a bound, for the sizing
      area = CGAL::to_double(PMP::area(boundary));
      if(given_curves) {
        take_curves(*given_curves, *given_corners);
        label_patches(CGAL::Constant_property_map<typename Surface_mesh::Edge_index, bool>(false));
      }
      else build_curves();
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

    // Validates and repairs a copy of the input (see the class documentation).
    Surface_mesh prepare(const Surface_mesh& input, bool detect_features)
    {
      namespace PMP = CGAL::Polygon_mesh_processing;
      if(detect_features && !(feature_angle > 0. && feature_angle <= 180.))
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
      if(const std::size_t open = number_of_border_edges(mesh)) {
        PMP::stitch_borders(mesh);   // the same edge written twice (STL, seams of OBJ parts)
        if(const std::size_t left = number_of_border_edges(mesh))
          throw std::invalid_argument("the surface is not closed (" + std::to_string(left) + " border edges)");
        warnings.push_back("stitched " + std::to_string(open / 2) + " pairs of coinciding border edges");
      }
      std::size_t degenerate = 0;
      for(Face_index f : mesh.faces())
        degenerate += PMP::is_degenerate_triangle_face(f, mesh) ? 1 : 0;
      if(degenerate > 0) {
        PMP::remove_degenerate_faces(mesh);
        mesh.collect_garbage();
        warnings.push_back("removed " + std::to_string(degenerate) + " degenerate faces");
        if(mesh.number_of_faces() == 0) throw std::invalid_argument("the surface has no faces but degenerate ones");
      }
      Face_pairs pairs;
      PMP::self_intersections(mesh, std::back_inserter(pairs));
      self_intersections = pairs.size();
      if(pairs.empty())
        PMP::orient_to_bound_a_volume(mesh);   // nested components (cavities) too
      else {
        orient_overlapping_components(mesh, pairs);
        warnings.push_back("the surface self-intersects (" + std::to_string(pairs.size())
                           + " pairs of faces): meshing the volume it winds around at least once");
      }
      // Coordinates near the limits of double overflow the volume (and the squared distances).
      const double v = CGAL::to_double(PMP::volume(mesh));
      if(!(v > 0) || !std::isfinite(v))
        throw std::invalid_argument("the surface bounds a zero, negative or non-finite volume");
      return mesh;
    }

    // The faces with the volume on one side only (winding number >= 1 on one side, 0 or less on
    // the other), each marked "f:lm_flipped" where the volume is on its outer side: without
    // self-intersections, the whole surface.
    Surface_mesh bounding_part() const
    {
      Surface_mesh part = surface;
      auto flipped = part.template add_property_map<Face_index, bool>("f:lm_flipped", false).first;
      if(self_intersections == 0) return part;
      std::vector<Face_index> buried;
      for(Face_index f : part.faces()) {
        const std::pair<Point_3, Point_3> sides = face_sides(part, f);
        if(sides.first == sides.second) { buried.push_back(f); continue; }
        const bool in = winding(sides.first) >= 1, out = winding(sides.second) >= 1;
        if(in == out) buried.push_back(f);
        else flipped[f] = out;
      }
      for(Face_index f : buried) CGAL::Euler::remove_face(part.halfedge(f), part);
      part.collect_garbage();
      return part;
    }

    // The given polylines without repeated consecutive points (their segments give tangents),
    // the given corners and the ends of the open ones, each once.
    void take_curves(const std::vector<Polyline>& given, const std::vector<Point_3>& given_corners)
    {
      corners = given_corners;
      for(const Polyline& g : given) {
        Polyline curve;
        for(const Point_3& p : g)
          if(curve.empty() || p != curve.back()) curve.push_back(p);
        if(curve.size() < 2) continue;
        if(curve.front() != curve.back()) { corners.push_back(curve.front()); corners.push_back(curve.back()); }
        curves.push_back(std::move(curve));
      }
      std::sort(corners.begin(), corners.end());
      corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    }

    // The surface patches: the connected components of the faces across the edges that are not
    // `constrained`.
    template <typename ConstrainedMap>
    void label_patches(ConstrainedMap constrained)
    {
      typedef typename Surface_mesh::Face_index Face_index;
      auto patch = boundary.template add_property_map<Face_index, std::size_t>("f:lm_patch", 0).first;
      number_of_patches = int(CGAL::Polygon_mesh_processing::connected_components(
          boundary, patch, CGAL::parameters::edge_is_constrained_map(constrained)));
      face_patches.reserve(boundary.number_of_faces());
      for(Face_index f : boundary.faces()) face_patches.push_back(int(patch[f]) + 1);
      boundary.remove_property_map(patch);
    }

    void build_curves()
    {
      typedef typename Surface_mesh::Edge_index Edge_index;
      typedef typename Surface_mesh::Vertex_index Vertex_index;
      auto is_sharp = boundary.template add_property_map<Edge_index, bool>("e:is_sharp", false).first;
      CGAL::Polygon_mesh_processing::detect_sharp_edges(boundary, feature_angle, is_sharp);
      Feature_graph graph;
      std::vector<Feature_vertex> graph_vertex(boundary.number_of_vertices(),
                                               boost::graph_traits<Feature_graph>::null_vertex());
      auto add_vertex = [&](Vertex_index v) {
        Feature_vertex& gv = graph_vertex[v.idx()];
        if(gv == boost::graph_traits<Feature_graph>::null_vertex())
          gv = boost::add_vertex(boundary.point(v), graph);
        return gv;
      };
      for(Edge_index e : boundary.edges())
        if(is_sharp[e])
          boost::add_edge(add_vertex(boundary.vertex(e, 0)), add_vertex(boundary.vertex(e, 1)), graph);
      label_patches(is_sharp);
      boundary.remove_property_map(is_sharp); // keep boundary() free of our bookkeeping

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
`CGAL::Polygon_mesh_processing::IO::read_polygon_mesh()`, which repairs and orients a polygon
soup, and builds the domain it bounds. Throws `std::runtime_error`
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
  // read as a polygon soup: duplicated points merged, degenerate and repeated polygons
  // removed, faces oriented consistently (non-manifold edges and vertices are split)
  if(!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(filename, mesh))
    throw std::runtime_error("'" + filename + "': cannot read a polygon mesh (unsupported "
                             "extension or malformed data, e.g. a coordinate such as nan)");
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
