// SPDX-License-Identifier: GPL-3.0-or-later
//
// Untangling after deform-to-fit (beyond the thesis): moves that remove the
// self-intersections a fit can make where the input is thinner than a cube,
// each certified exactly like any move of the optimizer (Deform_to_fit.h),
// whose friends these functions are.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_UNTANGLING_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_UNTANGLING_H

#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <iterator>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// Face pairs ordered by the indices of their faces, each pair's smaller
// index first: the order of the lists below, the same for any number of
// workers.
template <typename Mesh>
auto face_pair_order(const Mesh& mesh)
{
  const auto index = get_initialized_face_index_map(mesh);
  return [index](const auto& a, const auto& b) {
    return std::make_pair(get(index, a.first), get(index, a.second)) <
           std::make_pair(get(index, b.first), get(index, b.second));
  };
}

// The bounding box of face f of `mesh`, its vertices at `points`.
template <typename Mesh, typename Points>
Bbox_3 face_bbox(const Mesh& mesh, const Points& points, typename boost::graph_traits<Mesh>::face_descriptor f)
{
  const auto h = halfedge(f, mesh);
  return get(points, source(h, mesh)).bbox() + get(points, target(h, mesh)).bbox() +
         get(points, target(next(h, mesh), mesh)).bbox();
}

