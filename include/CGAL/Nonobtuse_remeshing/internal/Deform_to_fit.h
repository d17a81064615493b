// SPDX-License-Identifier: GPL-3.0-or-later
//
// The deform-to-fit optimizer (thesis, chapter 5): per-vertex quadratic
// programs over the linearized feasible regions, a greedy queue on the
// improvement, lazy evaluation, early smoothing and constrained Laplacian
// smoothing. Every move is certified exactly before it is applied, so the
// mesh satisfies the angle bounds at every moment.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_DEFORM_TO_FIT_IMPL_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_DEFORM_TO_FIT_IMPL_H

#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/angle_predicates.h>
#include <CGAL/Nonobtuse_remeshing/internal/border_notches.h>
#include <CGAL/Nonobtuse_remeshing/internal/closest_triangle.h>
#include <CGAL/Nonobtuse_remeshing/internal/distance_balance.h>
#include <CGAL/Nonobtuse_remeshing/internal/distance_guard.h>
#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>
#include <CGAL/Nonobtuse_remeshing/internal/feasible_region.h>
#include <CGAL/Nonobtuse_remeshing/internal/feature_attraction.h>
#include <CGAL/Nonobtuse_remeshing/internal/fit_objective.h>
#include <CGAL/Nonobtuse_remeshing/internal/parallel.h>
#include <CGAL/Nonobtuse_remeshing/internal/small_qp.h>
#include <CGAL/Nonobtuse_remeshing/internal/stuck_vertices.h>
#include <CGAL/Nonobtuse_remeshing/internal/untangling.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>
#include <CGAL/Nonobtuse_remeshing/statistics.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <cmath>
#include <queue>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {

namespace internal {

struct Deform_to_fit_options
{
  double alpha = 0.5;
  int drum_subdivisions = 2;
  int smoothing_steps = 2;
  double tolerance = 1e-4;  // a move must improve L by (tolerance * diagonal)^2
  std::size_t max_moves = std::size_t(-1);
  double max_seconds = 1e300;
  bool lazy_evaluation = true;
  bool early_smoothing = true;
  bool tangential_smoothing = true;
  bool attract_features = true;
  bool distance_guard = true;
  bool fill_border_notches = true;
  bool free_stuck_vertices = true;
  int last_stuck_rounds = 4;  // at most this many rounds of the last passes (stuck_vertices.h)
  bool balance_distance = true;
  int threads = 0;  // 0: one per core
};

// Reads and checks the fit's named parameters; throws Bad_parameter
// for one out of range.
template <typename NamedParameters>
Deform_to_fit_options deform_to_fit_options(const NamedParameters& np, int& rings)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  internal::Deform_to_fit_options o;  // its members hold the defaults
  o.alpha = choose_parameter(get_parameter(np, internal_np::alpha), o.alpha);
  o.drum_subdivisions = choose_parameter(get_parameter(np, internal_np::drum_subdivisions), o.drum_subdivisions);
  o.smoothing_steps = choose_parameter(get_parameter(np, internal_np::smoothing_steps), o.smoothing_steps);
  o.tolerance = choose_parameter(get_parameter(np, internal_np::fit_tolerance), o.tolerance);
  o.max_moves = choose_parameter(get_parameter(np, internal_np::max_moves), o.max_moves);
  o.max_seconds = choose_parameter(get_parameter(np, internal_np::max_seconds), o.max_seconds);
  o.lazy_evaluation = choose_parameter(get_parameter(np, internal_np::lazy_evaluation), o.lazy_evaluation);
  o.early_smoothing = choose_parameter(get_parameter(np, internal_np::early_smoothing), o.early_smoothing);
  o.tangential_smoothing = choose_parameter(get_parameter(np, internal_np::tangential_smoothing), o.tangential_smoothing);
  o.attract_features = choose_parameter(get_parameter(np, internal_np::attract_features), o.attract_features);
  o.distance_guard = choose_parameter(get_parameter(np, internal_np::distance_guard), o.distance_guard);
  o.fill_border_notches =
      choose_parameter(get_parameter(np, internal_np::fill_border_notches), o.fill_border_notches);
  o.free_stuck_vertices =
      choose_parameter(get_parameter(np, internal_np::free_stuck_vertices), o.free_stuck_vertices);
  o.balance_distance = choose_parameter(get_parameter(np, internal_np::balance_distance), o.balance_distance);
  o.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), o.threads);
  rings = choose_parameter(get_parameter(np, internal_np::quadric_rings), 0);
  if(o.threads < 0) throw Bad_parameter("the number of threads must be at least 0 (0: one per core)");
  if(!(o.alpha >= 0. && o.alpha <= 1.)) throw Bad_parameter("alpha must lie in [0, 1]");
  if(o.drum_subdivisions < 1 || o.drum_subdivisions > 16)
    throw Bad_parameter("the drum subdivisions k must lie in [1, 16]");
  if(rings < 0 || rings > 4) throw Bad_parameter("the quadric rings r must lie in [0, 4]");
  if(o.smoothing_steps < 0 || o.smoothing_steps > 100)
    throw Bad_parameter("the smoothing steps must lie in [0, 100]");
  if(!(o.tolerance > 0. && o.tolerance < 1.)) throw Bad_parameter("the fit tolerance must lie in (0, 1)");
  if(!(o.max_seconds >= 0.)) throw Bad_parameter("the time budget must be at least 0");
  return o;
}

// `Input` is the Closest_triangle of the input surface; the mesh's points
// are read and written through `VertexPointMap`.
template <typename TriangleMesh, typename VertexPointMap, typename Input, typename Visitor>
class Deform_to_fit
{
  using Point = Epick::Point_3;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Clock = std::chrono::steady_clock;

public:
  using Face_pairs = std::vector<std::pair<face_descriptor, face_descriptor> >;

