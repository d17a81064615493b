// SPDX-License-Identifier: GPL-3.0-or-later
//
// Deform-to-fit building blocks: the linearized feasible region F(v) is
// conservative (points strictly inside give exactly certified triangles),
// contains the initial meshes' vertices, and is not needlessly small; the
// fast 3-variable QP solver agrees with CGAL's exact one.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>
#include <CGAL/Nonobtuse_remeshing/deform_to_fit.h>
#include <CGAL/Nonobtuse_remeshing/internal/feasible_region.h>
#include <CGAL/Nonobtuse_remeshing/internal/small_qp.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <random>
#include <string>

namespace NR = CGAL::Nonobtuse_remeshing;
using namespace CGAL::Nonobtuse_remeshing::internal;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

namespace {

Mesh initial_mesh(const std::string& name, int resolution)
{
  const Mesh input = nonobtuse_test::load(name);
  Mesh output;
  NR::nonobtuse_marching_cubes(input, output, NR::parameters::resolution(resolution));
  return output;
}

// An initial mesh after deform-to-fit: its one-rings are no longer the
// Marching Cubes configurations.
Mesh fitted_mesh(const std::string& name, int resolution)
{
  Mesh m = initial_mesh(name, resolution);
  NR::deform_to_fit(m, nonobtuse_test::load(name));
  return m;
}

// The one-ring of v: frame (centred on v, scaled by its longest edge),
// F(v) in that frame, and the edges opposite v.
struct One_ring
{
  Local_frame frame;
  std::vector<Half_space> region;
  std::vector<std::pair<Point, Point> > opposite;
};

bool one_ring(const Mesh& m, Mesh::Vertex_index v, int k, One_ring& ring)
{
  ring.frame.origin = Eigen::Vector3d(m.point(v).x(), m.point(v).y(), m.point(v).z());
  ring.frame.scale = 0.;
  for(auto w : vertices_around_target(m.halfedge(v), m))
    ring.frame.scale = std::max(ring.frame.scale, std::sqrt(CGAL::squared_distance(m.point(v), m.point(w))));
  ring.region.clear();
  ring.opposite.clear();
  for(auto h : halfedges_around_target(m.halfedge(v), m))
    if(!m.is_border(h)) ring.opposite.emplace_back(m.point(m.target(m.next(h))), m.point(m.source(h)));
  return vertex_feasible_region(m, m.points(), v, k, ring.frame, ring.region);
}

double min_slack(const std::vector<Half_space>& region, const Eigen::Vector3d& x)
{
  double s = 1e300;
  for(const Half_space& h : region) s = std::min(s, h.slack(x));
  return s;
}

bool certified(const One_ring& ring, const Eigen::Vector3d& local)
{
  const Eigen::Vector3d g = ring.frame.to_global(local);
  const Point p(g[0], g[1], g[2]);
  const NR::Angle_bounds bounds;
  for(const auto& e : ring.opposite)
    if(!triangle_verdict(p, e.first, e.second, bounds).within_bounds()) return false;
  return true;
}

} // namespace

// (a) every vertex of the initial meshes lies in the closure of its F(v)
TEST(FeasibleRegion, InitialMeshVerticesLieInTheirRegion)
{
  for(const std::string name : {"sphere.off", "pig.off", "elephant.off", "nefertiti.off"}) {
    const Mesh m = initial_mesh(name, 40);
    std::size_t checked = 0;
    for(auto v : m.vertices()) {
      One_ring ring;
      ASSERT_TRUE(one_ring(m, v, 2, ring));
      EXPECT_GE(min_slack(ring.region, Eigen::Vector3d::Zero()), -1e-12) << name;
      EXPECT_EQ(ring.region.size(), ring.opposite.size() * (5 + 4 * 2));
      ++checked;
    }
    EXPECT_GT(checked, 1000u);
  }
}

