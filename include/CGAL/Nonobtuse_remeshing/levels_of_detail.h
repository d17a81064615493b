// SPDX-License-Identifier: GPL-3.0-or-later
//
// Levels of detail (beyond the thesis): each level of the angle-bounded
// decimation hierarchy (chapter 6) against a rebuild of the full mesh at the
// level's vertex count (the pipeline of chapters 4 and 5, then decimation to
// the count), keeping the closer of the two as measured. Decimation is
// adaptive but cannot move the regular right-angle grids that Marching Cubes
// leaves on flat and developable parts (every angle at its bound, every
// edge's feasible region empty), so on CAD parts it reaches a level only by
// collapses that cut creases and corners; a rebuild is uniform but has no
// such limit.

#ifndef CGAL_NONOBTUSE_REMESHING_LEVELS_OF_DETAIL_H
#define CGAL_NONOBTUSE_REMESHING_LEVELS_OF_DETAIL_H

#include <CGAL/Nonobtuse_remeshing/angle_bounded_decimation.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/distance_measures.h>
#include <CGAL/Nonobtuse_remeshing/internal/mesh_helpers.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_remesh.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>

#include <CGAL/boost/graph/copy_face_graph.h>

#include <chrono>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// One level of `levels_of_detail()`: the level of the decimation hierarchy
/// or, where it is closer to the full mesh, the rebuild of the full mesh at
/// the level's vertex count. `statistics` are those of the decimation either
/// way. Distances are symmetric Hausdorff distances to the full mesh, CGAL's
/// bounded-error estimate plus its error bound, as fractions of the full
/// mesh's bounding-box diagonal.
template <typename TriangleMesh>
struct Level_of_detail : Decimation_level<TriangleMesh>
{
  bool rebuilt = false;              ///< `mesh` is the rebuild, not the decimation
  double decimated_distance = -1.;   ///< of the decimation's level
  double rebuilt_distance = -1.;     ///< of the rebuild; -1 when it was not measured (see `rebuild_refused`)
  std::size_t rebuilt_vertices = 0;  ///< of the rebuild; 0 when it failed
  std::string rebuild_refused;       ///< why the rebuild could not be kept; empty when it was compared
  double seconds = 0.;               ///< rebuilding and measuring (the decimation's are in `statistics`)
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Levels of detail of `mesh`, a triangle mesh certified in [30, 90]
/// degrees, at `ratios` of its vertices (decreasing strictly within (0, 1)).
/// The levels of `angle_bounded_decimation_hierarchy()` come first; then
/// each level is compared with a rebuild: `nonobtuse_remesh()` of `mesh` for
/// the level's vertex count with its topology kept (where its initial mesh
/// has more vertices than the level, for a count scaled down by the excess,
/// twice at most), decimated to the level's count if still over it. The rebuild is kept when it has the topology of `mesh`,
/// no more vertices than the decimation's level and a smaller measured
/// Hausdorff distance to `mesh`. Levels are certified as the stages make
/// them, and keep the topology of `mesh`.
///
/// Decimation keeps its vertices where the surface needs them and wins on
/// curved surfaces; the rebuild wins where the decimation has to cut
/// creases: the regular right-angle grids of flat and developable parts.
///
/// Takes the named parameters of `angle_bounded_decimation_hierarchy()`
/// (the rebuild uses its `drum_subdivisions`, `min_interior_valence`,
/// `min_border_valence`, `relaxation` and `number_of_threads`; its
/// `decimation_visitor` sees only the hierarchy), and
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{hausdorff_relative_error} the error bound of each distance measured, as a
///     fraction of the bounding-box diagonal of `mesh`; default 1e-4
///     \cgalParamType{`double`} \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// Throws as `angle_bounded_decimation_hierarchy()` does. The levels after
/// one whose decimation stopped before its target are left out, as there.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<Level_of_detail<TriangleMesh> > levels_of_detail(const TriangleMesh& mesh,
                                                             const std::vector<double>& ratios,
                                                             const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const internal::Angle_bounded_decimation_options o = internal::decimation_options(np);
  const double relative_error = choose_parameter(get_parameter(np, internal_np::hausdorff_relative_error), 1e-4);
  if(!(relative_error > 0. && relative_error < 1.))
    throw Bad_parameter("the Hausdorff relative error must lie in (0, 1)");
  std::vector<Decimation_level<TriangleMesh> > hierarchy = angle_bounded_decimation_hierarchy(mesh, ratios, np);

