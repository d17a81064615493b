// SPDX-License-Identifier: GPL-3.0-or-later
//
// The distance balance at the end of deform-to-fit (beyond the thesis). The
// fit puts the vertices on the input, so that on a curved region every face
// lies on one side of it: inside a convex region by up to its sagitta s, the
// vertices at 0. The Hausdorff distance is then s where a mesh that straddles
// the input, its vertices s/2 outside and its faces' middles s/2 inside, has
// s/2. Each vertex moves along its normal by the middle of the range of the
// input's offsets seen from it and from the centroids of its faces, certified
// exactly like any move of the optimizer (Deform_to_fit.h), whose friend
// these functions are; three rounds, kept only if no face pair starts to
// cross and, with the distance guard, the distance, as the guard measures
// it and at the faces' centroids, does not grow.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_BALANCE_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_BALANCE_H

#include <CGAL/Nonobtuse_remeshing/internal/distance_guard.h>
#include <CGAL/Nonobtuse_remeshing/internal/untangling.h>

#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// The mesh's faces with, for each, its centroid and the input's point
// closest to it, found on the workers (each search starts from the closest
// triangle of one of the face's vertices).
template <typename Fit>
struct Face_offsets
{
  using face_descriptor = typename Fit::face_descriptor;

  explicit Face_offsets(const Fit& fit) : index(get_initialized_face_index_map(fit.mesh_))
  {
    for(face_descriptor f : faces(fit.mesh_)) {
      bound = (std::max)(bound, std::size_t(get(index, f)) + 1);
      list.push_back(f);
    }
    centroid.resize(bound);
    closest.resize(bound);
  }

  // Measures every face; returns the farthest centroid's distance.
  double measure(Fit& fit)
  {
    const auto& mesh = fit.mesh_;
    std::vector<double> far(list.size());
    fit.pool_.for_each(list.size(), [&](std::size_t j, int) {
      const auto h = halfedge(list[j], mesh);
      const Epick::Point_3 c = CGAL::centroid(fit.point(source(h, mesh)), fit.point(target(h, mesh)),
                                              fit.point(target(next(h, mesh), mesh)));
      const auto t = fit.input_.triangle(fit.input_.closest(c, fit.hint_[get(fit.index_, target(h, mesh))]));
      const Epick::Point_3 q = Epick().construct_projected_point_3_object()(t, c);
      const std::size_t k = get(index, list[j]);
      centroid[k] = Eigen::Vector3d(c.x(), c.y(), c.z());
      closest[k] = Eigen::Vector3d(q.x(), q.y(), q.z());
      far[j] = (closest[k] - centroid[k]).squaredNorm();
    });
    return far.empty() ? 0. : std::sqrt(*std::max_element(far.begin(), far.end()));
  }

  using Mesh = std::remove_reference_t<decltype(std::declval<Fit&>().mesh_)>;
  decltype(get_initialized_face_index_map(std::declval<const Mesh&>())) index;
  std::size_t bound = 0;
  std::vector<face_descriptor> list;
  std::vector<Eigen::Vector3d> centroid, closest;  // by face index
};

// Where vertex i should go: along its normal (the sum of its faces' area
// normals) by the middle of the range of the input's offsets along that
// normal, from the vertex and from its faces' centroids (as `offsets`
// measured them), at most a quarter of its shortest edge; false for a
// border vertex or one with no normal.
template <typename Fit>
bool balanced_position(const Fit& fit, const Face_offsets<Fit>& offsets, std::size_t i, Eigen::Vector3d& position)
{
  const auto& mesh = fit.mesh_;
  const auto v = fit.vertices_[i];
  if(is_border(v, mesh)) return false;
  const Eigen::Vector3d p = fit.position(i);
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double shortest = std::numeric_limits<double>::infinity();
  for(auto h : halfedges_around_target(v, mesh)) {
    const Epick::Point_3& a = fit.point(source(h, mesh));
    const Epick::Point_3& b = fit.point(target(next(h, mesh), mesh));
    const Eigen::Vector3d ea(a.x() - p[0], a.y() - p[1], a.z() - p[2]), eb(b.x() - p[0], b.y() - p[1], b.z() - p[2]);
    normal += eb.cross(ea);  // the face (v, b, a) in its orientation
    shortest = (std::min)(shortest, ea.norm());
  }
  const double length = normal.norm();
  if(!(length > 0.)) return false;
  normal /= length;
  // the vertex's closest input triangle is its hint
  const Epick::Point_3 q = Epick().construct_projected_point_3_object()(fit.input_.triangle(fit.hint_[i]), fit.point(v));
  double low = (Eigen::Vector3d(q.x(), q.y(), q.z()) - p).dot(normal), high = low;
  for(auto f : faces_around_target(halfedge(v, mesh), mesh)) {
    const std::size_t k = get(offsets.index, f);
    const double offset = (offsets.closest[k] - offsets.centroid[k]).dot(normal);
    low = (std::min)(low, offset);
    high = (std::max)(high, offset);
  }
  const double step = (std::max)(-0.25 * shortest, (std::min)(0.5 * (low + high), 0.25 * shortest));
  position = p + step * normal;
  return true;
}

