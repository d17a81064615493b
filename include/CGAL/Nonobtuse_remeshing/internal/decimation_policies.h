// SPDX-License-Identifier: GPL-3.0-or-later
//
// The policies of angle-bounded decimation (thesis, chapter 6) for CGAL's
// Surface_mesh_simplification::edge_collapse, which stays the engine:
//   placement  w* = argmin Q_u + Q_v over F(u, v) (equations 6.1, 6.2, 6.4),
//              with the feasible-region code and the QP of deform-to-fit;
//   cost       Q_u(w*) + Q_v(w*) (equation 6.5), no lazy evaluation (6.4:
//              edge_collapse re-costs every edge whose F(u, v) changed);
//   filter     the valence floor and the exact certification of every face
//              around w*;
//   visitor    carries the quadrics, Q_w = Q_u + Q_v (6.3).
// The placement and the cost share one quadratic form per edge:
// Q_u + Q_v + eps |x - m|^2, m the edge's midpoint, eps = 1e-3 tr(Q_u + Q_v)/3.
// The small eps term makes the QP strictly convex where the planes are
// parallel (flat regions, where Q_u + Q_v has rank one) and, there, breaks the
// ties of equation 6.5 by edge length, shortest first.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_DECIMATION_POLICIES_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_DECIMATION_POLICIES_H

#include <CGAL/Nonobtuse_remeshing/internal/angle_predicates.h>
#include <CGAL/Nonobtuse_remeshing/internal/certified_faces.h>
#include <CGAL/Nonobtuse_remeshing/internal/feasible_region.h>
#include <CGAL/Nonobtuse_remeshing/internal/quadric.h>
#include <CGAL/Nonobtuse_remeshing/internal/small_qp.h>
#include <CGAL/Nonobtuse_remeshing/statistics.h>

#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/optional.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {

namespace internal {

/// What the policies share: the quadrics, the options and the counters.
template <typename TriangleMesh, typename QuadricMap>
struct Decimation_context
{
  QuadricMap quadrics;
  int drum_subdivisions = 2;
  std::size_t min_interior_valence = 4, min_border_valence = 3;
  double diagonal = 1.;
  double ceiling_cost = std::numeric_limits<double>::infinity();  // the round's ceiling, as a cost
  Angle_bounds bounds;
  Angle_bounded_decimation_statistics* statistics = nullptr;
  std::size_t filter_refusals = 0, non_collapsable = 0;  // their difference: CGAL's topology and fold tests

  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  std::function<bool(vertex_descriptor)> frozen;  // vertices no collapse may take, when set

  // Q_u + Q_v of the edge (v0, v1); then the weight eps of its tie break.
  Quadric sum(vertex_descriptor v0, vertex_descriptor v1) const
  {
    Quadric q = get(quadrics, v0);
    q += get(quadrics, v1);
    return q;
  }
  static double tie_break(const Quadric& q) { return 1e-3 * q.A.trace() / 3.; }

  // The form of the file comment for the edge with quadric sum q, in the
  // frame's coordinates x_world = origin + scale x, divided by scale^2 (which
  // leaves the minimizer alone): 1/2 x^T G x + a^T x.
  static Small_qp form(const Quadric& q, const Local_frame& frame)
  {
    Small_qp qp;
    qp.G = 2. * (q.A + tie_break(q) * Eigen::Matrix3d::Identity());
    qp.a = 2. * (q.A * frame.origin + q.b) / frame.scale;
    return qp;
  }
  // The unconstrained minimum of that form, a lower bound of its minimum
  // over any region, at `x`: with y = x - m, (A + eps I) y = -(A m + b).
  // False when it is not unique (no planes and no points: eps = 0).
  static bool unconstrained_minimum(const Quadric& q, const Eigen::Vector3d& midpoint, Eigen::Vector3d& x)
  {
    const double eps = tie_break(q);
    if(!(eps > 0.)) return false;
    const Eigen::Matrix3d H = q.A + eps * Eigen::Matrix3d::Identity();
    x = midpoint + H.ldlt().solve(-(q.A * midpoint + q.b));
    return x.allFinite();
  }
  // A bound on the rounding of cost() at x: the magnitudes of its terms.
  static double cost_magnitude(const Quadric& q, const Eigen::Vector3d& midpoint, const Eigen::Vector3d& x)
  {
    return std::abs(x.dot(q.A * x)) + 2. * std::abs(q.b.dot(x)) + std::abs(q.c) +
           tie_break(q) * (x - midpoint).squaredNorm();
  }
  // The value of that form at the world point x (equation 6.5 with the tie
  // break), clamped at 0 against rounding.
  static double cost(const Quadric& q, const Eigen::Vector3d& midpoint, const Eigen::Vector3d& x)
  {
    return (std::max)(0., q(x) + tie_break(q) * (x - midpoint).squaredNorm());
  }

