// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pipeline behind nonobtuse_remesh(): the initial mesh (thesis, chapter
// 4), refined until its topology is the input's (beyond the thesis), the
// removal of bad-valence vertices (5.7), deform-to-fit (chapter 5) and, when
// the mesh is over the target vertex count, angle-bounded decimation to it
// (chapter 6), on meshes whose points are in their internal point maps, with
// one visitor for progress and cancellation across the stages.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_REMESHING_PIPELINE_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_REMESHING_PIPELINE_H

#include <CGAL/Nonobtuse_remeshing/deform_to_fit.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/Angle_bounded_decimation.h>
#include <CGAL/Nonobtuse_remeshing/internal/distance_bounded_decimation.h>
#include <CGAL/Nonobtuse_remeshing/internal/distance_measures.h>
#include <CGAL/Nonobtuse_remeshing/internal/mesh_helpers.h>
#include <CGAL/Nonobtuse_remeshing/internal/missing_components.h>
#include <CGAL/Nonobtuse_remeshing/internal/parallel.h>
#include <CGAL/Nonobtuse_remeshing/internal/topology_comparison.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>
#include <CGAL/Nonobtuse_remeshing/remeshing_stages.h>
#include <CGAL/Nonobtuse_remeshing/remove_bad_valence_vertices.h>
#include <CGAL/Nonobtuse_remeshing/resolution_for_target_vertices.h>

#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// With a target vertex count, the initial mesh can be built for more
// vertices, fitted, then decimated to the target, so that the decimation puts
// the vertices where the surface needs them. Measured at 10,000 vertices on
// CGAL's 17 sample meshes (see the manual), 2 lowers the Hausdorff distance
// on curved inputs by up to half, but the regular right-angle grids of CAD
// parts hardly decimate (cube-meshed 1.2% -> 1.9%; cylinder stops over the
// target at its error ceiling), so the default builds for the target itself.
constexpr double default_oversampling = 1.;

// Each refinement of the initial mesh multiplies the resolution by this: 1.56
// times the vertices, so that the first resolution that keeps the topology
// is found close to the one the budget gave.
constexpr double refinement_factor = 1.25;

// With a distance bound d, the first initial mesh has cubes of 5 d (but at
// least 16 cubes along the longest side, unless cubes of 1.25 d are fewer).
// The fitted mesh's Hausdorff distance to the input, measured at 10,000
// vertices on CGAL's 17 sample meshes, is 0.13 to 0.8 cubes on curved
// inputs and up to 1.35 cubes at the border corners and sharp edges of CAD
// parts, roughly in proportion to the cube. While the fitted mesh is over
// 0.8 d (within d but with little room left for the decimation, or over
// it) the grid is refined by the ratio that should bring it to 0.6 d (1.25
// to 2.5 times the resolution), up to 4 times the resolution of cubes of
// 1.25 d; a finer grid that fits no closer ends the refinement only from
// that resolution on (the distance at border corners does not fall with the
// cube at every step). Coarse to fine because a finer fitted mesh decimates
// less far: the decimation's quadrics sum more planes per area, so its
// ceiling stops it sooner. Measured at d = 0.2%, before the decimation's
// holds: sphere, blobby and knot1 end at 2,531, 31,802 and 7,608 vertices,
// where the first grid of cubes of 1.25 d (130,000 to 300,000 vertices)
// ended at 130,386, 100,190 and 143,810.
constexpr double first_cubes_per_distance = 5., finest_cubes_per_distance = 1.25;
constexpr int coarsest_first_resolution = 16;
constexpr double distance_room = 0.8, distance_aim = 0.6;

// The resolution whose cube is `cubes` times `max_distance`, a fraction of
// `diagonal`.
template <typename TriangleMesh>
int resolution_for_max_distance(const TriangleMesh& input, double max_distance, double diagonal, double cubes)
{
  const double longest = longest_side_of_faces(input, get(CGAL::vertex_point, input));
  return int((std::min)(1024., std::ceil(longest / (cubes * max_distance * diagonal))));
}

