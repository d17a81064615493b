// SPDX-License-Identifier: GPL-3.0-or-later
//
// The benchmarks' main: a bad file or parameter ends the run with a one-line
// error and exit code 3, as in the tool, instead of an uncaught exception.

#ifndef NONOBTUSE_BENCH_MAIN_H
#define NONOBTUSE_BENCH_MAIN_H

#include <exception>
#include <iostream>

namespace nonobtuse_bench {

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
