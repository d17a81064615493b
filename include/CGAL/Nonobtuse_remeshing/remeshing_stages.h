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
  fit            ///< deform-to-fit with constrained Laplacian smoothing (chapter 5)
};

/// \ingroup PkgNonobtuseRemeshingRef
/// The short name of `stage` in reports and on the command line: "init",
/// "valence" or "fit".
inline const char* stage_name(Remeshing_stage stage)
{
  switch(stage) {
  case Remeshing_stage::initial_mesh: return "init";
  case Remeshing_stage::valence: return "valence";
  case Remeshing_stage::fit: return "fit";
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
  }
  return "unknown";
}

/// \ingroup PkgNonobtuseRemeshingRef
/// The stage whose `stage_name()` is `name`; throws `Bad_parameter` for any
/// other name.
inline Remeshing_stage stage_from_name(const std::string& name)
{
  for(Remeshing_stage stage : {Remeshing_stage::initial_mesh, Remeshing_stage::valence, Remeshing_stage::fit})
    if(name == stage_name(stage)) return stage;
  throw Bad_parameter("unknown stage '" + name + "': one of init, valence, fit");
}

/// \ingroup PkgNonobtuseRemeshingRef
/// What a remeshing visitor is told while a stage runs.
struct Remeshing_progress
{
  Remeshing_stage stage = Remeshing_stage::initial_mesh;
  double fraction = -1.;  ///< of the stage done: 0 as it starts; -1 when it cannot be known (during the fit)
  const Deform_to_fit_statistics* fit = nullptr;  ///< during the fit, its statistics so far
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

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_REMESHING_STAGES_H
