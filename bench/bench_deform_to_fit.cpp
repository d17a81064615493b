// SPDX-License-Identifier: GPL-3.0-or-later
//
// Deform-to-fit benchmark in the layout of the thesis's Table 7.2: for each
// mesh and resolution, the fit's seconds, QP solves per second, and the
// error reached by the default fit, without lazy evaluation and without
// early smoothing. Errors are in % of the input's bounding-box diagonal.
//
//   bench_deform_to_fit [N] mesh.off...      (N defaults to 100)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>

#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>

#include "bench_main.h"

namespace NR = CGAL::Nonobtuse_remeshing;
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

int nonobtuse_bench::bench_deform_to_fit(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: bench_deform_to_fit [N] mesh.off...\n";
    return 2;
  }
  int first = 1, resolution = 100;
  if(std::string(argv[1]).find_first_not_of("0123456789") == std::string::npos) {
    resolution = std::atoi(argv[1]);
    first = 2;
  }
  std::cout << std::fixed << std::setprecision(3)
            << "mesh                  N  vertices  variant             fit s   moves    QP/s     "
               "Hausdorff %        mean %            pairs  certified\n";
  for(int a = first; a < argc; ++a) {
    Mesh input, initial;
    NR::read_triangle_mesh(argv[a], input);
    NR::nonobtuse_marching_cubes(input, initial, NR::parameters::resolution(resolution));
    const auto before = NR::quality_report(initial, &input);
    struct Variant
    {
      const char* name;
      bool lazy, early;
    };
    for(const Variant v : {Variant{"default", true, true}, Variant{"no lazy evaluation", false, true},
                           Variant{"no early smoothing", true, false}}) {
      Mesh mesh = initial;
      const auto s = NR::deform_to_fit(
          mesh, input,
          NR::parameters::combine(NR::parameters::lazy_evaluation(v.lazy), NR::parameters::early_smoothing(v.early)));
      const auto after = NR::quality_report(mesh, &input);
      std::string name = argv[a];
      name = name.substr(name.find_last_of('/') + 1);
      std::cout << std::left << std::setw(20) << name << std::right << std::setw(4) << resolution << std::setw(10)
                << s.vertices << "  " << std::left << std::setw(19) << v.name << std::right << std::setw(6)
                << s.seconds << std::setw(9) << s.moves << std::setw(9) << std::setprecision(0)
                << double(s.qp_solves) / s.seconds << std::setprecision(3) << "  "
                << before.distance->hausdorff_symmetric << " -> " << after.distance->hausdorff_symmetric << "  "
                << before.distance->mean_to_reference << " -> " << after.distance->mean_to_reference << std::setw(6)
                << after.self_intersections << "  " << (after.certified ? "yes" : "NO") << "\n"
                << std::flush;
    }
  }
  return 0;
}
