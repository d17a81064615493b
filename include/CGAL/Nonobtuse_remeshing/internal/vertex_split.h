// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vertex split, the operation the thesis's chapter 8 names as the missing
// tool for bad valences: an interior vertex w with ring r_0 .. r_{d-1}
// becomes two vertices w1 and w2 joined by an edge, w1 taking the arc
// r_0 .. r_j and w2 the arc r_j .. r_0; the wings r_0 and r_j gain one
// neighbour each, and no vertex loses one. It is the inverse of an edge
// collapse, so the topology does not change.
//
// The two new positions depend on each other (each is in the other's ring),
// so they are found by alternating QPs: w1 minimizes the distance to the
// centroid of its ring within its feasible region F (built as in
// feasible_region.h with w2 fixed), then w2 with w1 fixed, a few rounds. The
// linearization is a means only: the split is applied when every new face is
// certified exactly in the angle bounds and keeps the orientation of the face
// of w it replaces (a test in double, against folds).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_VERTEX_SPLIT_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_VERTEX_SPLIT_H

#include <CGAL/Nonobtuse_remeshing/internal/angle_predicates.h>
#include <CGAL/Nonobtuse_remeshing/internal/certified_faces.h>
#include <CGAL/Nonobtuse_remeshing/internal/feasible_region.h>
#include <CGAL/Nonobtuse_remeshing/internal/small_qp.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Dense>

#include <array>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

/// Minimizes |x - target|^2 over the feasible region of a vertex at `from`
/// whose opposite edges are `edges` (equation 5.17's form, with the target
/// the caller's); returns `from` when the region is empty or degenerate.
inline Eigen::Vector3d closest_feasible_point(const Eigen::Vector3d& from,
                                              const std::vector<std::array<Eigen::Vector3d, 2> >& edges,
                                              const Eigen::Vector3d& target, int k)
{
  Local_frame frame;
  frame.origin = from;
  frame.scale = 0.;
  for(const auto& e : edges)
    for(const Eigen::Vector3d& p : e) frame.scale = (std::max)(frame.scale, (p - from).norm());
  if(!(frame.scale > 0.)) return from;
  std::vector<Half_space> region;
  for(const auto& e : edges)
    if(!edge_feasible_region((e[0] - from) / frame.scale, (e[1] - from) / frame.scale, Eigen::Vector3d::Zero(), k,
                             region))
      return from;
  Small_qp qp;
  qp.G = 2. * Eigen::Matrix3d::Identity();
  qp.a = -2. * (target - from) / frame.scale;
  for(const Half_space& h : region) qp.add_constraint(h.normal, h.offset);
  const Qp_result r = solve_small_qp_with_fallback(qp);
  return r.status == Qp_status::optimal ? frame.to_global(r.x) : from;
}

// Violation energy of a split's new faces (corners: the ring, then w1 and
// w2): the squared excess of every angle outside [30.5, 89.5] degrees, a
// penalty on faces turning away from the face of w they replace, and the
// squared offset of w1 and w2 from the tangent plane at w, in units of the
// ring's size.
struct Split_energy
{
  std::vector<Eigen::Vector3d> corners;
  std::vector<std::array<int, 3> > faces;
  std::vector<Eigen::Vector3d> normals;  // unit
  Eigen::Vector3d w, n;                  // n unit
  double scale = 1.;

  double operator()(const Eigen::Matrix<double, 6, 1>& x)
  {
    const std::size_t d = corners.size() - 2;
    corners[d] = x.head<3>();
    corners[d + 1] = x.tail<3>();
    const double to_degrees = 180. / 3.14159265358979323846;
    double e = 0.;
    for(std::size_t f = 0; f < faces.size(); ++f) {
      const std::array<int, 3>& t = faces[f];
      for(int c = 0; c < 3; ++c) {
        const Eigen::Vector3d u = corners[std::size_t(t[(c + 1) % 3])] - corners[std::size_t(t[c])];
        const Eigen::Vector3d v = corners[std::size_t(t[(c + 2) % 3])] - corners[std::size_t(t[c])];
        const double cosine = u.dot(v) / (u.norm() * v.norm() + 1e-300);
        const double angle = std::acos((std::max)(-1., (std::min)(1., cosine))) * to_degrees;
        e += CGAL::square((std::max)(0., 30.5 - angle)) + CGAL::square((std::max)(0., angle - 89.5));
      }
      const Eigen::Vector3d m = (corners[std::size_t(t[1])] - corners[std::size_t(t[0])])
                                    .cross(corners[std::size_t(t[2])] - corners[std::size_t(t[0])]);
      e += 1e3 * CGAL::square((std::max)(0., 0.3 - m.dot(normals[f]) / (m.norm() + 1e-300)));
    }
    e += 10. * (CGAL::square((corners[d] - w).dot(n) / scale) + CGAL::square((corners[d + 1] - w).dot(n) / scale));
    return e;
  }
};

