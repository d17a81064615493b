// SPDX-License-Identifier: GPL-3.0-or-later
//
// Beyond the thesis: the decimation stage of nonobtuse_remesh() under a
// Hausdorff distance bound. The angle-bounded decimation (chapter 6) runs
// in passes of rising quadric ceilings through ever coarser levels, each
// kept as a polygon soup; the coarsest level whose measured distance to the
// input is within the bound becomes the output. Each pass's coarsest level
// is measured first, then, once one is over the bound, a binary search over
// that pass's levels, so a run measures a few levels, not all. Where the
// level after the one found goes over the bound, the vertices are held and
// the pass runs again from the level found: the Hausdorff distance is a
// maximum, and one spot (a border corner, a crease) would otherwise end the
// decimation of the whole surface.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_BOUNDED_DECIMATION_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_BOUNDED_DECIMATION_H

#include <CGAL/Nonobtuse_remeshing/internal/Angle_bounded_decimation.h>
#include <CGAL/Nonobtuse_remeshing/internal/distance_measures.h>
#include <CGAL/Nonobtuse_remeshing/internal/mesh_helpers.h>
#include <CGAL/Nonobtuse_remeshing/remeshing_stages.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// Each level has this fraction of the vertices of the one before: the
// output has at most 1 / 0.9 - 1 = 11% more vertices than the coarsest level
// within the bound would have.
constexpr double distance_level_ratio = 0.9;

// At most this many passes run again with held vertices; the points held
// are those of the level over the bound farther than this fraction of the
// bound from the input, or from which the input is. Measured at 0.2% on one
// thread: sphere 2,531 -> 1,494 vertices, blobby 31,802 -> 20,864, knot1
// 7,608 -> 6,162, elephant 157,162 -> 114,570, nefertiti 187,367 ->
// 168,630, mesh_with_border 87,289 -> 70,704 (the right-angle grids on its
// flat facets hardly decimate), in 1.4 to 2.5 times the time (the passes
// run again and a few dozen levels are measured).
constexpr int max_distance_holds = 8;
constexpr double distance_hold_threshold = 0.9;

// A mesh as points and triangles, the compact copy of a level.
template <typename Point>
struct Mesh_soup
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  Angle_bounded_decimation_statistics statistics;  // of the decimation when the level was reached
};

template <typename TriangleMesh>
auto soup_of(const TriangleMesh& mesh)
{
  using Point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  Mesh_soup<Point> soup;
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  for(auto v : vertices(mesh)) {
    put(index, v, soup.points.size());
    soup.points.push_back(get(CGAL::vertex_point, mesh, v));
  }
  soup.triangles.reserve(faces(mesh).size());
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    soup.triangles.push_back({get(index, source(h, mesh)), get(index, target(h, mesh)),
                              get(index, target(next(h, mesh), mesh))});
  }
  return soup;
}

// The vertices and face centroids of `mesh` farther than `threshold` from
// the faces in `tree`, appended to `far`; returns the farthest distance of
// them all.
template <typename TriangleMesh, typename Point>
double add_far_points(const TriangleMesh& mesh, const Face_tree<TriangleMesh>& tree, double threshold,
                      std::vector<Point>& far)
{
  const auto points = get(CGAL::vertex_point, mesh);
  double farthest = 0.;
  const auto test = [&](const Point& p) {
    const double d = std::sqrt(tree.squared_distance(p));
    farthest = (std::max)(farthest, d);
    if(d > threshold) far.push_back(p);
  };
  for(auto v : vertices(mesh)) test(get(points, v));
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    test(CGAL::centroid(get(points, source(h, mesh)), get(points, target(h, mesh)),
                        get(points, target(next(h, mesh), mesh))));
  }
  return farthest;
}

