// SPDX-License-Identifier: GPL-3.0-or-later
//
// Freeing stuck vertices once deform-to-fit's queue has converged (beyond
// the thesis). The greedy queue moves one vertex at a time within F(v), with
// the other corners of its faces fixed. A vertex can then stay far from the
// input because a corner of its one-ring sits at 90 or 30 degrees: moving the
// vertex towards the input would break that angle, and the neighbour that
// could give way gains nothing by moving, so it never does. Those few
// vertices set the Hausdorff distance of an otherwise close fit (blobby at
// 10,000 vertices: 0.386% against a 99.9% quantile of 0.179%).
//
// A stuck vertex is freed by moving it and its one-ring together: the vertex
// is put on the input (or on the feature sample it misses), or at the minimum
// of its objective, all the way or part of it; then each neighbour in turn
// solves its own QP (equation 5.15) over F(u) built around the vertex's new
// position, three sweeps round the ring, which moves it as little as its
// objective allows while making room. The group is certified exactly before
// it is kept, and it is kept only when the farthest from the input of its
// vertices and of the centroids and edge midpoints of their faces comes at
// least 10% closer. Last passes follow the distance balance, with one ring
// and with two, in rounds. These functions are friends of Deform_to_fit
// (Deform_to_fit.h).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_STUCK_VERTICES_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_STUCK_VERTICES_H

#include <CGAL/Nonobtuse_remeshing/internal/distance_guard.h>
#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>
#include <CGAL/Nonobtuse_remeshing/internal/feasible_region.h>
#include <CGAL/Nonobtuse_remeshing/internal/untangling.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// How far vertex j is from the input, squared: its distance to its closest
// input triangle or, when larger, the distance from a feature sample it
// attracts to the nearest of its faces (a tip or a crease the mesh misses).
// `hint`, j's closest triangle, is searched again from itself; `sample`
// receives the index of that feature sample, when there is one.
template <typename Fit>
double squared_gap(const Fit& fit, std::size_t j, typename Fit::face_descriptor& hint, std::size_t* sample = nullptr)
{
  using Point = typename Fit::Point;
  const auto v = fit.vertices_[j];
  const Point p = fit.point(v);
  hint = fit.input_.closest(p, hint);
  double gap = CGAL::squared_distance(p, fit.input_.triangle(hint));
  for(std::size_t k = fit.attracted_begin_[j]; k < fit.attracted_begin_[j + 1]; ++k) {
    const Point& s = fit.samples_[fit.attracted_[k]].first;
    double nearest = CGAL::squared_distance(s, p);
    for(auto h : halfedges_around_target(v, fit.mesh_)) {
      if(is_border(h, fit.mesh_)) continue;
      const Epick::Triangle_3 face(p, fit.point(source(h, fit.mesh_)), fit.point(target(next(h, fit.mesh_), fit.mesh_)));
      nearest = (std::min)(nearest, CGAL::squared_distance(s, face));
    }
    if(nearest > gap) {
      gap = nearest;
      if(sample) *sample = fit.attracted_[k];
    }
  }
  return gap;
}

