// SPDX-License-Identifier: GPL-3.0-or-later
//
// The benchmarks: each is a function, compiled together into one library
// (one unity file: each file alone would parse CGAL's headers again), and
// each program is bench_main.cpp calling one of them. A bad file or
// parameter ends the run with a one-line error and exit code 3, as in the
// tool, instead of an uncaught exception.

#ifndef NONOBTUSE_BENCH_MAIN_H
#define NONOBTUSE_BENCH_MAIN_H

#include <exception>
#include <iostream>

namespace nonobtuse_bench {

int bench_bad_valence(int argc, char** argv);
int bench_decimation(int argc, char** argv);
int bench_deform_to_fit(int argc, char** argv);
int bench_marching_cubes(int argc, char** argv);
int bench_small_qp(int argc, char** argv);
int bench_threads(int argc, char** argv);
int bench_vs_isotropic(int argc, char** argv);

inline int guarded(int (*bench)(int, char**), int argc, char** argv)
{
  try {
    return bench(argc, argv);
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 3;
  }
}

} // namespace nonobtuse_bench

#endif // NONOBTUSE_BENCH_MAIN_H
