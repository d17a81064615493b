// SPDX-License-Identifier: GPL-3.0-or-later
//
// The whole pipeline in one call: the initial mesh (thesis, chapter 4), the
// removal of bad-valence vertices (5.7) and deform-to-fit (chapter 5), with
// one visitor for progress and cancellation across the stages.

#ifndef CGAL_NONOBTUSE_REMESHING_NONOBTUSE_REMESH_H
#define CGAL_NONOBTUSE_REMESHING_NONOBTUSE_REMESH_H

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/deform_to_fit.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/missing_components.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>
#include <CGAL/Nonobtuse_remeshing/remove_bad_valence_vertices.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// The stages of `nonobtuse_remesh()`, in their order.
enum class Remeshing_stage
{
  initial_mesh,  ///< nonobtuse Marching Cubes (chapter 4)
  valence,       ///< removal of bad-valence vertices and vertex splits (5.7)
  fit            ///< deform-to-fit with constrained Laplacian smoothing (chapter 5)
};

/// \ingroup PkgNonobtuseRemeshingRef
/// What a remeshing visitor is told while a stage runs.
struct Remeshing_progress
{
  Remeshing_stage stage = Remeshing_stage::initial_mesh;
  double fraction = -1.;  ///< of the stage done: 0 as it starts; -1 when it cannot be known (during the fit)
  const Deform_to_fit_statistics* fit = nullptr;  ///< during the fit, its statistics so far
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Default visitor of `nonobtuse_remesh()`: never cancels. A visitor has
/// the three members below. `keep_going()` is called as each stage starts
/// (fraction 0) and, during the fit, before every move; returning false
/// stops the pipeline there, with the output certified (or empty, when the
/// initial mesh was not built yet). `stage_finished()` follows every stage
/// that ran, also one that was cancelled.
struct Default_remeshing_visitor
{
  void stage_started(Remeshing_stage) {}
  void stage_finished(Remeshing_stage, double /* seconds */) {}
  bool keep_going(const Remeshing_progress&) { return true; }
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Statistics of `nonobtuse_remesh()`: those of each stage that ran (the
/// thesis's Tables 4.1, 7.1 and 7.2) and the resolution used.
struct Nonobtuse_remeshing_statistics
{
  int resolution = 0;                      ///< cubes along the longest side, given or chosen
  std::size_t target_vertices = 0;         ///< 0 unless the resolution was chosen for a vertex count
  int trial_resolution = 0;                ///< with a target: the first resolution tried if it was redone, else 0
  std::size_t degenerate_faces_removed = 0; ///< zero-area input faces removed from a copy of the input first
  Marching_cubes_result initial_mesh;      ///< Table 4.1 (its face maps are left empty)
  bool valence_run = false;
  Bad_valence_removal_statistics valence;  ///< Table 7.1
  bool fit_run = false;
  Deform_to_fit_statistics fit;            ///< Table 7.2
  bool cancelled = false;                  ///< the visitor stopped the pipeline
  /// connected components of the input (beyond the thesis)
  std::size_t input_components = 0;
  /// input components none of whose vertices lies within a cube diagonal of
  /// the output: smaller or thinner than the resolution, they are lost
  std::size_t input_components_missing = 0;
  /// bounding-box diagonal of the largest missing input component
  double largest_missing_component = 0.;
  double seconds = 0.;
};

namespace internal {

// Vertices of the initial mesh per unit of area, times the squared cube
// size h: a plane crosses (|n_x| + |n_y| + |n_z|) / h^2 grid edges per unit
// of area, 1.5 / h^2 on average over normals, and the nonobtuse cases add
// cube centres. Measured at N = 40 and 100 on CGAL's 17 sample meshes: 1.65
// to 1.89 on curved ones, 2.07 to 2.27 on many small holes, 1.26 to 1.40 on
// mostly axis-aligned ones, 1.0 on an axis-aligned box.
constexpr double marching_cubes_vertex_density = 1.8;

// Passes the fit's progress on to a remeshing visitor.
template <typename Visitor>
struct Fit_progress_relay
{
  Visitor* visitor;
  bool keep_going(const Deform_to_fit_statistics& s)
  {
    Remeshing_progress p;
    p.stage = Remeshing_stage::fit;
    p.fit = &s;
    return visitor->keep_going(p);
  }
};

// Removes a Surface_mesh's garbage; meshes without garbage have nothing to do.
template <typename Mesh>
auto collect_garbage_of(Mesh& mesh, int) -> decltype(mesh.collect_garbage(), void())
{
  mesh.collect_garbage();
}
template <typename Mesh>
void collect_garbage_of(Mesh&, long) {}

} // namespace internal

/// \ingroup PkgNonobtuseRemeshingRef
/// The resolution (cubes along the longest side of the bounding box of the
/// faces) whose initial mesh of `input` should have about `target_vertices`
/// vertices: N = L sqrt(V / (c A)), with L the longest side, A the area and c = 1.8
/// the vertex density measured on curved surfaces (see the manual). Clamped
/// to [1, 1024]. Throws `Bad_input` for an input without area.
/// `np` may hold the `vertex_point_map` of `input`.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
int resolution_for_target_vertices(const TriangleMesh& input, std::size_t target_vertices,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Bbox_3 box;  // of the faces, as the grid's
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, input));
  for(auto f : faces(input))
    for(auto v : vertices_around_face(halfedge(f, input), input)) box += get(vpm, v).bbox();
  const double longest = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  if(longest < 1e-30 || longest > 1e30)  // as the grid refuses it
    throw Bad_input("the input's size is outside the supported range [1e-30, 1e30]: scale it");
  const double area = Polygon_mesh_processing::area(input, CGAL::parameters::vertex_point_map(vpm));
  if(!(area > 0.) || !(longest > 0.) || !std::isfinite(area))
    throw Bad_input("the input has no area to choose a resolution from");
  const double n = longest * std::sqrt(double(target_vertices) / (internal::marching_cubes_vertex_density * area));
  return int(std::lround((std::min)(1024., (std::max)(1., n))));
}

namespace internal {

// The pipeline of nonobtuse_remesh() on meshes whose points are in their
// internal point maps (any vertex_point_map in `np` is not used).
template <typename TriangleMesh, typename NamedParameters>
Nonobtuse_remeshing_statistics nonobtuse_remesh_pipeline(const TriangleMesh& input, TriangleMesh& output,
                                                         const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto seconds_since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  clear(output);
  if(num_faces(input) == 0 || !is_triangle_mesh(input))
    throw Bad_input("nonobtuse_remesh: the input must be a non-empty triangle mesh");

  Nonobtuse_remeshing_statistics stats;
  const Remeshing_stage last = choose_parameter(get_parameter(np, internal_np::stop_after), Remeshing_stage::fit);
  const bool valence_cleanup = choose_parameter(get_parameter(np, internal_np::valence_cleanup), true);
  const int k = choose_parameter(get_parameter(np, internal_np::drum_subdivisions), 2);
  if(last == Remeshing_stage::valence && !valence_cleanup)
    throw Bad_parameter("stopping after the valence stage contradicts skipping it");
  int rings = 0;
  internal::deform_to_fit_options(np, rings);  // the fit's parameters are checked before any work
  stats.target_vertices = choose_parameter(get_parameter(np, internal_np::target_vertices), std::size_t(0));
  stats.resolution = stats.target_vertices > 0 ? resolution_for_target_vertices(input, stats.target_vertices)
                                               : choose_parameter(get_parameter(np, internal_np::resolution), 100);
  if(stats.resolution < 1 || stats.resolution > 1024)
    throw Bad_parameter("the resolution must lie in [1, 1024]");
  const Sign_source signs = choose_parameter(get_parameter(np, internal_np::sign_source), Sign_source::patches);
  const double budget = choose_parameter(get_parameter(np, internal_np::memory_budget), default_memory_budget);
  if(!(budget > 0.)) throw Bad_parameter("the memory budget must be positive");

  auto given = choose_parameter(get_parameter(np, internal_np::remeshing_visitor), Default_remeshing_visitor());
  auto& visitor = internal::visitor_reference(given);
  // Asks the visitor at a stage boundary; false ends the pipeline there.
  const auto proceed = [&](Remeshing_stage stage, double fraction) {
    Remeshing_progress p;
    p.stage = stage;
    p.fraction = fraction;
    if(!visitor.keep_going(p)) stats.cancelled = true;
    return !stats.cancelled;
  };
  const auto finish = [&]() {
    if(num_faces(output) > 0) {
      const internal::Component_accounting accounting =
          internal::missing_components(input, output, std::sqrt(3.) * stats.initial_mesh.cube_size);
      stats.input_components = accounting.input_components;
      stats.input_components_missing = accounting.missing;
      stats.largest_missing_component = accounting.largest_missing_diameter;
    }
    stats.seconds = seconds_since(start);
    return stats;
  };

  // Zero-area input faces have no orientation to sign the cube corners
  // with, and leaving them out cuts the patches of chapter 4 apart (holes in
  // a closed input): the stages see a copy without them.
  const TriangleMesh* surface = &input;
  TriangleMesh repaired;
  std::size_t degenerate = 0;
  for(auto f : faces(input)) degenerate += Polygon_mesh_processing::is_degenerate_triangle_face(f, input);
  if(degenerate > 0) {
    copy_face_graph(input, repaired);
    Polygon_mesh_processing::remove_degenerate_faces(repaired);
    internal::collect_garbage_of(repaired, 0);
    if(num_faces(repaired) > 0 && is_triangle_mesh(repaired)) {
      surface = &repaired;
      stats.degenerate_faces_removed = degenerate;
    }
  }

  try {  // whatever throws, no partial mesh is left behind
    // Chapter 4: the initial mesh, certified in [35.26, 90] by construction.
    if(!proceed(Remeshing_stage::initial_mesh, 0.)) return finish();
    visitor.stage_started(Remeshing_stage::initial_mesh);
    auto stage_start = Clock::now();
    const auto build = [&](int resolution, TriangleMesh& mesh) {
      return nonobtuse_marching_cubes(
          *surface, mesh,
          parameters::combine(parameters::resolution(resolution), parameters::sign_source(signs),
                              parameters::memory_budget(budget)));
    };
    stats.initial_mesh = build(stats.resolution, output);
    if(stats.target_vertices > 0) {
      // off by more than 10%: once more at the resolution scaled by the
      // square root of the miss, kept if it builds a mesh
      const double ratio = double(stats.target_vertices) / double((std::max)(std::size_t(1), vertices(output).size()));
      const int redone =
          int(std::lround((std::min)(1024., (std::max)(1., double(stats.resolution) * std::sqrt(ratio)))));
      if((ratio < 1. / 1.1 || ratio > 1.1) && redone != stats.resolution) {
        TriangleMesh second;
        Marching_cubes_result r;
        bool built = true;
        try {
          r = build(redone, second);
        } catch(const Bad_input&) {
          built = false;
        }
        if(built && num_faces(second) > 0) {
          r.seconds += stats.initial_mesh.seconds;
          stats.initial_mesh = std::move(r);
          stats.trial_resolution = stats.resolution;
          stats.resolution = redone;
          output = std::move(second);
        }
      }
    }
    stats.initial_mesh.patch_faces.clear();
    stats.initial_mesh.face_patch.clear();
    if(num_faces(output) == 0)
      throw Bad_input("the initial mesh is empty: the input is too small or too thin for resolution " +
                                  std::to_string(stats.resolution));
    visitor.stage_finished(Remeshing_stage::initial_mesh, seconds_since(stage_start));
    if(last == Remeshing_stage::initial_mesh) return finish();

    // Section 5.7: bad valences out.
    if(valence_cleanup) {
      if(!proceed(Remeshing_stage::valence, 0.)) return finish();
      visitor.stage_started(Remeshing_stage::valence);
      stage_start = Clock::now();
      stats.valence = remove_bad_valence_vertices(
          output, parameters::combine(
                      parameters::vertex_split(choose_parameter(get_parameter(np, internal_np::vertex_split), true)),
                      parameters::drum_subdivisions(k)));
      stats.valence_run = true;
      internal::collect_garbage_of(output, 0);
      visitor.stage_finished(Remeshing_stage::valence, seconds_since(stage_start));
      if(last == Remeshing_stage::valence) return finish();
    }

    // Chapter 5: deform-to-fit, with the caller's fit parameters (the relay
    // takes the place of a fit_visitor among them).
    if(!proceed(Remeshing_stage::fit, 0.)) return finish();
    visitor.stage_started(Remeshing_stage::fit);
    stage_start = Clock::now();
    internal::Fit_progress_relay<std::remove_reference_t<decltype(visitor)> > relay{&visitor};
    stats.fit = deform_to_fit(output, *surface,
                              parameters::combine(np, parameters::fit_visitor(std::ref(relay)),
                                                  CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, output))));
    stats.fit_run = true;
    if(stats.fit.cancelled) stats.cancelled = true;
    visitor.stage_finished(Remeshing_stage::fit, seconds_since(stage_start));
    return finish();
  } catch(...) {
    clear(output);
    throw;
  }
}

} // namespace internal

