// SPDX-License-Identifier: GPL-3.0-or-later
//
// Filtered exact predicates deciding whether the angles of a triangle lie in
// [min, max], from the double coordinates as stored.
//
// At a corner with edge vectors u and v, let d = u.v and L = |u|^2 |v|^2. Then
// cos(angle) = d / sqrt(L), and with a bound written as cos = s * sqrt(q)
// (s the sign of the cosine, q its square):
//   angle <= max  <=>  cos >= s*sqrt(q)  <=>  s >= 0 ? (d >= 0 and d^2 >= q L)
//                                                   : (d >= 0 or  d^2 <= q L)
//   angle >= min  <=>  cos <= s*sqrt(q)  <=>  s >  0 ? (d <= 0 or  d^2 <= q L)
//                                                   : (d <= 0 and d^2 >= q L)
// For 90 degrees (s = 0, q = 0) the test is d >= 0; for 30 degrees (q = 3/4)
// it is d <= 0 or 4 d^2 <= 3 L (thesis, chapter 3: the well-shaped nonobtuse
// bound). Everything is a polynomial in the coordinates, so interval
// arithmetic decides almost always, and an exact rational decides the rest.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_ANGLE_PREDICATES_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_ANGLE_PREDICATES_H

#include <CGAL/Nonobtuse_remeshing/angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>

#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>
#include <CGAL/number_type_config.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/FPU.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

/// Verdict on one corner.
struct Corner_verdict
{
  bool too_small = false;
  bool too_large = false;
};

// Evaluates the two tests above with the number type NT. With Interval_nt the
// comparisons are Uncertain<bool>, and converting an undecided one to bool
// throws Uncertain_conversion_exception: the caller then retries exactly.
template <typename NT>
Corner_verdict corner_verdict(const double* apex, const double* p, const double* q,
                              const Angle_bounds& bounds)
{
  const NT ux = NT(p[0]) - NT(apex[0]), uy = NT(p[1]) - NT(apex[1]), uz = NT(p[2]) - NT(apex[2]);
  const NT vx = NT(q[0]) - NT(apex[0]), vy = NT(q[1]) - NT(apex[1]), vz = NT(q[2]) - NT(apex[2]);
  const NT d = ux * vx + uy * vy + uz * vz;
  const NT l = (ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz);
  const NT d2 = d * d;

  Corner_verdict verdict;
  const Cosine_bound& up = bounds.upper();
  const NT q_up = NT(up.factor_a) * NT(up.factor_b) * l;
  bool within_max;
  if(up.sign >= 0)
    within_max = bool(d >= 0) && bool(d2 >= q_up);
  else
    within_max = bool(d >= 0) || bool(d2 <= q_up);
  verdict.too_large = !within_max;

  const Cosine_bound& lo = bounds.lower();
  const NT q_lo = NT(lo.factor_a) * NT(lo.factor_b) * l;
  bool within_min;
  if(lo.sign > 0)
    within_min = bool(d <= 0) || bool(d2 <= q_lo);
  else
    within_min = bool(d <= 0) && bool(d2 >= q_lo);
  verdict.too_small = !within_min;
  return verdict;
}

// Degeneracy of a triangle, decided exactly: a zero-length edge, or three
// collinear points (zero area). Collinearity is the vanishing of the cross
// product of two edge vectors.
template <typename NT>
bool is_degenerate_triangle(const double* a, const double* b, const double* c)
{
  const NT ux = NT(b[0]) - NT(a[0]), uy = NT(b[1]) - NT(a[1]), uz = NT(b[2]) - NT(a[2]);
  const NT vx = NT(c[0]) - NT(a[0]), vy = NT(c[1]) - NT(a[1]), vz = NT(c[2]) - NT(a[2]);
  const NT cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
  return bool(cx == 0) && bool(cy == 0) && bool(cz == 0);
}

/// Verdict on one triangle, exact: interval arithmetic first, exact rationals
/// when intervals cannot decide.
struct Triangle_verdict
{
  bool degenerate = false;
  std::array<Corner_verdict, 3> corners;  // corner i is at vertex i

  bool within_bounds() const
  {
    if(degenerate) return false;
    for(const Corner_verdict& c : corners)
      if(c.too_small || c.too_large) return false;
    return true;
  }
};

template <typename NT>
Triangle_verdict triangle_verdict_with(const std::array<const double*, 3>& t,
                                       const Angle_bounds& bounds)
{
  Triangle_verdict verdict;
  verdict.degenerate = is_degenerate_triangle<NT>(t[0], t[1], t[2]);
  if(verdict.degenerate)
    return verdict;
  for(int i = 0; i < 3; ++i)
    verdict.corners[i] = corner_verdict<NT>(t[i], t[(i + 1) % 3], t[(i + 2) % 3], bounds);
  return verdict;
}