// Where `level` goes over a distance of `threshold` to `input` (whose faces
// are in `input_tree`), both ways: the vertices and face centroids of each
// farther than that from the other; at least the farthest of them (the
// measured maximum can lie inside a face, where no sample is over the
// threshold).
template <typename TriangleMesh>
auto far_points(const TriangleMesh& level, const TriangleMesh& input, const Face_tree<TriangleMesh>& input_tree,
                double threshold)
{
  using Point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  std::vector<Point> far;
  const Face_tree<TriangleMesh> to_level(faces(level).first, faces(level).second, level);
  const double farthest = (std::max)(add_far_points(level, input_tree, threshold, far),
                                     add_far_points(input, to_level, threshold, far));
  if(far.empty() && farthest > 0.) {
    add_far_points(level, input_tree, 0.9 * farthest, far);
    add_far_points(input, to_level, 0.9 * farthest, far);
  }
  return far;
}

// The vertices of `mesh` held at the points `spots`: those of the face
// closest to each and their neighbours.
template <typename TriangleMesh, typename Point>
auto held_vertices(const TriangleMesh& mesh, const std::vector<Point>& spots)
{
  auto held = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  for(auto v : vertices(mesh)) put(held, v, false);
  if(spots.empty()) return held;
  const Face_tree<TriangleMesh> tree(faces(mesh).first, faces(mesh).second, mesh);
  for(const Point& p : spots) {
    const auto f = tree.closest_point_and_primitive(p).second;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) {
      put(held, v, true);
      for(auto n : vertices_around_target(halfedge(v, mesh), mesh)) put(held, n, true);
    }
  }
  return held;
}