inline void describe_progress(Remeshing_progress& p, const Deform_to_fit_statistics& s)
{
  p.stage = Remeshing_stage::fit;
  p.fit = &s;
}
inline void describe_progress(Remeshing_progress& p, const Angle_bounded_decimation_statistics& s)
{
  p.stage = Remeshing_stage::decimation;
  p.decimation = &s;
}

// The parameters of nonobtuse_remesh(), read and checked, and its visitor
// behind fixed types: what the pipeline's core needs.
struct Remeshing_settings
{
  Remeshing_stage last = Remeshing_stage::decimation;
  bool valence_cleanup = true;
  bool vertex_split = true;
  int drum_subdivisions = 2;
  Deform_to_fit_options fit;
  int quadric_rings = 0;
  std::size_t target_vertices = 0;
  double max_distance = 0.;
  double oversampling = default_oversampling;
  int resolution = 100;  // when neither a target nor a distance gives it
  bool keep_topology = false;
  int max_resolution = 0;
  Angle_bounded_decimation_options decimation;
  bool has_max_error = false;
  Sign_source signs = Sign_source::automatic;
  double memory_budget = default_memory_budget;
  int threads = 0;
  std::function<bool(const Remeshing_progress&)> keep_going;
  std::function<void(Remeshing_stage)> stage_started;
  std::function<void(Remeshing_stage, double)> stage_finished;
};