  Deform_to_fit(TriangleMesh& mesh, VertexPointMap vpm, const Input& input, double diagonal,
                const Deform_to_fit_options& options, Visitor& visitor)
    : mesh_(mesh), vpm_(vpm), points_(epick_points(vpm)), input_(input), options_(options), visitor_(visitor), diagonal_(diagonal),
      threshold_(CGAL::square(options.tolerance * diagonal)),
      index_(get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh)), pool_(options.threads),
      workspaces_(std::size_t(pool_.workers()))
  {
    for(vertex_descriptor v : vertices(mesh_)) {
      put(index_, v, vertices_.size());
      vertices_.push_back(v);
    }
    const std::size_t n = vertices_.size();
    hint_.resize(n);
    pool_.for_each(n, [&](std::size_t i, int) { hint_[i] = input_.closest(point(vertices_[i])); });
    target_.resize(n);
    cost_.resize(n);
    stamp_.assign(n, 0);
    dirty_.assign(n, false);
    claimed_.assign(n, false);
    colour_classes();
    stats_.vertices = n;
    for(std::size_t i = 0; i < n; ++i) initial_.push_back(position(i));
    classify_borders();
    if(options_.attract_features || options_.distance_guard) {
      // Sample spacing: the summed edge length over num_edges(), which for a
      // Surface_mesh counts removed edges too. On a fresh mesh it is the mean
      // edge length; during the decimation's relaxation it is finer, and that
      // measured better than the mean over live edges (cow, 90% removed:
      // 1.20% Hausdorff against 1.66%, elephant 0.87% against 1.13%).
      double length = 0.;
      for(auto e : edges(mesh_))
        length += std::sqrt(CGAL::squared_distance(point(source(halfedge(e, mesh_), mesh_)),
                                                   point(target(halfedge(e, mesh_), mesh_))));
      const double spacing = length / double((std::max)(std::size_t(1), std::size_t(num_edges(mesh_))));
      samples_ = input_.feature_samples(spacing);
      if(options_.distance_guard) {
        for(const auto& sample : samples_) guard_points_.push_back(sample.first);
        add_face_samples(input_, spacing, guard_points_);
        start_mesh_side_ = mesh_side(*this, 0., nullptr);
      }
      if(options_.attract_features)
        owners_ = std::make_unique<Feature_sample_owners>(samples_, on_input_border_, spacing);
      else
        samples_.clear();
    }
    attracted_begin_.assign(n + 1, 0);
    stats_.feature_samples = samples_.size();
  }

  // Runs the fit on the pool's workers.
  Deform_to_fit_statistics run()
  {
    pool_.execute([this] { optimize(); });
    return stats_;
  }

