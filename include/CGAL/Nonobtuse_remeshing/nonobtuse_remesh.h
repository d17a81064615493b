// SPDX-License-Identifier: GPL-3.0-or-later
//
// The whole pipeline in one call: the initial mesh (thesis, chapter 4), the
// removal of bad-valence vertices (5.7), deform-to-fit (chapter 5) and, for
// a target vertex count, angle-bounded decimation (chapter 6), with one
// visitor for progress and cancellation across the stages.

#ifndef CGAL_NONOBTUSE_REMESHING_NONOBTUSE_REMESH_H
#define CGAL_NONOBTUSE_REMESHING_NONOBTUSE_REMESH_H

#include <CGAL/Nonobtuse_remeshing/internal/Remeshing_pipeline.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>
#include <CGAL/Nonobtuse_remeshing/remeshing_stages.h>
#include <CGAL/Nonobtuse_remeshing/resolution_for_target_vertices.h>

#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// Remeshes `input` (any triangle mesh: open or closed, any genus, several
/// components) into `output`, whose every angle lies in [30, 90] degrees,
/// certified exactly: nonobtuse Marching Cubes (`nonobtuse_marching_cubes()`),
/// then the removal of bad-valence vertices (`remove_bad_valence_vertices()`),
/// then deform-to-fit (`deform_to_fit()`).
///
/// Beyond the thesis, the topology of the initial mesh is compared with the
/// input's, per input component (`Topology_comparison`, in the statistics).
/// With `keep_topology` (the default), while it differs (parts thinner than a
/// cube cut off, holes opened), the initial mesh is rebuilt at 1.25 times the
/// resolution, up to `max_resolution`; the first mesh that matches is kept,
/// else the one with the fewest differences. With a `target_vertices` count
/// V, the initial mesh is built for `oversampling` times V vertices and the
/// fitted mesh, over V by more than 10%, is decimated to V
/// (`angle_bounded_decimation()`, its relaxation fitting to `input`): the
/// collapses keep the vertices where the surface needs them, and keep the
/// topology. With a `resolution`, a finer initial mesh kept for the topology
/// is decimated back in the same way, to the vertex count of the
/// resolution's own initial mesh (`decimation_target` in the statistics).
/// With a `max_distance` bound instead, the grid comes from the bound, is
/// refined while the fitted mesh has little room under it, and the output is
/// the coarsest decimation level measured within it (`Distance_bound_statistics`).
///
/// Each stage certifies every
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
///     default 100
///     \cgalParamType{`int`} \cgalParamNEnd
///   \cgalParamNBegin{target_vertices} about this many output vertices; when given and not 0, it
///     replaces `resolution`. The resolution comes from `resolution_for_target_vertices()` for
///     `oversampling` times the target; if the initial mesh misses that count by more than 10%, it
///     is rebuilt once at the resolution scaled by the square root of the ratio (and the first one
///     kept if that fails)
///     \cgalParamType{`std::size_t`} \cgalParamNEnd
///   \cgalParamNBegin{max_distance} instead of `resolution` and `target_vertices`, when not 0: the
///     fewest vertices whose symmetric Hausdorff distance to `input` is at most this fraction of
///     its bounding-box diagonal, in (0, 1]. The first grid's cube is 5 times the bound (at least 16
///     cubes along the longest side, unless cubes of 1.25 times the bound are fewer), refined while
///     the fitted mesh is over 0.8 times it; the fitted mesh is then decimated to the coarsest of
///     its levels (10% apart) measured within the bound with CGAL's bounded-error Hausdorff distance
///     (error: a fiftieth of the bound, added to each measurement). `Distance_bound_statistics`
///     says what was measured and whether the bound holds; when it does not (the cap), the output
///     is the closest fitted mesh. Needs the fit (`stop_after` the fit or the decimation)
///     \cgalParamType{`double`} \cgalParamNEnd
///   \cgalParamNBegin{oversampling} with `target_vertices`: the initial mesh is built for this many
///     times the target, in [1, 16]; default 1 (2 fits curved inputs closer, see the manual)
///     \cgalParamType{`double`} \cgalParamNEnd
///   \cgalParamNBegin{keep_topology} refine the initial mesh until its topology is the input's;
///     default true (false: the grid of the `resolution`, or of the `target_vertices` alone)
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{max_resolution} the cap of that refinement and of the one for `max_distance`,
///     in [1, 1024]; default 0: twice the resolution given or chosen for the target (about 4 times
///     the vertices), with `max_distance` four times the resolution of cubes of 1.25 times the
///     bound; a cap below the resolution means no refinement
///     \cgalParamType{`int`} \cgalParamNEnd
///   \cgalParamNBegin{sign_source} corner signs of the Marching Cubes; default `Sign_source::automatic`
///     \cgalParamType{`Sign_source`} \cgalParamNEnd
///   \cgalParamNBegin{memory_budget} see `nonobtuse_marching_cubes()`
///     \cgalParamType{`double`} \cgalParamNEnd
///   \cgalParamNBegin{valence_cleanup} run the removal of bad-valence vertices; default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{vertex_split} see `remove_bad_valence_vertices()`; default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{stop_after} the last stage to run; default `Remeshing_stage::decimation`
///     (which runs only with a `target_vertices` count the fitted mesh exceeds by more than 10%)
///     \cgalParamType{`Remeshing_stage`} \cgalParamNEnd
///   \cgalParamNBegin{alpha, drum_subdivisions, quadric_rings, smoothing_steps, fit_tolerance,
///     max_moves, max_seconds, lazy_evaluation, early_smoothing, tangential_smoothing,
///     attract_features, distance_guard, fill_border_notches, free_stuck_vertices, balance_distance,
///     number_of_threads} see `deform_to_fit()` (the drum subdivisions serve the valence stage
///     too) \cgalParamNEnd
///   \cgalParamNBegin{min_interior_valence, min_border_valence, max_error, relaxation} of the
///     decimation, see `angle_bounded_decimation()`, except that `max_error` defaults to one cube of
///     the grid `resolution_for_target_vertices()` gives for the target (divided by the diagonal),
///     so that no collapse moves the surface further than the pipeline's error without decimating;
///     with `max_distance`, a given `max_error` is the ceiling of a single pass instead of the four
///     passes' rising ones
///     \cgalParamNEnd
///   \cgalParamNBegin{remeshing_visitor} progress and cancellation, see `Default_remeshing_visitor`
///     (pass `std::ref(visitor)` to keep its state); it sees the fit's progress, so a `fit_visitor`
///     among the parameters is not used
///     \cgalParamType{a model of `RemeshingVisitor`} \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `input`; default its internal point map
///     \cgalParamType{a model of `ReadWritePropertyMap` (`ReadablePropertyMap` for a mesh only read) with the vertex descriptors as keys and points with double coordinates as values} \cgalParamNEnd
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
    internal::clear_keeping_maps(output, 0);
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