// The pipeline of nonobtuse_remesh() on meshes whose points are in their
// internal point maps, once its parameters are read: one instantiation per
// mesh type, whatever the parameters and the visitor.
template <typename TriangleMesh>
Nonobtuse_remeshing_statistics nonobtuse_remesh_with(const TriangleMesh& input, TriangleMesh& output,
                                                     const Remeshing_settings& settings)
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto seconds_since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  clear(output);
  Nonobtuse_remeshing_statistics stats;
  stats.target_vertices = settings.target_vertices;
  stats.oversampling = settings.oversampling;
  // with a target, the initial mesh is built for `oversampling` times its vertices
  const std::size_t initial_vertices = std::size_t(std::llround(stats.oversampling * double(stats.target_vertices)));
  const double input_diagonal = bbox_diagonal(input);
  stats.distance.max_distance = settings.max_distance;
  stats.distance.measurement_error = settings.max_distance / 50.;
  // with a distance bound, the resolution whose fitted mesh no longer needs to come closer
  const int settled_resolution =
      settings.max_distance > 0.
          ? resolution_for_max_distance(input, settings.max_distance, input_diagonal, finest_cubes_per_distance)
          : 0;
  stats.resolution =
      stats.target_vertices > 0 ? resolution_for_target_vertices(input, initial_vertices)
      : settings.max_distance > 0.
          ? (std::max)(resolution_for_max_distance(input, settings.max_distance, input_diagonal, first_cubes_per_distance),
                       (std::min)(coarsest_first_resolution, settled_resolution))
          : settings.resolution;
  if(stats.resolution < 1 || stats.resolution > 1024)
    throw Bad_parameter("the resolution must lie in [1, 1024]");
  stats.keep_topology = settings.keep_topology;
  stats.decimation_target = stats.target_vertices;

  // Asks the visitor at a stage boundary; false ends the pipeline there.
  const auto proceed = [&](Remeshing_stage stage, double fraction) {
    Remeshing_progress p;
    p.stage = stage;
    p.fraction = fraction;
    if(!settings.keep_going(p)) stats.cancelled = true;
    return !stats.cancelled;
  };
  // The fit's and the decimation's progress, relayed to the visitor.
  auto relay = keep_going_relay([&settings](const auto& s) {
    Remeshing_progress p;
    describe_progress(p, s);
    return settings.keep_going(p);
  });
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
    const auto build = [&](int resolution, TriangleMesh& mesh) {
      return nonobtuse_marching_cubes(
          *surface, mesh,
          parameters::combine(parameters::resolution(resolution), parameters::sign_source(settings.signs),
                              parameters::memory_budget(settings.memory_budget),
                              parameters::number_of_threads(settings.threads)));
    };
    double building = 0., comparing = 0.;  // over all the initial meshes built
    std::size_t budget_vertices = 0;       // of the first initial mesh
    // Chapter 4: the initial mesh at `resolution`, certified in [35.26, 90]
    // by construction (0: the first, from the parameters). Beyond the
    // thesis, its topology is compared with the input's and, with
    // keep_topology, finer grids are built while it differs (parts thinner
    // than a cube cut off, holes opened), up to the cap; the mesh kept is the
    // first that matches, else the one with the fewest border differences,
    // then the smallest mismatch (the coarsest among those). False when the
    // visitor cancels.
    const auto initial_stage = [&](int resolution) {
      if(!proceed(Remeshing_stage::initial_mesh, 0.)) return false;
      settings.stage_started(Remeshing_stage::initial_mesh);
      const auto stage_start = Clock::now();
      if(resolution == 0) {
        stats.initial_mesh = build(stats.resolution, output);
        if(stats.target_vertices > 0) {
          // off by more than 10%: once more at the resolution scaled by the
          // square root of the miss, kept if it builds a mesh
          const double ratio = double(initial_vertices) / double((std::max)(std::size_t(1), vertices(output).size()));
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
        if(num_faces(output) == 0)
          throw Bad_input("the initial mesh is empty: the input is too small or too thin for resolution " +
                          std::to_string(stats.resolution));
        stats.budget_resolution = stats.resolution;
        budget_vertices = vertices(output).size();
        if(stats.keep_topology || settings.max_distance > 0.)  // a cap below the resolution: no refinement
          stats.max_resolution =
              (std::max)(stats.resolution,
                         settings.max_resolution > 0
                             ? settings.max_resolution
                             : (std::min)(1024, settings.max_distance > 0. ? 4 * settled_resolution
                                                                           : 2 * stats.resolution));
      } else {
        TriangleMesh finer;
        Marching_cubes_result r = build(resolution, finer);
        if(num_faces(finer) == 0) throw Bad_input("the finer initial mesh is empty");
        stats.initial_mesh = std::move(r);
        stats.resolution = resolution;
        output = std::move(finer);
      }
      building += stats.initial_mesh.seconds;
      {
        Thread_pool pool(settings.threads);
        // the automatic signs tested the input for self-intersections already
        Topology_comparator<TriangleMesh> topology(
            *surface, pool, settings.signs != Sign_source::automatic || stats.initial_mesh.self_intersecting_input);
        stats.topology = topology.compare(output);
        comparing += topology.setup_seconds() + stats.topology.seconds;
        for(int r = stats.resolution; stats.keep_topology && !stats.topology.matches;) {
          r = (std::min)(stats.max_resolution, int(std::ceil(refinement_factor * r)));
          if(r <= stats.resolution || !proceed(Remeshing_stage::initial_mesh, 0.)) break;
          TriangleMesh finer;
          Marching_cubes_result built;
          try {
            built = build(r, finer);
          } catch(const Bad_input&) {
            break;  // over the memory budget, or a grid too fine for the input: the mesh kept so far stands
          }
          ++stats.refinements;
          building += built.seconds;
          Topology_comparison t = topology.compare(finer);
          comparing += t.seconds;
          if(t.matches || std::make_pair(t.border_mismatch, t.mismatch) <
                              std::make_pair(stats.topology.border_mismatch, stats.topology.mismatch)) {
            stats.initial_mesh = std::move(built);
            stats.resolution = r;
            stats.topology = std::move(t);
            output = std::move(finer);
          }
          if(stats.topology.matches || r == stats.max_resolution) break;
        }
        // a resolution sets the size: a finer mesh kept is decimated back to it
        if(stats.target_vertices == 0 && settings.max_distance == 0. && stats.resolution > stats.budget_resolution)
          stats.decimation_target = budget_vertices;
      }
      stats.initial_mesh.seconds = building;
      stats.topology.seconds = comparing;
      stats.initial_mesh.patch_faces.clear();
      stats.initial_mesh.face_patch.clear();
      settings.stage_finished(Remeshing_stage::initial_mesh, seconds_since(stage_start));
      return !stats.cancelled;
    };

    // Section 5.7, then chapter 5, on the initial mesh; false when the
    // pipeline ends here (the last stage asked for, or a cancel).
    double fitting = 0.;  // over all the fits run
    const auto valence_and_fit_stages = [&]() {
      if(settings.last == Remeshing_stage::initial_mesh) return false;
      // Section 5.7: bad valences out.
      if(settings.valence_cleanup) {
        if(!proceed(Remeshing_stage::valence, 0.)) return false;
        settings.stage_started(Remeshing_stage::valence);
        const auto stage_start = Clock::now();
        stats.valence = remove_bad_valence_vertices(
            output, parameters::combine(
                        parameters::vertex_split(settings.vertex_split),
                        parameters::drum_subdivisions(settings.drum_subdivisions)));
        stats.valence_run = true;
        internal::collect_garbage_of(output, 0);
        settings.stage_finished(Remeshing_stage::valence, seconds_since(stage_start));
        if(settings.last == Remeshing_stage::valence) return false;
      }
      // Chapter 5: deform-to-fit, with the caller's fit parameters (the
      // relay takes the place of a fit_visitor among them).
      if(!proceed(Remeshing_stage::fit, 0.)) return false;
      settings.stage_started(Remeshing_stage::fit);
      const auto stage_start = Clock::now();
      stats.fit = deform_to_fit_with(output, get(CGAL::vertex_point, output), *surface,
                                     get_const_property_map(CGAL::vertex_point, *surface), settings.fit,
                                     settings.quadric_rings, keep_going_function<Deform_to_fit_statistics>(relay));
      if(stats.fit.border_fills_undone) internal::collect_garbage_of(output, 0);  // the fills removed
      fitting += stats.fit.seconds;
      stats.fit.seconds = fitting;
      stats.fit_run = true;
      if(stats.fit.cancelled) stats.cancelled = true;
      settings.stage_finished(Remeshing_stage::fit, seconds_since(stage_start));
      return settings.last != Remeshing_stage::fit && !stats.cancelled;
    };

    if(!initial_stage(0)) return finish();
    bool going_on = valence_and_fit_stages();

    // Beyond the thesis, with a distance bound: the fitted mesh is measured
    // against the input, and rebuilt on finer grids while it has little room
    // under the bound or is over it, up to the cap; the closest is kept.
    Distance_bound_statistics& bound = stats.distance;
    const auto measure = [&](const TriangleMesh& mesh) {
      const auto measure_start = Clock::now();
      const double d = hausdorff_distance_bound(mesh, input, bound.measurement_error * input_diagonal, settings.threads);
      ++bound.measurements;
      bound.seconds += seconds_since(measure_start);
      return d / input_diagonal;
    };
    if(settings.max_distance > 0. && stats.fit_run && !stats.cancelled) {
      double distance = bound.fitted_distance = measure(output);  // of `output`; bound's: of the closest
      // the closest mesh while `output` is a finer one being built or farther
      std::unique_ptr<std::pair<TriangleMesh, Nonobtuse_remeshing_statistics> > closest;
      while(distance > distance_room * settings.max_distance && stats.resolution < stats.max_resolution) {
        const double factor = (std::min)(2.5, (std::max)(1.25, distance / (distance_aim * settings.max_distance)));
        const int resolution = (std::min)(stats.max_resolution, int(std::ceil(factor * stats.resolution)));
        if(!closest) closest = std::make_unique<std::pair<TriangleMesh, Nonobtuse_remeshing_statistics> >(output, stats);
        try {
          if(!initial_stage(resolution)) break;
        } catch(const Bad_input&) {  // over the memory budget, or a grid too fine for the input
          break;
        }
        ++bound.refinements;
        going_on = valence_and_fit_stages();
        if(stats.cancelled) break;
        distance = measure(output);
        if(distance < bound.fitted_distance) {
          bound.fitted_distance = distance;
          closest.reset();
        } else if(stats.resolution >= settled_resolution) {
          break;  // no closer, on a grid fine enough: the closer mesh stays
        }
      }
      if(closest) {  // the times, the measurements and a cancel stay counted
        const Distance_bound_statistics measured = bound;
        const bool cancelled = stats.cancelled;
        output = std::move(closest->first);
        stats = std::move(closest->second);
        bound = measured;
        stats.cancelled = cancelled;
        stats.initial_mesh.seconds = building;
        stats.fit.seconds = fitting;
      }
      bound.distance = bound.fitted_distance;
      bound.met = bound.distance <= settings.max_distance;
    }
    if(!going_on || (settings.max_distance > 0. && !bound.met)) return finish();

    // Chapter 6: a mesh over the target (oversampled, refined for its
    // topology), or refined beyond the resolution given, is decimated to
    // the target or to the resolution's vertex count, with the relaxation fitting it to the
    // input; the collapses keep the topology and the certification. With a
    // distance bound, the coarsest level within it.
    const bool over_target =
        stats.decimation_target > 0 && double(vertices(output).size()) > 1.1 * double(stats.decimation_target);
    if(!(over_target || settings.max_distance > 0.) || !proceed(Remeshing_stage::decimation, 0.)) return finish();
    settings.stage_started(Remeshing_stage::decimation);
    const auto stage_start = Clock::now();
    if(settings.max_distance > 0.) {
      stats.decimation = decimate_within_distance(output, *surface, input_diagonal, settings.decimation,
                                                  settings.has_max_error, relay, bound, measure);
      bound.met = bound.distance <= settings.max_distance;
    } else {
      const auto points = get(CGAL::vertex_point, output);
      const double diagonal = certified_mesh_diagonal(output, points);
      Angle_bounded_decimation_options o = settings.decimation;
      if(!settings.has_max_error) {
        // No collapse moves the surface by more than a cube of the grid the
        // target (or the resolution) alone gives: the error the pipeline
        // makes without decimating.
        const int coarse = stats.target_vertices > 0 ? resolution_for_target_vertices(input, stats.target_vertices)
                                                     : stats.budget_resolution;
        o.max_error = stats.initial_mesh.cube_size * double(stats.resolution) / double(coarse) / diagonal;
      }
      stats.decimation = angle_bounded_decimation_with(
          output, points, o, diagonal, {stats.decimation_target}, *surface, get(CGAL::vertex_point, *surface),
          keep_going_function<Angle_bounded_decimation_statistics>(relay),
          [](std::size_t, bool, const Angle_bounded_decimation_statistics&) {});
      internal::collect_garbage_of(output, 0);
    }
    stats.decimation_run = true;
    if(stats.decimation.stop_reason == Decimation_stop_reason::cancelled) stats.cancelled = true;
    settings.stage_finished(Remeshing_stage::decimation, seconds_since(stage_start));
    return finish();
  } catch(...) {
    clear(output);
    throw;
  }
}

