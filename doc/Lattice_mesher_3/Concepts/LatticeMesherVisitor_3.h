/*!
\ingroup PkgLatticeMesher3Concepts
\cgalConcept

A visitor that follows `CGAL::Lattice_particle_mesher_3::optimize()` and `tetrahedralize()`, and
`CGAL::lattice_mesh_3()`: `round_done()` is called after every optimization round, at every
coarse-to-fine level, and once more after the closing round; it may stop the optimization.
`stage_done()`, which a model may omit, is called after each stage of the mesh improvement.
Both are called from the calling thread, outside any parallel region, so they need no
synchronization.

Typical uses: print the progress (as the command-line program `lattice-mesh` does), record the
energy per round to plot the convergence, measure the time each stage took, or stop the
optimization at a time limit (the mesh is then made of the particles as they are).

`CGAL::lattice_mesh_3()` takes the visitor through the named parameter `visitor`, by value (it
is copied into the parameter pack) or as `std::ref(v)` to keep its state in `v`.

\cgalHasModel `CGAL::Lattice_mesher_3::Null_lattice_mesher_visitor`
\cgalHasModel `CGAL::Lattice_mesher_3::Stage_times_visitor`

\sa `CGAL::Lattice_mesher_3::Round_report`
*/
class LatticeMesherVisitor_3
{
public:
  /// \name Operations
  /// @{

  /*!
  called after each optimization round with what the round did: its coarse-to-fine `level`
  (0 is the final edge length), its index `round` within the level, whether it was the closing
  round (`final_round`, reported last), the number of particles, the numbers deleted and inserted
  before the round, the L-BFGS iterations, the total Gaussian Hole Kernel energy at the end of the
  round, the seconds elapsed since the optimization started, and the seconds the round spent
  deleting, inserting and in L-BFGS. Returns `false` to stop the
  optimization after this round (no further round, level or closing round); a model may return
  `void` instead, which goes on.
  */
  bool round_done(const CGAL::Lattice_mesher_3::Round_report& report);

  /*!
  optional: called after each stage of `CGAL::Lattice_particle_mesher_3::tetrahedralize()`
  (`"tetrahedralization"`, `"flips"`, `"smoothing"`, `"contractions"`, `"peeling"`, `"labels"`; flips,
  smoothing and contractions may come several times) with the seconds since the
  tetrahedralization started.
  */
  void stage_done(const char* stage, double seconds);

  /// @}
};