/// \ingroup PkgNonobtuseRemeshingRef
/// Remeshes `input` (any triangle mesh: open or closed, any genus, several
/// components) into `output`, whose every angle lies in [30, 90] degrees,
/// certified exactly: nonobtuse Marching Cubes (`nonobtuse_marching_cubes()`),
/// then the removal of bad-valence vertices (`remove_bad_valence_vertices()`),
/// then deform-to-fit (`deform_to_fit()`). Each stage certifies every
/// change it makes, so `output` is certified whenever this function
/// returns, also when the visitor cancels. `output` is cleared first and
/// has no garbage at the end. If `input` has zero-area faces, the stages
/// work on a copy from which CGAL's `remove_degenerate_faces()` removed them
/// (they cannot sign cube corners, and leaving them out would cut the
/// patches of chapter 4 apart). For levels of detail, pass `output` to
/// `angle_bounded_decimation_hierarchy()`.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{resolution} cubes along the longest side of the bounding box, in [1, 1024];
///     default 100 \cgalParamNEnd
///   \cgalParamNBegin{target_vertices} about this many output vertices; when given and not 0, it
///     replaces `resolution`. The resolution comes from `resolution_for_target_vertices()`; if the
///     initial mesh misses the target by more than 10%, it is rebuilt once at the resolution scaled
///     by the square root of the ratio (and the first one kept if that fails) \cgalParamNEnd
///   \cgalParamNBegin{sign_source} corner signs of the Marching Cubes; default `Sign_source::patches` \cgalParamNEnd
///   \cgalParamNBegin{memory_budget} see `nonobtuse_marching_cubes()` \cgalParamNEnd
///   \cgalParamNBegin{valence_cleanup} run the removal of bad-valence vertices; default true \cgalParamNEnd
///   \cgalParamNBegin{vertex_split} see `remove_bad_valence_vertices()`; default true \cgalParamNEnd
///   \cgalParamNBegin{stop_after} the last stage to run; default `Remeshing_stage::fit` \cgalParamNEnd
///   \cgalParamNBegin{alpha, drum_subdivisions, quadric_rings, smoothing_steps, fit_tolerance,
///     max_moves, max_seconds, lazy_evaluation, early_smoothing, tangential_smoothing,
///     attract_features} see `deform_to_fit()` (the drum subdivisions serve the valence stage
///     too) \cgalParamNEnd
///   \cgalParamNBegin{remeshing_visitor} progress and cancellation, see `Default_remeshing_visitor`
///     (pass `std::ref(visitor)` to keep its state); it sees the fit's progress, so a `fit_visitor`
///     among the parameters is not used \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `input`; default its internal point map \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// `np_out` may hold the `vertex_point_map` of `output`. When either map is given, the stages
/// run on copies whose points are in their internal point maps, and the result is copied
/// into `output` through its map. The points must have double coordinates (see
/// `deform_to_fit()`).
///
/// Throws `Bad_parameter` if a parameter is out of range, and `Bad_input` if
/// `input` is not a non-empty triangle mesh with some size or if its initial
/// mesh is empty (an input too small or too thin for the resolution) or over
/// the memory budget (`Memory_budget_exceeded`); `output` is then empty, as
/// after any exception.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename OutputNamedParameters = CGAL::parameters::Default_named_parameters>
Nonobtuse_remeshing_statistics nonobtuse_remesh(const TriangleMesh& input, TriangleMesh& output,
                                                const NamedParameters& np = CGAL::parameters::default_values(),
                                                const OutputNamedParameters& np_out = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_point_t>::value &&
               CGAL::parameters::is_default_parameter<OutputNamedParameters, CGAL::internal_np::vertex_point_t>::value) {
    return internal::nonobtuse_remesh_pipeline(input, output, np);
  } else {
    TriangleMesh in, out;
    copy_face_graph(input, in,
                    CGAL::parameters::vertex_point_map(choose_parameter(
                        get_parameter(np, CGAL::internal_np::vertex_point),
                        get_const_property_map(CGAL::vertex_point, input))));
    clear(output);
    const Nonobtuse_remeshing_statistics stats = internal::nonobtuse_remesh_pipeline(in, out, np);
    copy_face_graph(out, output, CGAL::parameters::default_values(),
                    CGAL::parameters::vertex_point_map(choose_parameter(
                        get_parameter(np_out, CGAL::internal_np::vertex_point),
                        get_property_map(CGAL::vertex_point, output))));
    return stats;
  }
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_NONOBTUSE_REMESH_H