// A semi-static filter in plain doubles, tried before the intervals: true
// only when every corner's two tests above hold with a relative margin of
// 2^-46 (128 units in the last place), above the rounding errors of this
// evaluation (d is off by at most about 7 units of the sum of its terms'
// magnitudes, the squared quantities by at most about 15 units). The
// difference vectors' largest components must lie in [2^-200, 2^200], so
// that no product overflows and an underflowed term moves d by less than
// the absolute margin 2^-900. When
// it returns true, every angle lies strictly inside the bounds (hence the
// triangle is not degenerate), which is what the exact path would find;
// anything else goes to the exact path.
inline bool surely_within_bounds(const std::array<const double*, 3>& t, const Angle_bounds& bounds)
{
  constexpr double rel = 0x1p-46, tiny = 0x1p-900, low = 0x1p-200, high = 0x1p200;
  const Cosine_bound& up = bounds.upper();
  const Cosine_bound& lo = bounds.lower();
  for(int i = 0; i < 3; ++i) {
    const double* a = t[i];
    const double* p = t[(i + 1) % 3];
    const double* q = t[(i + 2) % 3];
    const double ux = p[0] - a[0], uy = p[1] - a[1], uz = p[2] - a[2];
    const double vx = q[0] - a[0], vy = q[1] - a[1], vz = q[2] - a[2];
    const double mu = (std::max)({std::abs(ux), std::abs(uy), std::abs(uz)});
    const double mv = (std::max)({std::abs(vx), std::abs(vy), std::abs(vz)});
    if(!(mu >= low && mu <= high && mv >= low && mv <= high)) return false;  // NaN fails too
    const double d = ux * vx + uy * vy + uz * vz;
    const double e = rel * (std::abs(ux * vx) + std::abs(uy * vy) + std::abs(uz * vz)) + tiny;
    const double d_lo = d - e, d_hi = d + e;  // the exact d lies in [d_lo, d_hi]
    const double l = (ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz);
    const double d2_max = (std::max)(d_lo * d_lo, d_hi * d_hi) * (1. + rel);
    const double d2_min = (d_lo > 0. ? d_lo * d_lo : (d_hi < 0. ? d_hi * d_hi : 0.)) * (1. - rel);
    const double q_up = up.factor_a * up.factor_b * l, q_lo = lo.factor_a * lo.factor_b * l;
    const bool within_max =
        up.sign >= 0 ? (d_lo > 0. && d2_min > q_up * (1. + rel)) : (d_lo > 0. || d2_max < q_up * (1. - rel));
    const bool within_min =
        lo.sign > 0 ? (d_hi < 0. || d2_max < q_lo * (1. - rel)) : (d_hi < 0. && d2_min > q_lo * (1. + rel));
    if(!within_max || !within_min) return false;
  }
  return true;
}

inline Triangle_verdict triangle_verdict(const std::array<const double*, 3>& t,
                                         const Angle_bounds& bounds)
{
  if(surely_within_bounds(t, bounds)) return Triangle_verdict();  // not degenerate, every corner within
  {
    Protect_FPU_rounding<true> protection;
    try {
      return triangle_verdict_with<Interval_nt_advanced>(t, bounds);
    } catch(Uncertain_conversion_exception&) {}
  }
  return triangle_verdict_with<Exact_rational>(t, bounds);
}

// The certificate is about the doubles that are stored and written: points
// must have double coordinates (as with Epick or Simple_cartesian<double>).
template <typename Point>
Triangle_verdict triangle_verdict(const Point& a, const Point& b, const Point& c,
                                  const Angle_bounds& bounds)
{
  static_assert(std::is_same<typename std::decay<decltype(a.x())>::type, double>::value,
                "exact angle certification needs points with double coordinates");
  const double pa[3] = {a.x(), a.y(), a.z()};
  const double pb[3] = {b.x(), b.y(), b.z()};
  const double pc[3] = {c.x(), c.y(), c.z()};
  return triangle_verdict({pa, pb, pc}, bounds);
}

/// Approximate angle in degrees at `apex`, for reports only (the verdicts
/// above are exact). atan2 of |u x v| and u.v keeps small and large angles
/// accurate; dividing by pi before scaling keeps exact right angles at 90.
/// u and v are first scaled by powers of two, so that no product overflows
/// or underflows whatever the coordinates' magnitude.
template <typename Point>
double corner_angle_degrees(const Point& apex, const Point& p, const Point& q)
{
  double ux = p.x() - apex.x(), uy = p.y() - apex.y(), uz = p.z() - apex.z();
  double vx = q.x() - apex.x(), vy = q.y() - apex.y(), vz = q.z() - apex.z();
  int eu = 0, ev = 0;
  std::frexp((std::max)({std::abs(ux), std::abs(uy), std::abs(uz)}), &eu);
  std::frexp((std::max)({std::abs(vx), std::abs(vy), std::abs(vz)}), &ev);
  ux = std::ldexp(ux, -eu); uy = std::ldexp(uy, -eu); uz = std::ldexp(uz, -eu);
  vx = std::ldexp(vx, -ev); vy = std::ldexp(vy, -ev); vz = std::ldexp(vz, -ev);
  const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
  const double pi = 3.141592653589793238462643383279502884;
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), ux * vx + uy * vy + uz * vz) / pi * 180.;
}

// The 5-degree bin of `Angle_certificate::angle_histogram` of an angle shown
// within the bounds (bin 17 is [85, 90], bin 18 is (90, 95)).
inline int angle_bin(double degrees)
{
  if(degrees <= 90.) return (std::max)(0, (std::min)(17, int(degrees / 5.)));
  return (std::max)(18, (std::min)(35, int(degrees / 5.)));
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_ANGLE_PREDICATES_H
