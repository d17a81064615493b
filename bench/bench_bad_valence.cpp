// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bad-valence removal benchmark in the layout of the thesis's Table 7.1: for
// each mesh, the initial mesh's vertices and bad-valence counts (v2, v3 with
// its border part, interior v4), the same after removal only (the thesis's
// section 5.7) and after removal and split (the default), the seconds, and
// whether the result certifies with its topology unchanged.
//
//   bench_bad_valence [N] mesh.off...      (N defaults to 100)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>

#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <iostream>
#include <string>

#include "bench_main.h"

namespace NR = CGAL::Nonobtuse_remeshing;
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

namespace {

std::string counts(const NR::Valence_counts& c)
{
  std::ostringstream s;
  s << std::setw(5) << c.valence_2 << std::setw(6) << c.valence_3() << std::setw(6) << c.border_valence_3
    << std::setw(6) << c.interior_valence_4;
  return s.str();
}

bool same_topology(const NR::Quality_report& a, const NR::Quality_report& b)
{
  return a.euler_characteristic == b.euler_characteristic && a.border_cycles == b.border_cycles &&
         a.connected_components == b.connected_components && b.non_manifold_vertices == 0;
}

} // namespace

int nonobtuse_bench::bench_bad_valence(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: bench_bad_valence [N] mesh.off...\n";
    return 2;
  }
  int first = 1, resolution = 100;
  if(std::string(argv[1]).find_first_not_of("0123456789") == std::string::npos) {
    resolution = std::atoi(argv[1]);
    first = 2;
  }
  std::size_t before_all = 0, removal_all = 0, split_all = 0;
  std::cout << std::fixed << std::setprecision(3)
            << "mesh                     V_in     initial: v2    v3 (brd) int-v4   removal only: v2 v3 (brd) int-v4"
               "   removal+split: v2 v3 (brd) int-v4   V_out   splits  seconds  certified+topology\n";
  for(int a = first; a < argc; ++a) {
    Mesh input, initial;
    NR::read_triangle_mesh(argv[a], input);
    NR::nonobtuse_marching_cubes(input, initial, NR::parameters::resolution(resolution));
    const NR::Quality_report start = NR::quality_report(initial);
    Mesh removed = initial, split = initial;
    const auto r = NR::remove_bad_valence_vertices(removed, NR::parameters::vertex_split(false));
    const auto s = NR::remove_bad_valence_vertices(split);
    split.collect_garbage();
    removed.collect_garbage();
    const NR::Quality_report end = NR::quality_report(split), end_removed = NR::quality_report(removed);
    const bool ok = end.certified && end_removed.certified && same_topology(start, end) &&
                    same_topology(start, end_removed);
    std::string name = argv[a];
    name = name.substr(name.find_last_of('/') + 1);
    std::cout << std::left << std::setw(22) << name << std::right << std::setw(7) << s.vertices_before << "        "
              << counts(s.before) << "        " << counts(r.after) << "         " << counts(s.after) << std::setw(9)
              << s.vertices_after << std::setw(8) << s.splits << std::setw(9) << s.seconds << "  "
              << (ok ? "yes" : "NO") << "\n";
    before_all += s.before.total();
    removal_all += r.after.total();
    split_all += s.after.total();
  }
  std::cout << "bad vertices: " << before_all << " initially, " << removal_all << " after removal only ("
            << 100. * double(before_all - removal_all) / double(before_all) << "% gone), " << split_all
            << " after removal and split (" << 100. * double(before_all - split_all) / double(before_all)
            << "% gone)\n";
  return 0;
}
