// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cubical grid of the nonobtuse Marching Cubes (thesis, section 4.2),
// chosen so that every output coordinate is exact in double.
//
// The cube size is h = m * 2^e with an 8-bit integer m, the smallest such
// value at least (longest side) / N; the origin lies on the lattice
// 2^(e-10). Every output vertex (cube corner, edge midpoint, cube centre) is
// origin + p * h/2 for an integer p: an integer times 2^(e-10), exact in
// double. Right angles of the table are therefore exactly 90 degrees.
//
// The origin is shifted off the round lattice by fractions s/1024 of a cube,
// different along each axis, so that no input vertex lies on a grid plane,
// where votes would abstain: the first of a few shifts that keeps every input
// vertex at least 1e-9 cube away from the grid planes is used (round inputs
// like [-1, 1]^3 and earlier outputs of this package would otherwise meet
// them).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_GRID_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_GRID_H

#include <CGAL/Nonobtuse_remeshing/exceptions.h>

#include <CGAL/Bbox_3.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

class Grid
{
public:
  /// `points`: the input vertices, kept off the grid planes if possible.
  template <typename PointRange>
  Grid(const Bbox_3& box, int resolution, const PointRange& points)
  {
    if(resolution < 1 || resolution > 1024)
      throw Bad_parameter("resolution must be between 1 and 1024, got " + std::to_string(resolution));
    const double extent = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
    if(!(extent > 0.) || !std::isfinite(extent))
      throw Bad_input("the input's bounding box is flat or not finite");
    // The sign votes and the fit's distances are products of up to six
    // coordinate differences in double: keep them far from overflow and
    // underflow.
    if(extent < 1e-30 || extent > 1e30)
      throw Bad_input("the input's size is outside the supported range [1e-30, 1e30]: scale it");
    int exponent;
    const double fraction = std::frexp(extent / resolution, &exponent);  // in [0.5, 1)
    const int e = exponent - 8;
    const double m = std::ceil(std::ldexp(fraction, 8));  // integer in [128, 256]
    h_ = std::ldexp(m, e);
    const double unit = std::ldexp(1., e - 10);  // every coordinate is an integer times this
    if(!(unit > 1e-290))
      throw Bad_input("the input is too small to be meshed exactly in double");
    std::size_t best_on_planes = std::size_t(-1);
    for(int attempt = 0; attempt < 8; ++attempt) {
      place(box, m, e, attempt);
      std::size_t on_planes = 0;
      for(const auto& p : points)
        for(int a = 0; a < 3; ++a) {
          const double r = (p[a] - origin_[a]) / h_;
          on_planes += std::abs(r - std::round(r)) < 1e-9;
        }
      if(on_planes < best_on_planes) {
        best_on_planes = on_planes;
        best_attempt_ = attempt;
      }
      if(on_planes == 0) break;
    }
    place(box, m, e, best_attempt_);
    // exact while every coordinate is below 2^52 units
    for(int a = 0; a < 3; ++a)
      if(std::abs(origin_[a]) >= std::ldexp(unit, 52) ||
         std::abs(origin_[a] + cubes_[a] * h_) >= std::ldexp(unit, 52))
        throw Bad_input("the input lies too far from the origin for its size to be meshed "
                                    "exactly in double: translate it closer to the origin");
  }

  double cube_size() const { return h_; }
  int cubes(int axis) const { return cubes_[axis]; }
  double origin(int axis) const { return origin_[axis]; }

  /// Coordinate of half-index p along `axis` (corners at even p).
  double coordinate(int axis, std::int64_t half_index) const
  {
    return origin_[axis] + double(half_index) * (h_ / 2.);
  }

  /// Lowest cube index whose closed cube can contain coordinate x.
  int cube_floor(int axis, double x) const
  {
    return int(std::floor((x - origin_[axis]) / h_)) - 1;
  }

  std::int64_t cube_id(int i, int j, int k) const
  {
    return i + std::int64_t(cubes_[0]) * (j + std::int64_t(cubes_[1]) * k);
  }
  std::array<int, 3> cube_index(std::int64_t id) const
  {
    return {int(id % cubes_[0]), int((id / cubes_[0]) % cubes_[1]), int(id / (std::int64_t(cubes_[0]) * cubes_[1]))};
  }
  bool valid_cube(int i, int j, int k) const
  {
    return i >= 0 && j >= 0 && k >= 0 && i < cubes_[0] && j < cubes_[1] && k < cubes_[2];
  }

  /// Ids of grid corners, grid edges (3 per corner: along x, y, z) and grid
  /// faces (3 per corner: normal to x, y, z), from integer corner indices.
  std::int64_t corner_id(int i, int j, int k) const
  {
    return i + std::int64_t(cubes_[0] + 1) * (j + std::int64_t(cubes_[1] + 1) * k);
  }

  Bbox_3 cube_box(int i, int j, int k) const
  {
    return Bbox_3(coordinate(0, 2 * i), coordinate(1, 2 * j), coordinate(2, 2 * k),
                  coordinate(0, 2 * i + 2), coordinate(1, 2 * j + 2), coordinate(2, 2 * k + 2));
  }

private:
  // Origin shifted by a different fraction of a cube along each axis, so
  // that the diagonals of an earlier (dyadic) output do not run through the
  // grid lines either.
  void place(const Bbox_3& box, double m, int e, int attempt)
  {
    static const double fractions[8][3] = {{357, 611, 173}, {829, 449, 277}, {953, 71, 541},
                                           {197, 887, 419}, {683, 239, 761}, {113, 337, 919},
                                           {571, 983, 53},  {401, 131, 857}};
    for(int a = 0; a < 3; ++a) {
      const double lo = box.min(a), hi = box.max(a);
      origin_[a] = (std::floor(lo / h_) - 1.) * h_ + std::ldexp(m * fractions[attempt][a], e - 10);
      if(origin_[a] + h_ >= lo) origin_[a] -= h_;  // at least one cube of margin
      cubes_[a] = int(std::ceil((hi - origin_[a]) / h_)) + 1;
    }
  }

  double h_;
  int best_attempt_ = 0;
  double origin_[3];
  int cubes_[3];
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_GRID_H
