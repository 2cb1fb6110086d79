/*!
\ingroup PkgLatticeMesher3Concepts
\cgalConcept

\cgalRefines `Kernel`

The traits of `CGAL::Lattice_particle_mesher_3` and `CGAL::lattice_mesh_3()`: a CGAL kernel
whose coordinates convert to `double`, plus the fixed-size dense matrix and vector types in which
frames (`FrameField_3`) and isotropic-space vectors are expressed.

The optimizer, the insertion and deletion and the quality measures compute in `double` with
Eigen's fixed-size types; exact predicates of the kernel are used where a decision must be
robust (the Delaunay tetrahedralization, the orientation of tetrahedra).

\cgalHasModel `CGAL::Lattice_mesher_traits_3`

\sa `FrameField_3`
*/
class LatticeMesherTraits_3
{
public:
  /// \name Types
  /// @{

  /// the kernel this traits class refines
  typedef unspecified_type Kernel;

  /// the number type of the kernel, convertible to `double` by `CGAL::to_double()`
  typedef unspecified_type FT;

  /// the point type of the kernel
  typedef unspecified_type Point_3;

  /// the vector type of the kernel
  typedef unspecified_type Vector_3;

  /// 3x3 matrix of `double`: `Eigen::Matrix3d`. A frame T(p) is a `Matrix_3` whose columns are
  /// the lattice cube edges t1, t2, t3.
  typedef unspecified_type Matrix_3;

  /// 3-vector of `double`: `Eigen::Vector3d`, used in the hot loops
  typedef unspecified_type Vector_d3;

  /// @}
};
