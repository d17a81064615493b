// SPDX-License-Identifier: GPL-3.0-or-later
//
// The objective of one vertex in deform-to-fit (thesis, chapter 5): the
// distance term D as a quadric (equations 5.10-5.12), the smoothing term S
// (5.13, 5.14, and 5.17 alone in constrained Laplacian smoothing) and, beyond
// the thesis, the attraction of feature samples and the tangential metric,
// combined as L = alpha D + (1 - alpha) S (5.9, 5.15), and its form for the
// QP over F(v).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_FIT_OBJECTIVE_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_FIT_OBJECTIVE_H

#include <CGAL/Nonobtuse_remeshing/internal/feasible_region.h>
#include <CGAL/Nonobtuse_remeshing/internal/quadric.h>

#include <Eigen/Dense>

#include <limits>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// The objective as a sum of terms, in global coordinates:
// quadric_weight * Q(x) + sum weight * (x - point)^T metric (x - point).
struct Fit_objective
{
  struct Attractor
  {
    Eigen::Vector3d point;
    double weight;
    Eigen::Matrix3d metric;  // the identity, or the projection on a tangent plane
  };
  Quadric quadric;
  double quadric_weight = 0.;
  std::vector<Attractor> points;

  double value(const Eigen::Vector3d& x) const
  {
    double v = quadric.planes > 0 ? quadric_weight * quadric(x) : 0.;
    for(const Attractor& t : points) v += t.weight * (x - t.point).dot(t.metric * (x - t.point));
    return v;
  }

  // 1/2 x^T G x + a^T x in `frame` coordinates, x_global = origin + s x,
  // divided by s^2 so that the QP is well conditioned.
  void local_form(const Local_frame& frame, Eigen::Matrix3d& G, Eigen::Vector3d& a) const
  {
    G.setZero();
    a.setZero();
    if(quadric.planes > 0) {
      G += 2. * quadric_weight * quadric.A;
      a += 2. * quadric_weight * (quadric.A * frame.origin + quadric.b) / frame.scale;
    }
    for(const Attractor& t : points) {
      G += 2. * t.weight * t.metric;
      a += 2. * t.weight * t.metric * (frame.origin - t.point) / frame.scale;
    }
  }

  // An upper bound on how much lower the objective can be anywhere than at
  // the frame's origin, from its local form (G, a): s^2 a^T G^-1 a / 2 at the
  // unconstrained minimum, which no constrained one beats; infinity when G
  // is not positive definite.
  static double largest_decrease(const Local_frame& frame, const Eigen::Matrix3d& G, const Eigen::Vector3d& a)
  {
    const Eigen::LLT<Eigen::Matrix3d> llt(G);
    if(llt.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
    return 0.5 * frame.scale * frame.scale * a.dot(llt.solve(a));
  }
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_FIT_OBJECTIVE_H
