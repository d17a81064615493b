// SPDX-License-Identifier: GPL-3.0-or-later
//
// Untangling after deform-to-fit (beyond the thesis): moves that remove the
// self-intersections a fit can make where the input is thinner than a cube,
// each certified exactly like any move of the optimizer (Deform_to_fit.h),
// whose friends these functions are.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_UNTANGLING_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_UNTANGLING_H

#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// The mesh's self-intersecting face pairs, on the fit's workers, each pair
// and the list in the order of the face indices (the same for any number of
// workers).
template <typename Fit>
std::vector<std::pair<typename Fit::face_descriptor, typename Fit::face_descriptor> > intersecting_pairs(Fit& fit)
{
  using face_descriptor = typename Fit::face_descriptor;
  std::vector<std::pair<face_descriptor, face_descriptor> > pairs;
  const auto np = CGAL::parameters::vertex_point_map(fit.points_).geom_traits(Epick());
#ifdef CGAL_LINKED_WITH_TBB
  if(fit.pool_.workers() > 1)
    Polygon_mesh_processing::self_intersections<Parallel_tag>(faces(fit.mesh_), fit.mesh_, std::back_inserter(pairs),
                                                              np);
  else
#endif
    Polygon_mesh_processing::self_intersections(faces(fit.mesh_), fit.mesh_, std::back_inserter(pairs), np);
  const auto index = get_initialized_face_index_map(fit.mesh_);
  std::vector<std::pair<std::size_t, std::size_t> > keys;
  std::vector<std::pair<face_descriptor, face_descriptor> > by_index;
  for(auto& p : pairs) {
    if(get(index, p.second) < get(index, p.first)) std::swap(p.first, p.second);
    keys.emplace_back(get(index, p.first), get(index, p.second));
  }
  std::vector<std::size_t> order(pairs.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  for(std::size_t i : order) by_index.push_back(pairs[i]);
  return by_index;
}

// Vertex indices among n, each added once, in the order added.
struct Vertex_list
{
  explicit Vertex_list(std::size_t n) : chosen(n, false) {}
  // false if i was added before
  bool add(std::size_t i)
  {
    if(chosen[i]) return false;
    chosen[i] = true;
    indices.push_back(i);
    return true;
  }
  std::vector<std::size_t> indices;
  std::vector<bool> chosen;
};

// `seeds` (distinct vertex indices) and the `rings` rings of vertices
// around them, the seeds first.
template <typename Fit>
std::vector<std::size_t> region_around(const Fit& fit, const std::vector<std::size_t>& seeds, int rings)
{
  using vertex_descriptor = typename Fit::vertex_descriptor;
  Vertex_list region(fit.vertices_.size());
  for(std::size_t i : seeds) region.add(i);
  std::vector<std::size_t> front = seeds;
  for(int ring = 0; ring < rings; ++ring) {
    std::vector<std::size_t> next;
    for(std::size_t i : front)
      for(vertex_descriptor w : vertices_around_target(halfedge(fit.vertices_[i], fit.mesh_), fit.mesh_))
        if(region.add(get(fit.index_, w))) next.push_back(get(fit.index_, w));
    front.swap(next);
  }
  return region.indices;
}

// The points and closest input triangles of a region of the fit's vertices,
// to roll its moves back.
template <typename Fit>
class Saved_region
{
public:
  Saved_region(const Fit& fit, const std::vector<std::size_t>& region) : region_(region)
  {
    for(std::size_t i : region) {
      points_.push_back(fit.point(fit.vertices_[i]));
      hints_.push_back(fit.hint_[i]);
    }
  }
  void restore(Fit& fit) const
  {
    for(std::size_t j = 0; j < region_.size(); ++j) {
      put_point(fit.vpm_, fit.vertices_[region_[j]], points_[j]);
      fit.hint_[region_[j]] = hints_[j];
    }
  }

private:
  const std::vector<std::size_t>& region_;
  std::vector<Epick::Point_3> points_;
  std::vector<typename Fit::face_descriptor> hints_;
};

template <typename Fit>
bool untangle_attempt(Fit& fit, const std::vector<std::size_t>& region, typename Fit::Goal goal,
                      std::vector<std::pair<typename Fit::face_descriptor, typename Fit::face_descriptor> >& pairs,
                      bool strictly);

// Beyond the thesis: where the input is thinner than a cube, the fit can
// fold the mesh through itself. The vertices of each self-intersecting
// pair and the rings around them, wider each round, take constrained
// smoothing moves, or else move back towards their positions in the
// initial mesh (constrained and certified like any other move), keeping
// only what lowers the number of pairs, for at most five rounds; what
// remains is counted.
template <typename Fit>
void untangle(Fit& fit)
{
  using Clock = std::chrono::steady_clock;
  using face_descriptor = typename Fit::face_descriptor;
  using vertex_descriptor = typename Fit::vertex_descriptor;
  const Clock::time_point start = Clock::now();
  std::vector<std::pair<face_descriptor, face_descriptor> > pairs = intersecting_pairs(fit);
  fit.stats_.intersecting_pairs_found = pairs.size();
  for(int round = 1; round <= 5 && !pairs.empty() && !fit.stats_.budget_exhausted && !fit.stats_.cancelled; ++round) {
    Vertex_list own(fit.vertices_.size());
    for(const auto& p : pairs)
      for(face_descriptor f : {p.first, p.second})
        for(vertex_descriptor w : vertices_around_face(halfedge(f, fit.mesh_), fit.mesh_)) own.add(get(fit.index_, w));
    const std::vector<std::size_t> region = region_around(fit, own.indices, round);
    // Constrained smoothing of the region, kept unless it adds pairs; if
    // pairs are left, moves of the pairs' own vertices back towards the
    // initial mesh, kept only if they remove pairs. What is not kept is
    // rolled back to the certified state before it.
    if(untangle_attempt(fit, region, Fit::Goal::smooth, pairs, false)) continue;
    untangle_attempt(fit, own.indices, Fit::Goal::restore, pairs, true);
  }
  fit.stats_.intersecting_pairs = pairs.size();
  fit.stats_.untangling_seconds = fit.seconds_since(start);
}

// Moves the vertices of `region` towards `goal` (three passes); keeps the
// moves if they leave fewer pairs (or, unless `strictly`, as many) and
// updates `pairs`, else rolls them back. Returns whether pairs were removed.
template <typename Fit>
bool untangle_attempt(Fit& fit, const std::vector<std::size_t>& region, typename Fit::Goal goal,
                      std::vector<std::pair<typename Fit::face_descriptor, typename Fit::face_descriptor> >& pairs,
                      bool strictly)
{
  using face_descriptor = typename Fit::face_descriptor;
  const Saved_region<Fit> saved(fit, region);
  std::size_t moves = 0;
  for(int pass = 0; pass < 3; ++pass)
    for(std::size_t i : region) {
      Eigen::Vector3d best;
      double improvement;
      if(fit.stopped()) break;
      if(fit.solve(i, goal, best, improvement) && improvement > fit.threshold_ && fit.apply(i, best)) ++moves;
    }
  std::vector<std::pair<face_descriptor, face_descriptor> > left = intersecting_pairs(fit);
  if(left.size() < pairs.size() || (!strictly && left.size() == pairs.size())) {
    const bool removed = left.size() < pairs.size();
    fit.stats_.untangling_moves += moves;
    pairs.swap(left);
    return removed;
  }
  fit.stats_.moves -= moves;
  saved.restore(fit);
  return false;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_UNTANGLING_H
