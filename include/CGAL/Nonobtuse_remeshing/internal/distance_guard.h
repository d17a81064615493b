// SPDX-License-Identifier: GPL-3.0-or-later
//
// The distance guard after deform-to-fit (beyond the thesis): the fit must
// not end farther from the input than the mesh it started from. Where it
// would (a tip or a sharp edge that the smoothing rounded off, a feature
// sample taken over by a vertex that cannot reach it), the vertices around
// move back towards their start positions, certified exactly like any move
// of the optimizer (Deform_to_fit.h), whose friends these functions are.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_GUARD_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_GUARD_H

#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>
#include <CGAL/Nonobtuse_remeshing/internal/untangling.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// Points on the input's faces about `spacing` apart: each face's centroid,
// and the points of a barycentric grid fine enough for its longest side,
// except its corners (the input's vertices are feature samples).
template <typename Input>
void add_face_samples(const Input& input, double spacing, std::vector<Epick::Point_3>& points)
{
  for(auto f : faces(input.mesh())) {
    const Epick::Triangle_3 t = input.triangle(f);
    double longest = 0.;
    for(int i = 0; i < 3; ++i) longest = (std::max)(longest, CGAL::squared_distance(t[i], t[(i + 1) % 3]));
    const int n = int((std::min)(std::ceil(std::sqrt(longest) / spacing), 1e3));
    points.push_back(CGAL::centroid(t));
    for(int i = 0; i <= n; ++i)
      for(int j = 0; i + j <= n; ++j) {
        const int k = n - i - j;
        if(i == n || j == n || k == n) continue;  // a corner
        const double a = double(i) / n, b = double(j) / n, c = double(k) / n;
        points.emplace_back(a * t[0].x() + b * t[1].x() + c * t[2].x(), a * t[0].y() + b * t[1].y() + c * t[2].y(),
                            a * t[0].z() + b * t[1].z() + c * t[2].z());
      }
  }
}

// The mesh's vertices at their positions when the fit started (a readable
// property map).
template <typename Fit>
struct Start_point_map
{
  using key_type = typename Fit::vertex_descriptor;
  using value_type = Epick::Point_3;
  using reference = Epick::Point_3;
  using category = boost::readable_property_map_tag;
  const Fit* fit;
  Epick::Point_3 at(const key_type& v) const
  {
    const Eigen::Vector3d& p = fit->initial_[get(fit->index_, v)];
    return Epick::Point_3(p[0], p[1], p[2]);
  }
  friend Epick::Point_3 get(const Start_point_map& map, const key_type& v) { return map.at(v); }
};

