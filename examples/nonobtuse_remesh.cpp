// SPDX-License-Identifier: GPL-3.0-or-later
//
// The whole pipeline: any triangle mesh to a certified well-shaped nonobtuse
// mesh of about V vertices, then two coarser levels of detail. A visitor
// prints each stage and cancels the fit after a time budget; whatever
// happens, the output is certified in [30, 90] degrees, on the written file.
//
//   nonobtuse_remesh INPUT OUTPUT_BASE [TARGET_VERTICES [MAX_SECONDS]]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>

#include <chrono>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>

namespace NR = CGAL::Nonobtuse_remeshing;
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

struct Console_visitor
{
  double max_seconds;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  void stage_started(NR::Remeshing_stage stage) { std::cout << "stage " << int(stage) + 1 << " started\n"; }
  void stage_finished(NR::Remeshing_stage stage, double seconds)
  {
    std::cout << "stage " << int(stage) + 1 << " finished in " << seconds << " s\n";
  }
  bool keep_going(const NR::Remeshing_progress&)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < max_seconds;
  }
};

int main(int argc, char** argv)
{
  if(argc < 3 || argc > 5) {
    std::cerr << "usage: nonobtuse_remesh INPUT OUTPUT_BASE [TARGET_VERTICES [MAX_SECONDS]]\n";
    return 2;
  }
  try {
    Mesh input, output;
    NR::read_triangle_mesh(argv[1], input);
    Console_visitor visitor{argc == 5 ? std::atof(argv[4]) : 60.};
    const NR::Nonobtuse_remeshing_statistics s = NR::nonobtuse_remesh(
        input, output,
        NR::parameters::combine(NR::parameters::target_vertices(std::size_t(argc >= 4 ? std::atoll(argv[3]) : 5000)),
                                NR::parameters::remeshing_visitor(std::ref(visitor))));
    std::cout << "resolution " << s.resolution << ": " << vertices(output).size() << " vertices, fit rms distance "
              << s.fit.rms_distance << "% of the diagonal" << (s.cancelled ? " (cancelled: out of time)" : "") << "\n";
    const std::string base = argv[2];
    NR::write_mesh_atomically(base + ".off", output, NR::certifying_check(output));

    const auto levels = NR::angle_bounded_decimation_hierarchy(output, {0.5, 0.1});
    for(std::size_t i = 0; i < levels.size(); ++i)
      NR::write_mesh_atomically(base + "_lod" + std::to_string(i + 1) + ".off", levels[i].mesh,
                                NR::certifying_check(levels[i].mesh));
    const NR::Quality_report report = NR::quality_report(output, &input);
    std::cout << "wrote " << base << ".off and " << levels.size() << " levels, all certified in [30, 90] degrees; "
              << "Hausdorff distance to the input " << report.distance->hausdorff_symmetric << "% of its diagonal\n";
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
