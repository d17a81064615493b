// SPDX-License-Identifier: GPL-3.0-or-later
//
// The angle interval a mesh is certified in.

#ifndef CGAL_NONOBTUSE_REMESHING_ANGLE_BOUNDS_H
#define CGAL_NONOBTUSE_REMESHING_ANGLE_BOUNDS_H

#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/cosine_bounds.h>

#include <string>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// The requested angle interval [min, max], in degrees, and the exact cosine
/// bounds that certify it (see `certify_angle_bounds()`). Throws
/// `Bad_parameter` unless 0 <= min <= max <= 180.
class Angle_bounds
{
public:
  Angle_bounds(double min_degrees = 30., double max_degrees = 90.)
    : min_degrees_(min_degrees), max_degrees_(max_degrees)
  {
    if(!(min_degrees >= 0. && max_degrees <= 180. && min_degrees <= max_degrees))
      throw Bad_parameter("angle bounds must satisfy 0 <= min <= max <= 180, got [" +
                                  std::to_string(min_degrees) + ", " +
                                  std::to_string(max_degrees) + "]");
    lower_ = internal::cosine_bound(min_degrees, true);
    upper_ = internal::cosine_bound(max_degrees, false);
  }

  /// the bounds asked for
  double min_degrees() const { return min_degrees_; }
  double max_degrees() const { return max_degrees_; }
  /// true when both bounds are tested exactly as asked, false when a bound
  /// whose cosine is irrational was tightened by a tiny margin
  bool is_exact() const { return lower_.exact && upper_.exact; }

  /// \cond SKIP_IN_MANUAL
  const internal::Cosine_bound& lower() const { return lower_; }
  const internal::Cosine_bound& upper() const { return upper_; }
  /// \endcond

private:
  double min_degrees_, max_degrees_;
  internal::Cosine_bound lower_, upper_;
};

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_ANGLE_BOUNDS_H
