/*!
\ingroup PkgLatticeMesher3Concepts
\cgalConcept

The domain Omega to be meshed: a bounded volume with a closed boundary surface, optional sharp
feature curves and corners. The mesher needs an inside test, the closest point on the boundary
and on the feature curves, and the measures that size the initial particle set.

All queries are `const` and safe to call concurrently from several threads once the domain is
constructed (the models build their search structures in the constructor).

\cgalHasModel `CGAL::Lattice_mesher_3::Polyhedral_lattice_domain_3`
\cgalHasModel `CGAL::Lattice_mesher_3::Implicit_lattice_domain_3`
*/
class LatticeMeshDomain_3
{
public:
  /// \name Types
  /// @{
  typedef unspecified_type Geom_traits; ///< a CGAL kernel (e.g. `Epick`)
  typedef Geom_traits::Point_3 Point_3; ///< the point type
  typedef Geom_traits::Vector_3 Vector_3; /*!< \brief the vector type */
  /// `CGAL::Lattice_mesher_3::Boundary_projection_3<Geom_traits>`: the point, the unit outward
  /// normal (surface) or unit tangent (curve) there, the index of the curve (or -1), and the
  /// squared distance from the query.
  typedef unspecified_type Projection;
  /// @}

  /// bounding box of the domain
  CGAL::Bbox_3 bbox() const;
  /// `true` if `p` is strictly inside the domain
  bool is_inside(const Point_3& p) const;
  /// a lower bound of the distance from `p` to the boundary surface if `p` is inside, else 0;
  /// 0 is always valid. Meant to be far cheaper than `project_on_surface()`: the mesher skips
  /// the projections of particles that it places deep inside.
  double inside_distance_bound(const Point_3& p) const;
  /// closest point of the boundary surface to `p`, with the unit outward normal there
  Projection project_on_surface(const Point_3& p) const;
  /// number of feature curves (0 for a smooth domain)
  std::size_t number_of_curves() const;
  /// closest point to `p` on feature curve `curve`, with the unit tangent there
  Projection project_on_curve(const Point_3& p, std::size_t curve) const;
  /// closest point to `p` over all feature curves (`index` = -1 when there is none)
  Projection project_on_features(const Point_3& p) const;
  /// corners: points where the feature curves meet or turn sharply; meshes keep them as vertices
  const std::vector<Point_3>& corners() const;
  /// volume of the domain
  double volume() const;
  /// area of the boundary surface
  double area() const;
  /// total length of the feature curves (0 for a smooth domain)
  double curves_length() const;
  /// writes points of the boundary surface, at most `spacing` apart, to `out` (used for the
  /// Hausdorff distance between a mesh boundary and the surface)
  template <typename OutputIterator> OutputIterator sample_surface(double spacing, OutputIterator out) const;
  /// optional: the surface patch (from 1) of the boundary point closest to `p`; the mesh's
  /// boundary faces carry it (`Tetrahedral_mesh_3::boundary_patches`). Without it, the boundary
  /// is one patch.
  int surface_patch_index(const Point_3& p) const;
};
