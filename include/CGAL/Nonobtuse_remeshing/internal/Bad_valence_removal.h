// SPDX-License-Identifier: GPL-3.0-or-later
//
// Removal of bad-valence vertices (thesis, section 5.7, cases (a)-(g) of its
// Figure 5.6), followed by vertex splits for what removal cannot reach
// (chapter 8's future work). Every operation is checked for manifoldness
// and topology before it is applied, and its new faces are certified exactly
// in the angle bounds, so the mesh is certified at every moment.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_BAD_VALENCE_REMOVAL_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_BAD_VALENCE_REMOVAL_H

#include <CGAL/Nonobtuse_remeshing/internal/angle_predicates.h>
#include <CGAL/Nonobtuse_remeshing/internal/certified_faces.h>
#include <CGAL/Nonobtuse_remeshing/internal/feasible_region.h>
#include <CGAL/Nonobtuse_remeshing/internal/small_qp.h>
#include <CGAL/Nonobtuse_remeshing/internal/vertex_split.h>
#include <CGAL/Nonobtuse_remeshing/statistics.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {

namespace internal {

template <typename TriangleMesh, typename VertexPointMap>
class Bad_valence_removal
{
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;

public:
  Bad_valence_removal(TriangleMesh& mesh, VertexPointMap vpm, int k, bool split,
                      Bad_valence_removal_statistics& stats)
    : mesh_(mesh), vpm_(vpm), k_(k), split_(split), stats_(stats),
      gone_(get(CGAL::dynamic_vertex_property_t<bool>(), mesh))
  {
    for(vertex_descriptor v : vertices(mesh_)) put(gone_, v, false);
  }

  // Rounds of removal in the thesis's order, then splits, while they change
  // something (a removal may lower a neighbour to a bad valence that a split
  // raises again), at most 16.
  void run()
  {
    for(int round = 0; round < 16 && count_bad_valences(mesh_).total() > 0; ++round) {
      ++stats_.rounds;
      const std::size_t before = operations();
      removal_pass([&](vertex_descriptor v) { return valence(v) == (is_border_vertex(v) ? 2u : 3u) && remove(v); });
      removal_pass([&](vertex_descriptor v) { return !is_border_vertex(v) && valence(v) == 4 && remove(v); });
      removal_pass([&](vertex_descriptor v) { return is_border_vertex(v) && valence(v) == 3 && remove(v); });
      if(split_) split_pass();
      if(operations() == before) break;
    }
  }

  // One removal of v by the case of Figure 5.6 its valence selects; false
  // if no case applies or certifies.
  bool remove(vertex_descriptor v)
  {
    const std::size_t d = valence(v);
    if(is_border_vertex(v)) return d == 2 ? remove_border_2(v) : d == 3 && remove_border_3(v);
    return d == 3 ? remove_interior_3(v) : d == 4 && remove_interior_4(v);
  }

  // Raises the valence of v by one: splits an interior neighbour of valence
  // 6 or more with v as a wing, both halves keeping 5 or more; a neighbour of
  // valence 5 is first raised to 6 the same way (`depth` levels deep).
  bool raise(vertex_descriptor v, int depth)
  {
    std::vector<vertex_descriptor> fives;
    for(vertex_descriptor w : vertices_around_target(halfedge(v, mesh_), mesh_)) {
      if(is_border_vertex(w)) continue;
      if(valence(w) >= 6 && split_with_wing(w, v)) return true;
      if(valence(w) == 5) fives.push_back(w);
    }
    if(depth > 0)
      for(vertex_descriptor w : fives)
        if(raise(w, depth - 1) && split_with_wing(w, v)) return true;
    return false;
  }

private:
  bool is_border_vertex(vertex_descriptor v) const { return bool(is_border(v, mesh_)); }
  std::size_t valence(vertex_descriptor v) const { return degree(v, mesh_); }
  // Valence at least `interior` for an interior vertex, `border` for a
  // border one: the thesis's preconditions.
  bool at_least(vertex_descriptor v, std::size_t interior, std::size_t border) const
  {
    return valence(v) >= (is_border_vertex(v) ? border : interior);
  }
  Eigen::Vector3d position(vertex_descriptor v) const { return to_eigen(get(vpm_, v)); }
  bool edge_exists(vertex_descriptor a, vertex_descriptor b) const { return halfedge(a, b, mesh_).second; }

