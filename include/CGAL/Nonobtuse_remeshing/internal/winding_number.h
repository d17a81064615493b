// SPDX-License-Identifier: GPL-3.0-or-later
//
// The generalized winding number of the input triangles at a point
// (Jacobson, Kavan, Sorkine-Hornung 2013): the sum of the signed solid angles
// of the triangles seen from the point, over 4 pi. It is an integer off a
// closed surface (0 outside, 1 inside, 2 where two closed parts overlap, -1
// inside a part oriented inwards) even when the surface intersects itself,
// and stays close to one away from small gaps.
//
// Evaluated with a tree over the triangles (Barill, Dickson, Schmidt, Levin,
// Jacobson 2018): a node farther from the point than `far` times its radius
// contributes its dipole term, the solid angle of its summed area vector
// placed at its area centroid; nearer nodes are opened, and leaves are summed
// exactly. The cost per point is logarithmic in the number of triangles for
// points away from the surface.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_WINDING_NUMBER_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_WINDING_NUMBER_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

class Winding_number
{
public:
  using Vec = std::array<double, 3>;

  /// The tree over the triangles `t` with `usable[t]` (the others, zero-area,
  /// add nothing).
  Winding_number(const std::vector<Epick::Triangle_3>& triangles, const std::vector<bool>& usable)
  {
    std::vector<std::uint32_t> order;
    for(std::size_t t = 0; t < triangles.size(); ++t)
      if(usable[t]) order.push_back(std::uint32_t(t));
    std::vector<Vec> centroid(triangles.size());
    for(std::uint32_t t : order)
      for(int a = 0; a < 3; ++a)
        centroid[t][a] = (triangles[t][0][a] + triangles[t][1][a] + triangles[t][2][a]) / 3.;
    if(!order.empty()) {
      nodes_.emplace_back();
      build(0, triangles, centroid, order, 0, order.size());
    }
    corners_.reserve(order.size());
    for(std::uint32_t t : order) corners_.push_back({point(triangles[t][0]), point(triangles[t][1]), point(triangles[t][2])});
  }

  /// The winding number at `q`.
  double operator()(const Vec& q) const
  {
    if(nodes_.empty()) return 0.;
    double solid_angle = 0.;
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while(top > 0) {
      const Node& node = nodes_[stack[--top]];
      const Vec d = minus(node.centre, q);
      const double d2 = dot(d, d);
      if(d2 > far * far * node.radius2) {
        // dipole term: (p - q) . A / |p - q|^3 (Barill et al. 2018, eq. 9, first order)
        solid_angle += dot(d, node.area_vector) / (d2 * std::sqrt(d2));
      } else if(node.count > 0) {
        for(std::uint32_t i = node.first; i < node.first + node.count; ++i)
          solid_angle += triangle_solid_angle(corners_[i], q);
      } else {
        stack[top++] = node.first;      // left child
        stack[top++] = node.first + 1;  // right child
      }
    }
    return solid_angle / (4. * 3.14159265358979323846);
  }

  /// The exact (to rounding) sum over all triangles, for tests.
  double brute_force(const Vec& q) const
  {
    double solid_angle = 0.;
    for(const auto& c : corners_) solid_angle += triangle_solid_angle(c, q);
    return solid_angle / (4. * 3.14159265358979323846);
  }

  /// Nodes are opened nearer than this many radii.
  static constexpr double far = 3.;

private:
  struct Node
  {
    Vec centre{};        // area centroid
    Vec area_vector{};   // sum of the triangles' area vectors
    double radius2 = 0;  // squared radius of the ball around `centre` holding the triangles
    std::uint32_t first = 0;  // leaf: first triangle; inner node: left child (right is next)
    std::uint32_t count = 0;  // leaf: number of triangles; inner node: 0
  };

  static constexpr std::size_t leaf_size = 8;

  static Vec point(const Epick::Point_3& p) { return {p.x(), p.y(), p.z()}; }
  static Vec minus(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
  static double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  static Vec cross(const Vec& a, const Vec& b)
  {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }

  // Signed solid angle of a triangle seen from q (Van Oosterom and Strackee 1983).
  static double triangle_solid_angle(const std::array<Vec, 3>& t, const Vec& q)
  {
    const Vec a = minus(t[0], q), b = minus(t[1], q), c = minus(t[2], q);
    const double la = std::sqrt(dot(a, a)), lb = std::sqrt(dot(b, b)), lc = std::sqrt(dot(c, c));
    const double numerator = dot(a, cross(b, c));
    const double denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
    return 2. * std::atan2(numerator, denominator);
  }

  // Builds node `index` over order[begin, end) (the leaves' triangles are
  // contiguous ranges of `order`); children are split at the median centroid
  // along the longest side of the centroids' box.
  void build(std::uint32_t index, const std::vector<Epick::Triangle_3>& triangles, const std::vector<Vec>& centroid,
             std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end)
  {
    Node node;
    double area = 0.;
    Vec lo = centroid[order[begin]], hi = lo;
    for(std::size_t i = begin; i < end; ++i) {
      const Epick::Triangle_3& t = triangles[order[i]];
      const Vec n = cross(minus(point(t[1]), point(t[0])), minus(point(t[2]), point(t[0])));
      const double twice_area = std::sqrt(dot(n, n));
      area += twice_area;
      for(int a = 0; a < 3; ++a) {
        node.area_vector[a] += n[a] / 2.;
        node.centre[a] += twice_area * centroid[order[i]][a];
        lo[a] = (std::min)(lo[a], centroid[order[i]][a]);
        hi[a] = (std::max)(hi[a], centroid[order[i]][a]);
      }
    }
    for(int a = 0; a < 3; ++a) node.centre[a] = area > 0. ? node.centre[a] / area : (lo[a] + hi[a]) / 2.;
    for(std::size_t i = begin; i < end; ++i)
      for(int v = 0; v < 3; ++v) {
        const Vec d = minus(point(triangles[order[i]][v]), node.centre);
        node.radius2 = (std::max)(node.radius2, dot(d, d));
      }
    if(end - begin <= leaf_size) {
      node.first = std::uint32_t(begin);
      node.count = std::uint32_t(end - begin);
    } else {
      int axis = 0;
      for(int a = 1; a < 3; ++a)
        if(hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
      const std::size_t middle = begin + (end - begin) / 2;
      std::nth_element(order.begin() + std::ptrdiff_t(begin), order.begin() + std::ptrdiff_t(middle),
                       order.begin() + std::ptrdiff_t(end), [&](std::uint32_t s, std::uint32_t t) {
                         return centroid[s][axis] < centroid[t][axis] || (centroid[s][axis] == centroid[t][axis] && s < t);
                       });
      node.first = std::uint32_t(nodes_.size());  // the two children are stored side by side
      nodes_.resize(nodes_.size() + 2);
      build(node.first, triangles, centroid, order, begin, middle);
      build(node.first + 1, triangles, centroid, order, middle, end);
    }
    nodes_[index] = node;
  }

  std::vector<Node> nodes_;
  std::vector<std::array<Vec, 3> > corners_;  // the triangles' corners, in leaf order
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_WINDING_NUMBER_H