// (b) a million points strictly inside F(v) of real one-rings, spread by a
// hit-and-run walk from the vertex, all give exactly certified triangles;
// one-rings of initial meshes and of fitted ones
TEST(FeasibleRegion, PointsStrictlyInsideAreCertified)
{
  std::mt19937_64 rng(42);
  std::normal_distribution<double> gauss(0., 1.);
  std::uniform_real_distribution<double> uniform(0., 1.);
  std::size_t samples = 0, rejected = 0;
  for(const std::string name : {"sphere.off", "pig.off", "elephant.off", "mesh_with_border.off", "fitted pig.off",
                                "fitted elephant.off"}) {
    const Mesh m = name.rfind("fitted ", 0) == 0 ? fitted_mesh(name.substr(7), 40)
                                                 : initial_mesh(name, name == "sphere.off" ? 30 : 50);
    for(int k : {1, 2, 4}) {
      for(auto v : m.vertices()) {
        One_ring ring;
        ASSERT_TRUE(one_ring(m, v, k, ring));
        Eigen::Vector3d x = Eigen::Vector3d::Zero();
        for(int step = 0; step < 50; ++step) {
          const Eigen::Vector3d d = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
          double lo = -1e300, hi = 1e300;
          for(const Half_space& h : ring.region) {
            const double nd = h.normal.dot(d), t = -h.slack(x) / nd;
            if(nd > 0) lo = std::max(lo, t);
            else if(nd < 0) hi = std::min(hi, t);
          }
          if(!(hi > lo)) break;
          x += (lo + (hi - lo) * uniform(rng)) * d;
          if(min_slack(ring.region, x) <= 1e-9) continue;  // strictly inside only
          ++samples;
          if(!certified(ring, x)) ++rejected;
        }
      }
    }
  }
  EXPECT_GE(samples, 1000000u);
  EXPECT_EQ(rejected, 0u);
}

// (c) F(v) is a fair part of the true region: the volume ratio, estimated by
// uniform samples in the ring's box, on interior valence-6 vertices
TEST(FeasibleRegion, RegionIsNotNeedlesslySmall)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  const Mesh m = initial_mesh("sphere.off", 30);
  double ratio_sum = 0.;
  int rings = 0;
  for(auto v : m.vertices()) {
    if(m.is_border(v) || m.degree(v) != 6 || rings >= 20) continue;
    One_ring ring;
    ASSERT_TRUE(one_ring(m, v, 2, ring));
    std::size_t in_region = 0, in_truth = 0;
    for(int i = 0; i < 20000; ++i) {
      const Eigen::Vector3d x(uniform(rng), uniform(rng), uniform(rng));
      const bool inside = min_slack(ring.region, x) >= 0.;
      const bool truth = certified(ring, x);
      in_region += inside;
      in_truth += truth;
      EXPECT_FALSE(inside && !truth);
    }
    if(in_truth < 100) continue;  // a ring held by exact right angles has (almost) no volume to compare
    ratio_sum += double(in_region) / double(in_truth);
    ++rings;
  }
  ASSERT_GE(rings, 10);
  const double ratio = ratio_sum / rings;
  std::cout << "[ measured ] mean volume ratio F(v) / true region, k = 2, " << rings << " one-rings: " << ratio
            << "\n";
  EXPECT_GT(ratio, 0.1);
  EXPECT_LE(ratio, 1.);
}

TEST(FeasibleRegion, CollapseRegionUsesTheSurvivingFaces)
{
  const Mesh m = initial_mesh("sphere.off", 20);
  const auto h = *m.halfedges().begin();
  Local_frame frame;
  frame.origin = Eigen::Vector3d(m.point(m.target(h)).x(), m.point(m.target(h)).y(), m.point(m.target(h)).z());
  frame.scale = 1.;
  std::vector<Half_space> region;
  ASSERT_TRUE(collapse_feasible_region(m, m.points(), h, 2, frame, region));
  const std::size_t surviving = m.degree(m.source(h)) + m.degree(m.target(h)) - 4;  // closed mesh
  EXPECT_EQ(region.size(), surviving * (5 + 4 * 2));
}

