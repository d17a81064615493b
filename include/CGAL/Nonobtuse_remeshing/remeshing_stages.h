// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stages of nonobtuse_remesh() and their names, what its visitor is
// told while they run, and the statistics it returns.

#ifndef CGAL_NONOBTUSE_REMESHING_REMESHING_STAGES_H
#define CGAL_NONOBTUSE_REMESHING_REMESHING_STAGES_H

#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>
#include <CGAL/Nonobtuse_remeshing/statistics.h>
#include <CGAL/Nonobtuse_remeshing/visitors.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// The stages of `nonobtuse_remesh()`, in their order.
enum class Remeshing_stage
{
  initial_mesh,  ///< nonobtuse Marching Cubes (chapter 4)
  valence,       ///< removal of bad-valence vertices and vertex splits (5.7)
  fit,           ///< deform-to-fit with constrained Laplacian smoothing (chapter 5)
  decimation     ///< angle-bounded decimation to the target vertex count (chapter 6), when over it
};

/// \ingroup PkgNonobtuseRemeshingRef
/// The short name of `stage` in reports and on the command line: "init",
/// "valence", "fit" or "decimation".
inline const char* stage_name(Remeshing_stage stage)
{
  switch(stage) {
  case Remeshing_stage::initial_mesh: return "init";
  case Remeshing_stage::valence: return "valence";
  case Remeshing_stage::fit: return "fit";
  case Remeshing_stage::decimation: return "decimation";
  }
  return "unknown";
}

/// \ingroup PkgNonobtuseRemeshingRef
/// What `stage` does, in words (the thesis's section).
inline const char* stage_description(Remeshing_stage stage)
{
  switch(stage) {
  case Remeshing_stage::initial_mesh: return "nonobtuse Marching Cubes, chapter 4";
  case Remeshing_stage::valence: return "bad-valence removal and vertex split, section 5.7";
  case Remeshing_stage::fit: return "deform-to-fit, chapter 5";
  case Remeshing_stage::decimation: return "angle-bounded decimation, chapter 6";
  }
  return "unknown";
}

/// \ingroup PkgNonobtuseRemeshingRef
/// The stage whose `stage_name()` is `name`; throws `Bad_parameter` for any
/// other name.
inline Remeshing_stage stage_from_name(const std::string& name)
{
  for(Remeshing_stage stage : {Remeshing_stage::initial_mesh, Remeshing_stage::valence, Remeshing_stage::fit,
                                Remeshing_stage::decimation})
    if(name == stage_name(stage)) return stage;
  throw Bad_parameter("unknown stage '" + name + "': one of init, valence, fit, decimation");
}

/// \ingroup PkgNonobtuseRemeshingRef
/// What a remeshing visitor is told while a stage runs.
struct Remeshing_progress
{
  Remeshing_stage stage = Remeshing_stage::initial_mesh;
  double fraction = -1.;  ///< of the stage done: 0 as it starts; -1 when it cannot be known (during the fit)
  const Deform_to_fit_statistics* fit = nullptr;  ///< during the fit, its statistics so far
  const Angle_bounded_decimation_statistics* decimation = nullptr;  ///< during the decimation, its statistics so far
};