// The parameters of nonobtuse_remesh() read and checked (Bad_parameter for
// one out of range); the settings call `visitor`, which must outlive them.
template <typename NamedParameters, typename Visitor>
Remeshing_settings remeshing_settings(const NamedParameters& np, Visitor& visitor)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Remeshing_settings s;
  s.last = choose_parameter(get_parameter(np, internal_np::stop_after), s.last);
  s.valence_cleanup = choose_parameter(get_parameter(np, internal_np::valence_cleanup), s.valence_cleanup);
  s.vertex_split = choose_parameter(get_parameter(np, internal_np::vertex_split), s.vertex_split);
  s.drum_subdivisions = choose_parameter(get_parameter(np, internal_np::drum_subdivisions), s.drum_subdivisions);
  if(s.last == Remeshing_stage::valence && !s.valence_cleanup)
    throw Bad_parameter("stopping after the valence stage contradicts skipping it");
  s.fit = deform_to_fit_options(np, s.quadric_rings);  // the fit's parameters are checked before any work
  s.target_vertices = choose_parameter(get_parameter(np, internal_np::target_vertices), s.target_vertices);
  s.max_distance = choose_parameter(get_parameter(np, internal_np::max_distance), s.max_distance);
  if(!(s.max_distance >= 0. && s.max_distance <= 1.))
    throw Bad_parameter("the maximum distance must lie in (0, 1], a fraction of the input's diagonal (0: no bound)");
  if(s.max_distance > 0. && s.target_vertices > 0)
    throw Bad_parameter("give one of a target vertex count and a maximum distance");
  if(s.max_distance > 0. && (s.last == Remeshing_stage::initial_mesh || s.last == Remeshing_stage::valence))
    throw Bad_parameter("a maximum distance needs the fit: stop after the fit or the decimation");
  s.oversampling = choose_parameter(get_parameter(np, internal_np::oversampling), s.oversampling);
  if(!(s.oversampling >= 1. && s.oversampling <= 16.))
    throw Bad_parameter("the oversampling must lie in [1, 16]");
  s.resolution = choose_parameter(get_parameter(np, internal_np::resolution), s.resolution);
  s.keep_topology = choose_parameter(get_parameter(np, internal_np::keep_topology), true);
  s.max_resolution = choose_parameter(get_parameter(np, internal_np::max_resolution), s.max_resolution);
  if(s.max_resolution < 0 || s.max_resolution > 1024)
    throw Bad_parameter("the maximum resolution must lie in [1, 1024] (0: twice the resolution)");
  s.decimation = decimation_options(np);
  s.has_max_error = !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::max_error_t>::value;
  s.signs = choose_parameter(get_parameter(np, internal_np::sign_source), s.signs);
  s.memory_budget = choose_parameter(get_parameter(np, internal_np::memory_budget), s.memory_budget);
  if(!(s.memory_budget > 0.)) throw Bad_parameter("the memory budget must be positive");
  s.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), s.threads);
  s.keep_going = keep_going_function<Remeshing_progress>(visitor);
  s.stage_started = [&visitor](Remeshing_stage stage) { visitor.stage_started(stage); };
  s.stage_finished = [&visitor](Remeshing_stage stage, double seconds) { visitor.stage_finished(stage, seconds); };
  return s;
}