// Gradient descent with backtracking on the split energy from (p1, p2);
// `accept` (exact certification) is asked whenever the energy vanishes and
// at the end.
template <typename Accept>
bool refine_split(const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, Split_energy& energy, Accept accept)
{
  Eigen::Matrix<double, 6, 1> x;
  x << p1, p2;
  double e = energy(x);
  double step = 0.1 * energy.scale;
  for(int iteration = 0; iteration < 100 && step > 1e-6 * energy.scale; ++iteration) {
    if(e == 0.) break;
    Eigen::Matrix<double, 6, 1> g;
    const double h = 1e-7 * energy.scale;
    for(int i = 0; i < 6; ++i) {
      Eigen::Matrix<double, 6, 1> y = x;
      y[i] += h;
      const double up = energy(y);
      y[i] -= 2. * h;
      g[i] = (up - energy(y)) / (2. * h);
    }
    if(!(g.norm() > 0.)) break;
    g.normalize();
    for(;; step *= 0.5) {
      if(step <= 1e-6 * energy.scale) break;
      const Eigen::Matrix<double, 6, 1> y = x - step * g;
      const double ey = energy(y);
      if(ey < e) {
        x = y;
        e = ey;
        step *= 2.;
        break;
      }
    }
  }
  return accept(x.head<3>(), x.tail<3>());
}

/// A planned split of target(h_a) = target(h_b) = w, an interior vertex:
/// the wings are r_0 = source(h_a) and r_j = source(h_b). `new_point` goes
/// to the new vertex (arc r_0 .. r_j), `old_point` to w (arc r_j .. r_0).
template <typename Point, typename halfedge_descriptor>
struct Vertex_split_plan
{
  halfedge_descriptor h_a, h_b;
  Point new_point, old_point;
};