  bool keeps(vertex_descriptor a, vertex_descriptor b, vertex_descriptor c, const Eigen::Vector3d& normal) const
  {
    return keeps_face(get(vpm_, a), get(vpm_, b), get(vpm_, c), normal, bounds_);
  }
  // Normal of the face of h (not normalized).
  Eigen::Vector3d normal(halfedge_descriptor h) const
  {
    const Eigen::Vector3d a = position(source(h, mesh_)), b = position(target(h, mesh_)),
                          c = position(target(next(h, mesh_), mesh_));
    return (b - a).cross(c - a);
  }
  // Sum of the normals of the faces around v.
  Eigen::Vector3d normal(vertex_descriptor v) const
  {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for(halfedge_descriptor h : halfedges_around_target(v, mesh_))
      if(!is_border(h, mesh_)) n += normal(h);
    return n;
  }

  // Applies `step` to every vertex present at the start of the pass and not
  // removed since (splits, which add vertices, run in passes of their own).
  template <typename Step>
  void removal_pass(Step step)
  {
    std::vector<vertex_descriptor> present(vertices(mesh_).begin(), vertices(mesh_).end());
    for(vertex_descriptor v : present) put(gone_, v, false);
    for(vertex_descriptor v : present)
      if(!get(gone_, v)) step(v);
  }

  // (a) A border vertex of valence 2 and its face go, if its neighbours keep
  // a valence of at least 3 (no new valence-2 vertex: Figure 5.7).
  bool remove_border_2(vertex_descriptor v)
  {
    const auto border = is_border(v, mesh_);  // v0 -> v, on the border
    if(!border) return false;
    const halfedge_descriptor h = *border;
    const vertex_descriptor v0 = source(h, mesh_), v1 = target(next(h, mesh_), mesh_);
    if(valence(v0) < 4 || valence(v1) < 4) return remove_tooth(v, v0) || remove_tooth(v, v1);
    const halfedge_descriptor inside = opposite(h, mesh_);  // v -> v0, in the face (v, v0, v1)
    if(is_border(opposite(next(inside, mesh_), mesh_), mesh_))
      return false;  // a lone triangle: its component would vanish
    put(gone_, v, true);
    Euler::remove_face(inside, mesh_);  // v and its two edges go with the face
    ++stats_.border_valence_2_discarded;
    return true;
  }

  // Beyond the thesis: a border vertex v of valence 2 whose border neighbour
  // u has valence 3 (a "tooth" that the valence rule of (a) protects) goes
  // with u and their two faces, when this lowers the number of bad vertices:
  // the shared neighbour loses two, u's other neighbour one.
  bool remove_tooth(vertex_descriptor v, vertex_descriptor u)
  {
    if(valence(u) != 3 || !is_border_vertex(u)) return false;
    const auto tip = halfedge(v, u, mesh_);  // v -> u
    const halfedge_descriptor in_tooth = is_border(tip.first, mesh_) ? opposite(tip.first, mesh_) : tip.first;
    // The face of v is (v, u, m) or (u, v, m); u's other face is (u, m, o) or (m, u, o).
    const vertex_descriptor m = target(next(in_tooth, mesh_), mesh_);
    const auto um = halfedge(u, m, mesh_);
    if(!um.second || is_border(um.first, mesh_) || is_border(opposite(um.first, mesh_), mesh_)) return false;
    const halfedge_descriptor other = target(next(um.first, mesh_), mesh_) == v ? opposite(um.first, mesh_) : um.first;
    const vertex_descriptor o = target(next(other, mesh_), mesh_);
    const auto mo = halfedge(m, o, mesh_);
    if(o == v || !mo.second || is_border(mo.first, mesh_) || is_border(opposite(mo.first, mesh_), mesh_))
      return false;  // the edge (m, o) must keep a face
    auto bad_border = [](std::size_t d) { return d < 4; };
    const int change = -2 + int(bad_border(valence(m) - 2)) - int(bad_border(valence(m))) +
                       int(bad_border(valence(o) - 1)) - int(bad_border(valence(o)));
    if(change >= 0) return false;
    put(gone_, v, true);
    put(gone_, u, true);
    Euler::remove_face(in_tooth, mesh_);
    Euler::remove_face(other, mesh_);
    ++stats_.border_teeth_removed;
    return true;
  }

