// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of the initial mesh (nonobtuse Marching Cubes): seconds per
// resolution on the given meshes, and on a closed mesh of about 75,000
// triangles made by Loop subdivision of the first one. Not a test: run by
// hand, numbers go to the issue notes.
//
//   bench_marching_cubes [--repeat R] MESH...

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "bench_main.h"

namespace NR = CGAL::Nonobtuse_remeshing;
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

namespace {

// Best of `repeat` runs, in seconds, and the last result.
double time_init(const Mesh& input, int resolution, int repeat, NR::Marching_cubes_result& result)
{
  double best = 1e300;
  for(int i = 0; i < repeat; ++i) {
    Mesh output;
    const auto start = std::chrono::steady_clock::now();
    result = NR::nonobtuse_marching_cubes(input, output, NR::parameters::resolution(resolution));
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

void run(const std::string& name, const Mesh& input, int repeat)
{
  for(int resolution : {10, 40, 70, 100}) {
    NR::Marching_cubes_result r;
    const double seconds = time_init(input, resolution, repeat, r);
    std::cout << std::left << std::setw(28) << name << std::right << std::setw(8) << num_faces(input)
              << std::setw(6) << resolution << std::setw(10) << r.triangles_out << std::setw(6) << r.borders_out
              << std::setw(9) << r.patches_ignored << std::setw(9) << r.faces_stitched << std::setw(10)
              << std::fixed << std::setprecision(3) << seconds << "\n"
              << std::defaultfloat;
  }
}

} // namespace

int nonobtuse_bench::bench_marching_cubes(int argc, char** argv)
{
  int repeat = 3;
  std::vector<std::string> paths;
  for(int i = 1; i < argc; ++i) {
    if(std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else paths.push_back(argv[i]);
  }
  if(paths.empty()) {
    std::cerr << "usage: bench_marching_cubes [--repeat R] MESH...\n";
    return 2;
  }
  std::cout << "mesh                        in-tris     N  out-tris  bord  ignored stitched   seconds\n";
  Mesh first;
  for(const std::string& path : paths) {
    Mesh input;
    NR::read_triangle_mesh(path, input);
    if(first.is_empty()) first = input;
    run(path.substr(path.find_last_of('/') + 1), input, repeat);
  }
  // a closed input of about 75,000 triangles (25,000 to 100,000): the first
  // mesh, Loop-subdivided while that stays at most 100,000 triangles
  Mesh fine = first;
  while(num_faces(fine) * 4 <= 100000) CGAL::Subdivision_method_3::Loop_subdivision(fine);
  run("subdivided first mesh", fine, repeat);
  return 0;
}
