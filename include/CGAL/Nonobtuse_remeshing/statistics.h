// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the stages report: the statistics of the removal of bad-valence
// vertices (the thesis's Table 7.1), of deform-to-fit (Table 7.2) and of
// angle-bounded decimation (chapter 6), also handed to their visitors.

#ifndef CGAL_NONOBTUSE_REMESHING_STATISTICS_H
#define CGAL_NONOBTUSE_REMESHING_STATISTICS_H

#include <CGAL/boost/graph/helpers.h>

#include <cstddef>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// Bad-valence vertices (thesis, section 5.7 and Table 7.1): interior
/// vertices of valence below 5 or above 11 and border vertices of valence
/// below 4 cannot lie flat with every angle in [30, 90] degrees.
struct Valence_counts
{
  std::size_t valence_2 = 0;                  ///< v2 of Table 7.1 (border vertices; interior ones too, if any)
  std::size_t border_valence_3 = 0;           ///< of v3
  std::size_t interior_valence_3 = 0;         ///< of v3
  std::size_t interior_valence_4 = 0;         ///< int-v4
  std::size_t interior_valence_above_11 = 0;  ///< none in a Marching Cubes mesh (its maximum is 10)
  std::size_t valence_3() const { return border_valence_3 + interior_valence_3; }
  std::size_t total() const { return valence_2 + valence_3() + interior_valence_4 + interior_valence_above_11; }
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Counts the bad-valence vertices of `mesh`.
template <typename TriangleMesh>
Valence_counts count_bad_valences(const TriangleMesh& mesh)
{
  Valence_counts c;
  for(auto v : vertices(mesh)) {
    const std::size_t d = degree(v, mesh);
    const bool border = bool(is_border(v, mesh));
    if(d <= 2) ++c.valence_2;
    else if(d == 3) ++(border ? c.border_valence_3 : c.interior_valence_3);
    else if(d == 4 && !border) ++c.interior_valence_4;
    else if(d > 11 && !border) ++c.interior_valence_above_11;
  }
  return c;
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Statistics of `remove_bad_valence_vertices()`: the counts before and
/// after, and the operations done, by case of the thesis's Figure 5.6.
struct Bad_valence_removal_statistics
{
  Valence_counts before, after;
  std::size_t vertices_before = 0, vertices_after = 0;
  std::size_t border_valence_2_discarded = 0;    ///< case (a)
  std::size_t interior_valence_3_discarded = 0;  ///< case (b)
  std::size_t interior_valence_4_discarded = 0;  ///< case (c)
  std::size_t interior_valence_4_collapsed = 0;  ///< case (d)
  std::size_t border_valence_3_discarded = 0;    ///< case (e)
  std::size_t border_valence_3_collapsed = 0;    ///< cases (f) and (g)
  std::size_t border_teeth_removed = 0;          ///< valence-2 and valence-3 border pairs, beyond the thesis
  std::size_t splits = 0;                        ///< vertex splits
  std::size_t refused = 0;  ///< operations allowed by valence but refused by the exact certification
  std::size_t rounds = 0;   ///< rounds of removal then split
  double seconds = 0.;
};

/// \ingroup PkgNonobtuseRemeshingRef
/// What `deform_to_fit()` is doing when it calls its visitor.
enum class Deform_to_fit_stage { optimization, smoothing };

/// \ingroup PkgNonobtuseRemeshingRef
/// Statistics of `deform_to_fit()`, also handed to its visitor while it runs.
struct Deform_to_fit_statistics
{
  Deform_to_fit_stage stage = Deform_to_fit_stage::optimization;
  std::size_t vertices = 0;
  std::size_t feature_samples = 0;    ///< input vertices and sharp or border edge samples attracting the mesh
  std::size_t moves = 0;              ///< applied moves, optimization and smoothing
  std::size_t smoothing_moves = 0;    ///< of which by constrained Laplacian smoothing
  std::size_t qp_solves = 0;
  std::size_t qp_fallbacks = 0;       ///< the fast solver reported trouble: CGAL's solver answered
  std::size_t infeasible_regions = 0; ///< evaluations whose F(v) was empty (the vertex stays)
  std::size_t shortened_moves = 0;    ///< certified only after halving the step
  std::size_t rejected_moves = 0;     ///< no certified step within five halvings: not moved
  std::size_t undone_moves = 0;       ///< certified, but no descent once the closest triangle was updated
  std::size_t full_updates = 0;
  std::size_t smoothing_passes = 0;
  std::size_t intersecting_pairs_found = 0;  ///< self-intersecting face pairs after the fit, before untangling
  std::size_t intersecting_pairs = 0;        ///< self-intersecting face pairs left at the end
  std::size_t untangling_moves = 0;
  double start_distance = 0.;         ///< the distance guard's measure of the mesh as given: the farthest of
                                      ///< the input's feature samples from it and of its vertices from the
                                      ///< input, in % of the input's bounding-box diagonal (0 without the guard)
  double end_distance = 0.;           ///< the same at the end, at most `start_distance` unless
                                      ///< the guard's moves back could not bring it there
  std::size_t guard_moves = 0;        ///< moves back towards the start positions, by the distance guard
  std::size_t border_notches_filled = 0;  ///< notches of the mesh's borders filled with faces (then fitted again)
  std::size_t border_corners_filled = 0;  ///< corners of the input's border the mesh's cut off, filled with an ear
  std::size_t border_vertices_added = 0;  ///< vertices the fills added (one per notch fill with two faces, one per ear)
  bool border_fills_undone = false;       ///< fills were made, but the fit ended farther with them than without: removed
  std::size_t stuck_vertices_freed = 0;   ///< vertices far from the input moved closer together with their one-ring
  /// of those, freed and kept by the last passes, after the distance balance (one-ring and
  /// two-ring passes in up to four rounds; a pass rolled back counts 0)
  std::size_t stuck_vertices_freed_last = 0;
  std::size_t stuck_vertices_freed_two_rings = 0;  ///< of those freed last, freed with their two rings
  /// groups the last passes freed, then put back because their faces crossed others
  std::size_t stuck_vertices_put_back = 0;
  bool stuck_vertices_undone = false;     ///< the guard could not end the fit as close as its start after that: undone
  std::size_t balance_moves = 0;          ///< moves along the normals that make the mesh straddle the input
  double rms_distance = 0.;           ///< root mean square distance of the vertices to the input,
                                      ///< in % of the input's bounding-box diagonal (updated per phase)
  bool budget_exhausted = false;
  bool cancelled = false;
  /// seconds per phase, summed over every run of it (a state the fit rolls back to keeps them)
  double optimization_seconds = 0.;
  double smoothing_seconds = 0.;
  double untangling_seconds = 0.;
  double guard_seconds = 0.;
  double balance_seconds = 0.;
  double seconds = 0.;
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Why a decimation stopped.
enum class Decimation_stop_reason {
  target_reached,    ///< the target vertex count (the last level's) was reached
  max_error,         ///< the cheapest collapse left would exceed `max_error` (thesis, 6.5)
  no_collapse_left,  ///< no collapse left keeps the bounds, the valence floor and the topology
  round_limit,       ///< 64 rounds of collapses and relaxation ran
  cancelled,         ///< the visitor returned false
  max_distance       ///< in `nonobtuse_remesh()` with `max_distance`: a coarser level was measured over the bound
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Statistics of `angle_bounded_decimation()`. Distances are fractions of
/// the bounding-box diagonal of the mesh being decimated.
struct Angle_bounded_decimation_statistics
{
  std::size_t vertices_before = 0, vertices_after = 0, target_vertices = 0;
  std::size_t collapses = 0;
  std::size_t qp_solves = 0;      ///< QPs of the placements (equation 6.4): a drum-free pre-test, then F(u, v)
  std::size_t qp_fallbacks = 0;   ///< solves handed to CGAL's QP solver by the fast path
  std::size_t empty_regions = 0;  ///< placements refused: F(u, v) empty or degenerate
  /// placements left before the whole region, whose cost was over the round's ceiling already
  /// at the form's unconstrained minimum or at the drum-free pre-test
  std::size_t placements_over_ceiling = 0;
  std::size_t valence_refusals = 0;        ///< placements and collapses refused by the valence floor (attempts)
  std::size_t frozen_refusals = 0;  ///< placements refused at a vertex held where a level went over a distance bound
  std::size_t certification_refusals = 0;  ///< collapses refused by the exact certification (attempts)
  std::size_t topology_refusals = 0;       ///< collapses refused by CGAL's topology tests (its fold test reports none)
  std::size_t rounds = 0;            ///< runs of edge_collapse
  std::size_t relaxations = 0;       ///< deform-to-fit runs between rounds
  std::size_t relaxation_moves = 0;  ///< certified moves made by them
  double relaxation_seconds = 0.;
  double largest_collapse_error = 0.;  ///< sqrt of the largest cost collapsed
  /// sqrt of the cheapest cost left when the last round stopped at its ceiling (of a lower bound of
  /// it, for an edge left before its whole region was solved)
  double stopping_error = 0.;
  Decimation_stop_reason stop_reason = Decimation_stop_reason::no_collapse_left;
  double seconds = 0.;
};

/// \ingroup PkgNonobtuseRemeshingRef
/// The name of `reason` in reports: "target reached", "maximum error
/// reached", "no collapse left", "round limit" or "cancelled".
inline const char* stop_reason_name(Decimation_stop_reason reason)
{
  switch(reason) {
  case Decimation_stop_reason::target_reached: return "target reached";
  case Decimation_stop_reason::max_error: return "maximum error reached";
  case Decimation_stop_reason::no_collapse_left: return "no collapse left";
  case Decimation_stop_reason::round_limit: return "round limit";
  case Decimation_stop_reason::cancelled: return "cancelled";
  case Decimation_stop_reason::max_distance: return "distance bound reached";
  }
  return "unknown";
}


/// \ingroup PkgNonobtuseRemeshingRef
/// Calls `f(name, value)` for every field of `c`, in a fixed order, with
/// `name` the field's name in reports (the keys of the tool's JSON report,
/// whose text is made from the same calls); values are numbers, flags, the counts v2, v3 (border and interior), int-v4, int-v12+ and their total.
template <typename F>
void for_each_field(const Valence_counts& c, F&& f)
{
  f("v2", c.valence_2);
  f("v3", c.valence_3());
  f("v3_border", c.border_valence_3);
  f("v3_interior", c.interior_valence_3);
  f("int_v4", c.interior_valence_4);
  f("int_above_11", c.interior_valence_above_11);
  f("total", c.total());
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Calls `f(name, value)` for every field of `s`, in a fixed order, with
/// `name` the field's name in reports (the keys of the tool's JSON report,
/// whose text is made from the same calls); values are numbers, flags, and the `Valence_counts` before and after.
template <typename F>
void for_each_field(const Bad_valence_removal_statistics& s, F&& f)
{
  f("before", s.before);
  f("after", s.after);
  f("vertices_before", s.vertices_before);
  f("vertices_after", s.vertices_after);
  f("border_valence_2_discarded", s.border_valence_2_discarded);
  f("interior_valence_3_discarded", s.interior_valence_3_discarded);
  f("interior_valence_4_discarded", s.interior_valence_4_discarded);
  f("interior_valence_4_collapsed", s.interior_valence_4_collapsed);
  f("border_valence_3_discarded", s.border_valence_3_discarded);
  f("border_valence_3_collapsed", s.border_valence_3_collapsed);
  f("border_teeth_removed", s.border_teeth_removed);
  f("splits", s.splits);
  f("refused_by_certification", s.refused);
  f("rounds", s.rounds);
  f("seconds", s.seconds);
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Calls `f(name, value)` for every field of `s`, in a fixed order, with
/// `name` the field's name in reports (the keys of the tool's JSON report,
/// whose text is made from the same calls); values are numbers, flags, with distances in % of the input's bounding-box diagonal.
template <typename F>
void for_each_field(const Deform_to_fit_statistics& s, F&& f)
{
  f("vertices", s.vertices);
  f("feature_samples", s.feature_samples);
  f("moves", s.moves);
  f("smoothing_moves", s.smoothing_moves);
  f("qp_solves", s.qp_solves);
  f("qp_fallbacks", s.qp_fallbacks);
  f("infeasible_regions", s.infeasible_regions);
  f("shortened_moves", s.shortened_moves);
  f("rejected_moves", s.rejected_moves);
  f("undone_moves", s.undone_moves);
  f("full_updates", s.full_updates);
  f("smoothing_passes", s.smoothing_passes);
  f("intersecting_pairs_found", s.intersecting_pairs_found);
  f("untangling_moves", s.untangling_moves);
  f("intersecting_pairs", s.intersecting_pairs);
  f("start_distance_percent", s.start_distance);
  f("end_distance_percent", s.end_distance);
  f("guard_moves", s.guard_moves);
  f("border_notches_filled", s.border_notches_filled);
  f("border_corners_filled", s.border_corners_filled);
  f("border_vertices_added", s.border_vertices_added);
  f("border_fills_undone", s.border_fills_undone);
  f("stuck_vertices_freed", s.stuck_vertices_freed);
  f("stuck_vertices_freed_last", s.stuck_vertices_freed_last);
  f("stuck_vertices_freed_two_rings", s.stuck_vertices_freed_two_rings);
  f("stuck_vertices_put_back", s.stuck_vertices_put_back);
  f("stuck_vertices_undone", s.stuck_vertices_undone);
  f("balance_moves", s.balance_moves);
  f("rms_vertex_distance_percent", s.rms_distance);
  f("budget_exhausted", s.budget_exhausted);
  f("cancelled", s.cancelled);
  f("optimization_seconds", s.optimization_seconds);
  f("smoothing_seconds", s.smoothing_seconds);
  f("untangling_seconds", s.untangling_seconds);
  f("guard_seconds", s.guard_seconds);
  f("balance_seconds", s.balance_seconds);
  f("seconds", s.seconds);
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Calls `f(name, value)` for every field of `s`, in a fixed order, with
/// `name` the field's name in reports (the keys of the tool's JSON report,
/// whose text is made from the same calls); values are numbers, flags, the `Decimation_stop_reason`, and errors in % of the diagonal.
template <typename F>
void for_each_field(const Angle_bounded_decimation_statistics& s, F&& f)
{
  f("vertices_before", s.vertices_before);
  f("vertices_after", s.vertices_after);
  f("target_vertices", s.target_vertices);
  f("stop_reason", s.stop_reason);
  f("target_reached", s.stop_reason == Decimation_stop_reason::target_reached);
  f("collapses", s.collapses);
  f("qp_solves", s.qp_solves);
  f("qp_fallbacks", s.qp_fallbacks);
  f("empty_regions", s.empty_regions);
  f("placements_over_ceiling", s.placements_over_ceiling);
  f("valence_refusals", s.valence_refusals);
  f("frozen_refusals", s.frozen_refusals);
  f("certification_refusals", s.certification_refusals);
  f("topology_refusals", s.topology_refusals);
  f("rounds", s.rounds);
  f("relaxations", s.relaxations);
  f("relaxation_moves", s.relaxation_moves);
  f("relaxation_seconds", s.relaxation_seconds);
  f("largest_collapse_error_percent", 100. * s.largest_collapse_error);
  f("stopping_error_percent", 100. * s.stopping_error);
  f("seconds", s.seconds);
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_STATISTICS_H
