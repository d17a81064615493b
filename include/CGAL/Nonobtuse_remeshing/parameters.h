// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of the Nonobtuse_remeshing package.
//
// CGAL 5.5's Named_function_parameters accepts any type as a tag, so the package
// defines its own tags here, a `parameters` namespace of free functions that
// create them, and `combine()` to chain them with CGAL's own named parameters
// (CGAL 5.5 has no member for that; CGAL functions ignore tags they do not know).
//
//   namespace NR = CGAL::Nonobtuse_remeshing;
//   NR::certify_angle_bounds(mesh, NR::parameters::combine(
//       NR::parameters::min_angle(35.), CGAL::parameters::vertex_point_map(vpm)));

#ifndef CGAL_NONOBTUSE_REMESHING_PARAMETERS_H
#define CGAL_NONOBTUSE_REMESHING_PARAMETERS_H

#include <CGAL/Nonobtuse_remeshing/internal/named_parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <functional>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal_np {

#define CGAL_NONOBTUSE_TAGS(X)                                                  \
  X(min_angle_t, min_angle)               /* lower angle bound, degrees */      \
  X(max_angle_t, max_angle)               /* upper angle bound, degrees */      \
  X(hausdorff_relative_error_t,                                                 \
    hausdorff_relative_error)             /* Hausdorff error, fraction of diag*/\
  X(maximum_self_intersections_t,                                               \
    maximum_self_intersections)           /* cap on reported face pairs */      \
  X(resolution_t, resolution)             /* cubes along the longest side */    \
  X(sign_source_t, sign_source)           /* Marching Cubes corner signs */     \
  X(alpha_t, alpha)                       /* fit vs smoothness weight */        \
  X(drum_subdivisions_t, drum_subdivisions) /* k of the drum planes */          \
  X(quadric_rings_t, quadric_rings)       /* r of the fitting quadric */        \
  X(smoothing_steps_t, smoothing_steps)   /* constrained smoothing passes */    \
  X(fit_tolerance_t, fit_tolerance)       /* stop below this improvement */     \
  X(max_moves_t, max_moves)               /* budget in moves */                 \
  X(max_seconds_t, max_seconds)           /* budget in seconds */               \
  X(lazy_evaluation_t, lazy_evaluation)   /* thesis 5.6 */                      \
  X(early_smoothing_t, early_smoothing)   /* thesis 5.6 */                      \
  X(tangential_smoothing_t, tangential_smoothing) /* S along the input only */  \
  X(attract_features_t, attract_features) /* input tips and creases hold */     \
  X(distance_guard_t, distance_guard)     /* the fit ends no farther */         \
  X(fill_border_notches_t, fill_border_notches) /* border staircases filled */  \
  X(free_stuck_vertices_t, free_stuck_vertices) /* moved with their rings */    \
  X(balance_distance_t, balance_distance) /* the mesh straddles the input */    \
  X(fit_visitor_t, fit_visitor)           /* progress and cancellation */      \
  X(vertex_split_t, vertex_split)         /* splits after removal */        \
  X(target_vertices_t, target_vertices)   /* vertices of the result */       \
  X(vertex_ratio_t, vertex_ratio)         /* decimation: fraction to keep */ \
  X(max_error_t, max_error)               /* decimation: fraction of diag */ \
  X(min_interior_valence_t,                                                     \
    min_interior_valence)                 /* decimation: valence floor */    \
  X(min_border_valence_t,                                                       \
    min_border_valence)                   /* decimation: valence floor */    \
  X(decimation_visitor_t, decimation_visitor) /* progress, cancellation */ \
  X(relaxation_t, relaxation)             /* decimation: fit between rounds */ \
  X(valence_cleanup_t, valence_cleanup)   /* pipeline: run section 5.7 */    \
  X(stop_after_t, stop_after)             /* pipeline: last stage to run */  \
  X(remeshing_visitor_t, remeshing_visitor) /* pipeline: progress, cancel */ \
  X(memory_budget_t, memory_budget)       /* bytes the initial mesh may use */ \
  X(number_of_threads_t, number_of_threads) /* workers, 0: one per core */ \
  X(keep_topology_t, keep_topology)       /* pipeline: refine the grid */    \
  X(max_resolution_t, max_resolution)     /* pipeline: refinement cap */    \
  X(oversampling_t, oversampling)         /* pipeline: initial / target */ \
  X(max_distance_t, max_distance)         /* pipeline: Hausdorff bound */

#define CGAL_NONOBTUSE_DECLARE_TAG(TAG, NAME) enum TAG { NAME };
CGAL_NONOBTUSE_TAGS(CGAL_NONOBTUSE_DECLARE_TAG)
#undef CGAL_NONOBTUSE_DECLARE_TAG

} // namespace internal_np

namespace parameters {

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::default_values;
using CGAL::parameters::get_parameter_reference;

#define CGAL_NONOBTUSE_DECLARE_FUNCTION(TAG, NAME)                              \
  template <typename T>                                                         \
  Named_function_parameters<T, internal_np::TAG> NAME(const T& value)           \
  {                                                                             \
    return Named_function_parameters<T, internal_np::TAG>(value);               \
  }
CGAL_NONOBTUSE_TAGS(CGAL_NONOBTUSE_DECLARE_FUNCTION)
#undef CGAL_NONOBTUSE_DECLARE_FUNCTION

/// Combines named-parameter chains, this package's and CGAL's, into one.
/// When a tag appears twice, the value from the later argument wins.
template <typename NP>
const NP& combine(const NP& np) { return np; }

template <typename NP1, typename NP2, typename... NPs>
auto combine(const NP1& np1, const NP2& np2, const NPs&... nps)
{
  return combine(internal::append(np1, np2), nps...);
}

} // namespace parameters

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#undef CGAL_NONOBTUSE_TAGS

#endif // CGAL_NONOBTUSE_REMESHING_PARAMETERS_H
