// The cubical grid of the nonobtuse Marching Cubes (thesis, section 4.2),
// chosen so that every output coordinate is exact in double.
//
// The cube size is h = m * 2^e with an 8-bit integer m, the smallest such
// value at least (longest side) / N; the origin lies on the lattice
// 2^(e-10). Every output vertex (cube corner, edge midpoint, cube centre) is
// origin + p * h/2 for an integer p: an integer times 2^(e-10), exact in
// double. Right angles of the table are therefore exactly 90 degrees.
//
// The origin is shifted by 357/1024 of a cube from the round lattice, so
// that inputs whose coordinates are round numbers (a cube [-1, 1]^3, an
// earlier output) do not fall on grid planes, where votes would abstain.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_GRID_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_GRID_H

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
  Grid(const Bbox_3& box, int resolution)
  {
    if(resolution < 1 || resolution > 4096)
      throw std::invalid_argument("resolution must be between 1 and 4096, got " + std::to_string(resolution));
    const double extent = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
    if(!(extent > 0.) || !std::isfinite(extent))
      throw std::invalid_argument("the input's bounding box is flat or not finite");
    int exponent;
    const double fraction = std::frexp(extent / resolution, &exponent);  // in [0.5, 1)
    const int e = exponent - 8;
    const double m = std::ceil(std::ldexp(fraction, 8));  // integer in [128, 256]
    h_ = std::ldexp(m, e);
    const double shift = std::ldexp(m * 357., e - 10);
    for(int a = 0; a < 3; ++a) {
      const double lo = a == 0 ? box.xmin() : (a == 1 ? box.ymin() : box.zmin());
      const double hi = a == 0 ? box.xmax() : (a == 1 ? box.ymax() : box.zmax());
      origin_[a] = (std::floor(lo / h_) - 1.) * h_ + shift;
      if(origin_[a] + h_ >= lo) origin_[a] -= h_;  // at least one cube of margin
      cubes_[a] = int(std::ceil((hi - origin_[a]) / h_)) + 1;
    }
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
  double h_;
  double origin_[3];
  int cubes_[3];
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_GRID_H
