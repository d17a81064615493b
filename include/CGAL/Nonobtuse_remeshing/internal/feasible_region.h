// SPDX-License-Identifier: GPL-3.0-or-later
//
// The linearized feasible region of a vertex (thesis, sections 5.1-5.2) and
// of an edge collapse (equations 6.1-6.2): a convex polyhedron of positions
// where every triangle around the vertex keeps its angles in [30, 90]
// degrees, built as the intersection of 5 + 4k half-spaces per one-ring edge.
//
// For a one-ring edge e = (a, b) and a reference point y (the vertex itself,
// or the midpoint of the edge to collapse), with L = |b - a|, e^ = (b - a)/L,
// q = (a + b)/2 and n0 the unit normal of e towards y in the plane (a, b, y):
//   U: e^.(x - a) >= 0 and V: -e^.(x - b) >= 0    the angles at a and b are at
//                                                 most 90 degrees (exact);
//   R: u.(x - q) >= L/2, u = (y - q)/|y - q|      tangent plane to the sphere
//                                                 of diameter e: x sees e at
//                                                 most at 90 degrees;
//   S: (-e^/2 + sqrt(3)/2 n0).(x - a) >= 0 and T: (e^/2 + sqrt(3)/2 n0).(x - b)
//   >= 0                                          tangent planes to the 30
//                                                 degree cones at a and b;
//   M_i+-, N_i+- (i = 1..k)                       the "drum": the region where
//                                                 x sees e at 30 degrees or
//                                                 more is, inside the slab
//                                                 U-V, a barrel around e whose
//                                                 profile is rho(s) = sqrt(3)/2
//                                                 L + sqrt(L^2 - s^2); its wedge
//                                                 towards y (up to where R cuts
//                                                 it) is approximated from
//                                                 inside by 4k planes through
//                                                 points of the barrel.
// Every half-space contains only points that satisfy the exact condition it
// stands for, so the region is conservative; the exact certification after
// each move remains the judge.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_FEASIBLE_REGION_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_FEASIBLE_REGION_H

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

/// The half-space normal . x >= offset.
struct Half_space
{
  Eigen::Vector3d normal;
  double offset;

  double slack(const Eigen::Vector3d& x) const { return normal.dot(x) - offset; }
};

/// Coordinates local to a one-ring: centred on a point and divided by the
/// ring's size, so that the planes and the QP are well conditioned.
struct Local_frame
{
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double scale = 1.;

  template <typename Point>
  Eigen::Vector3d to_local(const Point& p) const
  {
    return (Eigen::Vector3d(to_double(p.x()), to_double(p.y()), to_double(p.z())) - origin) / scale;
  }
  Eigen::Vector3d to_global(const Eigen::Vector3d& x) const { return origin + scale * x; }
};

namespace feasible {

// Half-space through three points, oriented so that `inside` is on the
// feasible side.
inline Half_space through(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                          const Eigen::Vector3d& inside)
{
  Eigen::Vector3d n = (p1 - p0).cross(p2 - p0).normalized();
  if(n.dot(inside - p0) < 0) n = -n;
  return {n, n.dot(p0)};
}

} // namespace feasible

/// Appends the 5 + 4k half-spaces of edge (a, b) with reference point y
/// (thesis, equation 5.5, with i = 1..k as its text and plane count say).
/// Returns false, appending nothing, when y is on the line of the edge.
inline bool edge_feasible_region(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& y,
                                 int k, std::vector<Half_space>& out)
{
  CGAL_precondition(k >= 1 && k <= 16);
  const double sqrt3 = std::sqrt(3.);
  const Eigen::Vector3d q = 0.5 * (a + b);
  const double L = (b - a).norm();
  if(!(L > 0.)) return false;
  const Eigen::Vector3d e = (b - a) / L;
  const Eigen::Vector3d t = y - q;
  const Eigen::Vector3d across = t - t.dot(e) * e;
  if(!(across.norm() > 1e-12 * L)) return false;
  const Eigen::Vector3d n0 = across.normalized();
  const Eigen::Vector3d b0 = e.cross(n0);
  const Eigen::Vector3d u = t.normalized();

  out.push_back({e, e.dot(a)});                                           // U
  out.push_back({-e, -e.dot(b)});                                         // V
  out.push_back({u, u.dot(q) + 0.5 * L});                                 // R
  const Eigen::Vector3d nS = -0.5 * e + 0.5 * sqrt3 * n0;
  const Eigen::Vector3d nT = 0.5 * e + 0.5 * sqrt3 * n0;
  out.push_back({nS, nS.dot(a)});                                         // S
  out.push_back({nT, nT.dot(b)});                                         // T

  // Drum: the wedge of the barrel between the half-planes through e at
  // angles -theta_k..theta_k from n0, where theta_k is where R meets the
  // barrel's end circles (the wider end), split into k slices per side.
  const double alpha = std::abs(e.dot(u));
  const double theta_k = std::acos(std::sqrt((1. - alpha) / (1. + alpha)) / (2. * sqrt3));
  // the directions at angles i theta_k / k, i = 0..k, from n0 towards +-b0
  std::array<double, 17> cosine, sine;  // k <= 16
  cosine[0] = 1.;
  sine[0] = 0.;
  for(int i = 1; i <= k; ++i) {
    cosine[i] = std::cos(theta_k * i / k);
    sine[i] = std::sin(theta_k * i / k);
  }
  for(int side : {1, -1}) {
    auto direction = [&](int i) { return Eigen::Vector3d(cosine[i] * n0 + (side * sine[i]) * b0); };
    // the barrel's points at angle i on the circles through a and b
    const Eigen::Vector3d d0 = direction(0);
    Eigen::Vector3d m_prev = a + sqrt3 * L * d0, n_prev = b + sqrt3 * L * d0;
    for(int i = 1; i <= k; ++i) {
      const Eigen::Vector3d d = direction(i);
      const Eigen::Vector3d m = a + sqrt3 * L * d, n = b + sqrt3 * L * d;
      const Eigen::Vector3d w = q + (1. + 0.5 * sqrt3) * L * d;
      out.push_back(feasible::through(m_prev, m, w, q));                  // M_i
      out.push_back(feasible::through(n_prev, n, w, q));                  // N_i
      m_prev = m;
      n_prev = n;
    }
  }
  return true;
}