private:
  // Optimization first and last, with the smoothing passes in between
  // (thesis, 5.5); early smoothing (5.6) starts a smoothing pass when the
  // queue first stalls instead of completing that phase with full updates.
  void optimize()
  {
    start_ = Clock::now();
    phase_start_ = start_;
    int smoothing_left = options_.smoothing_steps;
    evaluate_all();
    while(!stopped()) {
      if(greedy_round()) continue;
      // Nothing can move with the current evaluations.
      const bool stale = moved_since_update_ > 0 || std::find(dirty_.begin(), dirty_.end(), true) != dirty_.end();
      if(smoothing_left > 0 && (!stale || options_.early_smoothing)) {
        smooth();
        --smoothing_left;
        if(stopped()) break;
        evaluate_all();
      } else if(stale) {
        full_update();
      } else if(!fill_border_notches() && !free_stuck_vertices()) {
        break;  // converged
      }
    }
    end_phase(Deform_to_fit_stage::optimization);
    if(!stats_.budget_exhausted && !stats_.cancelled) untangle_and_guard();
    if(before_fills_ && !stats_.budget_exhausted && !stats_.cancelled) keep_or_undo_the_fills();
    if(before_stuck_ && stats_.end_distance > stats_.start_distance && !stats_.budget_exhausted && !stats_.cancelled)
      undo_the_freeing();
    update_rms_distance();
    stats_.seconds = seconds_since(start_);
  }

  struct Entry
  {
    double improvement;
    std::size_t vertex;
    std::size_t stamp;
    bool operator<(const Entry& other) const { return improvement < other.improvement; }
  };

  using Objective = Fit_objective;

  // A worker's scratch space and counters.
  struct Workspace
  {
    std::vector<Half_space> region;
    Small_qp qp;
    Objective objective;
    std::size_t qp_solves = 0, qp_fallbacks = 0, infeasible_regions = 0;
  };

  // The outcome of one vertex's work in a parallel round.
  enum class Outcome { evaluated, moved, shortened, undone, rejected };
  struct Work
  {
    std::size_t vertex;
    bool evaluation;  // evaluate a dirty vertex, or move a clean one
    Outcome outcome;
    double improvement;
    Eigen::Vector3d best;
    double cost;  // the objective at the vertex, when its QP was solved
  };

  // Moves of vertices that share no edge cannot interact: each one's faces,
  // objective and feasible region involve its one-ring only. Each round of
  // the greedy queue takes at most this many such vertices off its top; a
  // constant, so that the result does not depend on the number of threads.
  static constexpr std::size_t round_size = 32;

  static double seconds_since(Clock::time_point t)
  {
    return std::chrono::duration<double>(Clock::now() - t).count();
  }

  bool stopped()
  {
    if(stats_.cancelled || stats_.budget_exhausted) return true;  // once stopped, stopped (the visitor is asked once)
    if(stats_.moves >= options_.max_moves || seconds_since(start_) > options_.max_seconds) {
      stats_.budget_exhausted = true;
      return true;
    }
    if(!visitor_.keep_going(stats_)) {
      stats_.cancelled = true;
      return true;
    }
    return false;
  }

  void end_phase(Deform_to_fit_stage stage)
  {
    const double s = seconds_since(phase_start_);
    (stage == Deform_to_fit_stage::optimization ? stats_.optimization_seconds : stats_.smoothing_seconds) += s;
    phase_start_ = Clock::now();
  }

  Eigen::Vector3d position(std::size_t i) const
  {
    const Point& p = point(vertices_[i]);
    return Eigen::Vector3d(p.x(), p.y(), p.z());
  }

  // A border cycle of the mesh follows a border of the input when each of its
  // vertices lies within two of its longest edges of the input's border; its
  // vertices then fit that border (equation 5.12). Other border cycles (a
  // hole the initial mesh opened where the input has none) fit the surface
  // like interior vertices instead of flying to a distant input border.
  void classify_borders()
  {
    on_input_border_.assign(vertices_.size(), false);
    if(!input_.has_border()) return;
    std::vector<bool> done(vertices_.size(), false);
    for(auto h : halfedges(mesh_)) {
      if(!is_border(h, mesh_) || done[get(index_, target(h, mesh_))]) continue;
      double longest = 0., farthest = 0.;
      std::vector<std::size_t> cycle;
      for(auto c : halfedges_around_face(h, mesh_)) {
        const std::size_t i = get(index_, target(c, mesh_));
        cycle.push_back(i);
        done[i] = true;
        const Point& p = point(target(c, mesh_));
        longest = (std::max)(longest, std::sqrt(CGAL::squared_distance(p, point(source(c, mesh_)))));
        farthest = (std::max)(farthest, std::sqrt(CGAL::squared_distance(p, input_.closest_on_border(p))));
      }
      if(farthest <= 2. * longest)
        for(std::size_t i : cycle) on_input_border_[i] = true;
    }
  }

  // Hands every feature sample of the input to its nearest mesh vertex (a
  // border sample to the nearest vertex that fits the input's border), as a
  // contiguous list per vertex; vertices whose list changed become dirty.
  void attract_features()
  {
    if(samples_.empty()) return;
    std::vector<Point> points;
    points.reserve(vertices_.size());
    for(std::size_t i = 0; i < vertices_.size(); ++i) points.push_back(point(vertices_[i]));
    const std::vector<std::pair<std::size_t, std::size_t> > owner = (*owners_)(points, pool_);
    std::vector<std::size_t> attracted, begin(vertices_.size() + 1, 0);
    attracted.reserve(owner.size());
    for(std::size_t i = 0, j = 0; i < vertices_.size(); ++i) {
      begin[i] = attracted.size();
      for(; j < owner.size() && owner[j].first == i; ++j) attracted.push_back(owner[j].second);
      const bool changed =
          !std::equal(attracted.begin() + begin[i], attracted.end(), attracted_.begin() + attracted_begin_[i],
                      attracted_.begin() + attracted_begin_[i + 1]);
      if(changed) dirty_[i] = true;
    }
    begin[vertices_.size()] = attracted.size();
    attracted_.swap(attracted);
    attracted_begin_.swap(begin);
  }

  // What a vertex minimises: L (equation 5.9), S alone (constrained
  // Laplacian smoothing, equation 5.17), or the distance to its position in
  // the initial mesh (untangling).
  enum class Goal { fit, smooth, restore };

  // Written into `o` (a worker's, reused: no allocation once its vector
  // has grown).
  void objective(std::size_t i, Goal goal, Objective& o) const
  {
    o.quadric = Quadric();
    o.quadric_weight = 0.;
    o.points.clear();
    if(goal == Goal::restore) {
      o.points.push_back({initial_[i], 1., Eigen::Matrix3d::Identity()});
      return;
    }
    const bool smoothing_only = goal == Goal::smooth;
    const vertex_descriptor v = vertices_[i];
    const double beta = smoothing_only ? 1. : 1. - options_.alpha;
    const double alpha = smoothing_only ? 0. : options_.alpha;
    // S (equations 5.13-5.14): the one-ring centroid, or the midpoint of the
    // two border neighbours
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    int count = 0;
    const bool border_vertex = bool(is_border(v, mesh_));
    for(auto h : halfedges_around_target(v, mesh_))
      if(!border_vertex || is_border(h, mesh_) || is_border(opposite(h, mesh_), mesh_)) {
        const Point& p = point(source(h, mesh_));
        centre += Eigen::Vector3d(p.x(), p.y(), p.z());
        ++count;
      }
    centre /= double((std::max)(count, 1));
    Eigen::Matrix3d metric = Eigen::Matrix3d::Identity();
    // D (equations 5.11-5.12): the quadric of the closest input triangle and
    // its r-ring over its number of planes, or the squared distance to the
    // input's border. Beyond the thesis, the feature samples owned by the
    // vertex join D as point terms: they hold tips, creases and border
    // corners that S would round off. A sample weighs as much as four planes:
    // with one, the Hausdorff distance of the cow and of the shark at
    // N = 100 ended above the initial mesh's; with four, 13% and 21% below.
    const double sample_weight = 4.;
    if(alpha > 0.) {
      const std::size_t owned = attracted_begin_[i + 1] - attracted_begin_[i];
      o.points.reserve(owned + 2);  // the samples, the border point, the centre
      double w = alpha;
      if(on_input_border_[i]) {
        w /= double(1 + owned);
        const Point b = input_.closest_on_border(point(v));
        o.points.push_back({Eigen::Vector3d(b.x(), b.y(), b.z()), w, Eigen::Matrix3d::Identity()});
      } else {
        o.quadric = input_.quadric(hint_[i]);
        w /= double((std::max)(std::size_t(1), o.quadric.planes + owned));
        o.quadric_weight = w;
        // Beyond the thesis: S acts along the input's tangent plane only, so
        // that it evens the vertices out without pulling the surface inwards.
        if(options_.tangential_smoothing) {
          const Eigen::Vector3d n = input_.normal(hint_[i]);
          metric -= n * n.transpose();
        }
      }
      for(std::size_t j = attracted_begin_[i]; j < attracted_begin_[i + 1]; ++j) {
        const Point& p = samples_[attracted_[j]].first;
        o.points.push_back({Eigen::Vector3d(p.x(), p.y(), p.z()), sample_weight * w, Eigen::Matrix3d::Identity()});
      }
    }
    o.points.push_back({centre, beta, metric});
  }

  // The frame of vertex i's one-ring: centred on the vertex, scaled by its
  // longest edge.
  Local_frame frame(std::size_t i) const
  {
    Local_frame f;
    f.origin = position(i);
    f.scale = 0.;
    for(vertex_descriptor w : vertices_around_target(halfedge(vertices_[i], mesh_), mesh_)) {
      const Point& p = point(w);
      f.scale = (std::max)(f.scale, (Eigen::Vector3d(p.x(), p.y(), p.z()) - f.origin).norm());
    }
    return f;
  }

  // Solves vertex i's QP (equation 5.15, or 5.17 when smoothing) over F(v);
  // returns false when F(v) is empty or cannot be built, or, with
  // `bound_gain`, when no position at all improves the vertex's objective by
  // more than the threshold (then no move is worth its QP: a cheap bound
  // decides before F(v) is built). `margin` (in units of the one-ring's size)
  // shrinks F(v), so that an optimum on its boundary is not rounded out.
  // `cost`, when given, receives the objective at the vertex.
  bool solve(std::size_t i, Goal goal, Workspace& ws, Eigen::Vector3d& best, double& improvement,
             double* cost = nullptr, bool bound_gain = true, double margin = 0.) const
  {
    const Local_frame f = frame(i);
    if(!(f.scale > 0.)) return false;
    Objective& o = ws.objective;
    objective(i, goal, o);
    o.local_form(f, ws.qp.G, ws.qp.a);
    if(bound_gain && !(Objective::largest_decrease(f, ws.qp.G, ws.qp.a) > threshold_)) return false;
    ws.region.clear();
    if(!vertex_feasible_region(mesh_, points_, vertices_[i], options_.drum_subdivisions, f, ws.region))
      return false;
    ws.qp.normals.clear();
    ws.qp.offsets.clear();
    for(const Half_space& h : ws.region) ws.qp.add_constraint(h.normal, h.offset + margin);
    ++ws.qp_solves;
    const Qp_result r = solve_small_qp_with_fallback(ws.qp, &ws.qp_fallbacks);
    if(r.status != Qp_status::optimal) {
      ++ws.infeasible_regions;
      return false;
    }
    best = f.to_global(r.x);
    const double here = o.value(f.origin);
    improvement = here - o.value(best);  // H(v), equation 5.16
    if(cost) *cost = here;
    return true;
  }

  bool solve(std::size_t i, Goal goal, Eigen::Vector3d& best, double& improvement)
  {
    const bool solved = solve(i, goal, workspaces_[0], best, improvement);
    collect_counters();
    return solved;
  }

  void collect_counters()
  {
    for(Workspace& ws : workspaces_) {
      stats_.qp_solves += ws.qp_solves;
      stats_.qp_fallbacks += ws.qp_fallbacks;
      stats_.infeasible_regions += ws.infeasible_regions;
      ws.qp_solves = ws.qp_fallbacks = ws.infeasible_regions = 0;
    }
  }

  // Vertex i's evaluation: its optimum and the improvement H(v), 0 when its
  // QP has no solution.
  void evaluate(Work& w, Workspace& ws) const
  {
    w.best = position(w.vertex);
    if(!solve(w.vertex, Goal::fit, ws, w.best, w.improvement, &w.cost)) w.improvement = 0.;
  }

  void record_evaluation(const Work& w)
  {
    dirty_[w.vertex] = false;
    target_[w.vertex] = w.best;
    cost_[w.vertex] = w.cost;
    queue_.push({w.improvement, w.vertex, ++stamp_[w.vertex]});
  }

  // Evaluates the listed vertices in parallel, then queues them in order.
  void evaluate(const std::vector<std::size_t>& list)
  {
    work_.resize(list.size());
    pool_.for_each(list.size(), [&](std::size_t j, int worker) {
      work_[j].vertex = list[j];
      evaluate(work_[j], workspaces_[worker]);
    });
    collect_counters();
    for(const Work& w : work_) record_evaluation(w);
  }

  void evaluate_all()
  {
    attract_features();
    queue_ = std::priority_queue<Entry>();
    std::vector<std::size_t> all(vertices_.size());
    for(std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    evaluate(all);
    moved_since_update_ = 0;
    update_rms_distance();
  }

  // A full update (thesis, 5.6): the feature samples find their nearest
  // vertex again, and every vertex whose evaluation may be out of date is
  // evaluated; the others' evaluations are current.
  void full_update()
  {
    ++stats_.full_updates;
    attract_features();
    std::vector<std::size_t> dirty;
    for(std::size_t i = 0; i < vertices_.size(); ++i)
      if(dirty_[i]) dirty.push_back(i);
    evaluate(dirty);
    moved_since_update_ = 0;
  }

  // Beyond the thesis (border_notches.h): once the queue is converged, the
  // notches of the borders that fit the input's are filled, at most four
  // passes; the vertices around each fill, and the new ones, are evaluated
  // again. Returns whether a pass filled some.
  bool fill_border_notches()
  {
    if(!options_.fill_border_notches || fill_passes_ == 4 || !input_.has_border()) return false;
    if(fill_passes_++ == 0) input_corners_ = input_border_corners(input_);
    Border_notch_filler<TriangleMesh, VertexPointMap, Input> fill(mesh_, vpm_, input_, input_corners_, bounds_);
    const auto fills = fill([this](vertex_descriptor v) { return bool(on_input_border_[get(index_, v)]); },
                            [this] {  // the fit before the first fill, for keep_or_undo_the_fills()
                              if(!before_fills_ && options_.distance_guard)
                                before_fills_ = std::make_unique<Fit_state>(*this, true);
                            });
    if(fills.notches + fills.corners == 0) {
      fill_passes_ = 4;
      return false;
    }
    stats_.border_notches_filled += fills.notches;
    stats_.border_corners_filled += fills.corners;
    stats_.border_vertices_added += fills.added.size();
    for(vertex_descriptor w : fills.added) {
      put(index_, w, vertices_.size());
      vertices_.push_back(w);
      hint_.push_back(input_.closest(point(w)));
      target_.emplace_back(position(vertices_.size() - 1));
      cost_.push_back(0.);
      stamp_.push_back(0);
      dirty_.push_back(false);
      claimed_.push_back(false);
      initial_.push_back(position(vertices_.size() - 1));  // the guard's and the untangling's start
      on_input_border_.push_back(true);  // on a border that fits the input's, as the notch it fills
      attracted_begin_.push_back(attracted_begin_.back());
    }
    stats_.vertices = vertices_.size();
    for(face_descriptor f : fills.faces) {
      const auto h = halfedge(f, mesh_);
      filled_faces_.push_back({get(index_, source(h, mesh_)), get(index_, target(h, mesh_)),
                               get(index_, target(next(h, mesh_), mesh_))});
    }
    classes_.clear();
    colour_classes();
    // a smoothing pass over the fills and two rings around them evens the
    // new faces out with the rest, then their rings are evaluated again
    // (measured at 10,000 vertices: elephant-with-holes 1.59% -> 1.42%
    // Hausdorff, nefertiti 0.51% -> 0.49%; a pass over the whole mesh cost
    // 30% to 90% more fit time for no more on the borders)
    std::vector<bool> region(vertices_.size(), false);
    std::vector<std::size_t> members;
    for(vertex_descriptor v : fills.touched) grow(get(index_, v), region, members);
    for(int ring = 0; ring < 2; ++ring)
      for(std::size_t j = 0, end = members.size(); j < end; ++j)
        for(vertex_descriptor w : vertices_around_target(halfedge(vertices_[members[j]], mesh_), mesh_))
          grow(get(index_, w), region, members);
    smooth(&region);
    for(std::size_t i : members) {
      dirty_[i] = true;
      for(vertex_descriptor w : vertices_around_target(halfedge(vertices_[i], mesh_), mesh_)) dirty_[get(index_, w)] = true;
    }
    full_update();
    return true;
  }

  // The points and the per-vertex state of the fit, and its statistics;
  // with `measured`, also the guard's measure of its distance to the input.
  struct Fit_state
  {
    Fit_state(Deform_to_fit& fit, bool measured)
      : distance(measured ? 100. * guard_distance(fit, 0., nullptr) / fit.diagonal_ : 0.), hint(fit.hint_),
        target(fit.target_), cost(fit.cost_), stamp(fit.stamp_), initial(fit.initial_),
        on_input_border(fit.on_input_border_), attracted(fit.attracted_), attracted_begin(fit.attracted_begin_),
        stats(fit.stats_)
    {
      for(vertex_descriptor v : fit.vertices_) points.push_back(get(fit.vpm_, v));
    }
    double distance;  // in % of the diagonal, as the statistics' distances
    std::vector<typename boost::property_traits<VertexPointMap>::value_type> points;
    std::vector<face_descriptor> hint;
    std::vector<Eigen::Vector3d> target;
    std::vector<double> cost;
    std::vector<std::size_t> stamp;
    std::vector<Eigen::Vector3d> initial;
    std::vector<bool> on_input_border;
    std::vector<std::size_t> attracted, attracted_begin;
    Deform_to_fit_statistics stats;
  };

  // Back to state `s`, with as many vertices as it had (the connectivity is
  // the caller's).
  void restore(const Fit_state& s)
  {
    const std::size_t n = s.points.size();
    for(std::size_t i = 0; i < n; ++i) put(vpm_, vertices_[i], s.points[i]);
    hint_ = s.hint;
    target_ = s.target;
    cost_ = s.cost;
    stamp_ = s.stamp;
    dirty_.assign(n, false);
    claimed_.assign(n, false);
    initial_ = s.initial;
    on_input_border_ = s.on_input_border;
    attracted_ = s.attracted;
    attracted_begin_ = s.attracted_begin;
    classes_.clear();
    colour_classes();
    guard_hints_.clear();  // they may name faces removed since
    // the time spent stays spent: the phases' seconds are not rolled back
    const Deform_to_fit_statistics spent = stats_;
    stats_ = s.stats;
    stats_.optimization_seconds = spent.optimization_seconds;
    stats_.smoothing_seconds = spent.smoothing_seconds;
    stats_.untangling_seconds = spent.untangling_seconds;
    stats_.guard_seconds = spent.guard_seconds;
    stats_.balance_seconds = spent.balance_seconds;
  }

  // The fills removed, last first (Euler::remove_face removes the vertices
  // left isolated), down to the first `n` vertices.
  void remove_fills(std::size_t n)
  {
    for(auto c = filled_faces_.rbegin(); c != filled_faces_.rend(); ++c)
      Euler::remove_face(halfedge(vertices_[(*c)[0]], vertices_[(*c)[1]], mesh_).first, mesh_);
    vertices_.resize(n);
  }

  // The fills added again, as they were first (new vertices first, in order).
  void add_fills_again(std::size_t n)
  {
    for(std::size_t i = vertices_.size(); i < n; ++i) {
      const vertex_descriptor w = add_vertex(mesh_);
      put(index_, w, i);
      vertices_.push_back(w);
    }
    for(const auto& c : filled_faces_) {
      const std::array<vertex_descriptor, 3> corners{vertices_[c[0]], vertices_[c[1]], vertices_[c[2]]};
      if(Euler::add_face(corners, mesh_) == boost::graph_traits<TriangleMesh>::null_face())
        throw std::logic_error("fill_border_notches: a fill could not be added again");
    }
  }

  // The fills are kept when the fit, untangled and guarded, ends no farther
  // from the input with them than without them, as the guard measures it.
  // Without them means: from the fit as the first fill found it, the
  // untangling and the guard, which is where the fit would have ended
  // without fills; that is computed only when the fit with them ends
  // farther than the guard measured it before them. Measured case: the raw
  // Marching Cubes mesh of mesh_with_border at N = 60, whose fit after the
  // fills moved on to a fold that the untangling undid by moving vertices
  // back towards the initial mesh: 1.57% Hausdorff with the fills, 0.74%
  // without.
  void keep_or_undo_the_fills()
  {
    if(!(stats_.end_distance > before_fills_->distance)) return;
    const Fit_state with(*this, false);
    remove_fills(before_fills_->points.size());
    end_from(*before_fills_);
    if(stats_.end_distance <= with.stats.end_distance || stats_.budget_exhausted || stats_.cancelled) {
      stats_.border_fills_undone = true;
      return;
    }
    add_fills_again(with.points.size());
    restore(with);
  }

  static void grow(std::size_t i, std::vector<bool>& region, std::vector<std::size_t>& members)
  {
    if(region[i]) return;
    region[i] = true;
    members.push_back(i);
  }

  bool conflicts(std::size_t i) const
  {
    if(claimed_[i]) return true;
    for(vertex_descriptor w : vertices_around_target(halfedge(vertices_[i], mesh_), mesh_))
      if(claimed_[get(index_, w)]) return true;
    return false;
  }

  // One round of the greedy queue: takes the best vertices off the queue,
  // each sharing no edge with one taken before (the others wait for the next
  // round), up to `round_size`; evaluates those that are dirty (lazy
  // evaluation: only when they matter) and moves the others, in parallel,
  // then records the outcomes in the order they were taken. Returns false
  // when no vertex improves by more than the threshold.
  bool greedy_round()
  {
    std::vector<Entry> waiting;
    std::size_t moves = 0;
    const std::size_t moves_left = options_.max_moves - stats_.moves;
    while(!queue_.empty() && work_round_.size() < round_size && waiting.size() < round_size) {
      const Entry top = queue_.top();
      if(top.stamp != stamp_[top.vertex]) {  // superseded
        queue_.pop();
        continue;
      }
      const bool evaluation = dirty_[top.vertex];
      if(!evaluation && (!(top.improvement > threshold_) || moves == moves_left)) break;
      queue_.pop();
      if(conflicts(top.vertex)) {
        waiting.push_back(top);
        continue;
      }
      claimed_[top.vertex] = true;
      work_round_.push_back({top.vertex, evaluation, Outcome::evaluated, 0., Eigen::Vector3d::Zero(), 0.});
      if(!evaluation) ++moves;
    }
    for(const Entry& e : waiting) queue_.push(e);
    if(work_round_.empty()) return false;
    pool_.for_each(work_round_.size(), [&](std::size_t j, int worker) {
      Work& w = work_round_[j];
      if(w.evaluation) {
        w.outcome = Outcome::evaluated;
        evaluate(w, workspaces_[worker]);
        return;
      }
      w.outcome = try_move(w.vertex, target_[w.vertex], workspaces_[worker], &cost_[w.vertex]);
      if(w.outcome == Outcome::moved || w.outcome == Outcome::shortened) evaluate(w, workspaces_[worker]);
    });
    collect_counters();
    std::vector<std::size_t> neighbours;
    for(const Work& w : work_round_) {
      claimed_[w.vertex] = false;
      if(w.evaluation) {
        record_evaluation(w);
        continue;
      }
      record_move(w.outcome);
      if(w.outcome == Outcome::undone || w.outcome == Outcome::rejected) {
        queue_.push({0., w.vertex, ++stamp_[w.vertex]});  // out of the queue until a neighbour moves
        continue;
      }
      record_evaluation(w);
      for(vertex_descriptor v : vertices_around_target(halfedge(vertices_[w.vertex], mesh_), mesh_))
        if(!dirty_[get(index_, v)]) {
          dirty_[get(index_, v)] = true;  // evaluated when it reaches the top, or in a full update
          if(!options_.lazy_evaluation) neighbours.push_back(get(index_, v));
        }
    }
    work_round_.clear();
    if(!options_.lazy_evaluation) evaluate(neighbours);
    return true;
  }

  // Every face around vertex i, with i at p, is within [30, 90] exactly.
  bool certified_at(std::size_t i, const Point& p) const
  {
    const vertex_descriptor v = vertices_[i];
    for(auto h : halfedges_around_target(v, mesh_)) {
      if(is_border(h, mesh_)) continue;
      const Point& a = point(source(h, mesh_));
      const Point& b = point(target(next(h, mesh_), mesh_));
      if(!triangle_verdict(p, b, a, bounds_).within_bounds()) return false;
    }
    return true;
  }

  // Moves vertex i towards `target`, halving the step until the faces around
  // it certify exactly (at most five times). Given the vertex's current
  // objective `cost_before` (its evaluation's: a clean vertex's objective has
  // not changed since), a move whose new closest triangle leaves the vertex's
  // cost no lower than before by the threshold is undone: D changes with the
  // closest triangle, and without this test a vertex can hop between two
  // triangles for ever. Writes vertex i's point and closest triangle, and
  // the worker's scratch objective in `ws`, only.
  Outcome try_move(std::size_t i, const Eigen::Vector3d& target, Workspace& ws, const double* cost_before)
  {
    const Eigen::Vector3d from = position(i);
    const Point old_point = point(vertices_[i]);
    Eigen::Vector3d step = target - from;
    for(int attempt = 0; attempt < 5; ++attempt, step *= 0.5) {
      const Eigen::Vector3d to = from + step;
      const Point p(to[0], to[1], to[2]);
      if(p == old_point) break;  // rounds to no move
      if(!certified_at(i, p)) continue;
      const face_descriptor old_hint = hint_[i];
      put_point(vpm_, vertices_[i], p);
      hint_[i] = input_.closest(p, old_hint);
      if(cost_before) {
        objective(i, Goal::fit, ws.objective);
        if(!(ws.objective.value(to) < *cost_before - threshold_)) {
          put_point(vpm_, vertices_[i], old_point);
          hint_[i] = old_hint;
          return Outcome::undone;
        }
      }
      return attempt > 0 ? Outcome::shortened : Outcome::moved;
    }
    return Outcome::rejected;
  }

  void record_move(Outcome outcome)
  {
    switch(outcome) {
    case Outcome::undone: ++stats_.undone_moves; break;
    case Outcome::rejected: ++stats_.rejected_moves; break;
    case Outcome::shortened: ++stats_.shortened_moves; CGAL_FALLTHROUGH;
    case Outcome::moved: ++stats_.moves; ++moved_since_update_; break;
    case Outcome::evaluated: break;
    }
  }

  // Moves vertex i towards `target` without the descent test.
  bool apply(std::size_t i, const Eigen::Vector3d& target)
  {
    const Outcome outcome = try_move(i, target, workspaces_[0], nullptr);
    record_move(outcome);
    return outcome == Outcome::moved || outcome == Outcome::shortened;
  }

  // Greedy colouring in index order: no edge joins two vertices of a class.
  void colour_classes()
  {
    std::vector<int> colour(vertices_.size(), -1);
    std::vector<bool> used;
    for(std::size_t i = 0; i < vertices_.size(); ++i) {
      used.assign(used.size(), false);
      for(vertex_descriptor w : vertices_around_target(halfedge(vertices_[i], mesh_), mesh_)) {
        const int c = colour[get(index_, w)];
        if(c < 0) continue;
        if(std::size_t(c) >= used.size()) used.resize(c + 1, false);
        used[c] = true;
      }
      std::size_t c = 0;
      while(c < used.size() && used[c]) ++c;
      colour[i] = int(c);
      if(c >= classes_.size()) classes_.resize(c + 1);
      classes_[c].push_back(i);
    }
  }

  // Constrained Laplacian smoothing (thesis, 5.5): every vertex (or those
  // flagged in `only`) once towards its smoothing optimum (equation 5.17)
  // within F(v), a colour class after another, the vertices of a class (no
  // two share an edge) in parallel.
  void smooth(const std::vector<bool>* only = nullptr)
  {
    end_phase(Deform_to_fit_stage::optimization);
    stats_.stage = Deform_to_fit_stage::smoothing;
    if(!only) ++stats_.smoothing_passes;  // the fills' local passes are theirs
    for(const std::vector<std::size_t>& members : classes_)
      // in chunks within the move budget, so that it holds exactly
      for(std::size_t begin = 0; begin < members.size() && !stopped();) {
        const std::size_t end = begin + (std::min)(members.size() - begin, options_.max_moves - stats_.moves);
        work_.resize(end - begin);
        pool_.for_each(end - begin, [&](std::size_t j, int worker) {
          Work& w = work_[j];
          w.vertex = members[begin + j];
          w.outcome = Outcome::evaluated;
          if(only && !(*only)[w.vertex]) return;
          if(!solve(w.vertex, Goal::smooth, workspaces_[worker], w.best, w.improvement) ||
             !(w.improvement > threshold_))
            return;
          w.outcome = try_move(w.vertex, w.best, workspaces_[worker], nullptr);
        });
        collect_counters();
        for(const Work& w : work_) {
          record_move(w.outcome);
          if(w.outcome == Outcome::moved || w.outcome == Outcome::shortened) ++stats_.smoothing_moves;
        }
        begin = end;
      }
    std::fill(dirty_.begin(), dirty_.end(), false);
    end_phase(Deform_to_fit_stage::smoothing);
    stats_.stage = Deform_to_fit_stage::optimization;
  }

  // Beyond the thesis: the untangling (untangling.h), then the distance
  // guard (distance_guard.h), which goes on from the pairs the untangling
  // left, then the distance balance (distance_balance.h), from the pairs
  // the guard left, then a last pass over the stuck vertices
  // (stuck_vertices.h), from the pairs the balance left.
  void untangle_and_guard()
  {
    Face_pairs pairs = internal::untangle(*this);
    std::optional<double> guarded;  // the guard's measure of the mesh, when it ran
    if(options_.distance_guard && !stats_.budget_exhausted && !stats_.cancelled) {
      internal::Guard_outcome<Deform_to_fit> outcome = internal::guard_the_distance(*this, std::move(pairs));
      pairs = std::move(outcome.pairs);
      guarded = outcome.distance;
    }
    if(options_.balance_distance && !stats_.budget_exhausted && !stats_.cancelled)
      pairs = internal::balance_the_distance(*this, std::move(pairs), guarded);
    if(options_.free_stuck_vertices && !stats_.budget_exhausted && !stats_.cancelled)
      internal::free_stuck_vertices_last(*this, pairs, guarded.has_value());
  }
  template <typename Fit>
  friend typename Fit::Face_pairs untangle(Fit& fit);
  template <typename Fit>
  friend std::vector<std::size_t> region_around(const Fit& fit, const std::vector<std::size_t>& seeds, int rings);
  template <typename Fit>
  friend class Saved_region;
  template <typename Fit, typename FaceRange>
  friend typename Fit::Face_pairs intersecting_pairs_among(Fit& fit, const FaceRange& range);
  template <typename Fit>
  friend typename Fit::Face_pairs intersecting_pairs(Fit& fit);
  template <typename Fit>
  friend typename Fit::Face_pairs intersecting_pairs_after(Fit& fit, const std::vector<std::size_t>& moved,
                                                          const typename Fit::Face_pairs& before);
  template <typename Fit>
  friend bool untangle_attempt(Fit& fit, const std::vector<std::size_t>& region, typename Fit::Goal goal,
                               typename Fit::Face_pairs& pairs, bool strictly);

  // Beyond the thesis (stuck_vertices.h): once the queue is converged (and
  // the borders filled), at most four passes free the vertices farthest from
  // the input together with their one-rings; the queue then resumes.
  bool free_stuck_vertices()
  {
    if(!options_.free_stuck_vertices || stuck_passes_ == 4) return false;
    if(stuck_passes_++ == 0 && options_.distance_guard) before_stuck_ = std::make_unique<Fit_state>(*this, false);
    if(!internal::free_stuck_vertices(*this, 1, nullptr)) {
      if(stuck_passes_ == 1) before_stuck_.reset();
      stuck_passes_ = 4;
      return false;
    }
    full_update();
    return true;
  }

  // The distance guard promises a fit no farther from the input than its
  // start. When it cannot keep that promise after stuck vertices were freed
  // (measured once: rotor at 10,000 vertices, whose start mesh crosses
  // itself, 1.477% against its start's 1.434%), the fit from before the
  // first pass is untangled and guarded too, and the closer of the two, as
  // the guard measures them, is kept. The passes come after the border
  // fills, so the connectivity is the same; when the fills were undone, the
  // fit is already back before the passes.
  void undo_the_freeing()
  {
    if(stats_.border_fills_undone) return;
    const Fit_state with(*this, false);
    end_from(*before_stuck_);
    if(stats_.end_distance > with.stats.end_distance && !stats_.budget_exhausted && !stats_.cancelled)
      restore(with);
    else
      stats_.stuck_vertices_undone = true;
  }

  // Back to state `s`, then the untangling and the distance guard, as at the
  // end of the optimization.
  void end_from(const Fit_state& s)
  {
    restore(s);
    untangle_and_guard();
  }
  template <typename Fit>
  friend bool free_stuck_vertices(Fit& fit, std::size_t rings, std::vector<std::vector<std::size_t> >* freed_groups);
  template <typename Fit>
  friend std::size_t free_stuck_vertices_kept(Fit& fit, std::size_t rings, typename Fit::Face_pairs& pairs,
                                              bool guarded);
  template <typename Fit>
  friend bool put_back_crossing_groups(Fit& fit, const Saved_region<Fit>& saved,
                                       const std::vector<std::vector<std::size_t> >& groups,
                                       const typename Fit::Face_pairs& before, typename Fit::Face_pairs& after,
                                       std::size_t& put_back);
  template <typename Fit>
  friend void free_stuck_vertices_last(Fit& fit, const typename Fit::Face_pairs& pairs, bool guarded);
  template <typename Fit>
  friend std::size_t free_stuck_vertex(Fit& fit, const std::vector<std::size_t>& group,
                                       typename Fit::Workspace& ws);
  template <typename Fit>
  friend double squared_gap(const Fit& fit, std::size_t j, typename Fit::face_descriptor& hint, std::size_t* sample);
  template <typename Fit>
  friend double farthest_of(const Fit& fit, const std::vector<std::size_t>& group,
                            std::vector<typename Fit::face_descriptor>& hints, double limit);

  // Beyond the thesis: distance_guard.h.
  template <typename Fit>
  friend struct Start_point_map;
  template <typename Fit, typename Points>
  friend double input_side(Fit& fit, const Points& points, double limit, Vertex_list* far);
  template <typename Fit>
  friend double mesh_side(Fit& fit, double limit, Vertex_list* far);
  template <typename Fit>
  friend double guard_distance(Fit& fit, double limit, Vertex_list* far);
  template <typename Fit>
  friend Guard_outcome<Fit> guard_the_distance(Fit& fit, typename Fit::Face_pairs pairs);

  // Beyond the thesis: distance_balance.h.
  template <typename Fit>
  friend struct Face_offsets;
  template <typename Fit>
  friend bool balanced_position(const Fit& fit, const Face_offsets<Fit>& offsets, std::size_t i,
                                Eigen::Vector3d& position);
  template <typename Fit>
  friend typename Fit::Face_pairs balance_the_distance(Fit& fit, typename Fit::Face_pairs pairs,
                                                      std::optional<double> guarded);

  void update_rms_distance()
  {
    std::vector<double> distances(vertices_.size());
    pool_.for_each(vertices_.size(), [&](std::size_t i, int) {
      distances[i] = CGAL::squared_distance(point(vertices_[i]), input_.triangle(hint_[i]));
    });
    double sum = 0.;
    for(double d : distances) sum += d;
    stats_.rms_distance = vertices_.empty() ? 0. : 100. * std::sqrt(sum / double(vertices_.size())) / diagonal_;
  }

  Point point(vertex_descriptor v) const { return get(points_, v); }

  TriangleMesh& mesh_;
  VertexPointMap vpm_;
  Epick_points_t<VertexPointMap> points_;
  const Input& input_;
  const Deform_to_fit_options options_;
  Visitor& visitor_;
  const double diagonal_;
  const double threshold_;
  const Angle_bounds bounds_;

  typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::type index_;
  std::vector<vertex_descriptor> vertices_;
  std::vector<face_descriptor> hint_;  // closest input triangle
  std::vector<bool> on_input_border_;
  std::vector<std::pair<Point, bool> > samples_;  // feature samples, see Closest_triangle
  std::vector<std::size_t> attracted_;            // sample indices, grouped by nearest vertex
  std::vector<std::size_t> attracted_begin_;      // vertex i owns attracted_[begin[i], begin[i+1])
  std::unique_ptr<Feature_sample_owners> owners_;
  std::vector<Point> guard_points_;  // feature and face samples, for the distance guard
  double start_mesh_side_ = 0.;      // the guard's mesh side of the mesh as given (distance_guard.h)
  std::vector<face_descriptor> guard_hints_;  // each guard point's closest face at the guard's last measurement
  std::vector<Eigen::Vector3d> initial_;  // positions in the mesh as given
  std::vector<Eigen::Vector3d> target_;
  std::vector<double> cost_;  // the objective at each vertex, as its evaluation found it
  std::vector<std::size_t> stamp_;
  std::vector<bool> dirty_;
  std::size_t moved_since_update_ = 0;
  std::priority_queue<Entry> queue_;
  std::vector<bool> claimed_;                      // taken in the current round
  std::vector<std::vector<std::size_t> > classes_;  // colour classes, for the smoothing
  int fill_passes_ = 0;                             // passes of fill_border_notches() made
  std::vector<Point> input_corners_;                // the input's border corners, for the fills' ears
  int stuck_passes_ = 0;                            // passes of free_stuck_vertices() made
  std::unique_ptr<Fit_state> before_fills_;         // the fit before the first fill
  std::unique_ptr<Fit_state> before_stuck_;         // the fit before the first freeing of stuck vertices
  std::vector<std::array<std::size_t, 3> > filled_faces_;  // the fills' faces, by vertex index, in order
  Thread_pool pool_;
  std::vector<Workspace> workspaces_;  // one per worker
  std::vector<Work> work_, work_round_;
  Deform_to_fit_statistics stats_;
  Clock::time_point start_, phase_start_;
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_DEFORM_TO_FIT_IMPL_H