// `mesh`, fitted and certified, within the bound (`bounds.fitted_distance`),
// is decimated by `decimation_options` towards levels of
// distance_level_ratio^i times its vertices, the relaxation fitting it to
// `surface`; `mesh` becomes the coarsest level whose `measure` (its
// distance to the input, plus the measurement error, as a fraction of
// `input_diagonal`) is at most bounds.max_distance. Returns the decimation's
// statistics up to that level.
template <typename TriangleMesh, typename Relay, typename Measure>
Angle_bounded_decimation_statistics decimate_within_distance(TriangleMesh& mesh, const TriangleMesh& surface,
                                                             double input_diagonal,
                                                             Angle_bounded_decimation_options options, bool has_max_error,
                                                             Relay& relay, Distance_bound_statistics& bounds,
                                                             const Measure& measure)
{
  const auto points = get(CGAL::vertex_point, mesh);
  const double diagonal = certified_mesh_diagonal(mesh, points);

  // Passes with ceilings d, 2d, 4d, 8d: the quadrics, fresh at each pass,
  // sum the planes of the mesh the pass starts from, so their error
  // overestimates the distance a collapse adds; a pass whose coarsest level
  // is measured within the bound hands it to the next. Measured at d = 1%:
  // the passes after the first take the sphere from 883 to 104 vertices;
  // passes of a constant ceiling (d or d / 2) stop sooner, removing under 2%.
  using Soup = decltype(soup_of(mesh));
  Angle_bounded_decimation_statistics result;
  result.vertices_before = vertices(mesh).size();
  double good_distance = bounds.fitted_distance;
  using Point = typename boost::property_traits<decltype(points)>::value_type;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  std::vector<Point> spots;  // where levels went over the bound
  std::unique_ptr<Face_tree<TriangleMesh> > surface_tree;  // built at the first hold
  const double ceiling = has_max_error ? options.max_error : bounds.max_distance * input_diagonal / diagonal;
  for(int pass = 0; pass < (has_max_error ? 1 : 4); ++pass) {
    options.max_error = ceiling * double(1 << pass);
    std::vector<std::size_t> targets;
    for(double n = distance_level_ratio * double(vertices(mesh).size()); n >= 4.; n *= distance_level_ratio)
      if(targets.empty() || std::size_t(n) < targets.back()) targets.push_back(std::size_t(n));
    std::vector<Soup> levels;  // finest first: the mesh the pass starts from, then each level reached
    levels.push_back(soup_of(mesh));
    levels.back().statistics = result;
    const std::size_t before = vertices(mesh).size();
    const auto held = held_vertices(mesh, spots);
    const auto add = [&result](Angle_bounded_decimation_statistics s) {  // this pass's onto the passes' before
      s.vertices_before = result.vertices_before;
      for(auto [sum, part] : {std::make_pair(&s.collapses, result.collapses), {&s.qp_solves, result.qp_solves},
                              {&s.qp_fallbacks, result.qp_fallbacks}, {&s.empty_regions, result.empty_regions},
                              {&s.valence_refusals, result.valence_refusals},
                              {&s.frozen_refusals, result.frozen_refusals},
                              {&s.certification_refusals, result.certification_refusals},
                              {&s.topology_refusals, result.topology_refusals}, {&s.rounds, result.rounds},
                              {&s.relaxations, result.relaxations}, {&s.relaxation_moves, result.relaxation_moves}})
        *sum += part;
      s.relaxation_seconds += result.relaxation_seconds;
      s.largest_collapse_error = (std::max)(s.largest_collapse_error, result.largest_collapse_error);
      s.seconds += result.seconds;
      return s;
    };
    Angle_bounded_decimation_statistics run =
        add(angle_bounded_decimation_with(mesh, points, options, diagonal, targets, surface,
                                          get(CGAL::vertex_point, surface),
                                          keep_going_function<Angle_bounded_decimation_statistics>(relay),
                                          [&](std::size_t, bool reached, const Angle_bounded_decimation_statistics& s) {
                                            if(!reached) return;
                                            levels.push_back(soup_of(mesh));
                                            levels.back().statistics = add(s);
                                          },
                                          spots.empty() ? std::function<bool(vertex_descriptor)>()
                                                        : [&held](vertex_descriptor v) { return bool(get(held, v)); }));
    collect_garbage_of(mesh, 0);
    bounds.levels += levels.size();
    if(run.stop_reason == Decimation_stop_reason::cancelled) {  // a certified mesh all the same
      bounds.distance = measure(mesh);
      return run;
    }
    const double d = measure(mesh);
    if(d <= bounds.max_distance) {
      result = run;
      good_distance = d;
      if(vertices(mesh).size() + before / 50 >= before) break;  // the pass removed under 2%
      continue;
    }
    // levels[good] is within the bound (the mesh the pass started from
    // is), the mesh at `bad` is not: halve the range until they are
    // neighbours
    std::size_t good = 0, bad = levels.size();
    while(bad - good > 1) {
      const std::size_t middle = (good + bad) / 2;
      TriangleMesh candidate;
      Polygon_mesh_processing::polygon_soup_to_polygon_mesh(levels[middle].points, levels[middle].triangles, candidate);
      const double m = measure(candidate);
      if(m <= bounds.max_distance) {
        good = middle;
        good_distance = m;
      } else {
        bad = middle;
      }
    }
    // where the mesh just over the bound (the next level, or the pass's
    // last mesh) is over it, its vertices are held, and the pass runs again
    const bool hold = !has_max_error && bounds.holds < max_distance_holds;
    if(hold) {
      if(!surface_tree)
        surface_tree = std::make_unique<Face_tree<TriangleMesh> >(faces(surface).first, faces(surface).second, surface);
      const double over_bound = bounds.max_distance * input_diagonal;
      TriangleMesh next;
      if(bad < levels.size())
        Polygon_mesh_processing::polygon_soup_to_polygon_mesh(levels[bad].points, levels[bad].triangles, next);
      const TriangleMesh& over = bad < levels.size() ? next : mesh;
      const auto far = far_points(over, surface, *surface_tree, distance_hold_threshold * over_bound);
      spots.insert(spots.end(), far.begin(), far.end());
      if(&over != &mesh) {
        const auto farther = far_points(mesh, surface, *surface_tree, over_bound);
        spots.insert(spots.end(), farther.begin(), farther.end());
      }
    }
    clear(mesh);
    Polygon_mesh_processing::polygon_soup_to_polygon_mesh(levels[good].points, levels[good].triangles, mesh);
    result = levels[good].statistics;
    result.seconds = run.seconds;
    result.stop_reason = Decimation_stop_reason::max_distance;
    if(!hold) break;
    ++bounds.holds;
    --pass;
  }
  bounds.distance = good_distance;
  result.vertices_after = result.target_vertices = vertices(mesh).size();
  return result;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_BOUNDED_DECIMATION_H
