/*!
\ingroup PkgLatticeMesher3Concepts
\cgalConcept

A frame field T: at every point p of the domain, a 3x3 matrix T(p) whose columns t1, t2, t3 are
the edges of the desired lattice cube at p, that is their directions and their lengths relative
to the target edge length l*. The matrix B(p) = T(p)^-1 maps the physical space to the isotropic
space, in which the particles are optimized into the unit BCC or FCC lattice scaled by l*, and in
which the quality of the output mesh is measured.

- An orthonormal T (a rotation, i.e. a cross field) gives an isotropic mesh whose lattice turns
  with the field; a non-orthogonal or stretched T gives an anisotropic mesh.
- The BCC and FCC one-rings are invariant under the 48 symmetries of the cube, so any of the
  24 rotated labelings of a frame gives the same energy: neighbouring frames need no matching.
- T(p) must be invertible wherever it is evaluated (inside the domain and on its boundary). The
  stages throw `std::domain_error`, naming the point, when a frame is not finite or its condition
  number exceeds 1e8.
- `frame()` is called concurrently from several OpenMP threads: it must be thread-safe.

The field is evaluated at particle positions, at pair midpoints, at tetrahedron centroids and at
edge midpoints; a field known only at samples (a discrete field) returns the frame of the sample
closest to the query point.

\cgalHasModel `CGAL::Lattice_mesher_3::Constant_frame_field_3`
\cgalHasModel `CGAL::Lattice_mesher_3::Function_frame_field_3`
\cgalHasModel `CGAL::Lattice_mesher_3::Rotation_y_frame_field_3`
\cgalHasModel `CGAL::Lattice_mesher_3::Planar_layer_frame_field_3`
\cgalHasModel `CGAL::Lattice_mesher_3::Cylindrical_layer_frame_field_3`
\cgalHasModel `CGAL::Lattice_mesher_3::Discrete_frame_field_3`

\sa `LatticeMesherTraits_3`
*/
class FrameField_3
{
public:
  /// \name Types
  /// The models provide these types, which are those of the traits (`LatticeMesherTraits_3`)
  /// the mesher uses.
  /// @{

  /// the point type, `LatticeMesherTraits_3::Point_3`
  typedef unspecified_type Point_3;

  /// the matrix type, `LatticeMesherTraits_3::Matrix_3` (`Eigen::Matrix3d`)
  typedef unspecified_type Matrix_3;

  /// @}

  /// \name Operations
  /// @{

  /*!
  returns T(p): its columns are the lattice cube edges t1, t2, t3 at `p`. The result may also be
  returned by constant reference.
  */
  Matrix_3 frame(const Point_3& p) const;

  /// @}
};
