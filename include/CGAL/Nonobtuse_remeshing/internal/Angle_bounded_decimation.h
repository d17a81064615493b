// SPDX-License-Identifier: GPL-3.0-or-later
//
// Angle-bounded decimation (thesis, chapter 6): the initial quadrics
// (equations 5.10 and 6.3), the stop predicate (the targets, early
// termination of 6.5, cancellation) and the runs of CGAL's edge_collapse with
// the policies of decimation_policies.h. A hierarchy is one decimation with
// several targets: the mesh is handed to a sink each time the vertex count
// reaches the next target.
//
// Beyond the thesis, relaxation: on a fitted nonobtuse mesh most angles sit
// at their bounds, and after a few collapses four edges in five have an empty
// F(u, v) (exact probes confirm: the regions are empty, not just their
// linearization), so a single greedy run stalls near 40% of the vertices
// removed, its last collapses costing tens of % of the diagonal. So the
// decimation runs in rounds: each collapses while the cheapest cost stays
// below a ceiling (sqrt of the cost, from 1e-3 of the diagonal, doubling
// each round, capped by max_error), then deform-to-fit (chapter 5, certified
// after every move) fits the decimated mesh to the full one, which gives the
// angles room again. The quadrics carry over from round to round.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_ANGLE_BOUNDED_DECIMATION_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_ANGLE_BOUNDED_DECIMATION_H

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/Deform_to_fit.h>
#include <CGAL/Nonobtuse_remeshing/internal/closest_triangle.h>
#include <CGAL/Nonobtuse_remeshing/internal/decimation_policies.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

struct Angle_bounded_decimation_options
{
  int drum_subdivisions = 2;
  std::size_t min_interior_valence = 4;  // the thesis's results: no interior v3,
  std::size_t min_border_valence = 3;    // no v2
  double max_error = std::numeric_limits<double>::infinity();  // fraction of the diagonal
  bool relaxation = true;
  double first_ceiling = 1e-3;         // fraction of the diagonal
  double relaxation_tolerance = 1e-3;  // the fit's tolerance
  int max_rounds = 64;
  int threads = 0;  // the relaxation's workers, 0: one per core
};

// Reads and checks the parameters shared by both entry points; throws
// Bad_parameter before anything changes.
template <typename NamedParameters>
Angle_bounded_decimation_options decimation_options(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Angle_bounded_decimation_options o;  // its members hold the defaults
  o.drum_subdivisions = choose_parameter(get_parameter(np, internal_np::drum_subdivisions), o.drum_subdivisions);
  o.min_interior_valence = choose_parameter(get_parameter(np, internal_np::min_interior_valence), o.min_interior_valence);
  o.min_border_valence = choose_parameter(get_parameter(np, internal_np::min_border_valence), o.min_border_valence);
  o.max_error = choose_parameter(get_parameter(np, internal_np::max_error), o.max_error);
  o.relaxation = choose_parameter(get_parameter(np, internal_np::relaxation), o.relaxation);
  o.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), o.threads);
  if(o.threads < 0) throw Bad_parameter("the number of threads must be at least 0 (0: one per core)");
  if(o.drum_subdivisions < 1 || o.drum_subdivisions > 16)
    throw Bad_parameter("the drum subdivisions k must lie in [1, 16]");
  if(o.min_interior_valence < 3 || o.min_interior_valence > 12)
    throw Bad_parameter("the interior valence floor must lie in [3, 12]");
  if(o.min_border_valence < 2 || o.min_border_valence > 12)
    throw Bad_parameter("the border valence floor must lie in [2, 12]");
  if(!(o.max_error > 0.)) throw Bad_parameter("the maximum error must be positive");
  return o;
}

// The ratios of a hierarchy's levels; throws Bad_parameter unless they
// decrease strictly within (0, 1).
inline void check_level_ratios(const std::vector<double>& ratios)
{
  if(ratios.empty()) throw Bad_parameter("the hierarchy needs at least one ratio");
  for(std::size_t i = 0; i < ratios.size(); ++i)
    if(!(ratios[i] > 0. && ratios[i] < 1.) || (i > 0 && !(ratios[i] < ratios[i - 1])))
      throw Bad_parameter("the ratios of the levels must decrease strictly within (0, 1)");
}

