// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1 (thesis, chapter 4): the initial mesh by nonobtuse Marching Cubes.
// Its vertices lie at cube-edge midpoints and cube centres, so every angle
// lies in [35.26, 90] degrees; the written file is certified on re-reading.
//
//   nonobtuse_marching_cubes INPUT OUTPUT [RESOLUTION]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>

#include <cstdlib>
#include <iostream>
#include <stdexcept>

namespace NR = CGAL::Nonobtuse_remeshing;
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

int main(int argc, char** argv)
{
  if(argc != 3 && argc != 4) {
    std::cerr << "usage: nonobtuse_marching_cubes INPUT OUTPUT [RESOLUTION]\n";
    return 2;
  }
  try {
    Mesh input, initial;
    NR::read_triangle_mesh(argv[1], input);
    const int resolution = argc == 4 ? std::atoi(argv[3]) : 60;
    // patch-based corner signs (the default) work for open inputs too
    const NR::Marching_cubes_result r =
        NR::nonobtuse_marching_cubes(input, initial, NR::parameters::resolution(resolution));
    std::cout << "grid " << r.resolution << ": " << r.triangles_out << " triangles, " << r.borders_out
              << " borders, " << r.patches_ignored << " patches ignored, angles in [" << r.min_angle << ", "
              << r.max_angle << "]\n";
    NR::write_mesh_atomically(argv[2], initial, NR::certifying_check(initial));
    std::cout << "wrote " << argv[2] << ", certified in [30, 90] degrees\n";
  } catch(const std::exception& e) {  // Bad_input, Output_error, invalid_argument
    std::cerr << "error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