// The largest gap among the vertices `group`, with their closest triangles
// searched again from `hints`, and the largest distance from the input of
// the centroids and edge midpoints of the faces around them: a group that
// brings its vertices in can push its faces' interiors out. Each face and
// each edge is measured once (a two-ring group has about 45 faces and 65
// edges, against 115 faces and 340 midpoints counted around each vertex),
// its search started from the hint of the first group vertex it touches.
// Stops at the first distance at least `limit` (a trial that cannot pass)
// and returns that distance.
template <typename Fit>
double farthest_of(const Fit& fit, const std::vector<std::size_t>& group,
                   std::vector<typename Fit::face_descriptor>& hints, double limit)
{
  using Point = typename Fit::Point;
  using face_descriptor = typename Fit::face_descriptor;
  double farthest = 0.;
  for(std::size_t j = 0; j < group.size(); ++j) {
    farthest = (std::max)(farthest, squared_gap(fit, group[j], hints[j]));
    if(std::sqrt(farthest) >= limit) return std::sqrt(farthest);
  }
  std::vector<std::pair<face_descriptor, face_descriptor> > faces;  // each face, with its search's hint
  const auto position = [&](face_descriptor f) {  // faces.size() when not listed
    return std::size_t(std::find_if(faces.begin(), faces.end(), [&](const auto& e) { return e.first == f; }) -
                       faces.begin());
  };
  for(std::size_t j = 0; j < group.size(); ++j)
    for(auto h : halfedges_around_target(fit.vertices_[group[j]], fit.mesh_))
      if(!is_border(h, fit.mesh_) && position(face(h, fit.mesh_)) == faces.size())
        faces.emplace_back(face(h, fit.mesh_), hints[j]);
  const auto measure = [&](const Point& p, face_descriptor hint) {  // whether the trial may still pass
    farthest = (std::max)(farthest, CGAL::squared_distance(p, fit.input_.triangle(fit.input_.closest(p, hint))));
    return std::sqrt(farthest) < limit;
  };
  for(std::size_t k = 0; k < faces.size(); ++k) {
    const auto h = halfedge(faces[k].first, fit.mesh_);
    const Point& a = fit.point(source(h, fit.mesh_));
    const Point& b = fit.point(target(h, fit.mesh_));
    const Point& c = fit.point(target(next(h, fit.mesh_), fit.mesh_));
    if(!measure(CGAL::centroid(a, b, c), faces[k].second)) return std::sqrt(farthest);
    for(auto g : halfedges_around_face(h, fit.mesh_)) {
      // an edge between two listed faces is measured from the first
      const auto o = opposite(g, fit.mesh_);
      if(!is_border(o, fit.mesh_) && position(face(o, fit.mesh_)) < k) continue;
      if(!measure(CGAL::midpoint(fit.point(source(g, fit.mesh_)), fit.point(target(g, fit.mesh_))), faces[k].second))
        return std::sqrt(farthest);
    }
  }
  return std::sqrt(farthest);
}

// Tries to free vertex group[0] with the rest of `group`, its one-ring, in
// the worker's workspace `ws`; returns how many of the group's vertices it
// moved (0: not freed, the group as it was). It writes the group's points
// and closest triangles only, and reads no farther than the one-rings of
// the group's vertices.
template <typename Fit>
std::size_t free_stuck_vertex(Fit& fit, const std::vector<std::size_t>& group, typename Fit::Workspace& ws)
{
  using Point = typename Fit::Point;
  using face_descriptor = typename Fit::face_descriptor;
  const std::size_t i = group[0];
  const Local_frame f = fit.frame(i);
  if(!(f.scale > 0.)) return 0;

  // where the vertex should go: the point of the input (or the feature
  // sample) its gap is measured to, then the minimum of its objective
  std::vector<Eigen::Vector3d> targets;
  face_descriptor hint = fit.hint_[i];
  std::size_t sample = std::size_t(-1);
  squared_gap(fit, i, hint, &sample);
  const Point there = sample != std::size_t(-1)
                          ? fit.samples_[sample].first
                          : Epick().construct_projected_point_3_object()(fit.input_.triangle(hint), fit.point(fit.vertices_[i]));
  targets.emplace_back(there.x(), there.y(), there.z());
  fit.objective(i, Fit::Goal::fit, ws.objective);
  Eigen::Matrix3d G;
  Eigen::Vector3d a;
  ws.objective.local_form(f, G, a);
  const Eigen::LLT<Eigen::Matrix3d> llt(G);
  if(llt.info() == Eigen::Success) targets.push_back(f.to_global(-llt.solve(a)));

  std::vector<Point> before;
  std::vector<face_descriptor> hints_before;
  for(std::size_t j : group) {
    before.push_back(fit.point(fit.vertices_[j]));
    hints_before.push_back(fit.hint_[j]);
  }
  std::vector<face_descriptor> hints = hints_before;
  const double farthest_before = farthest_of(fit, group, hints, std::numeric_limits<double>::infinity());
  // a neighbour's F(u) left empty by a trial position is no evaluation's
  const std::size_t infeasible = ws.infeasible_regions;
  const Eigen::Vector3d from = f.origin;
  for(const Eigen::Vector3d& target : targets)
    for(double step : {1., 0.75, 0.5, 0.25}) {
      const Eigen::Vector3d to = from + step * (target - from);
      put_point(fit.vpm_, fit.vertices_[i], Point(to[0], to[1], to[2]));
      for(int sweep = 0; sweep < 3; ++sweep)
        for(std::size_t j = 1; j < group.size(); ++j) {
          Eigen::Vector3d best;
          double improvement;
          // no bound on the gain (the neighbour may have to lose), and a
          // margin inside F(u), whose boundary the optimum usually touches
          if(fit.solve(group[j], Fit::Goal::fit, ws, best, improvement, nullptr, false, 1e-6))
            put_point(fit.vpm_, fit.vertices_[group[j]], Point(best[0], best[1], best[2]));
        }
      bool certified = true;
      for(std::size_t j = 0; j < group.size() && certified; ++j)
        certified = fit.certified_at(group[j], fit.point(fit.vertices_[group[j]]));
      hints = hints_before;
      if(certified && farthest_of(fit, group, hints, 0.9 * farthest_before) < 0.9 * farthest_before) {
        std::size_t moved = 0;
        for(std::size_t j = 0; j < group.size(); ++j) {
          fit.hint_[group[j]] = hints[j];
          if(fit.point(fit.vertices_[group[j]]) != before[j]) ++moved;
        }
        ws.infeasible_regions = infeasible;
        return moved;
      }
      for(std::size_t j = 0; j < group.size(); ++j) put_point(fit.vpm_, fit.vertices_[group[j]], before[j]);
    }
  ws.infeasible_regions = infeasible;
  return 0;
}

