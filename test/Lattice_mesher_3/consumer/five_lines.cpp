// The README's C++ use, as a user writes it: the front function's header first, nothing else.
#include <CGAL/lattice_mesh_3.h>
#include <iostream>

int main(int argc, char** argv)
{
  namespace LM = CGAL::Lattice_mesher_3;
  typedef CGAL::Epick K;
  LM::Polyhedral_lattice_domain_3<K> domain = LM::read_polyhedral_lattice_domain_3<K>(argv[argc - 1]);
  LM::Constant_frame_field_3<CGAL::Lattice_mesher_traits_3<K> > field;   // T = I
  LM::Tetrahedral_mesh_3<K::Point_3> mesh = CGAL::lattice_mesh_3(domain, field, CGAL::parameters::number_of_vertices(3000));
  std::cout << mesh.points.size() << " vertices, " << mesh.tets.size() << " tetrahedra\n";
  return mesh.tets.empty() ? 1 : 0;
}