  // (b) An interior vertex of valence 3 goes and its ring becomes a
  // triangle, if each ring vertex keeps a valence of at least 5 (3 on the
  // border).
  bool remove_interior_3(vertex_descriptor v)
  {
    for(vertex_descriptor r : vertices_around_target(halfedge(v, mesh_), mesh_))
      if(!at_least(r, 6, 4)) return false;  // (the ring of a tetrahedron's apex fails here)
    // With r_i = source(g_i), g_{i+1} = opposite(next(g_i)), the faces around
    // v are (r_i, v, r_{i+1}) and the ring's face runs (r_0, r_2, r_1).
    const halfedge_descriptor h = halfedge(v, mesh_);
    const vertex_descriptor r0 = source(h, mesh_), r1 = target(next(h, mesh_), mesh_);
    const vertex_descriptor r2 = target(next(opposite(next(h, mesh_), mesh_), mesh_), mesh_);
    if(!keeps(r0, r2, r1, normal(v))) return refuse();
    put(gone_, v, true);
    Euler::remove_center_vertex(h, mesh_);
    ++stats_.interior_valence_3_discarded;
    return true;
  }

  // (c) An interior vertex of valence 4 goes and the quadrilateral of its
  // ring is cut along the diagonal that spares two opposite ring vertices of
  // valence 6 or more (5 on the border); else (d) it collapses into a
  // neighbour.
  bool remove_interior_4(vertex_descriptor v)
  {
    // r[i] = source(g[i]), faces (r[i], v, r[i+1]); the quadrilateral left
    // without v runs (r[0], r[3], r[2], r[1]).
    std::array<halfedge_descriptor, 4> g;
    std::array<vertex_descriptor, 4> r;
    g[0] = halfedge(v, mesh_);
    for(int i = 0; i < 4; ++i) {
      if(i > 0) g[i] = opposite(next(g[i - 1], mesh_), mesh_);
      r[i] = source(g[i], mesh_);
    }
    const Eigen::Vector3d n = normal(v);
    for(int i = 0; i < 2; ++i) {
      // r[i] and r[i+2] lose v; the diagonal joins r[i+1] and r[i+3].
      const vertex_descriptor p = r[i], q = r[i + 2], s = r[(i + 1) % 4], t = r[(i + 3) % 4];
      if(!at_least(p, 6, 5) || !at_least(q, 6, 5) || edge_exists(s, t)) continue;
      if(!keeps(p, t, s, n) || !keeps(t, q, s, n)) {
        refuse();
        continue;
      }
      put(gone_, v, true);
      const halfedge_descriptor rest = Euler::remove_center_vertex(g[0], mesh_);
      halfedge_descriptor to_s = rest, to_t = rest;
      while(target(to_s, mesh_) != s) to_s = next(to_s, mesh_);
      while(target(to_t, mesh_) != t) to_t = next(to_t, mesh_);
      Euler::split_face(to_s, to_t, mesh_);
      ++stats_.interior_valence_4_discarded;
      return true;
    }
    // (d) collapse (v, r[i]) if r[i] keeps a valence of 5 (4 on the border)
    // and its two ring neighbours keep 5 (4).
    for(int i = 0; i < 4; ++i)
      if(at_least(r[i], 5, 4) && at_least(r[(i + 1) % 4], 6, 5) && at_least(r[(i + 3) % 4], 6, 5) &&
         collapse(v, r[i])) {
        ++stats_.interior_valence_4_collapsed;
        return true;
      }
    return false;
  }