// The guard's input side: the farthest of the guard points (the input's
// feature samples: its vertices, thinned to one per cell of the sample
// spacing, and points along its sharp and border edges; and points on its
// faces, add_face_samples) from the mesh with its vertices at `points`.
// With `far`, also the corners of the face closest to each guard point
// farther than `limit`. Where two faces are equally close (a point nearest
// to their common edge, as on CAD parts), the face a query finds depends on
// where its search starts, and so would the vertices moved back: every
// distance that counts is that of a query without a start. Only the points
// that can count are asked: each point's distance to the face found closest
// at the previous measurement (the vertices moved little since; at the
// first, the face of the search tree's nearest reference point) bounds its
// distance from above; the points are asked by decreasing bound until the
// next bound is below the farthest distance found, then, with `far`, those
// whose bound is over `limit` (bounds widened by a relative 1e-9 and 1e-12 of the
// diagonal: the mesh's triangles are well shaped, so the kernel's projections
// onto them are accurate to the last bits). The result is that of asking
// every point; on elephant at 10,000 vertices this measure had been a sixth
// of the run. Queries run on the fit's workers; the result does not depend
// on their number.
template <typename Fit, typename Points>
double input_side(Fit& fit, const Points& points, double limit, Vertex_list* far)
{
  using Mesh = std::remove_reference_t<decltype(fit.mesh_)>;
  using Primitive = AABB_face_graph_triangle_primitive<Mesh, Points>;
  using Tree = AABB_tree<AABB_traits<Epick, Primitive> >;
  const std::vector<Epick::Point_3>& guard = fit.guard_points_;
  if(guard.empty()) return 0.;
  Tree tree(faces(fit.mesh_).first, faces(fit.mesh_).second, fit.mesh_, points);
  std::vector<typename Fit::face_descriptor>& hints = fit.guard_hints_;
  // The search tree of hints takes the faces' reference points in the order
  // of faces(mesh), as the tree's own accelerate_distance_queries() does
  // before build() reorders its primitives (after, the unhinted queries
  // would answer ties differently); so the two can be built side by side.
  std::vector<typename Tree::Point_and_primitive_id> references;
  references.reserve(num_faces(fit.mesh_));
  for(auto f : faces(fit.mesh_)) references.emplace_back(get(points, target(halfedge(f, fit.mesh_), fit.mesh_)), f);
  fit.pool_.invoke([&] { tree.build(); },
                   [&] { tree.accelerate_distance_queries(references.begin(), references.end()); });
  if(hints.size() != guard.size()) {  // the first measurement: the faces of the search tree's nearest reference points
    hints.resize(guard.size());
    fit.pool_.for_each(guard.size(), [&](std::size_t s, int) { hints[s] = tree.best_hint(guard[s]).second; });
  }
  std::vector<double> bound(guard.size());
  fit.pool_.for_each(guard.size(), [&](std::size_t s, int) {
    const auto h = halfedge(hints[s], fit.mesh_);
    const Epick::Triangle_3 t(get(points, source(h, fit.mesh_)), get(points, target(h, fit.mesh_)),
                              get(points, target(next(h, fit.mesh_), fit.mesh_)));
    bound[s] = std::sqrt(CGAL::squared_distance(guard[s], t)) * (1. + 1e-9) + 1e-12 * fit.diagonal_;
  });
  // the points by decreasing bound (a heap: the points taken off its top are
  // few), asked in batches until the next bound is below the farthest
  // distance found
  std::vector<std::size_t> heap(guard.size());
  std::iota(heap.begin(), heap.end(), std::size_t(0));
  const auto lower = [&](std::size_t a, std::size_t b) {
    return bound[a] < bound[b] || (bound[a] == bound[b] && a > b);
  };
  std::make_heap(heap.begin(), heap.end(), lower);
  std::vector<double> nearest(guard.size(), -1.);
  std::vector<std::size_t> batch;
  const auto ask = [&] {
    fit.pool_.for_each(batch.size(), [&](std::size_t j, int) {
      const std::size_t s = batch[j];
      const auto hit = tree.closest_point_and_primitive(guard[s]);
      nearest[s] = std::sqrt(CGAL::squared_distance(guard[s], hit.first));
      hints[s] = hit.second;
    });
  };
  double farthest = 0.;
  while(!heap.empty() && bound[heap.front()] >= farthest) {
    batch.clear();
    while(batch.size() < 64 && !heap.empty() && bound[heap.front()] >= farthest) {
      batch.push_back(heap.front());
      std::pop_heap(heap.begin(), heap.end(), lower);
      heap.pop_back();
    }
    ask();
    for(std::size_t s : batch) farthest = (std::max)(farthest, nearest[s]);
  }
  if(far) {
    batch.clear();
    std::copy_if(heap.begin(), heap.end(), std::back_inserter(batch), [&](std::size_t s) { return bound[s] > limit; });
    ask();
    for(std::size_t s = 0; s < guard.size(); ++s)
      if(nearest[s] > limit)
        for(auto v : vertices_around_face(halfedge(hints[s], fit.mesh_), fit.mesh_)) far->add(get(fit.index_, v));
  }
  return farthest;
}

// The guard's mesh side: the farthest of the mesh's vertices, where they
// are now, from the input (their closest input triangles are the fit's
// hints); with `far`, also those farther than `limit`.
template <typename Fit>
double mesh_side(Fit& fit, double limit, Vertex_list* far)
{
  std::vector<double> from_mesh(fit.vertices_.size());
  fit.pool_.for_each(fit.vertices_.size(), [&](std::size_t i, int) {
    const Epick::Point_3 p = fit.point(fit.vertices_[i]);
    from_mesh[i] = std::sqrt(CGAL::squared_distance(p, fit.input_.triangle(fit.hint_[i])));
  });
  double farthest = 0.;
  for(std::size_t i = 0; i < from_mesh.size(); ++i) {
    farthest = (std::max)(farthest, from_mesh[i]);
    if(far && from_mesh[i] > limit) far->add(i);
  }
  return farthest;
}

// The distance between the fit's mesh, as it is now, and the input as the
// guard measures it (both sides); with `far`, also the vertices near what
// is farther than `limit`, in the order found.
template <typename Fit>
double guard_distance(Fit& fit, double limit, Vertex_list* far)
{
  const double from_input = input_side(fit, fit.points_, limit, far);
  return (std::max)(from_input, mesh_side(fit, limit, far));
}