// The self-intersecting pairs among the faces `range` of the fit's mesh, in
// face_pair_order. With several workers and many faces, the faces are cut
// into one slab per worker across the longest side of their bounding box, at
// quantiles of their boxes' centres, and the slabs are searched in
// parallel: a face is in every slab its box meets, so the two faces of a
// crossing pair (their boxes overlap) share a slab, and a pair found in two
// slabs is kept once. The list does not depend on the number of workers.
// (PMP's own parallel search, which copies its boxes four times and
// searches sixteen pairs of quarters, was slower than one thread on two.)
template <typename Fit, typename FaceRange>
typename Fit::Face_pairs intersecting_pairs_among(Fit& fit, const FaceRange& range)
{
  using face_descriptor = typename Fit::face_descriptor;
  const auto np = CGAL::parameters::vertex_point_map(fit.points_).geom_traits(Epick());
  const std::vector<face_descriptor> all(std::begin(range), std::end(range));
  const std::size_t slabs = all.size() >= 4096 ? std::size_t(fit.pool_.workers()) : 1;
  std::vector<typename Fit::Face_pairs> found(slabs);
  if(slabs == 1) {
    Polygon_mesh_processing::self_intersections(all, fit.mesh_, std::back_inserter(found[0]), np);
  } else {
    std::vector<Bbox_3> boxes(all.size());
    Bbox_3 whole;
    for(std::size_t j = 0; j < all.size(); ++j) {
      boxes[j] = face_bbox(fit.mesh_, fit.points_, all[j]);
      whole += boxes[j];
    }
    int axis = 0;
    for(int a = 1; a < 3; ++a)
      if(whole.max(a) - whole.min(a) > whole.max(axis) - whole.min(axis)) axis = a;
    std::vector<double> centres(all.size());
    for(std::size_t j = 0; j < all.size(); ++j) centres[j] = boxes[j].min(axis) + boxes[j].max(axis);
    std::vector<double> cuts(slabs + 1);  // slab k: [cuts[k], cuts[k + 1]] (in twice the coordinate)
    cuts.front() = -std::numeric_limits<double>::infinity();
    cuts.back() = std::numeric_limits<double>::infinity();
    for(std::size_t k = 1; k < slabs; ++k) {
      const auto quantile = centres.begin() + all.size() * k / slabs;
      std::nth_element(centres.begin(), quantile, centres.end());
      cuts[k] = *quantile;
    }
    fit.pool_.for_each(slabs, [&](std::size_t k, int) {
      std::vector<face_descriptor> mine;
      for(std::size_t j = 0; j < all.size(); ++j)
        if(2 * boxes[j].max(axis) >= cuts[k] && 2 * boxes[j].min(axis) <= cuts[k + 1]) mine.push_back(all[j]);
      Polygon_mesh_processing::self_intersections(mine, fit.mesh_, std::back_inserter(found[k]), np);
    });
  }
  typename Fit::Face_pairs pairs;
  for(const auto& f : found) pairs.insert(pairs.end(), f.begin(), f.end());
  const auto index = get_initialized_face_index_map(fit.mesh_);
  for(auto& p : pairs)
    if(get(index, p.second) < get(index, p.first)) std::swap(p.first, p.second);
  std::sort(pairs.begin(), pairs.end(), face_pair_order(fit.mesh_));
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

// The mesh's self-intersecting face pairs, in face_pair_order.
template <typename Fit>
typename Fit::Face_pairs intersecting_pairs(Fit& fit)
{
  return intersecting_pairs_among(fit, faces(fit.mesh_));
}

// The same list as intersecting_pairs(fit) when only the vertices `moved`
// moved since `before` was that list: a pair of faces neither of which
// moved is as it was, and a face that meets a moved face has a box that
// overlaps the moved face's, so only the moved faces and those are tested
// again. The untangling's attempts and the guard's rounds move a few
// hundred vertices each; rotor at 10,000 vertices tested its whole mesh 23
// times in its fit (0.55 s of 2.9 s). When the moved faces are half the
// mesh or more (the distance balance moves nearly every vertex), the whole
// mesh is tested at once: the boxes' pass before the test would cost as
// much as the test.
template <typename Fit>
typename Fit::Face_pairs intersecting_pairs_after(Fit& fit, const std::vector<std::size_t>& moved,
                                                  const typename Fit::Face_pairs& before)
{
  using face_descriptor = typename Fit::face_descriptor;
  const face_descriptor none = boost::graph_traits<std::remove_reference_t<decltype(fit.mesh_)> >::null_face();
  using Box = Box_intersection_d::Box_with_info_d<double, 3, face_descriptor, Box_intersection_d::ID_FROM_BOX_ADDRESS>;
  const auto index = get_initialized_face_index_map(fit.mesh_);
  std::size_t bound = 0;  // above every face index (a Surface_mesh's may have gaps where faces were removed)
  for(face_descriptor f : faces(fit.mesh_)) bound = (std::max)(bound, std::size_t(get(index, f)) + 1);
  std::vector<bool> is_moved(bound, false), tested(bound, false);
  std::vector<face_descriptor> again;
  for(std::size_t i : moved)
    for(face_descriptor f : faces_around_target(halfedge(fit.vertices_[i], fit.mesh_), fit.mesh_))
      if(f != none && !is_moved[get(index, f)]) {
        is_moved[get(index, f)] = tested[get(index, f)] = true;
        again.push_back(f);
      }
  if(2 * again.size() >= std::size_t(num_faces(fit.mesh_))) return intersecting_pairs(fit);
  const auto box = [&](face_descriptor f) { return Box(face_bbox(fit.mesh_, fit.points_, f), f); };
  std::vector<Box> moved_boxes;
  for(face_descriptor f : again) moved_boxes.push_back(box(f));
  // the faces whose boxes meet a moved face's, the mesh's faces cut in one
  // part per worker (box_intersection_d sorts both its ranges: each part
  // has its own copy of the moved faces' boxes)
  const std::vector<face_descriptor> all(faces(fit.mesh_).begin(), faces(fit.mesh_).end());
  const std::size_t parts = std::size_t(fit.pool_.workers());
  std::vector<std::vector<face_descriptor> > met(parts);
  fit.pool_.for_each(parts, [&](std::size_t k, int) {
    std::vector<Box> mine(moved_boxes), part;
    for(std::size_t j = all.size() * k / parts; j < all.size() * (k + 1) / parts; ++j) part.push_back(box(all[j]));
    box_intersection_d(mine.begin(), mine.end(), part.begin(), part.end(),
                       [&](const Box&, const Box& b) { met[k].push_back(b.info()); });
  });
  for(const std::vector<face_descriptor>& part : met)
    for(face_descriptor f : part)
      if(!tested[get(index, f)]) {
        tested[get(index, f)] = true;
        again.push_back(f);
      }
  const auto moves = [&](const auto& p) { return is_moved[get(index, p.first)] || is_moved[get(index, p.second)]; };
  typename Fit::Face_pairs kept, found, pairs;
  std::remove_copy_if(before.begin(), before.end(), std::back_inserter(kept), moves);
  const typename Fit::Face_pairs among = intersecting_pairs_among(fit, again);
  std::copy_if(among.begin(), among.end(), std::back_inserter(found), moves);
  std::merge(kept.begin(), kept.end(), found.begin(), found.end(), std::back_inserter(pairs), face_pair_order(fit.mesh_));
  return pairs;
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
  // The region's vertices whose points differ from the saved ones.
  std::vector<std::size_t> moved(const Fit& fit) const
  {
    std::vector<std::size_t> list;
    for(std::size_t j = 0; j < region_.size(); ++j)
      if(fit.point(fit.vertices_[region_[j]]) != points_[j]) list.push_back(region_[j]);
    return list;
  }
  void restore(Fit& fit) const
  {
    for(std::size_t j = 0; j < region_.size(); ++j) {
      put_point(fit.vpm_, fit.vertices_[region_[j]], points_[j]);
      fit.hint_[region_[j]] = hints_[j];
    }
  }
  // Only the region's vertices at `positions` (positions in the region, which
  // are the vertices' indices when the region is every vertex).
  void restore(Fit& fit, const std::vector<std::size_t>& positions) const
  {
    for(std::size_t j : positions) {
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
                      typename Fit::Face_pairs& pairs, bool strictly);

// Beyond the thesis: where the input is thinner than a cube, the fit can
// fold the mesh through itself. The vertices of each self-intersecting
// pair and the rings around them, wider each round, take constrained
// smoothing moves, or else move back towards their positions in the
// initial mesh (constrained and certified like any other move), keeping
// only what lowers the number of pairs, for at most five rounds; what
// remains is counted and returned (the distance guard goes on from it).
template <typename Fit>
typename Fit::Face_pairs untangle(Fit& fit)
{
  using Clock = std::chrono::steady_clock;
  using face_descriptor = typename Fit::face_descriptor;
  using vertex_descriptor = typename Fit::vertex_descriptor;
  const Clock::time_point start = Clock::now();
  typename Fit::Face_pairs pairs = intersecting_pairs(fit);
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
  fit.stats_.untangling_seconds += fit.seconds_since(start);
  return pairs;
}

// Moves the vertices of `region` towards `goal` (three passes); keeps the
// moves if they leave fewer pairs (or, unless `strictly`, as many) and
// updates `pairs`, else rolls them back. Returns whether pairs were removed.
template <typename Fit>
bool untangle_attempt(Fit& fit, const std::vector<std::size_t>& region, typename Fit::Goal goal,
                      typename Fit::Face_pairs& pairs, bool strictly)
{
  const Saved_region<Fit> saved(fit, region);
  std::size_t moves = 0;
  for(int pass = 0; pass < 3; ++pass)
    for(std::size_t i : region) {
      Eigen::Vector3d best;
      double improvement;
      if(fit.stopped()) break;
      if(fit.solve(i, goal, best, improvement) && improvement > fit.threshold_ && fit.apply(i, best)) ++moves;
    }
  typename Fit::Face_pairs left = intersecting_pairs_after(fit, region, pairs);
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
