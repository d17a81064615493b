// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 4 (thesis, chapter 6): angle-bounded decimation of a certified mesh
// into a hierarchy of coarser meshes, every level certified in [30, 90]
// degrees. Level i is written as OUTPUT_BASE_i.off.
//
//   angle_bounded_decimation CERTIFIED_MESH OUTPUT_BASE [RATIO...]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Nonobtuse_remeshing/angle_bounded_decimation.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>

#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace NR = CGAL::Nonobtuse_remeshing;
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

int main(int argc, char** argv)
{
  if(argc < 3) {
    std::cerr << "usage: angle_bounded_decimation CERTIFIED_MESH OUTPUT_BASE [RATIO...]\n";
    return 2;
  }
  try {
    Mesh mesh;
    NR::read_triangle_mesh(argv[1], mesh);
    std::vector<double> ratios;
    for(int i = 3; i < argc; ++i) ratios.push_back(std::atof(argv[i]));
    if(ratios.empty()) ratios = {0.5, 0.25, 0.1};
    // one decimation hands out a level at each ratio; max_error stops it
    // early where collapses would move the surface more than 2% of the diagonal
    const auto levels = NR::angle_bounded_decimation_hierarchy(mesh, ratios, NR::parameters::max_error(0.02));
    for(std::size_t i = 0; i < levels.size(); ++i) {
      const auto& level = levels[i];
      const std::string path = std::string(argv[2]) + "_" + std::to_string(i + 1) + ".off";
      std::cout << "level " << i + 1 << ": " << vertices(level.mesh).size() << " vertices (target "
                << level.target_vertices << (level.reached ? ", reached" : ", not reached") << "), "
                << level.statistics.collapses << " collapses, " << level.statistics.rounds << " rounds\n";
      NR::write_mesh_atomically(path, level.mesh, NR::certifying_check(level.mesh));
      std::cout << "wrote " << path << ", certified in [30, 90] degrees\n";
    }
    return levels.size() == ratios.size() ? 0 : 1;
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 3;
  }
}
