// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cosine of an angle bound, held exactly as sign * sqrt(a * b) with a and
// b doubles: exactly the bound for the angles whose cosine has a rational
// square (0, 30, 45, 60, 90, 120, 135, 150, 180 degrees), otherwise moved by
// 1e-12 in the safe direction (angle_bounds.h).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_COSINE_BOUNDS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_COSINE_BOUNDS_H

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// A cosine value c = sign * sqrt(factor_a * factor_b), held exactly: the two
// factors are doubles whose product is taken in exact arithmetic.
struct Cosine_bound
{
  int sign = 0;
  double factor_a = 0.;
  double factor_b = 0.;
  bool exact = true;  // true when the bound is the requested angle itself
};

// Angles whose cosine has a rational square: their bound is tested exactly.
inline bool exact_cosine_bound(double degrees, Cosine_bound& bound)
{
  struct Entry { double degrees; int sign; double square; };
  static const Entry table[] = {
    {0., 1, 1.},     {30., 1, 0.75},  {45., 1, 0.5},   {60., 1, 0.25},
    {90., 0, 0.},    {120., -1, 0.25}, {135., -1, 0.5}, {150., -1, 0.75},
    {180., -1, 1.}};
  for(const Entry& e : table)
    if(e.degrees == degrees) {
      bound.sign = e.sign;
      bound.factor_a = e.square;
      bound.factor_b = 1.;
      bound.exact = true;
      return true;
    }
  return false;
}

// Conservative rounding for other bounds: the double cosine of the bound is
// within 2e-15 of the true value, so moving it by 1e-12 in the safe direction
// proves a bound never looser than the one requested (tighter by about
// 1e-12 / sin(bound) radians; more, up to 1.5e-6 radians, within a few
// micro-degrees of 0 and 180, where the cosine is flat).
constexpr double cosine_safety_margin = 1e-12;

inline Cosine_bound cosine_bound(double degrees, bool is_lower_bound)
{
  Cosine_bound bound;
  if(exact_cosine_bound(degrees, bound))
    return bound;
  const double pi = 3.141592653589793238462643383279502884;
  double c = std::cos(degrees / 180. * pi);
  // A lower angle bound needs cos(angle) <= c: shrink c. An upper one, grow it.
  c += is_lower_bound ? -cosine_safety_margin : cosine_safety_margin;
  c = (std::min)(1., (std::max)(-1., c));
  bound.sign = (c > 0) ? 1 : ((c < 0) ? -1 : 0);
  bound.factor_a = std::abs(c);
  bound.factor_b = std::abs(c);
  bound.exact = false;
  return bound;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_COSINE_BOUNDS_H
