// SPDX-License-Identifier: GPL-3.0-or-later
//
// Angle-bounded decimation benchmark (thesis, chapter 6 and Figures
// 7.1-7.6): each input is remeshed as `remesh` does (init, valence, fit at
// resolution N), then decimated into the levels 0.5 and 0.1 (50% and 90% of
// the vertices removed) in one run. Per level: vertices, seconds from the
// full mesh, why it stopped, exact certification, topology kept (Euler
// characteristic, borders, components, manifold), and the Hausdorff distance
// to the full-resolution nonobtuse mesh in % of its diagonal; the refusals
// (attempts), the largest collapse error (% of the diagonal), the rounds and
// the seconds of relaxation among the level's seconds.
//
//   bench_decimation [N] [--max-error PCT] [-k K] mesh.off...      (N defaults to 100)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>

#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "bench_main.h"

namespace NR = CGAL::Nonobtuse_remeshing;
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

namespace {

const char* reason(NR::Decimation_stop_reason r)
{
  switch(r) {
  case NR::Decimation_stop_reason::target_reached: return "target";
  case NR::Decimation_stop_reason::max_error: return "max-error";
  case NR::Decimation_stop_reason::no_collapse_left: return "no-collapse";
  case NR::Decimation_stop_reason::round_limit: return "round-limit";
  case NR::Decimation_stop_reason::cancelled: return "cancelled";
  }
  return "?";
}

} // namespace

int nonobtuse_bench::bench_decimation(int argc, char** argv)
{
  int resolution = 100;
  double max_error = 0.;
  int k = 2;
  std::vector<std::string> paths;
  for(int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if(arg == "--max-error" && a + 1 < argc) max_error = std::atof(argv[++a]);
    else if(arg == "-k" && a + 1 < argc) k = std::atoi(argv[++a]);
    else if(arg.find_first_not_of("0123456789") == std::string::npos) resolution = std::atoi(arg.c_str());
    else paths.push_back(arg);
  }
  if(paths.empty()) {
    std::cerr << "usage: bench_decimation [N] [--max-error PCT] mesh.off...\n";
    return 2;
  }
  std::cout << std::fixed << std::setprecision(3)
            << "mesh                   full V  level  target      V   dec s  stop         QP solves  certified  "
               "topology  Hausdorff %   refusals: empty F  valence  certification  topology  largest %  rounds  "
               "relax s\n";
  for(const std::string& path : paths) {
    Mesh input, mesh;
    NR::read_triangle_mesh(path, input);
    NR::nonobtuse_marching_cubes(input, mesh, NR::parameters::resolution(resolution));
    NR::remove_bad_valence_vertices(mesh);
    mesh.collect_garbage();
    NR::deform_to_fit(mesh, input);
    const NR::Quality_report full = NR::quality_report(mesh);
    const auto levels = NR::angle_bounded_decimation_hierarchy(
        mesh, {0.5, 0.1},
        NR::parameters::combine(NR::parameters::max_error(max_error > 0. ? max_error / 100. : 1e300),
                                NR::parameters::drum_subdivisions(k)));
    std::string name = path.substr(path.find_last_of('/') + 1);
    for(std::size_t i = 0; i < levels.size(); ++i) {
      const auto& level = levels[i];
      const NR::Quality_report r = NR::quality_report(level.mesh, &mesh);
      const bool topology = r.euler_characteristic == full.euler_characteristic &&
                            r.border_cycles == full.border_cycles &&
                            r.connected_components == full.connected_components && r.non_manifold_vertices == 0;
      std::cout << std::left << std::setw(20) << name << std::right << std::setw(9) << vertices(mesh).size()
                << std::setw(7) << (i == 0 ? 0.5 : 0.1) << std::setw(8) << level.target_vertices << std::setw(7)
                << vertices(level.mesh).size() << std::setw(8) << level.statistics.seconds << "  " << std::left
                << std::setw(12) << (level.reached ? "reached" : reason(level.statistics.stop_reason))
                << std::right << std::setw(10) << level.statistics.qp_solves << "  " << std::setw(9)
                << (r.certified ? "yes" : "NO") << "  " << std::setw(8) << (topology ? "kept" : "CHANGED")
                << std::setw(13) << r.distance->hausdorff_symmetric << std::setw(19)
                << level.statistics.empty_regions << std::setw(9) << level.statistics.valence_refusals
                << std::setw(15) << level.statistics.certification_refusals << std::setw(10)
                << level.statistics.topology_refusals << std::setw(11) << 100. * level.statistics.largest_collapse_error
                << std::setw(8) << level.statistics.rounds << std::setw(9) << level.statistics.relaxation_seconds << "\n"
                << std::flush;
    }
  }
  return 0;
}