  // The valence floor (thesis, Figure 7.5): collapsing (v0, v1) creates w
  // of valence d0 + d1 - 2 - (number of faces of the edge), on the border if
  // either end is, and takes one from the apex of each face of the edge.
  template <typename Profile>
  bool valences_allow(const Profile& profile) const
  {
    const TriangleMesh& mesh = profile.surface_mesh();
    auto valence_floor = [&](bool border) { return border ? min_border_valence : min_interior_valence; };
    const std::size_t faces = std::size_t(profile.left_face_exists()) + std::size_t(profile.right_face_exists());
    const std::size_t dw = degree(profile.v0(), mesh) + degree(profile.v1(), mesh) - 2 - faces;
    const bool w_border = bool(is_border(profile.v0(), mesh)) || bool(is_border(profile.v1(), mesh));
    if(dw < valence_floor(w_border)) return false;
    for(int side = 0; side < 2; ++side) {
      if(!(side == 0 ? profile.left_face_exists() : profile.right_face_exists())) continue;
      const vertex_descriptor apex = side == 0 ? profile.vL() : profile.vR();
      if(degree(apex, mesh) - 1 < valence_floor(bool(is_border(apex, mesh)))) return false;
    }
    return true;
  }
};

/// Placement policy: w* of equation 6.4, or none (the collapse is then
/// forbidden) when the valence floor forbids it, F(u, v) is empty or
/// degenerate, or the QP fails.
template <typename Context>
class Angle_bounded_placement
{
public:
  explicit Angle_bounded_placement(const Context* context) : context_(context) {}

  template <typename Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile) const
  {
    using Point = typename Profile::Point;
    Angle_bounded_decimation_statistics& s = *context_->statistics;
    if(context_->frozen && (context_->frozen(profile.v0()) || context_->frozen(profile.v1()))) {
      ++s.frozen_refusals;
      return boost::none;
    }
    // Cheap and monotone (valences only fall until an edge is re-costed), so
    // tested before the QP; the filter tests it again at collapse time.
    if(!context_->valences_allow(profile)) {
      ++s.valence_refusals;
      return boost::none;
    }
    const auto& mesh = profile.surface_mesh();
    const auto vpm = profile.vertex_point_map();
    const Local_frame frame = collapse_frame(mesh, vpm, profile.v0_v1());
    if(!(frame.scale > 0.)) {
      ++s.empty_regions;
      return boost::none;
    }
    const Quadric q = context_->sum(profile.v0(), profile.v1());
    const Eigen::Vector3d midpoint = 0.5 * (to_eigen(profile.p0()) + to_eigen(profile.p1()));
    const bool ceiling = context_->ceiling_cost < std::numeric_limits<double>::infinity();
    // Over the round's ceiling already at the form's unconstrained minimum
    // (with margins for the rounding of both evaluations), the edge cannot be
    // collapsed in this round: that minimum stands as its placement (its key
    // in the queue), and no region is built.
    Eigen::Vector3d low;
    if(ceiling && Context::unconstrained_minimum(q, midpoint, low) &&
       Context::cost(q, midpoint, low) >
           (1. + 1e-6) * context_->ceiling_cost + 1e-9 * Context::cost_magnitude(q, midpoint, low)) {
      ++s.placements_over_ceiling;
      return Point(low[0], low[1], low[2]);
    }
    const Small_qp form = Context::form(q, frame);
    // F(u, v) lies within its half-spaces without the drum (k = 0: U, V, R,
    // S, T, no trigonometry), where four empty regions in five are empty
    // already, at about a third of the cost; then the whole region. The
    // cost at the drum-free optimum is a lower bound of the cost in F(u, v):
    // over the round's ceiling, the edge cannot be collapsed in this round,
    // so that optimum stands as its placement (its key in the queue; a
    // popped edge is placed again) and the whole region is not built.
    Qp_result r;
    for(int k : {0, context_->drum_subdivisions}) {
      region_.clear();
      if(!collapse_feasible_region(mesh, vpm, profile.v0_v1(), k, frame, region_)) {
        ++s.empty_regions;
        return boost::none;
      }
      qp_.G = form.G;
      qp_.a = form.a;
      qp_.normals.clear();
      qp_.offsets.clear();
      for(const Half_space& h : region_) qp_.add_constraint(h.normal, h.offset);
      ++s.qp_solves;
      r = solve_small_qp_with_fallback(qp_, &s.qp_fallbacks);
      if(r.status != Qp_status::optimal) {
        ++s.empty_regions;
        return boost::none;
      }
      if(k == 0 && ceiling) {
        // a margin for the solver's rounding: a bound near the ceiling solves the whole region
        if(Context::cost(q, midpoint, frame.to_global(r.x)) > (1. + 1e-6) * context_->ceiling_cost) {
          ++s.placements_over_ceiling;
          break;
        }
      }
    }
    const Eigen::Vector3d x = frame.to_global(r.x);
    return Point(x[0], x[1], x[2]);
  }

private:
  const Context* context_;
  // reused: edge_collapse holds the policy by const reference
  mutable std::vector<Half_space> region_;
  mutable Small_qp qp_;
};