// One pass over the vertices whose gap is at least half the largest,
// largest first, each moved with its `rings` rings (its group: 1, the
// one-ring; 2, the one-ring and the ring around it) when no group freed
// before in the pass has touched them. Returns whether some were freed;
// their groups and the rings around are then dirty, and the groups are
// appended to `freed_groups` when it is given.
//
// The candidates are tried in rounds, in parallel, with the outcome of
// trying them one after the other in their order: a round takes them in
// order, at most Fit::round_size, each at least 2 * rings + 2 edges from
// every candidate before it that is not yet tried (a try writes its group,
// within `rings` edges of the candidate, and reads one edge farther, so it
// cannot see nor be seen by those); the others wait for the next round, in
// their order. The outcomes are recorded in the round's order, so the result
// does not depend on the number of threads.
template <typename Fit>
bool free_stuck_vertices(Fit& fit, std::size_t rings, std::vector<std::vector<std::size_t> >* freed_groups)
{
  const std::size_t n = fit.vertices_.size();
  std::vector<double> gap(n);
  fit.pool_.for_each(n, [&](std::size_t i, int) {
    auto hint = fit.hint_[i];
    gap[i] = squared_gap(fit, i, hint);
  });
  const double largest = n == 0 ? 0. : *std::max_element(gap.begin(), gap.end());
  std::vector<std::size_t> candidates;
  for(std::size_t i = 0; i < n; ++i)
    if(gap[i] > 0. && gap[i] >= 0.25 * largest) candidates.push_back(i);
  std::sort(candidates.begin(), candidates.end(),
            [&](std::size_t a, std::size_t b) { return gap[a] != gap[b] ? gap[a] > gap[b] : a < b; });
  auto ring = [&](std::size_t j) { return vertices_around_target(halfedge(fit.vertices_[j], fit.mesh_), fit.mesh_); };
  std::vector<bool> touched(n, false), claimed(n, false), in_group(n, false);
  // the candidate, then its rings one after the other, each in the order
  // of the one before
  auto group_of = [&](std::size_t i) {
    std::vector<std::size_t> group{i};
    in_group[i] = true;
    for(std::size_t r = 0, begin = 0; r < rings; ++r) {
      const std::size_t end = group.size();
      for(std::size_t k = begin; k < end; ++k)
        for(auto w : ring(group[k]))
          if(!in_group[get(fit.index_, w)]) {
            in_group[get(fit.index_, w)] = true;
            group.push_back(get(fit.index_, w));
          }
      begin = end;
    }
    for(std::size_t j : group) in_group[j] = false;
    return group;
  };
  std::vector<std::vector<std::size_t> > groups;
  std::vector<std::size_t> moved, claims, waiting, still_waiting;
  std::size_t next = 0, freed = 0;  // candidates[next, end) not yet seen
  while((!waiting.empty() || next < candidates.size()) && !fit.stopped()) {
    groups.clear();
    still_waiting.clear();
    std::size_t budget = fit.options_.max_moves - fit.stats_.moves;  // the move budget holds exactly
    // those waiting from the round before come first: they are earlier
    // in the order than those not yet seen
    for(std::size_t k = 0; groups.size() < Fit::round_size && (k < waiting.size() || next < candidates.size()); ++k) {
      const std::size_t i = k < waiting.size() ? waiting[k] : candidates[next++];
      std::vector<std::size_t> group = group_of(i);
      if(std::any_of(group.begin(), group.end(), [&](std::size_t j) { return touched[j]; })) continue;
      const bool wait = std::any_of(group.begin(), group.end(), [&](std::size_t j) { return claimed[j]; }) ||
                        budget < group.size();
      for(std::size_t j : group)  // the ring around the group, which those after it must not reach
        for(auto w : ring(j))
          if(!claimed[get(fit.index_, w)]) {
            claimed[get(fit.index_, w)] = true;
            claims.push_back(get(fit.index_, w));
          }
      if(wait) {
        still_waiting.push_back(i);
        continue;
      }
      budget -= group.size();
      groups.push_back(std::move(group));
      if(groups.size() == Fit::round_size)  // the rest of those waiting wait on
        for(++k; k < waiting.size(); ++k) still_waiting.push_back(waiting[k]);
    }
    waiting.swap(still_waiting);
    if(groups.empty()) break;  // the rest wait for a budget that is spent
    for(std::size_t j : claims) claimed[j] = false;
    claims.clear();
    moved.assign(groups.size(), 0);
    fit.pool_.for_each(groups.size(), [&](std::size_t g, int worker) {
      moved[g] = free_stuck_vertex(fit, groups[g], fit.workspaces_[worker]);
    });
    for(std::size_t g = 0; g < groups.size(); ++g) {
      if(moved[g] == 0) continue;
      ++freed;
      fit.stats_.moves += moved[g];
      fit.moved_since_update_ += moved[g];
      for(std::size_t j : groups[g]) {
        touched[j] = true;
        fit.dirty_[j] = true;
        for(auto w : ring(j)) fit.dirty_[get(fit.index_, w)] = true;
      }
      if(freed_groups) freed_groups->push_back(groups[g]);
    }
  }
  fit.collect_counters();
  fit.stats_.stuck_vertices_freed += freed;
  return freed > 0;
}