/// \ingroup PkgNonobtuseRemeshingRef
/// The topology of the initial mesh against the input's (beyond the thesis).
/// Each output component belongs to the input component nearest to it. An
/// input component keeps its topology when exactly one output component
/// belongs to it, with its number of border cycles and its Euler
/// characteristic. Input components that cross themselves or each other are
/// compared as one group by components and border cycles only: the output is
/// the surface of their union, whose genus may legitimately differ. The
/// input is the mesh the function received, less its zero-area faces.
struct Topology_comparison
{
  bool compared = false;  ///< false when the initial mesh was not built
  bool matches = false;   ///< no group differs
  std::size_t input_components = 0, input_border_cycles = 0;
  long long input_euler_characteristic = 0;
  std::size_t output_components = 0, output_border_cycles = 0;
  long long output_euler_characteristic = 0;
  std::size_t input_groups = 0;     ///< input components, those that cross each other counted as one
  std::size_t crossing_groups = 0;  ///< groups that cross themselves or each other (Euler characteristic not compared)
  std::size_t groups_differing = 0;
  /// over the groups that differ: |components - 1| + |border cycles - the input's| + |Euler
  /// characteristic - the input's| / 2 rounded up (a part cut off counts 2, a handle closed 1)
  std::size_t mismatch = 0;
  /// over the groups that differ: |border cycles - the input's| (a part of `mismatch`). The
  /// refinement prefers the mesh with the fewest of these first: a hole opened in a closed
  /// surface (or an input border closed) changes what the surface bounds, a part cut off or a
  /// handle closed does not
  std::size_t border_mismatch = 0;
  std::string difference;  ///< the first difference in words; empty when the topology matches
  double seconds = 0.;     ///< spent comparing, over all the initial meshes built, the input's setup included
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Calls `f(name, value)` for every field of `t`, as the `for_each_field()`
/// of statistics.h; `difference` is a string.
template <typename F>
void for_each_field(const Topology_comparison& t, F&& f)
{
  f("compared", t.compared);
  f("matches", t.matches);
  f("input_components", t.input_components);
  f("input_border_cycles", t.input_border_cycles);
  f("input_euler_characteristic", t.input_euler_characteristic);
  f("output_components", t.output_components);
  f("output_border_cycles", t.output_border_cycles);
  f("output_euler_characteristic", t.output_euler_characteristic);
  f("input_groups", t.input_groups);
  f("crossing_groups", t.crossing_groups);
  f("groups_differing", t.groups_differing);
  f("mismatch", t.mismatch);
  f("border_mismatch", t.border_mismatch);
  f("difference", t.difference);
  f("seconds", t.seconds);
}

/// \ingroup PkgNonobtuseRemeshingRef
/// The Hausdorff distance bound of `nonobtuse_remesh()` (beyond the thesis):
/// what was asked, what was measured and whether the bound holds. Distances
/// are fractions of the bounding-box diagonal of the input; a measured
/// distance is CGAL's `bounded_error_symmetric_Hausdorff_distance()` plus
/// its error bound, so the true distance is at most that.
struct Distance_bound_statistics
{
  double max_distance = 0.;        ///< the bound asked for; 0: none
  double measurement_error = 0.;   ///< the error bound of each measurement (a fiftieth of the bound)
  double fitted_distance = 0.;     ///< measured on the fitted mesh kept
  double distance = 0.;            ///< measured on the output
  bool met = false;                ///< `distance` is at most `max_distance`
  int refinements = 0;             ///< finer grids built because the fitted mesh was over the bound
  std::size_t levels = 0;          ///< decimation levels kept as candidates, the fitted mesh included
  int holds = 0;                   ///< decimation passes run again with vertices held where a level went over
  std::size_t measurements = 0;    ///< Hausdorff distances measured
  double seconds = 0.;             ///< spent measuring
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Calls `f(name, value)` for every field of `d`, as the `for_each_field()`
/// of statistics.h.
template <typename F>
void for_each_field(const Distance_bound_statistics& d, F&& f)
{
  f("max_distance", d.max_distance);
  f("measurement_error", d.measurement_error);
  f("fitted_distance", d.fitted_distance);
  f("distance", d.distance);
  f("met", d.met);
  f("refinements", d.refinements);
  f("holds", d.holds);
  f("levels", d.levels);
  f("measurements", d.measurements);
  f("seconds", d.seconds);
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Statistics of `nonobtuse_remesh()`: those of each stage that ran (the
/// thesis's Tables 4.1, 7.1 and 7.2) and the resolution used.
struct Nonobtuse_remeshing_statistics
{
  int resolution = 0;                      ///< cubes along the longest side of the initial mesh kept
  std::size_t target_vertices = 0;         ///< 0 unless the resolution was chosen for a vertex count
  double oversampling = 1.;                ///< with a target: the initial mesh was built for this many times its vertices
  int trial_resolution = 0;                ///< with a target: the first resolution tried if it was redone, else 0
  int budget_resolution = 0;               ///< the resolution given, or chosen for the target, before any refinement
  bool keep_topology = false;              ///< finer initial meshes were allowed until the topology matched
  int max_resolution = 0;                  ///< the cap of that refinement
  int refinements = 0;                     ///< finer initial meshes built for the topology
  /// the vertex count the decimation stage aims at: the target; with a resolution, the vertices of
  /// its initial mesh when a finer one was kept for the topology (so that the output keeps the
  /// size the resolution gives); else 0
  std::size_t decimation_target = 0;
  Topology_comparison topology;            ///< of the initial mesh kept
  std::size_t degenerate_faces_removed = 0; ///< zero-area input faces removed from a copy of the input first
  Marching_cubes_result initial_mesh;      ///< Table 4.1 (its face maps are left empty)
  bool valence_run = false;
  Bad_valence_removal_statistics valence;  ///< Table 7.1
  bool fit_run = false;
  Deform_to_fit_statistics fit;            ///< Table 7.2
  bool decimation_run = false;
  Angle_bounded_decimation_statistics decimation;  ///< from the fitted mesh to the target vertex count or distance bound
  Distance_bound_statistics distance;      ///< with `max_distance`
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

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_REMESHING_STAGES_H
