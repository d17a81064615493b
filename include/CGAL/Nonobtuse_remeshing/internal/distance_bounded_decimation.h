// SPDX-License-Identifier: GPL-3.0-or-later
//
// Beyond the thesis: the decimation stage of nonobtuse_remesh() under a
// Hausdorff distance bound. The angle-bounded decimation (chapter 6) runs
// in passes of rising quadric ceilings through ever coarser levels, each
// kept as a polygon soup; the coarsest level whose measured distance to the
// input is within the bound becomes the output. Each pass's coarsest level
// is measured first, then, once one is over the bound, a binary search over
// that pass's levels, so a run measures a few levels, not all.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_BOUNDED_DECIMATION_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_BOUNDED_DECIMATION_H

#include <CGAL/Nonobtuse_remeshing/internal/Angle_bounded_decimation.h>
#include <CGAL/Nonobtuse_remeshing/internal/mesh_helpers.h>
#include <CGAL/Nonobtuse_remeshing/remeshing_stages.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// Each level has this fraction of the vertices of the one before: the
// output has at most 1 / 0.9 - 1 = 11% more vertices than the coarsest level
// within the bound would have.
constexpr double distance_level_ratio = 0.9;

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
    const auto add = [&result](Angle_bounded_decimation_statistics s) {  // this pass's onto the passes' before
      s.vertices_before = result.vertices_before;
      for(auto [sum, part] : {std::make_pair(&s.collapses, result.collapses), {&s.qp_solves, result.qp_solves},
                              {&s.qp_fallbacks, result.qp_fallbacks}, {&s.empty_regions, result.empty_regions},
                              {&s.valence_refusals, result.valence_refusals},
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
                                          }));
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
    clear(mesh);
    Polygon_mesh_processing::polygon_soup_to_polygon_mesh(levels[good].points, levels[good].triangles, mesh);
    result = levels[good].statistics;
    result.seconds = run.seconds;
    result.stop_reason = Decimation_stop_reason::max_distance;
    break;
  }
  bounds.distance = good_distance;
  result.vertices_after = result.target_vertices = vertices(mesh).size();
  return result;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_BOUNDED_DECIMATION_H