// The bounding-box diagonal of `mesh`, which must be a triangle mesh
// certified in [30, 90] degrees; throws Bad_input otherwise.
template <typename TriangleMesh, typename VertexPointMap>
double certified_mesh_diagonal(const TriangleMesh& mesh, VertexPointMap vpm)
{
  if(!is_triangle_mesh(mesh)) throw Bad_input("angle_bounded_decimation: not a triangle mesh");
  if(!certify_angle_bounds(mesh, CGAL::parameters::vertex_point_map(vpm)).is_certified())
    throw Bad_input("angle_bounded_decimation needs a mesh certified in [30, 90] degrees");
  const Bbox_3 box = Polygon_mesh_processing::bbox(mesh, CGAL::parameters::vertex_point_map(vpm));
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

template <typename TriangleMesh, typename VertexPointMap, typename Visitor>
class Angle_bounded_decimation
{
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using Quadric_map = typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<Quadric> >::type;
  using Context = Decimation_context<TriangleMesh, Quadric_map>;
  using Self = Angle_bounded_decimation;

public:
  Angle_bounded_decimation(TriangleMesh& mesh, VertexPointMap vpm, const Angle_bounded_decimation_options& options,
                           double diagonal, Visitor& visitor)
    : mesh_(mesh), vpm_(vpm), options_(options), visitor_(visitor)
  {
    context_.quadrics = get(CGAL::dynamic_vertex_property_t<Quadric>(), mesh_);
    context_.drum_subdivisions = options.drum_subdivisions;
    context_.min_interior_valence = options.min_interior_valence;
    context_.min_border_valence = options.min_border_valence;
    context_.diagonal = diagonal;
    context_.statistics = &stats_;
  }

  // Decimates towards the decreasing `targets` (vertex counts), calling
  // `sink(i, true, stats)` when the count reaches targets[i], and
  // `sink(i, false, stats)` for the first target not reached, if the
  // decimation stops before it. `reference` is the full mesh, the target of
  // the relaxation, with its points in `reference_points`.
  template <typename ReferencePointMap, typename Sink>
  Angle_bounded_decimation_statistics run(const std::vector<std::size_t>& targets, const TriangleMesh& reference,
                                          ReferencePointMap reference_points, Sink sink)
  {
    start_ = std::chrono::steady_clock::now();
    targets_ = targets;
    stats_.vertices_before = vertices_ = vertices(mesh_).size();
    stats_.target_vertices = targets_.empty() ? vertices_ : targets_.back();
    initialize_quadrics();
    emit_ = [&](bool reached) {
      update_statistics();
      Angle_bounded_decimation_statistics level = stats_;
      level.target_vertices = targets_[next_];
      if(reached) level.stop_reason = Decimation_stop_reason::target_reached;
      sink(next_, reached, level);
      ++next_;
    };

    Angle_bounded_placement<Context> placement(&context_);
    Angle_bounded_cost<Context> cost(&context_);
    Angle_bounded_filter<Context> filter(&context_);
    Quadric_visitor<TriangleMesh, Context, Self> visitor(&context_, this);
    const Stop stop{this};
    ceiling_ = options_.relaxation ? (std::min)(options_.first_ceiling, options_.max_error) : options_.max_error;
    std::unique_ptr<Closest_triangle<TriangleMesh, ReferencePointMap> > closest;
    for(int round = 0; reach_levels() && round < options_.max_rounds; ++round) {
      ++stats_.rounds;
      const std::size_t before = stats_.collapses;
      stopped_by_ceiling_ = stopped_at_max_error_ = false;
      context_.ceiling_cost = (ceiling_ * context_.diagonal) * (ceiling_ * context_.diagonal);  // infinite without one
      stats_.stopping_error = 0.;
      Surface_mesh_simplification::edge_collapse(
          mesh_, stop,
          CGAL::parameters::vertex_point_map(vpm_).get_cost(cost).get_placement(placement).filter(filter).visitor(
              visitor));
      if(!reach_levels() || stats_.stop_reason == Decimation_stop_reason::cancelled) break;
      // Below max_error the ceiling rises; at max_error a round must remove
      // 2% of the vertices to go on, with no collapse left under the ceiling
      // 0.5%.
      const bool below_max_error = stopped_by_ceiling_ && ceiling_ < options_.max_error;
      const std::size_t removed = stats_.collapses - before;
      const std::size_t enough = stopped_by_ceiling_ ? vertices_ / 50 : vertices_ / 200;
      if(!below_max_error && (removed == 0 || removed < enough)) break;
      if(below_max_error) ceiling_ = (std::min)(2. * ceiling_, options_.max_error);
      if(!options_.relaxation) break;
      if(removed > 0) {
        if(!closest) closest.reset(new Closest_triangle<TriangleMesh, ReferencePointMap>(reference, reference_points, 0));
        relax(*closest);
      }
      if(stats_.stop_reason == Decimation_stop_reason::cancelled) break;
    }
    if(!reach_levels()) stats_.stop_reason = Decimation_stop_reason::target_reached;
    else if(stats_.stop_reason != Decimation_stop_reason::cancelled)
      stats_.stop_reason = stopped_at_max_error_ ? Decimation_stop_reason::max_error
                           : stats_.rounds == std::size_t(options_.max_rounds) ? Decimation_stop_reason::round_limit
                                                                            : Decimation_stop_reason::no_collapse_left;
    if(next_ < targets_.size()) emit_(false);
    emit_ = nullptr;
    update_statistics();
    return stats_;
  }

  void collapsed() { --vertices_; }

  // The vertices no collapse may take (none when `held` is empty).
  void hold(std::function<bool(vertex_descriptor)> held) { context_.frozen = std::move(held); }

private:
  // Deform-to-fit of the decimated mesh to the full one (certified after
  // every move, connectivity unchanged); the quadrics stay.
  template <typename Input>
  void relax(const Input& closest)
  {
    Deform_to_fit_options o;
    o.tolerance = options_.relaxation_tolerance;
    o.threads = options_.threads;
    o.distance_guard = false;  // each round's collapses moved the surface already; the error bound rules
    o.fill_border_notches = false;  // the connectivity is the decimation's
    // the next round's collapses move the surface again: one round of the
    // last passes of the stuck vertices (hand at 10,000 vertices: four took
    // its relaxations from 1.4 to 3.8 s)
    o.last_stuck_rounds = 1;
    // the decimation's visitor decides
    auto fit_visitor = keep_going_relay([this](const Deform_to_fit_statistics&) { return visitor_.keep_going(stats_); });
    Deform_to_fit<TriangleMesh, VertexPointMap, Input, decltype(fit_visitor)> fit(mesh_, vpm_, closest,
                                                                                 context_.diagonal, o, fit_visitor);
    const Deform_to_fit_statistics f = fit.run();
    ++stats_.relaxations;
    stats_.relaxation_moves += f.moves;
    stats_.relaxation_seconds += f.seconds;
    if(f.cancelled) stats_.stop_reason = Decimation_stop_reason::cancelled;
  }

  void update_statistics()
  {
    stats_.vertices_after = vertices_;
    stats_.topology_refusals = context_.non_collapsable - context_.filter_refusals;
    stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  // Equation 5.10 for interior vertices (the planes of the incident faces),
  // equation 6.3 for border vertices (the squared distance to themselves).
  void initialize_quadrics()
  {
    for(vertex_descriptor v : vertices(mesh_)) {
      Quadric q;
      const Eigen::Vector3d p = to_eigen(get(vpm_, v));
      if(is_border(v, mesh_)) {
        q.add_point(p);
      } else {
        for(auto h : halfedges_around_target(v, mesh_)) {
          const Eigen::Vector3d a = to_eigen(get(vpm_, source(h, mesh_))),
                                c = to_eigen(get(vpm_, target(next(h, mesh_), mesh_)));
          const Eigen::Vector3d n = (p - a).cross(c - a);
          if(n.norm() > 0.) q.add_plane(n.normalized(), -n.normalized().dot(p));
        }
      }
      put(context_.quadrics, v, q);
    }
  }

  // Hands every target reached to the sink; true while a target is left.
  bool reach_levels()
  {
    while(next_ < targets_.size() && vertices_ <= targets_[next_]) emit_(true);
    return next_ < targets_.size();
  }

  // The stop predicate, called before each collapse with the cheapest cost.
  struct Stop
  {
    Self* self;
    template <typename FT, typename Profile>
    bool operator()(const FT& cost, const Profile&, std::size_t, std::size_t) const
    {
      Angle_bounded_decimation_statistics& s = self->stats_;
      if(!self->reach_levels()) return true;
      const double error = std::sqrt(double(cost)) / self->context_.diagonal;
      if(error > self->ceiling_) {
        self->stopped_by_ceiling_ = true;
        self->stopped_at_max_error_ = !(self->ceiling_ < self->options_.max_error);
        s.stopping_error = error;
        return true;
      }
      if(!self->visitor_.keep_going(s)) {
        s.stop_reason = Decimation_stop_reason::cancelled;
        return true;
      }
      return false;
    }
  };

  TriangleMesh& mesh_;
  VertexPointMap vpm_;
  const Angle_bounded_decimation_options options_;
  Visitor& visitor_;
  Context context_;
  Angle_bounded_decimation_statistics stats_;
  std::vector<std::size_t> targets_;
  std::size_t next_ = 0, vertices_ = 0;
  std::function<void(bool)> emit_;
  double ceiling_ = 0.;
  bool stopped_by_ceiling_ = false, stopped_at_max_error_ = false;
  std::chrono::steady_clock::time_point start_;
};

// The decimation towards `targets` once its parameters are read, the full
// mesh `reference` being the relaxation's target and `level` called at each
// target (see Angle_bounded_decimation::run()): one instantiation per mesh
// type and point maps, whatever the parameters and the visitor.
template <typename TriangleMesh, typename VertexPointMap, typename ReferencePointMap>
Angle_bounded_decimation_statistics angle_bounded_decimation_with(
    TriangleMesh& mesh, VertexPointMap vpm, const Angle_bounded_decimation_options& o, double diagonal,
    const std::vector<std::size_t>& targets, const TriangleMesh& reference, ReferencePointMap reference_vpm,
    const Keep_going_function<Angle_bounded_decimation_statistics>& keep_going,
    const std::function<void(std::size_t, bool, const Angle_bounded_decimation_statistics&)>& level,
    const std::function<bool(typename boost::graph_traits<TriangleMesh>::vertex_descriptor)>& held = {})
{
  auto visitor = keep_going_relay(keep_going);
  Angle_bounded_decimation<TriangleMesh, VertexPointMap, decltype(visitor)> decimation(mesh, vpm, o, diagonal, visitor);
  decimation.hold(held);
  return decimation.run(targets, reference, reference_vpm, level);
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

// With NonobtuseRemeshing::Compiled (compiled_surface_mesh.h): the declarations
// of its instantiations; src/compiled/angle_bounded_decimation.cpp defines
// CGAL_NONOBTUSE_REMESHING_INSTANTIATE_DECIMATION, and there they are the instantiations.
#ifdef CGAL_NONOBTUSE_REMESHING_COMPILED
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
#ifndef CGAL_NONOBTUSE_REMESHING_INSTANTIATE_DECIMATION
extern
#endif
template Angle_bounded_decimation_statistics angle_bounded_decimation_with(
    Compiled_mesh&, Compiled_point_map, const Angle_bounded_decimation_options&, double,
    const std::vector<std::size_t>&, const Compiled_mesh&, Compiled_point_map,
    const Keep_going_function<Angle_bounded_decimation_statistics>&,
    const std::function<void(std::size_t, bool, const Angle_bounded_decimation_statistics&)>&,
    const std::function<bool(boost::graph_traits<Compiled_mesh>::vertex_descriptor)>&);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
#endif

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_ANGLE_BOUNDED_DECIMATION_H