  // The full mesh with its points in its internal map, as the stages take it.
  TriangleMesh full;
  copy_face_graph(mesh, full,
                  CGAL::parameters::vertex_point_map(choose_parameter(
                      get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, mesh))));
  const double diagonal = internal::bbox_diagonal(full);
  const double error = relative_error * diagonal;
  const auto distance = [&](const TriangleMesh& m) {
    return internal::hausdorff_distance_bound(m, full, error, o.threads) / diagonal;
  };

  std::vector<Level_of_detail<TriangleMesh> > levels;
  for(Decimation_level<TriangleMesh>& d : hierarchy) {
    const auto start = std::chrono::steady_clock::now();
    levels.emplace_back();
    Level_of_detail<TriangleMesh>& level = levels.back();
    static_cast<Decimation_level<TriangleMesh>&>(level) = std::move(d);
    level.decimated_distance = distance(level.mesh);

    TriangleMesh rebuild;
    const auto remesh = [&](std::size_t count, Remeshing_stage last) {
      rebuild = TriangleMesh();
      return nonobtuse_remesh(
          full, rebuild,
          parameters::combine(parameters::target_vertices(count), parameters::keep_topology(true),
                              parameters::stop_after(last), parameters::drum_subdivisions(o.drum_subdivisions),
                              parameters::min_interior_valence(o.min_interior_valence),
                              parameters::min_border_valence(o.min_border_valence),
                              parameters::relaxation(o.relaxation), parameters::number_of_threads(o.threads)));
    };
    try {
      // A grid's vertex count is known once its initial mesh is built (the
      // fit keeps it). Over the level's count, the count asked is scaled down
      // by the excess (twice at most) before the fit runs, rather than
      // decimated: collapses on a regular grid cut its creases.
      std::size_t asked = level.target_vertices;
      for(int probe = 0;; ++probe) {
        const Nonobtuse_remeshing_statistics s = remesh(asked, Remeshing_stage::valence);
        if(!s.topology.matches) {
          level.rebuild_refused = "its topology differs: " + s.topology.difference;
          break;
        }
        // refined for the topology, the pipeline decimates to the count asked
        const std::size_t n = s.refinements > 0 ? asked : vertices(rebuild).size();
        if(n <= level.target_vertices || probe == 2 || asked < 8) break;
        asked = (std::max)(std::size_t(4), std::size_t(double(asked) * double(level.target_vertices) / double(n)));
      }
      if(level.rebuild_refused.empty()) {
        remesh(asked, Remeshing_stage::decimation);
        if(vertices(rebuild).size() > level.target_vertices)
          angle_bounded_decimation(
              rebuild, parameters::combine(parameters::target_vertices(level.target_vertices),
                                           parameters::drum_subdivisions(o.drum_subdivisions),
                                           parameters::min_interior_valence(o.min_interior_valence),
                                           parameters::min_border_valence(o.min_border_valence),
                                           parameters::relaxation(o.relaxation),
                                           parameters::number_of_threads(o.threads)));
        level.rebuilt_vertices = vertices(rebuild).size();
      }
    } catch(const Bad_input& e) {
      level.rebuild_refused = std::string("it failed: ") + e.what();
    }
    if(level.rebuild_refused.empty() && level.rebuilt_vertices > vertices(level.mesh).size())
      level.rebuild_refused = "it has more vertices than the decimation's level";
    if(level.rebuild_refused.empty()) {
      level.rebuilt_distance = distance(rebuild);
      if(level.rebuilt_distance < level.decimated_distance) {
        internal::collect_garbage_of(rebuild, 0);  // the collapses' removed elements
        level.mesh = std::move(rebuild);
        level.rebuilt = true;
        level.reached = vertices(level.mesh).size() <= level.target_vertices;
      }
    }
    level.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return levels;
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_LEVELS_OF_DETAIL_H