namespace {

// Random instances whose feasible set contains a ball; every tenth one is
// made infeasible.
Small_qp random_qp(std::mt19937_64& rng, bool infeasible)
{
  std::normal_distribution<double> gauss(0., 1.);
  std::uniform_real_distribution<double> uniform(0., 1.);
  Small_qp qp;
  Eigen::Matrix3d A;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) A(i, j) = gauss(rng);
  qp.G = A * A.transpose() + 0.1 * Eigen::Matrix3d::Identity();
  qp.a = 3. * Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
  const Eigen::Vector3d centre = 0.3 * Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
  const int m = 30 + int(rng() % 100);
  for(int i = 0; i < m; ++i) {
    const Eigen::Vector3d d = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
    qp.add_constraint(-d, -(d.dot(centre) + 0.2 + uniform(rng)));
  }
  if(infeasible) {
    qp.add_constraint(Eigen::Vector3d(1, 0, 0), 5.);
    qp.add_constraint(Eigen::Vector3d(-1, 0, 0), -4.);
  }
  return qp;
}

// The two solvers agree, except on regions that are empty by less than the
// fast solver's tolerance: an initial mesh has exact right angles, whose
// planes pass exactly through the vertex; once rounded to double, several of
// them may miss each other by 1e-13, which CGAL's exact solver calls
// infeasible. Such a disagreement is accepted only when the fast solution
// violates no constraint by more than 1e-12, and it is counted.
void expect_same(const Small_qp& qp, const std::string& what, std::size_t& optimal, std::size_t& infeasible,
                 std::size_t* borderline = nullptr)
{
  const Qp_result fast = solve_small_qp(qp);
  const Qp_result reference = solve_small_qp_reference(qp);
  ASSERT_NE(fast.status, Qp_status::trouble) << what;
  if(borderline != nullptr && fast.status == Qp_status::optimal && reference.status == Qp_status::infeasible) {
    double violation = 0.;
    for(std::size_t i = 0; i < qp.normals.size(); ++i)
      violation = std::max(violation, qp.offsets[i] - qp.normals[i].dot(fast.x));
    ASSERT_LE(violation, 1e-12) << what;
    ++*borderline;
    return;
  }
  ASSERT_EQ(fast.status, reference.status) << what;
  if(fast.status == Qp_status::optimal) {
    ASSERT_LE((fast.x - reference.x).norm(), 1e-9) << what;  // the one-ring size is 1 here
    ++optimal;
  } else {
    ++infeasible;
  }
}

} // namespace

// The fast solver against CGAL's on 10^4 instances: random ones, and real
// feasible regions of initial meshes with a smoothing objective pulled
// towards a random target, so that constraints are active.
TEST(SmallQp, FastSolverMatchesCgalReference)
{
  std::mt19937_64 rng(2024);
  std::size_t optimal = 0, infeasible = 0;
  for(int i = 0; i < 5000; ++i) expect_same(random_qp(rng, i % 10 == 0), "random " + std::to_string(i), optimal, infeasible);
  std::normal_distribution<double> gauss(0., 1.);
  std::size_t real = 0, borderline = 0;
  for(const std::string name : {"sphere.off", "pig.off", "elephant.off"}) {
    const Mesh m = initial_mesh(name, 40);
    std::size_t taken = 0;
    for(auto v : m.vertices()) {
      if(taken++ == 1700) break;
      One_ring ring;
      ASSERT_TRUE(one_ring(m, v, 2, ring));
      Small_qp qp;
      qp.G = 2. * Eigen::Matrix3d::Identity();  // |x - target|^2
      const Eigen::Vector3d target = 0.5 * Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
      qp.a = -2. * target;
      qp.normals.reserve(ring.region.size());
      for(const Half_space& h : ring.region) qp.add_constraint(h.normal, h.offset);
      expect_same(qp, name, optimal, infeasible, &borderline);
      ++real;
    }
  }
  std::cout << "[ measured ] " << optimal << " optimal, " << infeasible << " infeasible, " << borderline
            << " borderline of " << real << " real instances\n";
  EXPECT_GE(optimal + infeasible + borderline, 10000u);
  EXPECT_GT(infeasible, 400u);
  EXPECT_GE(real, 5000u);
  EXPECT_LT(borderline, real / 20);
}