// Three rounds of balancing moves, each from the offsets measured after the
// one before, from the face pairs `pairs` that cross (those the untangling
// and the guard left). The rounds are kept when no face pair starts to cross
// and, with the distance guard (`guarded`: its measure of the mesh as the
// guard left it), when the larger of the guard's measure and the farthest
// face centroid does not grow and the guard's measure stays within its
// start (the guard's promise); otherwise they are rolled back and run once
// more with half the steps. Without the guard (the decimation's relaxation,
// whose levels are measured by the caller), the distance is not measured.
// Returns the face pairs that cross after it.
template <typename Fit>
typename Fit::Face_pairs balance_the_distance(Fit& fit, typename Fit::Face_pairs pairs, std::optional<double> guarded)
{
  const auto start = std::chrono::steady_clock::now();
  const std::size_t n = fit.vertices_.size();
  const double promise = (std::max)(fit.stats_.start_distance, fit.stats_.end_distance) * fit.diagonal_ / 100.;
  Face_offsets<Fit> offsets(fit);
  const double farthest = offsets.measure(fit), distance = (std::max)(guarded.value_or(0.), farthest);
  const std::vector<Eigen::Vector3d> start_centroid = offsets.centroid, start_closest = offsets.closest;
  std::vector<std::size_t> all(n);
  for(std::size_t i = 0; i < n; ++i) all[i] = i;
  const Saved_region<Fit> saved(fit, all);
  std::vector<Eigen::Vector3d> targets(n);
  std::vector<char> movable(n), moved(n), step(n);
  constexpr int rounds = 3;
  for(double scale : {1., 0.5}) {
    std::size_t moves = 0;
    double after = farthest;
    std::fill(moved.begin(), moved.end(), 0);
    for(int round = 0; round < rounds && !fit.stopped(); ++round) {
      fit.pool_.for_each(n, [&](std::size_t i, int) {
        movable[i] = balanced_position(fit, offsets, i, targets[i]);
        if(movable[i]) targets[i] = fit.position(i) + scale * (targets[i] - fit.position(i));
      });
      std::size_t round_moves = 0;
      for(const std::vector<std::size_t>& members : fit.classes_) {
        fit.pool_.for_each(members.size(), [&](std::size_t j, int worker) {
          const std::size_t i = members[j];
          step[i] = 0;
          if(!movable[i]) return;
          const auto outcome = fit.try_move(i, targets[i], fit.workspaces_[worker], nullptr);
          step[i] = outcome == Fit::Outcome::moved || outcome == Fit::Outcome::shortened;
        });
        for(std::size_t i : members)
          if(step[i]) {
            moved[i] = 1;
            ++round_moves;
          }
      }
      if(round_moves == 0) break;
      moves += round_moves;
      // the next round's offsets; after the last, the guard's check needs them
      if(guarded || round + 1 < rounds) after = offsets.measure(fit);
    }
    if(moves == 0) break;
    std::vector<std::size_t> list;
    for(std::size_t i = 0; i < n; ++i)
      if(moved[i]) list.push_back(i);
    typename Fit::Face_pairs after_pairs = intersecting_pairs_after(fit, list, pairs);
    bool keep = after_pairs.size() <= pairs.size();
    double guard_after = 0.;
    if(keep && guarded) {
      // an infinite limit: only the farthest points are asked again without a start face
      guard_after = guard_distance(fit, std::numeric_limits<double>::infinity(), nullptr);
      keep = (std::max)(guard_after, after) <= distance && guard_after <= (std::max)(*guarded, promise);
    }
    if(keep) {
      pairs.swap(after_pairs);
      fit.stats_.balance_moves += moves;
      fit.stats_.moves += moves;
      if(guarded) fit.stats_.end_distance = 100. * guard_after / fit.diagonal_;
      break;
    }
    saved.restore(fit);
    offsets.centroid = start_centroid;
    offsets.closest = start_closest;
  }
  fit.stats_.intersecting_pairs = pairs.size();
  fit.stats_.balance_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return pairs;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_BALANCE_H
