// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 (thesis, chapter 5): deform-to-fit. Every vertex of the initial
// mesh solves a small quadratic program over its linearized feasible region;
// each move is certified exactly before it is applied, so the mesh stays in
// [30, 90] degrees at every moment. A visitor reports progress and stops the
// fit after a budget of moves.
//
//   deform_to_fit INPUT OUTPUT [RESOLUTION [MAX_MOVES]]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Nonobtuse_remeshing/deform_to_fit.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>

#include <cstdlib>
#include <functional>
#include <iostream>
#include <stdexcept>

namespace NR = CGAL::Nonobtuse_remeshing;
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

// Prints a line every 10,000 moves and stops at the budget.
struct Budget_visitor
{
  std::size_t budget;
  std::size_t reported = 0;
  bool keep_going(const NR::Deform_to_fit_statistics& s)
  {
    if(s.moves >= reported + 10000) {
      reported = s.moves;
      std::cout << "  " << s.moves << " moves, rms vertex distance " << s.rms_distance << "% of the diagonal\n";
    }
    return s.moves < budget;
  }
};

int main(int argc, char** argv)
{
  if(argc < 3 || argc > 5) {
    std::cerr << "usage: deform_to_fit INPUT OUTPUT [RESOLUTION [MAX_MOVES]]\n";
    return 2;
  }
  try {
    Mesh input, mesh;
    NR::read_triangle_mesh(argv[1], input);
    NR::nonobtuse_marching_cubes(input, mesh, NR::parameters::resolution(argc >= 4 ? std::atoi(argv[3]) : 60));
    Budget_visitor visitor{argc == 5 ? std::size_t(std::atoll(argv[4])) : std::size_t(-1)};
    const NR::Deform_to_fit_statistics s = NR::deform_to_fit(
        mesh, input,
        NR::parameters::combine(NR::parameters::alpha(0.5), NR::parameters::smoothing_steps(2),
                                NR::parameters::fit_visitor(std::ref(visitor))));
    std::cout << s.moves << " moves (" << s.smoothing_moves << " by smoothing) in " << s.seconds << " s; rms vertex "
              << "distance " << s.rms_distance << "% of the diagonal" << (s.cancelled ? "; stopped at the budget" : "")
              << "\n";
    NR::write_mesh_atomically(argv[2], mesh, NR::certifying_check(mesh));
    std::cout << "wrote " << argv[2] << ", certified in [30, 90] degrees\n";
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