  // (e) A border vertex of valence 3 with neighbours v0, v1, v2 (v0 and v2
  // on the border) goes and (v0, v1, v2) becomes a face, if v1 keeps a
  // valence of 5 (4 on the border); else (f) it collapses into v0 or v2 if v1
  // keeps 5 (4), or (g) into v1 if v1 is interior of valence 6 or more and
  // v0 and v2 keep 4.
  bool remove_border_3(vertex_descriptor v)
  {
    const auto border = is_border(v, mesh_);  // v0 -> v, on the border
    if(!border) return false;
    const halfedge_descriptor h = *border;
    // The faces around v are (v2, v, v1) and (v1, v, v0); without v, the
    // face (v0, v1, v2).
    const vertex_descriptor v0 = source(h, mesh_), v2 = target(next(h, mesh_), mesh_);
    const halfedge_descriptor from_v2 = opposite(next(h, mesh_), mesh_);
    const halfedge_descriptor middle = opposite(next(from_v2, mesh_), mesh_);  // v1 -> v
    const vertex_descriptor v1 = source(middle, mesh_);
    if(v1 == v0 || v1 == v2) return false;
    const Eigen::Vector3d n = normal(v);
    if(at_least(v1, 6, 5) && !edge_exists(v0, v2)) {
      if(keeps(v0, v1, v2, n)) {
        put(gone_, v, true);
        const halfedge_descriptor quad = Euler::join_face(middle, mesh_);  // (v2, v, v0, v1)
        halfedge_descriptor to_v2 = quad, to_v0 = quad;
        while(target(to_v2, mesh_) != v2) to_v2 = next(to_v2, mesh_);
        while(target(to_v0, mesh_) != v0) to_v0 = next(to_v0, mesh_);
        const halfedge_descriptor cut = Euler::split_face(to_v2, to_v0, mesh_);  // v2 -> v0 or v0 -> v2
        const halfedge_descriptor ear = target(next(cut, mesh_), mesh_) == v ? cut : opposite(cut, mesh_);
        Euler::remove_face(ear, mesh_);
        ++stats_.border_valence_3_discarded;
        return true;
      }
      refuse();
    }
    if(at_least(v1, 6, 5)) {
      for(vertex_descriptor end : {v2, v0})
        if(valence(end) >= 3 && collapse(v, end)) {
          ++stats_.border_valence_3_collapsed;
          return true;
        }
    }
    if(!is_border_vertex(v1) && valence(v1) >= 6 && valence(v0) >= 5 && valence(v2) >= 5 && collapse(v, v1)) {
      ++stats_.border_valence_3_collapsed;
      return true;
    }
    return false;
  }

  std::size_t operations() const
  {
    return stats_.border_valence_2_discarded + stats_.interior_valence_3_discarded +
           stats_.interior_valence_4_discarded + stats_.interior_valence_4_collapsed +
           stats_.border_valence_3_discarded + stats_.border_valence_3_collapsed + stats_.border_teeth_removed +
           stats_.splits;
  }

  bool refuse()
  {
    ++stats_.refused;
    return false;
  }