/// F(v) (thesis, equations 5.6-5.7): the half-spaces of every edge opposite
/// v in its incident faces (h edges inside, h - 1 on the border), in `frame`
/// coordinates, with v's position as the reference point. Returns false when
/// an edge is degenerate for the construction.
template <typename TriangleMesh, typename VertexPointMap>
bool vertex_feasible_region(const TriangleMesh& mesh, VertexPointMap vpm,
                            typename boost::graph_traits<TriangleMesh>::vertex_descriptor v, int k,
                            const Local_frame& frame, std::vector<Half_space>& out)
{
  const Eigen::Vector3d y = frame.to_local(get(vpm, v));
  for(auto h : halfedges_around_target(v, mesh)) {
    if(is_border(h, mesh)) continue;
    const Eigen::Vector3d a = frame.to_local(get(vpm, target(next(h, mesh), mesh)));
    const Eigen::Vector3d b = frame.to_local(get(vpm, source(h, mesh)));
    if(!edge_feasible_region(a, b, y, k, out)) return false;
  }
  return true;
}

/// The frame of F(u, v) for the collapse of the edge of `h`: centred on the
/// edge's midpoint, scaled by the farthest vertex of the two ends' rings
/// (scale 0 when all coincide).
template <typename TriangleMesh, typename VertexPointMap>
Local_frame collapse_frame(const TriangleMesh& mesh, VertexPointMap vpm,
                           typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h)
{
  auto position = [&](auto v) {
    const auto& p = get(vpm, v);
    return Eigen::Vector3d(to_double(p.x()), to_double(p.y()), to_double(p.z()));
  };
  Local_frame frame;
  frame.origin = 0.5 * (position(source(h, mesh)) + position(target(h, mesh)));
  frame.scale = 0.;
  for(auto end : {source(h, mesh), target(h, mesh)})
    for(auto x : vertices_around_target(halfedge(end, mesh), mesh))
      frame.scale = (std::max)(frame.scale, (position(x) - frame.origin).norm());
  return frame;
}

/// F(u, v) (thesis, equations 6.1-6.2) for the collapse of the edge of `h`:
/// the edges opposite u or v in the faces that survive the collapse, with
/// the edge's midpoint as the reference point.
template <typename TriangleMesh, typename VertexPointMap>
bool collapse_feasible_region(const TriangleMesh& mesh, VertexPointMap vpm,
                              typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, int k,
                              const Local_frame& frame, std::vector<Half_space>& out)
{
  const auto u = source(h, mesh), v = target(h, mesh);
  const Eigen::Vector3d y = 0.5 * (frame.to_local(get(vpm, u)) + frame.to_local(get(vpm, v)));
  for(auto end : {u, v})
    for(auto g : halfedges_around_target(end, mesh)) {
      if(is_border(g, mesh)) continue;
      const auto a = target(next(g, mesh), mesh), b = source(g, mesh);
      if(a == u || a == v || b == u || b == v) continue;  // a face of the collapsed edge
      if(!edge_feasible_region(frame.to_local(get(vpm, a)), frame.to_local(get(vpm, b)), y, k, out))
        return false;
    }
  return true;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_FEASIBLE_REGION_H
