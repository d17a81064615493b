// SPDX-License-Identifier: GPL-3.0-or-later
//
// Angle-bounded decimation (thesis, chapter 6): quadric-error edge collapses
// that keep every angle in [30, 90] degrees, and the hierarchy of coarser
// meshes they make.

#ifndef CGAL_NONOBTUSE_REMESHING_ANGLE_BOUNDED_DECIMATION_H
#define CGAL_NONOBTUSE_REMESHING_ANGLE_BOUNDED_DECIMATION_H

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/Angle_bounded_decimation.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>
#include <CGAL/Nonobtuse_remeshing/visitors.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// One level of `angle_bounded_decimation_hierarchy()`.
template <typename TriangleMesh>
struct Decimation_level
{
  TriangleMesh mesh;
  std::size_t target_vertices = 0;
  bool reached = false;  ///< false: the decimation stopped before the target (see `statistics.stop_reason`)
  Angle_bounded_decimation_statistics statistics;  ///< from the full mesh to this level
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Angle-bounded decimation (thesis, chapter 6) of `mesh`, whose angles
/// must lie in [30, 90] degrees: CGAL's `Surface_mesh_simplification::
/// edge_collapse` with the thesis's policies. Each edge (u, v) is placed at
/// w* = argmin Q_u + Q_v over its linearized feasible region F(u, v)
/// (equations 6.1-6.4; Q is the sum of the squared distances to the planes
/// of the faces around an interior vertex, equation 5.10, and the squared
/// distance to a border vertex itself, equation 6.3), costs Q_u(w*) + Q_v(w*)
/// (6.5, with a tie break by edge length, see the manual), and collapses
/// cheapest first, every cost kept current (no lazy evaluation, 6.4). A
/// collapse goes ahead only if every face around w* certifies exactly in
/// [30, 90] degrees, no vertex falls below the valence floor, and the link
/// condition holds: the mesh is certified after every collapse, and stays
/// manifold with its Euler characteristic, borders and components.
///
/// Beyond the thesis, with `relaxation` (the default), the collapses run in
/// rounds under a rising cost ceiling and deform-to-fit (chapter 5) fits the
/// decimated mesh to the full one between rounds: on a fitted nonobtuse mesh
/// most edges soon have an empty F(u, v), and the thesis's single greedy run
/// stalls near 40% of the vertices removed (see the manual). The relaxation
/// ends with the fit's distance balance (`deform_to_fit()`), unmeasured: the
/// caller measures the levels. Every fitting move is certified too.
///
/// The decimation stops at the target vertex count, when the cheapest
/// collapse left would place w* farther than `max_error` from the planes and
/// points its quadric sums (sqrt of the cost, early termination of 6.5), when
/// no collapse is left (after a relaxation, if on), or when the visitor
/// cancels; `stop_reason` says which. Removed elements may leave garbage in a
/// `Surface_mesh` (call `collect_garbage()`). The points are read and
/// written through the `vertex_point_map`, and decided exactly on their double
/// coordinates, as in `deform_to_fit()`.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{target_vertices} vertices to keep; default from `vertex_ratio`
///     \cgalParamType{`std::size_t`} \cgalParamNEnd
///   \cgalParamNBegin{vertex_ratio} fraction of the vertices to keep, in (0, 1]; default 0.5
///     \cgalParamType{`double`} \cgalParamNEnd
///   \cgalParamNBegin{max_error} early termination, a fraction of the mesh's bounding-box diagonal;
///     default none
///     \cgalParamType{`double`} \cgalParamNEnd
///   \cgalParamNBegin{min_interior_valence} no collapse makes an interior vertex of lower valence;
///     default 4
///     \cgalParamType{`std::size_t`} \cgalParamNEnd
///   \cgalParamNBegin{min_border_valence} the same for border vertices; default 3
///     \cgalParamType{`std::size_t`} \cgalParamNEnd
///   \cgalParamNBegin{drum_subdivisions} k of F(u, v), in [1, 16]; default 2
///     \cgalParamType{`int`} \cgalParamNEnd
///   \cgalParamNBegin{relaxation} rounds with deform-to-fit between them; false: the thesis's
///     single greedy run; default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads} threads of the relaxation, see `deform_to_fit()`;
///     default 0 (one per core)
///     \cgalParamType{`int`} \cgalParamNEnd
///   \cgalParamNBegin{decimation_visitor} progress and cancellation, see `Default_decimation_visitor`
///     (pass `std::ref(visitor)` to keep its state)
///     \cgalParamType{a model of `DecimationVisitor`} \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `mesh`; default the mesh's internal point map
///     \cgalParamType{a model of `ReadWritePropertyMap` (`ReadablePropertyMap` for a mesh only read) with the vertex descriptors as keys and points with double coordinates as values} \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// Throws, leaving `mesh` unchanged, `Bad_parameter` if a parameter is out of
/// range and `Bad_input` if `mesh` is not a triangle mesh certified in
/// [30, 90] degrees.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Angle_bounded_decimation_statistics angle_bounded_decimation(
    TriangleMesh& mesh, const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const internal::Angle_bounded_decimation_options o = internal::decimation_options(np);
  const double ratio = choose_parameter(get_parameter(np, internal_np::vertex_ratio), 0.5);
  if(!(ratio > 0. && ratio <= 1.)) throw Bad_parameter("the vertex ratio must lie in (0, 1]");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, mesh));
  const double diagonal = internal::certified_mesh_diagonal(mesh, vpm);
  const std::size_t n = vertices(mesh).size();
  const std::size_t target =
      choose_parameter(get_parameter(np, internal_np::target_vertices), std::size_t(std::llround(ratio * double(n))));
  auto given = choose_parameter(get_parameter(np, internal_np::decimation_visitor), Default_decimation_visitor());
  TriangleMesh reference;  // the full mesh, which the relaxation fits to
  if(o.relaxation) copy_face_graph(mesh, reference, CGAL::parameters::vertex_point_map(vpm));
  return internal::angle_bounded_decimation_with(
      mesh, vpm, o, diagonal, {target}, reference, get_const_property_map(CGAL::vertex_point, reference),
      internal::keep_going_function<Angle_bounded_decimation_statistics>(internal::visitor_reference(given)),
      [](std::size_t, bool, const Angle_bounded_decimation_statistics&) {});
}