/// Plans the split of the interior vertex target(h_a) with wings source(h_a)
/// and source(h_b); returns false unless both positions certify every new
/// face exactly within `bounds` with the orientation of the face it replaces.
template <typename TriangleMesh, typename VertexPointMap>
bool plan_vertex_split(
    const TriangleMesh& mesh, VertexPointMap vpm, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h_a,
    typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h_b, int k, const Angle_bounds& bounds,
    Vertex_split_plan<typename boost::property_traits<VertexPointMap>::value_type,
                      typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& plan)
{
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Edge = std::array<Eigen::Vector3d, 2>;
  // The ring in face order: face i is (r_i, w, r_{i+1}); h_b is halfedge i = j.
  std::vector<Point> ring;
  int j = -1;
  for(auto g = h_a;;) {
    if(is_border(g, mesh)) return false;
    if(g == h_b) j = int(ring.size());
    ring.push_back(get(vpm, source(g, mesh)));
    g = opposite(next(g, mesh), mesh);
    if(g == h_a) break;
  }
  const int d = int(ring.size());
  if(j < 2 || j > d - 2) return false;
  const Point& w = get(vpm, target(h_a, mesh));
  const Eigen::Vector3d pw = to_eigen(w);
  auto r = [&](int i) { return to_eigen(ring[std::size_t(i % d)]); };

  // Exact certification of the d + 2 new faces, in face order, each facing
  // the side of the face of w it replaces.
  auto keeps = [&](const Point& a, const Point& b, const Point& c, const Eigen::Vector3d& normal) {
    return keeps_face(a, b, c, normal, bounds);
  };
  auto old_normal = [&](int i) { return Eigen::Vector3d((pw - r(i)).cross(r(i + 1) - r(i))); };
  auto certified = [&](const Point& q1, const Point& q2) {
    for(int i = 0; i < d; ++i)
      if(!keeps(ring[std::size_t(i)], i < j ? q1 : q2, ring[std::size_t((i + 1) % d)], old_normal(i))) return false;
    return keeps(ring[0], q2, q1, old_normal(d - 1) + old_normal(0)) &&
           keeps(ring[std::size_t(j)], q1, q2, old_normal(j - 1) + old_normal(j));
  };

  auto accept = [&](const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
    const Point q1(p1[0], p1[1], p1[2]), q2(p2[0], p2[1], p2[2]);
    if(!certified(q1, q2)) return false;
    plan.h_a = h_a;
    plan.h_b = h_b;
    plan.new_point = q1;
    plan.old_point = q2;
    return true;
  };
  // The new faces as corner indices: 0..d-1 the ring, d w1, d+1 w2; their
  // old normals; the normal at w.
  std::vector<std::array<int, 3> > faces;
  std::vector<Eigen::Vector3d> normals;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for(int i = 0; i < d; ++i) {
    faces.push_back({i, i < j ? d : d + 1, (i + 1) % d});
    normals.push_back(old_normal(i));
    normal += old_normal(i);
  }
  faces.push_back({0, d + 1, d});
  normals.push_back(old_normal(d - 1) + old_normal(0));
  faces.push_back({j, d, d + 1});
  normals.push_back(old_normal(j - 1) + old_normal(j));
  std::vector<Eigen::Vector3d> corners;
  for(int i = 0; i < d; ++i) corners.push_back(r(i));

  // Start inside each arc, then alternate the two QPs; the first round
  // whose positions certify wins (the alternation does not converge to a
  // certified pair in general, so it is not run to the end).
  Eigen::Vector3d m1 = Eigen::Vector3d::Zero(), m2 = Eigen::Vector3d::Zero();
  for(int i = 1; i < j; ++i) m1 += r(i) / double(j - 1);
  for(int i = j + 1; i < d; ++i) m2 += r(i) / double(d - j - 1);
  Eigen::Vector3d p1 = pw + 0.3 * (m1 - pw), p2 = pw + 0.3 * (m2 - pw);
  for(int round = 0; round < 8; ++round) {
    for(int side = 0; side < 2; ++side) {
      const int first = side == 0 ? 0 : j, last = side == 0 ? j : d;  // the arc's faces
      const Eigen::Vector3d other = side == 0 ? p2 : p1;
      std::vector<Edge> edges;
      Eigen::Vector3d centre = other;
      for(int i = first; i < last; ++i) {
        edges.push_back({r(i), r(i + 1)});
        centre += r(i);
      }
      centre += r(last);
      centre /= double(last - first + 2);
      edges.push_back({r(first), other});  // the two wing faces
      edges.push_back({r(last), other});
      Eigen::Vector3d& p = side == 0 ? p1 : p2;
      p = closest_feasible_point(p, edges, centre, k);
    }
    if(accept(p1, p2)) return true;
  }
  // The linearized regions are conservative and may leave no room: descend
  // on the angle violations themselves, then certify again.
  Split_energy energy;
  energy.corners = corners;
  energy.corners.resize(std::size_t(d + 2));
  energy.faces = faces;
  for(const Eigen::Vector3d& m : normals) energy.normals.push_back(m.normalized());
  energy.w = pw;
  energy.n = normal.normalized();
  energy.scale = 0.;
  for(const Eigen::Vector3d& c : corners) energy.scale += (c - pw).norm() / double(d);
  return refine_split(p1, p2, energy, accept);
}
/// Applies a planned split; returns the new vertex.
template <typename TriangleMesh, typename VertexPointMap, typename Plan>
typename boost::graph_traits<TriangleMesh>::vertex_descriptor
apply_vertex_split(TriangleMesh& mesh, VertexPointMap vpm, const Plan& plan)
{
  const auto w = target(plan.h_a, mesh);
  // split_vertex makes the faces of h_a and h_b quadrilaterals (r_0, w,
  // w_new, r_1) and (r_j, w_new, w, r_{j+1}); each is cut at its wing.
  const auto fresh = Euler::split_vertex(plan.h_a, plan.h_b, mesh);
  const auto w_new = source(fresh, mesh);
  Euler::split_face(prev(plan.h_a, mesh), next(plan.h_a, mesh), mesh);
  Euler::split_face(prev(plan.h_b, mesh), next(plan.h_b, mesh), mesh);
  put(vpm, w_new, plan.new_point);
  put(vpm, w, plan.old_point);
  return w_new;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_VERTEX_SPLIT_H
