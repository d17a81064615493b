// SPDX-License-Identifier: GPL-3.0-or-later
//
// The main of every benchmark program: NONOBTUSE_BENCH names the benchmark
// (a function of bench_main.h), set per program by CMake.

#include "bench_main.h"

int main(int argc, char** argv) { return nonobtuse_bench::guarded(nonobtuse_bench::NONOBTUSE_BENCH, argc, argv); }
