// SPDX-License-Identifier: GPL-3.0-or-later
//
// Deform-to-fit on several cores: for each mesh, the initial mesh for about V
// vertices (Marching Cubes and the valence stage, as nonobtuse_remesh builds
// it), then the fit with 1 to T threads, R times each, the thread counts in
// turn (the fastest run counts: shared machines are noisy). Prints the
// seconds per thread count, the speedup of T threads over one, the QP solves
// per vertex, and whether every run gave the same points, bit for bit; last,
// the median speedup. Not a test: run by hand, numbers go to the README.
//
//   bench_threads [--target-vertices V] [--threads T] [--repeat R] mesh.off...
//   (V defaults to 10000, T to 2, R to 5)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "bench_main.h"

namespace NR = CGAL::Nonobtuse_remeshing;
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

int nonobtuse_bench::bench_threads(int argc, char** argv)
{
  std::size_t target = 10000;
  int max_threads = 2, repeat = 5;
  std::vector<std::string> paths;
  for(int i = 1; i < argc; ++i) {
    if(std::strcmp(argv[i], "--target-vertices") == 0 && i + 1 < argc) target = std::size_t(std::atol(argv[++i]));
    else if(std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) max_threads = std::atoi(argv[++i]);
    else if(std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) repeat = std::atoi(argv[++i]);
    else paths.push_back(argv[i]);
  }
  if(paths.empty() || max_threads < 1 || repeat < 1) {
    std::cerr << "usage: bench_threads [--target-vertices V] [--threads T] [--repeat R] mesh.off...\n";
    return 2;
  }
  std::cout << "fit seconds (fastest of " << repeat << "), initial meshes for about " << target << " vertices\n"
            << std::left << std::setw(22) << "mesh" << std::right << std::setw(9) << "vertices";
  for(int t = 1; t <= max_threads; ++t) std::cout << std::setw(9) << (std::to_string(t) + " thr");
  std::cout << std::setw(9) << "speedup" << std::setw(10) << "QP/vertex" << "  identical\n";
  std::vector<double> speedups;
  for(const std::string& path : paths) {
    Mesh input, initial;
    NR::read_triangle_mesh(path, input);
    NR::nonobtuse_remesh(input, initial,
                         NR::parameters::combine(NR::parameters::target_vertices(target),
                                                 NR::parameters::stop_after(NR::Remeshing_stage::valence)));
    std::vector<double> best(std::size_t(max_threads) + 1, 1e300);
    std::vector<double> reference;
    bool identical = true;
    std::size_t solves = 0;
    for(int run = 0; run < repeat; ++run)
      for(int t = 1; t <= max_threads; ++t) {
        Mesh mesh = initial;
        const NR::Deform_to_fit_statistics s =
            NR::deform_to_fit(mesh, input, NR::parameters::number_of_threads(t));
        best[std::size_t(t)] = (std::min)(best[std::size_t(t)], s.seconds);
        solves = s.qp_solves;
        std::vector<double> points;
        for(auto v : vertices(mesh))
          for(int c = 0; c < 3; ++c) points.push_back(mesh.point(v)[c]);
        if(reference.empty()) reference = points;
        else if(points != reference) identical = false;
      }
    const double speedup = best[1] / best[std::size_t(max_threads)];
    speedups.push_back(speedup);
    std::cout << std::left << std::setw(22) << path.substr(path.find_last_of('/') + 1) << std::right << std::setw(9)
              << vertices(initial).size() << std::fixed << std::setprecision(3);
    for(int t = 1; t <= max_threads; ++t) std::cout << std::setw(9) << best[std::size_t(t)];
    std::cout << std::setprecision(2) << std::setw(9) << speedup << std::setprecision(1) << std::setw(10)
              << double(solves) / double(vertices(initial).size()) << "  " << (identical ? "yes" : "NO") << "\n"
              << std::defaultfloat;
  }
  std::sort(speedups.begin(), speedups.end());
  const std::size_t m = speedups.size();
  std::cout << "median speedup with " << max_threads << " threads: " << std::setprecision(3)
            << (m % 2 ? speedups[m / 2] : 0.5 * (speedups[m / 2 - 1] + speedups[m / 2])) << "\n";
  return 0;
}