// The pipeline of nonobtuse_remesh() on meshes whose points are in their
// internal point maps (any vertex_point_map in `np` is not used).
template <typename TriangleMesh, typename NamedParameters>
Nonobtuse_remeshing_statistics nonobtuse_remesh_pipeline(const TriangleMesh& input, TriangleMesh& output,
                                                         const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  clear(output);
  if(num_faces(input) == 0 || !is_triangle_mesh(input))
    throw Bad_input("nonobtuse_remesh: the input must be a non-empty triangle mesh");
  // a visitor given by value is copied, one given with std::ref is used in place
  auto given = choose_parameter(get_parameter(np, internal_np::remeshing_visitor), Default_remeshing_visitor());
  return nonobtuse_remesh_with(input, output, remeshing_settings(np, visitor_reference(given)));
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

// With NonobtuseRemeshing::Compiled (compiled_surface_mesh.h): the declarations
// of its instantiations; src/compiled/nonobtuse_remesh.cpp defines
// CGAL_NONOBTUSE_REMESHING_INSTANTIATE_PIPELINE, and there they are the instantiations.
#ifdef CGAL_NONOBTUSE_REMESHING_COMPILED
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
#ifndef CGAL_NONOBTUSE_REMESHING_INSTANTIATE_PIPELINE
extern
#endif
template Nonobtuse_remeshing_statistics nonobtuse_remesh_with(const Compiled_mesh&, Compiled_mesh&,
                                                              const Remeshing_settings&);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
#endif

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_REMESHING_PIPELINE_H
