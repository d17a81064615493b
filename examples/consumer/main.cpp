// SPDX-License-Identifier: GPL-3.0-or-later
//
// Links the installed package: certifies a mesh and prints its verdict.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>

#include <iostream>

int main(int argc, char** argv)
{
  namespace NR = CGAL::Nonobtuse_remeshing;
  using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  if(argc != 2) {
    std::cerr << "usage: consumer MESH\n";
    return 2;
  }
  Mesh mesh;
  try {
    NR::read_triangle_mesh(argv[1], mesh);
  } catch(const NR::Bad_input& e) {
    std::cerr << "bad input: " << e.what() << "\n";
    return 3;
  }
  const auto certificate = NR::certify_angle_bounds(mesh);
  std::cout << "faces " << certificate.faces << " certified "
            << (certificate.is_certified() ? "yes" : "no") << "\n";
  return 0;
}