// What guard_the_distance leaves: the self-intersecting face pairs, and its
// measure (guard_distance) of the mesh as it ends.
template <typename Fit>
struct Guard_outcome
{
  typename Fit::Face_pairs pairs;
  double distance;
};

// Where the fitted mesh is farther from the input than the mesh it started
// from (as guard_distance measures both), the vertices near the excess and
// the rings around them, wider each round, move back towards their start
// positions (ten passes of certified moves), for at most eight rounds; a
// round is kept only if it lowers the distance and adds no self-intersecting
// face pair (`pairs`: those the untangling left), else it is rolled back;
// returns the pairs left and the guard's measure of the mesh as it ends.
// Measured on rotor at N = 50 (the one of
// CGAL's 17 sample meshes whose fit ended farther than its start at N = 50
// and 100): three passes and five rounds brought the guard's measure from
// 1.91% only to 1.54%, the start being 1.43%; ten passes and eight rounds
// reach 1.43% in six.
template <typename Fit>
Guard_outcome<Fit> guard_the_distance(Fit& fit, typename Fit::Face_pairs pairs)
{
  const auto start = std::chrono::steady_clock::now();
  // the mesh the fit started from: its input side now, from the start
  // positions, its mesh side as measured when the fit started
  const double limit = (std::max)(input_side(fit, Start_point_map<Fit>{&fit}, 0., nullptr), fit.start_mesh_side_);
  Vertex_list far(fit.vertices_.size());
  double distance = guard_distance(fit, limit, &far);
  for(int round = 1; round <= 8 && distance > limit && !fit.stopped(); ++round) {
    const std::vector<std::size_t> region = region_around(fit, far.indices, round);
    const Saved_region<Fit> saved(fit, region);
    std::size_t moves = 0;
    for(int pass = 0; pass < 10 && !fit.stopped(); ++pass)
      for(std::size_t i : region) {
        Eigen::Vector3d best;
        double improvement;
        if(fit.solve(i, Fit::Goal::restore, best, improvement) && improvement > fit.threshold_ &&
           fit.apply(i, best))
          ++moves;
      }
    Vertex_list still_far(fit.vertices_.size());
    double after = moves > 0 ? guard_distance(fit, limit, &still_far) : distance;
    typename Fit::Face_pairs pairs_after;
    const std::size_t untangling_moves = fit.stats_.untangling_moves;
    if(moves > 0 && after < distance) {
      // Moving back towards the start can bring back crossings the start
      // mesh had and the untangling removed: the round's vertices of the
      // crossing faces take the untangling's smoothing moves (up to three
      // attempts), and the distance is measured again.
      auto found = intersecting_pairs_after(fit, region, pairs);
      Vertex_list in_round(fit.vertices_.size());
      for(std::size_t i : region) in_round.add(i);
      for(int attempt = 0; attempt < 3 && found.size() > pairs.size() && !fit.stopped(); ++attempt) {
        std::vector<std::size_t> own;
        for(const auto& p : found)
          for(auto f : {p.first, p.second})
            for(auto w : vertices_around_face(halfedge(f, fit.mesh_), fit.mesh_))
              if(in_round.chosen[get(fit.index_, w)]) own.push_back(get(fit.index_, w));
        std::sort(own.begin(), own.end());
        own.erase(std::unique(own.begin(), own.end()), own.end());
        if(own.empty() || !untangle_attempt(fit, own, Fit::Goal::smooth, found, true)) break;
      }
      if(fit.stats_.untangling_moves != untangling_moves) {
        still_far = Vertex_list(fit.vertices_.size());
        after = guard_distance(fit, limit, &still_far);
      }
      pairs_after = std::move(found);
    }
    if(after < distance && pairs_after.size() <= pairs.size()) {
      fit.stats_.guard_moves += moves;
      distance = after;
      pairs = std::move(pairs_after);
      far = std::move(still_far);
      continue;
    }
    fit.stats_.moves -= moves + (fit.stats_.untangling_moves - untangling_moves);
    fit.stats_.untangling_moves = untangling_moves;
    saved.restore(fit);
  }
  fit.stats_.intersecting_pairs = pairs.size();
  fit.stats_.start_distance = 100. * limit / fit.diagonal_;
  fit.stats_.end_distance = 100. * distance / fit.diagonal_;
  fit.stats_.guard_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {std::move(pairs), distance};
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_GUARD_H