/// Cost policy: equation 6.5, none without a placement.
template <typename Context>
class Angle_bounded_cost
{
public:
  explicit Angle_bounded_cost(const Context* context) : context_(context) {}

  template <typename Profile>
  boost::optional<typename Profile::FT> operator()(const Profile& profile,
                                                   const boost::optional<typename Profile::Point>& placement) const
  {
    if(!placement) return boost::none;
    const Eigen::Vector3d midpoint = 0.5 * (to_eigen(profile.p0()) + to_eigen(profile.p1()));
    return Context::cost(context_->sum(profile.v0(), profile.v1()), midpoint, to_eigen(*placement));
  }

private:
  const Context* context_;
};

/// Filter: the collapse to w* goes ahead only if the valence floor holds
/// and every face around w* certifies exactly in the bounds and keeps its
/// orientation, so the mesh is certified after every collapse.
template <typename Context>
class Angle_bounded_filter
{
public:
  explicit Angle_bounded_filter(Context* context) : context_(context) {}

  template <typename Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile,
                                                      boost::optional<typename Profile::Point> placement) const
  {
    if(!placement) return boost::none;
    Angle_bounded_decimation_statistics& s = *context_->statistics;
    if(!context_->valences_allow(profile)) {
      ++s.valence_refusals;
      ++context_->filter_refusals;
      return boost::none;
    }
    if(!collapse_keeps_faces(profile.surface_mesh(), profile.vertex_point_map(), profile.v0_v1(), *placement,
                             context_->bounds)) {
      ++s.certification_refusals;
      ++context_->filter_refusals;
      return boost::none;
    }
    return placement;
  }

private:
  Context* context_;
};

/// Visitor of edge_collapse: Q_w = Q_u + Q_v after each collapse (thesis,
/// 6.3), and the counts. `Driver` gets `collapsed()` after each collapse.
template <typename TriangleMesh, typename Context, typename Driver>
class Quadric_visitor : public Surface_mesh_simplification::Edge_collapse_visitor_base<TriangleMesh>
{
public:
  Quadric_visitor(Context* context, Driver* driver) : context_(context), driver_(driver) {}

  template <typename Profile, typename Cost>
  void OnSelected(const Profile&, const Cost& cost, std::size_t, std::size_t)
  {
    selected_cost_ = cost ? double(*cost) : 0.;
  }
  template <typename Profile, typename Placement>
  void OnCollapsing(const Profile& profile, const Placement&)
  {
    sum_ = context_->sum(profile.v0(), profile.v1());
  }
  template <typename Profile, typename Vertex>
  void OnCollapsed(const Profile&, Vertex kept)
  {
    put(context_->quadrics, kept, sum_);
    Angle_bounded_decimation_statistics& s = *context_->statistics;
    ++s.collapses;
    s.largest_collapse_error = (std::max)(s.largest_collapse_error, std::sqrt(selected_cost_) / context_->diagonal);
    driver_->collapsed();
  }
  template <typename Profile>
  void OnNonCollapsable(const Profile&)
  {
    ++context_->non_collapsable;
  }

private:
  Context* context_;
  Driver* driver_;
  Quadric sum_;
  double selected_cost_ = 0.;
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_DECIMATION_POLICIES_H
