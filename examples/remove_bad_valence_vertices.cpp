// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 2 (thesis, section 5.7): removal of bad-valence vertices from the
// initial mesh, and vertex splits for those that removal cannot reach. The
// counts before and after are the columns of the thesis's Table 7.1.
// The mesh is a CGAL::Polyhedron_3 here: every function of the package
// takes any FaceGraph (the other examples use CGAL::Surface_mesh).
//
//   remove_bad_valence_vertices INPUT OUTPUT [RESOLUTION]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>
#include <CGAL/Nonobtuse_remeshing/remove_bad_valence_vertices.h>

#include <cstdlib>
#include <iostream>
#include <stdexcept>

namespace NR = CGAL::Nonobtuse_remeshing;
using Mesh = CGAL::Polyhedron_3<CGAL::Exact_predicates_inexact_constructions_kernel>;

int main(int argc, char** argv)
{
  if(argc != 3 && argc != 4) {
    std::cerr << "usage: remove_bad_valence_vertices INPUT OUTPUT [RESOLUTION]\n";
    return 2;
  }
  try {
    Mesh input, mesh;
    NR::read_triangle_mesh(argv[1], input);
    NR::nonobtuse_marching_cubes(input, mesh, NR::parameters::resolution(argc == 4 ? std::atoi(argv[3]) : 60));
    const NR::Bad_valence_removal_statistics s = NR::remove_bad_valence_vertices(mesh);
    std::cout << "vertices " << s.vertices_before << " -> " << s.vertices_after << "; bad valences (v2, v3, interior v4) "
              << s.before.valence_2 << ", " << s.before.valence_3() << ", " << s.before.interior_valence_4 << " -> "
              << s.after.valence_2 << ", " << s.after.valence_3() << ", " << s.after.interior_valence_4 << "; "
              << s.splits << " splits, " << s.refused << " operations refused by the exact certification\n";
    NR::write_mesh_atomically(argv[2], mesh, NR::certifying_check(mesh));
    std::cout << "wrote " << argv[2] << ", certified in [30, 90] degrees\n";
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
