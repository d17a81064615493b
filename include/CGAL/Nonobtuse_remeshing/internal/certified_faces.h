// SPDX-License-Identifier: GPL-3.0-or-later
//
// The check every local operation passes before it is applied: each face it
// creates certifies exactly in the angle bounds, on the doubles that will be
// stored, and faces the side of the face it replaces (beyond the thesis: a
// test in double, a guard against folds; the bound is what is exact).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_CERTIFIED_FACES_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_CERTIFIED_FACES_H

#include <CGAL/Nonobtuse_remeshing/internal/angle_predicates.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

template <typename Point>
Eigen::Vector3d to_eigen(const Point& p)
{
  return Eigen::Vector3d(to_double(p.x()), to_double(p.y()), to_double(p.z()));
}

/// The triangle (a, b, c), in this order, certifies exactly within `bounds`
/// and faces the side of `normal`.
template <typename Point>
bool keeps_face(const Point& a, const Point& b, const Point& c, const Eigen::Vector3d& normal,
                const Angle_bounds& bounds)
{
  if(!triangle_verdict(a, b, c, bounds).within_bounds()) return false;
  return (to_eigen(b) - to_eigen(a)).cross(to_eigen(c) - to_eigen(a)).dot(normal) > 0.;
}

/// The collapse of the edge of `h` to the point `p` keeps every face that
/// survives it: each face around either end, except the edge's own, with
/// that end moved to `p`, passes `keeps_face()`.
template <typename TriangleMesh, typename VertexPointMap, typename Point>
bool collapse_keeps_faces(const TriangleMesh& mesh, VertexPointMap vpm,
                          typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const Point& p,
                          const Angle_bounds& bounds)
{
  const auto u = source(h, mesh), v = target(h, mesh);
  for(auto end : {u, v})
    for(auto g : halfedges_around_target(end, mesh)) {
      if(is_border(g, mesh)) continue;
      const auto a = source(g, mesh), b = target(next(g, mesh), mesh);
      if(a == u || a == v || b == u || b == v) continue;  // a face of the collapsed edge
      const Eigen::Vector3d pa = to_eigen(get(vpm, a)), pb = to_eigen(get(vpm, b));
      const Eigen::Vector3d normal = (to_eigen(get(vpm, end)) - pa).cross(pb - pa);
      if(!keeps_face(get(vpm, a), p, get(vpm, b), normal, bounds)) return false;  // (a, end, b) -> (a, p, b)
    }
  return true;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_CERTIFIED_FACES_H
