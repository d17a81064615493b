// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of the per-vertex QP: microseconds per solve of the fast
// Goldfarb-Idnani path against CGAL's exact solver, on the feasible regions
// F(v) (k = 2) of an initial mesh, with a smoothing objective pulled towards
// a random target so that constraints are active. Not a test.
//
//   bench_small_qp MESH [RESOLUTION]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>
#include <CGAL/Nonobtuse_remeshing/internal/feasible_region.h>
#include <CGAL/Nonobtuse_remeshing/internal/small_qp.h>

#include <chrono>
#include <iostream>
#include <random>

#include "bench_main.h"

namespace NR = CGAL::Nonobtuse_remeshing;
using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

int nonobtuse_bench::bench_small_qp(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: bench_small_qp MESH [RESOLUTION]\n";
    return 2;
  }
  Mesh input, mesh;
  NR::read_triangle_mesh(argv[1], input);
  NR::nonobtuse_marching_cubes(input, mesh, NR::parameters::resolution(argc > 2 ? std::atoi(argv[2]) : 40));
  std::mt19937_64 rng(1);
  std::normal_distribution<double> gauss(0., 1.);
  std::vector<NR::internal::Small_qp> problems;
  std::size_t constraints = 0;
  for(auto v : mesh.vertices()) {
    NR::internal::Local_frame frame;
    frame.origin = Eigen::Vector3d(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z());
    frame.scale = 0.;
    for(auto w : vertices_around_target(mesh.halfedge(v), mesh))
      frame.scale = std::max(frame.scale, std::sqrt(CGAL::squared_distance(mesh.point(v), mesh.point(w))));
    std::vector<NR::internal::Half_space> region;
    if(!NR::internal::vertex_feasible_region(mesh, mesh.points(), v, 2, frame, region)) continue;
    NR::internal::Small_qp qp;
    qp.G = 2. * Eigen::Matrix3d::Identity();
    qp.a = -Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
    for(const auto& h : region) qp.add_constraint(h.normal, h.offset);
    constraints += region.size();
    problems.push_back(std::move(qp));
  }
  auto time = [&](auto solve, std::size_t count) {
    const auto start = std::chrono::steady_clock::now();
    std::size_t optimal = 0;
    for(std::size_t i = 0; i < count; ++i) optimal += solve(problems[i % problems.size()]).status == NR::internal::Qp_status::optimal;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::make_pair(seconds / count, optimal);
  };
  const auto fast = time([](const NR::internal::Small_qp& qp) { return NR::internal::solve_small_qp(qp); }, problems.size() * 20);
  const auto reference = time([](const NR::internal::Small_qp& qp) { return NR::internal::solve_small_qp_reference(qp); },
                              std::min<std::size_t>(problems.size(), 2000));
  std::cout << problems.size() << " one-rings, " << double(constraints) / problems.size() << " constraints on average\n"
            << "fast (Goldfarb-Idnani): " << fast.first * 1e6 << " us per solve\n"
            << "CGAL QP (exact Gmpzf):  " << reference.first * 1e6 << " us per solve\n";
  return 0;
}