  // Collapses the edge (v, w) to the point of F(v, w) closest to the edge's
  // midpoint (equation 5.18), if the link condition holds and every face
  // around that point certifies exactly and keeps its orientation.
  bool collapse(vertex_descriptor v, vertex_descriptor w)
  {
    const auto vw = halfedge(v, w, mesh_);
    if(!vw.second || !Euler::does_satisfy_link_condition(edge(vw.first, mesh_), mesh_)) return false;
    const Local_frame frame = collapse_frame(mesh_, vpm_, vw.first);
    region_.clear();
    if(!(frame.scale > 0.) || !collapse_feasible_region(mesh_, vpm_, vw.first, k_, frame, region_)) return refuse();
    Small_qp qp;
    qp.G = 2. * Eigen::Matrix3d::Identity();  // |x - q|^2 with q the midpoint, the frame's origin
    qp.a.setZero();
    for(const Half_space& s : region_) qp.add_constraint(s.normal, s.offset);
    const Qp_result r = solve_small_qp_with_fallback(qp);
    if(r.status != Qp_status::optimal) return refuse();
    const Eigen::Vector3d x = frame.to_global(r.x);
    const Point p(x[0], x[1], x[2]);
    if(!collapse_keeps_faces(mesh_, vpm_, vw.first, p, bounds_)) return refuse();
    const vertex_descriptor kept = Euler::collapse_edge(edge(vw.first, mesh_), mesh_);
    put(gone_, kept == v ? w : v, true);
    put(vpm_, kept, p);
    return true;
  }

  // Raises the valence of each bad vertex (and of each border vertex of
  // valence 3 next to a valence-2 one, whose removal it blocks) by splits.
  void split_pass()
  {
    std::vector<vertex_descriptor> chosen;
    for(vertex_descriptor v : vertices(mesh_)) {
      if(is_bad(v)) chosen.push_back(v);
      if(is_border_vertex(v) && valence(v) == 2)
        for(vertex_descriptor w : vertices_around_target(halfedge(v, mesh_), mesh_))
          if(valence(w) == 3) chosen.push_back(w);
    }
    for(vertex_descriptor v : chosen)
      while(valence(v) < (is_border_vertex(v) ? 4u : 5u) && raise(v, 2)) {}
  }

  bool is_bad(vertex_descriptor v) const
  {
    const std::size_t d = valence(v);
    return is_border_vertex(v) ? d < 4 : (d < 5 || d > 11);
  }

  // Splits the interior vertex w (valence d >= 6) with `wing` as one wing
  // and the other wing j ring steps away, j in [3, d - 3] so that both
  // halves keep a valence of 5 or more, the most balanced first.
  bool split_with_wing(vertex_descriptor w, vertex_descriptor wing)
  {
    const auto from_wing = halfedge(wing, w, mesh_);
    if(!from_wing.second) return false;
    std::vector<halfedge_descriptor> ring;  // the halfedges into w, from the wing's on
    for(halfedge_descriptor g = from_wing.first;;) {
      ring.push_back(g);
      g = opposite(next(g, mesh_), mesh_);
      if(g == from_wing.first) break;
    }
    const std::size_t d = ring.size();
    std::vector<std::size_t> wings;
    for(std::size_t j = 3; j + 3 <= d; ++j) wings.push_back(j);
    std::sort(wings.begin(), wings.end(), [&](std::size_t x, std::size_t y) {
      return std::abs(2 * double(x) - double(d)) < std::abs(2 * double(y) - double(d));
    });
    for(std::size_t j : wings) {
      const vertex_descriptor other_wing = source(ring[j], mesh_);
      if(!is_border_vertex(other_wing) && valence(other_wing) >= 11) continue;  // would become bad
      Vertex_split_plan<Point, halfedge_descriptor> plan;
      if(plan_vertex_split(mesh_, vpm_, ring[0], ring[j], k_, bounds_, plan)) {
        apply_vertex_split(mesh_, vpm_, plan);
        ++stats_.splits;
        return true;
      }
      refuse();
    }
    return false;
  }

  TriangleMesh& mesh_;
  VertexPointMap vpm_;
  const int k_;
  const bool split_;
  const Angle_bounds bounds_;
  Bad_valence_removal_statistics& stats_;
  typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<bool> >::type gone_;
  std::vector<Half_space> region_;
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_BAD_VALENCE_REMOVAL_H