// After a freeing pass that made face pairs cross that did not cross before
// (`before`; `after` holds those crossing now), each group with a vertex on
// a face of a new pair is put back where `saved` has it, as long as the
// faces around it still certify exactly (a group freed later in the pass
// may border it and have been certified against its new position); then
// the pairs are found again, up to three times. Returns whether no more
// pairs cross than before, with the number of groups put back in
// `put_back`; false when a group cannot be put back, and the pass must then
// be rolled back whole.
template <typename Fit>
bool put_back_crossing_groups(Fit& fit, const Saved_region<Fit>& saved,
                              const std::vector<std::vector<std::size_t> >& groups,
                              const typename Fit::Face_pairs& before, typename Fit::Face_pairs& after,
                              std::size_t& put_back)
{
  const std::size_t n = fit.vertices_.size();
  std::vector<std::size_t> group_of(n, groups.size());
  for(std::size_t g = 0; g < groups.size(); ++g)
    for(std::size_t j : groups[g]) group_of[j] = g;
  std::vector<bool> is_back(groups.size(), false);
  put_back = 0;
  for(int attempt = 0; attempt < 3 && after.size() > before.size(); ++attempt) {
    typename Fit::Face_pairs fresh;
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(fresh),
                        face_pair_order(fit.mesh_));
    std::vector<std::size_t> back;  // the groups to put back, in order
    for(const auto& pair : fresh)
      for(auto f : {pair.first, pair.second})
        for(auto v : vertices_around_face(halfedge(f, fit.mesh_), fit.mesh_)) {
          const std::size_t g = group_of[get(fit.index_, v)];
          if(g < groups.size() && !is_back[g]) {
            is_back[g] = true;
            back.push_back(g);
          }
        }
    if(back.empty()) return false;
    std::sort(back.begin(), back.end());
    for(std::size_t g : back) saved.restore(fit, groups[g]);
    for(std::size_t g : back)
      for(std::size_t j : groups[g]) {
        if(!fit.certified_at(j, fit.point(fit.vertices_[j]))) return false;
        for(auto w : vertices_around_target(halfedge(fit.vertices_[j], fit.mesh_), fit.mesh_))
          if(!fit.certified_at(get(fit.index_, w), fit.point(w))) return false;
      }
    put_back += back.size();
    after = intersecting_pairs_after(fit, saved.moved(fit), before);
  }
  return after.size() <= before.size();
}

