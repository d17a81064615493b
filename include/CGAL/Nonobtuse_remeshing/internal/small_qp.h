// SPDX-License-Identifier: GPL-3.0-or-later
//
// The per-vertex quadratic program of deform-to-fit (thesis, equation 5.15)
// and of the collapse placement (equations 6.1-6.2): three variables,
//   minimize 1/2 x^T G x + a^T x   subject to   n_i . x >= b_i,
// with G symmetric positive definite and a few dozen to a few hundred
// half-spaces.
//
// Fast path: the dual active-set method of Goldfarb and Idnani (1983), in
// double. It starts from the unconstrained minimum and adds the most violated
// constraint while keeping the active set dual-feasible; with three
// variables the active set has at most three independent normals, so its
// projections are recomputed directly from G^-1 (no factor updates).
// Reference: CGAL's exact QP solver, used in tests and as the fallback when
// the fast path reports trouble. Neither is what makes a move safe: every
// move is certified exactly afterwards.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_SMALL_QP_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_SMALL_QP_H

#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <boost/container/static_vector.hpp>

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

struct Small_qp
{
  Eigen::Matrix3d G = Eigen::Matrix3d::Identity();
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> normals;  // constraint i: normals[i] . x >= offsets[i]
  std::vector<double> offsets;

  void add_constraint(const Eigen::Vector3d& normal, double offset)
  {
    normals.push_back(normal);
    offsets.push_back(offset);
  }
  double objective(const Eigen::Vector3d& x) const { return 0.5 * x.dot(G * x) + a.dot(x); }
};

enum class Qp_status { optimal, infeasible, trouble };

// Active-set matrices: at most three columns, kept on the stack.
using Matrix_3_upto3 = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3>;
using Matrix_upto3 = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
using Vector_upto3 = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;

struct Qp_result
{
  Qp_status status = Qp_status::trouble;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
};

/// Goldfarb-Idnani dual active-set solver. `tolerance` is the constraint
/// violation accepted at the optimum, in the units of the offsets (the caller
/// scales the problem to the one-ring size).
inline Qp_result solve_small_qp(const Small_qp& qp, double tolerance = 1e-12, int max_iterations = 200)
{
  Qp_result result;
  const Eigen::LLT<Eigen::Matrix3d> cholesky(qp.G);
  if(cholesky.info() != Eigen::Success) return result;  // trouble: G not positive definite
  const Eigen::Matrix3d G_inv = cholesky.solve(Eigen::Matrix3d::Identity());
  Eigen::Vector3d x = -G_inv * qp.a;

  // at most three constraints are active (a fourth is dependent, below)
  boost::container::static_vector<int, 3> active;        // indices of the active constraints
  boost::container::static_vector<double, 3> multiplier; // their Lagrange multipliers (>= 0)
  const int m = int(qp.normals.size());
  auto slack = [&](int i) { return qp.normals[i].dot(x) - qp.offsets[i]; };

  for(int iteration = 0; iteration < max_iterations; ++iteration) {
    // Step 1: the most violated constraint; none means optimal.
    int p = -1;
    double worst = -tolerance;
    for(int i = 0; i < m; ++i) {
      const double s = slack(i);
      if(s < worst) { worst = s; p = i; }
    }
    if(p < 0) {
      result.status = Qp_status::optimal;
      result.x = x;
      return result;
    }
    const Eigen::Vector3d& np = qp.normals[p];
    double u_p = 0.;  // multiplier of p while it enters

    // Step 2: move until p becomes active, dropping blocking constraints.
    for(;; ++iteration) {
      if(iteration >= max_iterations) return result;
      const int q = int(active.size());
      const Eigen::Vector3d G_inv_np = G_inv * np;
      Eigen::Vector3d z = G_inv_np;
      Vector_upto3 r(q);
      if(q > 0) {
        Matrix_3_upto3 N(3, q);
        for(int j = 0; j < q; ++j) N.col(j) = qp.normals[active[j]];
        const Matrix_upto3 M = N.transpose() * G_inv * N;
        const Eigen::FullPivLU<Matrix_upto3> lu(M);
        if(!lu.isInvertible()) return result;  // trouble: dependent active normals
        r = lu.solve(N.transpose() * G_inv_np);  // N* n_p, with N* = M^-1 N^T G^-1
        z -= G_inv * (N * r);                     // H n_p, with H = G^-1 - G^-1 N N*
      }
      // partial step: the first active multiplier to reach zero
      double t1 = std::numeric_limits<double>::infinity();
      int k = -1;
      for(int j = 0; j < q; ++j)
        if(r[j] > 0 && multiplier[j] / r[j] < t1) { t1 = multiplier[j] / r[j]; k = j; }
      // full step: p becomes active
      // n_p is (numerically) a combination of the active normals when the
      // curvature along z is negligible against the free curvature n_p.G^-1.n_p
      // With three active normals nothing is left to move along.
      const double curvature = z.dot(np);
      const bool dependent = q == 3 || curvature <= 1e-10 * G_inv_np.dot(np);
      const double t2 = dependent ? std::numeric_limits<double>::infinity() : -slack(p) / curvature;
      if(k < 0 && dependent) {
        result.status = Qp_status::infeasible;
        return result;
      }
      const double t = (std::min)(t1, t2);
      if(!dependent) x += t * z;
      for(int j = 0; j < q; ++j) multiplier[j] -= t * r[j];
      u_p += t;
      if(t == t2) {  // p joins the active set
        active.push_back(p);
        multiplier.push_back(u_p);
        break;
      }
      active.erase(active.begin() + k);  // the blocking constraint leaves
      multiplier.erase(multiplier.begin() + k);
    }
  }
  return result;
}

/// The same problem solved by CGAL's QP solver, exactly (Gmpzf).
inline Qp_result solve_small_qp_reference(const Small_qp& qp)
{
  Quadratic_program<double> program(LARGER, false, 0, false, 0);
  for(int i = 0; i < 3; ++i) {
    program.set_c(i, qp.a[i]);
    for(int j = 0; j <= i; ++j)
      if(qp.G(i, j) != 0.) program.set_d(i, j, qp.G(i, j));  // CGAL stores 2D = G
  }
  for(int row = 0; row < int(qp.normals.size()); ++row) {
    for(int i = 0; i < 3; ++i)
      if(qp.normals[row][i] != 0.) program.set_a(i, row, qp.normals[row][i]);
    program.set_b(row, qp.offsets[row]);
  }
  const Quadratic_program_solution<Gmpzf> solution = solve_quadratic_program(program, Gmpzf());
  Qp_result result;
  if(solution.is_infeasible()) {
    result.status = Qp_status::infeasible;
  } else if(solution.is_optimal()) {
    result.status = Qp_status::optimal;
    int i = 0;
    for(auto it = solution.variable_values_begin(); it != solution.variable_values_end() && i < 3; ++it, ++i)
      result.x[i] = to_double(*it);
  }
  return result;
}

/// Fast path with the reference as fallback when it reports trouble (counted
/// in `fallbacks` when given).
inline Qp_result solve_small_qp_with_fallback(const Small_qp& qp, std::size_t* fallbacks = nullptr)
{
  const Qp_result fast = solve_small_qp(qp);
  if(fast.status != Qp_status::trouble) return fast;
  if(fallbacks) ++*fallbacks;
  return solve_small_qp_reference(qp);
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_SMALL_QP_H
