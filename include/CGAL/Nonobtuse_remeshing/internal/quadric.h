// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quadric error: a sum of squared distances to planes (Garland and Heckbert;
// the thesis's equation 5.10) and, for border vertices in decimation, to
// points (equation 6.3). Additive, so a collapsed vertex takes the sum of
// its two ends' quadrics (section 6.3).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_QUADRIC_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_QUADRIC_H

#include <Eigen/Dense>

#include <cstddef>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

/// Q(x) = x^T A x + 2 b.x + c, with the number of planes it sums.
struct Quadric
{
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();  // sum n n^T (+ I per point)
  Eigen::Vector3d b = Eigen::Vector3d::Zero();  // sum d n (- w per point)
  double c = 0.;                                // sum d^2 (+ |w|^2 per point)
  std::size_t planes = 0;

  /// The plane n.x + d = 0, n of unit length (equation 5.10).
  void add_plane(const Eigen::Vector3d& n, double d)
  {
    A += n * n.transpose();
    b += d * n;
    c += d * d;
    ++planes;
  }
  /// |x - w|^2 (equation 6.3).
  void add_point(const Eigen::Vector3d& w)
  {
    A += Eigen::Matrix3d::Identity();
    b -= w;
    c += w.squaredNorm();
  }
  Quadric& operator+=(const Quadric& other)
  {
    A += other.A;
    b += other.b;
    c += other.c;
    planes += other.planes;
    return *this;
  }
  double operator()(const Eigen::Vector3d& x) const { return x.dot(A * x) + 2. * b.dot(x) + c; }
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_QUADRIC_H