// One freeing pass with `rings` rings, kept when no face pair crosses but
// those of `pairs` (the pairs crossing before it; updated when it is kept),
// once the groups that made new pairs cross are put back
// (put_back_crossing_groups), and, with the distance guard (`guarded`), when
// the guard's measure does not grow; otherwise rolled back whole. Returns how
// many groups it freed and kept.
template <typename Fit>
std::size_t free_stuck_vertices_kept(Fit& fit, std::size_t rings, typename Fit::Face_pairs& pairs, bool guarded)
{
  const std::size_t n = fit.vertices_.size();
  std::vector<std::size_t> all(n);
  for(std::size_t i = 0; i < n; ++i) all[i] = i;
  const Saved_region<Fit> saved(fit, all);
  const std::size_t moves = fit.stats_.moves, freed = fit.stats_.stuck_vertices_freed;
  std::vector<std::vector<std::size_t> > groups;
  if(!free_stuck_vertices(fit, rings, &groups)) return 0;
  typename Fit::Face_pairs after = intersecting_pairs_after(fit, saved.moved(fit), pairs);
  std::size_t put_back = 0;
  bool keep = after.size() <= pairs.size() || put_back_crossing_groups(fit, saved, groups, pairs, after, put_back);
  keep = keep && put_back < groups.size();
  double distance = 0.;
  if(keep && guarded) {
    // an infinite limit: only the farthest points are asked again without a start face
    distance = guard_distance(fit, std::numeric_limits<double>::infinity(), nullptr);
    keep = distance <= fit.stats_.end_distance * fit.diagonal_ / 100.;
  }
  if(keep) {
    if(guarded) fit.stats_.end_distance = 100. * distance / fit.diagonal_;
    fit.stats_.intersecting_pairs = after.size();
    pairs.swap(after);
    fit.stats_.moves = moves + saved.moved(fit).size();
    fit.stats_.stuck_vertices_freed -= put_back;
    fit.stats_.stuck_vertices_put_back += put_back;
    return fit.stats_.stuck_vertices_freed - freed;
  }
  saved.restore(fit);
  fit.stats_.moves = moves;
  fit.stats_.stuck_vertices_freed = freed;
  return 0;
}

// The last pass. The passes above run while the queue has work: it resumes
// after each and can move a freed vertex back out (sphere at 10,000
// vertices: the same vertex freed in three passes, then back), and the
// distance balance moves every vertex after them. So once the fit is
// untangled, guarded and balanced, one more pass frees the vertices left
// farthest, with nothing after it, then a pass with their two rings, which
// frees some that their one-rings cannot (a neighbour held by its own ring:
// at 10,000 vertices elephant-with-holes 1.32% -> 1.06%, femur 0.86% ->
// 0.57% Hausdorff). Each of the two is kept or rolled back on its own
// (free_stuck_vertices_kept), so a two-ring pass that fails the checks does
// not undo the one-ring pass before it. The pair of passes runs again while
// it frees some, at most four times by default: a group freed makes room for
// another (cylinder at 10,000 vertices: 24 groups in one round, 222 in four,
// 0.356% -> 0.204% Hausdorff).
template <typename Fit>
void free_stuck_vertices_last(Fit& fit, const typename Fit::Face_pairs& pairs, bool guarded)
{
  typename Fit::Face_pairs crossing = pairs;
  fit.stats_.stuck_vertices_put_back = 0;
  fit.stats_.stuck_vertices_freed_last = fit.stats_.stuck_vertices_freed_two_rings = 0;
  for(int round = 0; round < fit.options_.last_stuck_rounds; ++round) {
    const std::size_t one = free_stuck_vertices_kept(fit, 1, crossing, guarded);
    const std::size_t two = free_stuck_vertices_kept(fit, 2, crossing, guarded);
    fit.stats_.stuck_vertices_freed_two_rings += two;
    fit.stats_.stuck_vertices_freed_last += one + two;
    if(one + two == 0) break;
  }
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_STUCK_VERTICES_H