/// \ingroup PkgNonobtuseRemeshingRef
/// A hierarchy of certified meshes (thesis, chapter 6 and Figures 7.1-7.6):
/// one decimation of a copy of `mesh` that hands out a copy each time the
/// vertex count reaches `ratios[i]` times the vertices of `mesh`. The
/// ratios must decrease strictly within (0, 1). If the decimation stops
/// before a target (see `angle_bounded_decimation()`), that level holds the
/// mesh where it stopped, with `reached` false, and the levels after it are
/// left out. Takes the named parameters of `angle_bounded_decimation()`
/// except the targets; `mesh` is not changed (its points are read through the
/// `vertex_point_map`; the levels hold theirs in their internal point maps).
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<Decimation_level<TriangleMesh> > angle_bounded_decimation_hierarchy(
    const TriangleMesh& mesh, const std::vector<double>& ratios,
    const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  internal::check_level_ratios(ratios);
  const internal::Angle_bounded_decimation_options o = internal::decimation_options(np);
  const auto input_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_const_property_map(CGAL::vertex_point, mesh));
  const double diagonal = internal::certified_mesh_diagonal(mesh, input_vpm);

  TriangleMesh work;
  copy_face_graph(mesh, work, CGAL::parameters::vertex_point_map(input_vpm));
  std::vector<std::size_t> targets;
  for(double r : ratios) targets.push_back(std::size_t(std::llround(r * double(vertices(mesh).size()))));
  auto given = choose_parameter(get_parameter(np, internal_np::decimation_visitor), Default_decimation_visitor());
  std::vector<Decimation_level<TriangleMesh> > levels;
  internal::angle_bounded_decimation_with(
      work, get(CGAL::vertex_point, work), o, diagonal, targets, mesh, input_vpm,
      internal::keep_going_function<Angle_bounded_decimation_statistics>(internal::visitor_reference(given)),
      [&](std::size_t i, bool reached, const Angle_bounded_decimation_statistics& s) {
        levels.emplace_back();
        copy_face_graph(work, levels.back().mesh);
        levels.back().target_vertices = targets[i];
        levels.back().reached = reached;
        levels.back().statistics = s;
      });
  return levels;
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_ANGLE_BOUNDED_DECIMATION_H
