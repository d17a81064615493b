// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads a mesh, certifies its angles exactly in [30, 90] degrees and in a
// user-chosen interval, and prints the quality report's topology summary.
//
//   certify_mesh mesh.off [min_degrees max_degrees]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>

#include <cstdlib>
#include <iostream>

namespace NR = CGAL::Nonobtuse_remeshing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

int main(int argc, char** argv)
{
  if(argc != 2 && argc != 4) {
    std::cerr << "usage: certify_mesh MESH [MIN_DEGREES MAX_DEGREES]\n";
    return 2;
  }
  Mesh mesh;
  try {
    NR::read_triangle_mesh(argv[1], mesh);
  } catch(const NR::Bad_input& e) {
    std::cerr << "bad input: " << e.what() << "\n";
    return 3;
  }

  const auto nonobtuse = NR::certify_angle_bounds(mesh);  // [30, 90] by default
  std::cout << "[30, 90]: " << (nonobtuse.is_certified() ? "certified" : "not certified")
            << ", angles from " << nonobtuse.min_angle << " to " << nonobtuse.max_angle << "\n";

  if(argc == 4) {
    const double lo = std::atof(argv[2]), hi = std::atof(argv[3]);
    const auto custom = NR::certify_angle_bounds(
        mesh, NR::parameters::combine(NR::parameters::min_angle(lo), NR::parameters::max_angle(hi)));
    std::cout << "[" << lo << ", " << hi << "]: "
              << (custom.is_certified() ? "certified" : "not certified") << " ("
              << custom.too_small_corners << " corners too small, " << custom.too_large_corners
              << " too large)\n";
  }

  const NR::Quality_report report = NR::quality_report(mesh);
  std::cout << "borders: " << report.border_cycles << ", components: " << report.connected_components
            << ", Euler characteristic: " << report.euler_characteristic << "\n";
  return nonobtuse.is_certified() ? 0 : 1;
}
