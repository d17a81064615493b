// SPDX-License-Identifier: GPL-3.0-or-later
//
// Phase 1 of the nonobtuse Marching Cubes (thesis, section 4.2.1): every grid
// cube that intersects an input triangle, with the list of those triangles.
//
// A bounding-box-driven scan: for each triangle, the cubes of its bounding
// box that its supporting plane reaches (a double test with a safety margin)
// are tested exactly with CGAL's triangle-box intersection (closed boxes,
// filtered exact predicates). A triangle touching a cube's face belongs to
// both cubes that share it.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_MESH_CUBE_INTERSECTION_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_MESH_CUBE_INTERSECTION_H

#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>
#include <CGAL/Nonobtuse_remeshing/internal/grid.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

/// Cubes met by the input, sorted by id, each with its sorted triangle list.
struct Cube_triangles
{
  std::vector<std::int64_t> cube_ids;
  std::vector<std::size_t> first;  // triangles of cube c: triangles[first[c] .. first[c+1])
  std::vector<std::size_t> triangles;

  std::size_t size() const { return cube_ids.size(); }
};

// Triangles with `usable[t]` false (degenerate ones) are left out. Returns
// false, with `result` empty, as soon as there are more than `max_pairs`
// (cube, triangle) pairs: the caller's memory budget is then exceeded.
inline bool mesh_cube_intersection(const Grid& grid, const std::vector<Epick::Triangle_3>& triangles,
                                   const std::vector<bool>& usable, std::size_t max_pairs, Cube_triangles& result)
{
  std::vector<std::pair<std::int64_t, std::size_t> > pairs;
  const double h = grid.cube_size();
  for(std::size_t t = 0; t < triangles.size(); ++t) {
    if(!usable[t]) continue;
    const Epick::Triangle_3& tri = triangles[t];
    const Bbox_3 box = tri.bbox();
    int lo[3], hi[3];
    for(int a = 0; a < 3; ++a) {
      lo[a] = (std::max)(0, grid.cube_floor(a, box.min(a)));
      hi[a] = (std::min)(grid.cubes(a) - 1, grid.cube_floor(a, box.max(a)) + 2);
    }
    // Supporting plane, in double, to skip cubes it cannot reach. The margin
    // covers the rounding of n and of the products (n is accurate to about
    // 1e-15 |e1||e2| / |n| relative; needles, where that is large, skip the
    // shortcut and go to the exact test).
    const Epick::Vector_3 e1 = tri[1] - tri[0], e2 = tri[2] - tri[0];
    const Epick::Vector_3 n = CGAL::cross_product(e1, e2);
    const double nx = n.x(), ny = n.y(), nz = n.z();
    const double n2 = nx * nx + ny * ny + nz * nz;
    const bool use_plane = n2 > 1e-6 * e1.squared_length() * e2.squared_length();
    const double reach = 0.5 * h * (std::abs(nx) + std::abs(ny) + std::abs(nz));
    const double diameter = std::sqrt((box.max(0) - box.min(0)) * (box.max(0) - box.min(0)) +
                                      (box.max(1) - box.min(1)) * (box.max(1) - box.min(1)) +
                                      (box.max(2) - box.min(2)) * (box.max(2) - box.min(2)));
    const double margin = 1e-9 * std::sqrt(n2) * (diameter + 4 * h);
    if(pairs.size() > max_pairs) return false;
    auto test = [&](int i, int j, int k) {
      if(use_plane) {
        const double cx = grid.coordinate(0, 2 * i + 1) - tri[0].x();
        const double cy = grid.coordinate(1, 2 * j + 1) - tri[0].y();
        const double cz = grid.coordinate(2, 2 * k + 1) - tri[0].z();
        if(std::abs(nx * cx + ny * cy + nz * cz) > reach + margin) return;
      }
      if(CGAL::do_intersect(tri, grid.cube_box(i, j, k)))
        pairs.emplace_back(grid.cube_id(i, j, k), t);
    };
    if(!use_plane) {  // needles: every cube of the bounding box
      for(int k = lo[2]; k <= hi[2]; ++k)
        for(int j = lo[1]; j <= hi[1]; ++j)
          for(int i = lo[0]; i <= hi[0]; ++i) test(i, j, k);
      continue;
    }
    // Along the axis d where the normal is largest, the plane crosses each
    // column of cubes in a short range: scan the columns of the two other
    // axes and, in each, only the cubes the plane can reach (plus one on each
    // side), so that a large slanted triangle costs its area, not its volume.
    const double normal[3] = {nx, ny, nz};
    const int d = std::abs(nx) >= std::abs(ny) ? (std::abs(nx) >= std::abs(nz) ? 0 : 2)
                                               : (std::abs(ny) >= std::abs(nz) ? 1 : 2);
    const int u = (d + 1) % 3, w = (d + 2) % 3;
    const double level = nx * tri[0].x() + ny * tri[0].y() + nz * tri[0].z();
    for(int a = lo[u]; a <= hi[u]; ++a)
      for(int b = lo[w]; b <= hi[w]; ++b) {
        double low = 1e300, high = -1e300;
        for(int corner = 0; corner < 4; ++corner) {
          const double xu = grid.coordinate(u, 2 * (a + (corner & 1)));
          const double xw = grid.coordinate(w, 2 * (b + (corner >> 1)));
          const double xd = (level - normal[u] * xu - normal[w] * xw) / normal[d];
          low = (std::min)(low, xd);
          high = (std::max)(high, xd);
        }
        const int from = (std::max)(lo[d], grid.cube_floor(d, low) - 1);
        const int to = (std::min)(hi[d], grid.cube_floor(d, high) + 3);
        for(int c = from; c <= to; ++c) {
          int index[3];
          index[d] = c;
          index[u] = a;
          index[w] = b;
          test(index[0], index[1], index[2]);
        }
      }
  }
  if(pairs.size() > max_pairs) return false;
  std::sort(pairs.begin(), pairs.end());
  for(const auto& p : pairs) {
    if(result.cube_ids.empty() || result.cube_ids.back() != p.first) {
      result.cube_ids.push_back(p.first);
      result.first.push_back(result.triangles.size());
    }
    result.triangles.push_back(p.second);
  }
  result.first.push_back(result.triangles.size());
  return true;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_MESH_CUBE_INTERSECTION_H
