// SPDX-License-Identifier: GPL-3.0-or-later
//
// Deform-to-fit (thesis, chapter 5): moves the vertices of a certified mesh
// towards the input surface, keeping every angle in [30, 90] degrees.

#ifndef CGAL_NONOBTUSE_REMESHING_DEFORM_TO_FIT_H
#define CGAL_NONOBTUSE_REMESHING_DEFORM_TO_FIT_H

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/Deform_to_fit.h>
#include <CGAL/Nonobtuse_remeshing/internal/closest_triangle.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>
#include <CGAL/Nonobtuse_remeshing/visitors.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>

namespace CGAL {
namespace Nonobtuse_remeshing {

namespace internal {

// deform_to_fit() once its parameters are read: one instantiation per mesh
// type and point maps, whatever the parameters and the visitor.
template <typename TriangleMesh, typename VertexPointMap, typename InputPointMap>
Deform_to_fit_statistics deform_to_fit_with(TriangleMesh& mesh, VertexPointMap vpm, const TriangleMesh& input,
                                            InputPointMap input_vpm, const Deform_to_fit_options& o, int rings,
                                            const Keep_going_function<Deform_to_fit_statistics>& keep_going)
{
  if(num_faces(input) == 0) throw Bad_input("deform_to_fit: the input has no face");
  if(!is_triangle_mesh(input)) throw Bad_input("deform_to_fit: the input is not a triangle mesh");
  if(!certify_angle_bounds(mesh, CGAL::parameters::vertex_point_map(vpm)).is_certified())
    throw Bad_input("deform_to_fit needs a mesh certified in [30, 90] degrees");

  const Bbox_3 box = Polygon_mesh_processing::bbox(input, CGAL::parameters::vertex_point_map(input_vpm));
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  if(!(diagonal > 0.)) throw Bad_input("deform_to_fit: the input's bounding box has no size");
  auto visitor = keep_going_relay(keep_going);
  using Input = Closest_triangle<TriangleMesh, InputPointMap>;
  const Input closest(input, input_vpm, rings);
  Deform_to_fit<TriangleMesh, VertexPointMap, Input, decltype(visitor)> optimizer(mesh, vpm, closest, diagonal, o,
                                                                                 visitor);
  return optimizer.run();
}

} // namespace internal

/// \ingroup PkgNonobtuseRemeshingRef
/// Deform-to-fit (thesis, chapter 5): moves the vertices of `mesh`, whose
/// angles must already lie in [30, 90] degrees (the initial mesh's do), to
/// fit `input`. Each vertex solves the quadratic program of the thesis's
/// equation 5.15, L = alpha D + (1 - alpha) S over its linearized feasible
/// region F(v); the vertex with the largest improvement moves first. Each
/// move is certified exactly before it is applied (or shortened, or
/// skipped), so `mesh` is certified at every moment, also when the budget
/// runs out or the visitor cancels. The connectivity does not change, except
/// where border notches are filled (below).
///
/// Beyond the thesis, two terms keep the fit close in the Hausdorff sense:
/// S acts along the input's tangent plane only (`tangential_smoothing`), and
/// the input's vertices and points along its sharp and border edges attract
/// their nearest mesh vertex (`attract_features`). Both can be switched off
/// to run the thesis's objective as written. A distance guard
/// (`distance_guard`) then makes sure the fit does not end farther from the
/// input than the mesh it started from, as it measures both: the farthest of
/// the input's feature samples and of points on its faces about an edge apart
/// from the mesh, and of the mesh's vertices from the input. Where the fit
/// ends farther, the vertices around the excess move back towards their start
/// positions, certified like every move, in rounds kept only when they lower
/// that distance and add no self-intersection; `start_distance` and
/// `end_distance` in the statistics are the two values.
///
/// On an open input, the Marching Cubes leave each border as a staircase of
/// the grid, its notches up to a cube inside the input's border, where the
/// fit cannot pull them out without breaking the bounds. Once the queue
/// converges, the notches of the borders that follow the input's are filled
/// (`fill_border_notches`): a border vertex whose faces' angles sum to more
/// than 200 degrees, a quarter of an edge or more inside the input's border,
/// gets the face joining its two border neighbours, or two faces around a
/// new border vertex where that face would be obtuse, each new face
/// certified exactly and crossing no face of the mesh, only towards the
/// input's border and over the input; a corner of the input's border (its
/// faces' angles summing to at most 150 degrees) that the mesh's border cuts
/// off gets an ear, a face on the nearest border edge with a new vertex at
/// the corner; the fit then goes on, at most four
/// such passes. The Euler characteristic, the border cycles and the
/// components stay; `mesh` gains the new vertices and faces. When the fit
/// ends farther from the input with the fills than it would have without
/// them (as the distance guard measures both), they are removed again and
/// the fit ends as without them (`border_fills_undone`; a `Surface_mesh`
/// keeps the removed elements as garbage, as after any Euler operation).
///
/// A vertex can stay far from the input because a corner of its one-ring
/// sits at a bound: moving it would break that angle, and the neighbour
/// that could make room gains nothing by moving. Once the queue converges,
/// the vertices at least half as far from the input as the farthest (or
/// whose attracted feature samples are) are freed (`free_stuck_vertices`):
/// each is put on the input, or at its objective's minimum, all the way or
/// part of it, while its neighbours solve their own QPs around its new
/// position; the group is certified exactly and kept only when its farthest
/// vertex comes 10% closer. At most four such passes, after the border
/// fills, the queue resuming after each (`stuck_vertices_freed`). If the
/// distance guard then cannot end the fit as close as its start, the fit
/// from before the first pass is finished too and the closer one kept
/// (`stuck_vertices_undone` when that is the one before the passes).
///
/// With its vertices on the input, every face of a curved region lies on one
/// side of it, by up to its sagitta. After the guard, the distance balance
/// (`balance_distance`) moves every interior vertex along its normal by the
/// middle of the range of the input's offsets seen from the vertex and from
/// its faces' centroids, so that the mesh straddles the input, certified like
/// every move, in three rounds kept only if they make no face pair cross
/// and, with the guard, neither its measure nor the farthest face centroid
/// grows (else run once more with half the steps; `balance_moves`). A last
/// pass frees the vertices left farthest once more, each with its one-ring,
/// then with its two rings (`stuck_vertices_freed_last`,
/// `stuck_vertices_freed_two_rings`), each kept on its own once the groups
/// whose faces cross others are put back (`stuck_vertices_put_back`), if no
/// more face pairs cross than before it and, with the guard, its measure does
/// not grow; the two run again while they free some, at most four times.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{alpha} weight of the distance term D, in [0, 1]; default 0.5
///     \cgalParamType{`double`} \cgalParamNEnd
///   \cgalParamNBegin{drum_subdivisions} k, the drum planes per side of F(v), in [1, 16]; default 2
///     \cgalParamType{`int`} \cgalParamNEnd
///   \cgalParamNBegin{quadric_rings} r, the rings of input triangles around the closest one
///     whose planes make D, in [0, 4]; default 0
///     \cgalParamType{`int`} \cgalParamNEnd
///   \cgalParamNBegin{smoothing_steps} constrained Laplacian smoothing passes, in [0, 100]; default 2
///     \cgalParamType{`int`} \cgalParamNEnd
///   \cgalParamNBegin{fit_tolerance} a move must improve L by (fit_tolerance * input bounding-box
///     diagonal)^2; the fit stops when no vertex can; default 1e-4
///     \cgalParamType{`double`} \cgalParamNEnd
///   \cgalParamNBegin{max_moves} budget in moves; default unlimited
///     \cgalParamType{`std::size_t`} \cgalParamNEnd
///   \cgalParamNBegin{max_seconds} budget in seconds; default unlimited
///     \cgalParamType{`double`} \cgalParamNEnd
///   \cgalParamNBegin{lazy_evaluation} a moved vertex's neighbours are re-evaluated only when they reach the top of the queue (thesis, 5.6); default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{early_smoothing} a smoothing pass starts when the queue first stalls (thesis, 5.6); default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{tangential_smoothing} S acts along the input's tangent plane only (beyond the thesis); default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{attract_features} the input's vertices and points along its sharp and border edges attract their nearest mesh vertex (beyond the thesis); default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{distance_guard} moves back where the fit would end farther from the input than the mesh it started from (beyond the thesis); default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{fill_border_notches} fills the notches of the borders, and the corners of the input's border they cut off, with faces that bring them out to the input's border (beyond the thesis); default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{free_stuck_vertices} moves the vertices left farthest from the input together with their one-rings (beyond the thesis); default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{balance_distance} moves the vertices along their normals until the mesh straddles the input (beyond the thesis); default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads} threads that move vertices sharing no edge at the same
///     time (oneTBB; without it, one); 0 for one per core; the result is the same, bit for bit,
///     for any number; default 0
///     \cgalParamType{`int`} \cgalParamNEnd
///   \cgalParamNBegin{fit_visitor} progress and cancellation, see `Default_deform_to_fit_visitor`
///     (pass `std::ref(visitor)` to keep its state)
///     \cgalParamType{a model of `DeformToFitVisitor`} \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `mesh`, read and written (also for the vertices the border fills add); default the mesh's
///     internal point map
///     \cgalParamType{a model of `ReadWritePropertyMap` (`ReadablePropertyMap` for a mesh only read) with the vertex descriptors as keys and points with double coordinates as values} \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// `np_input` may hold the `vertex_point_map` of `input` (read only). The points must have
/// double coordinates (for example of `Exact_predicates_inexact_constructions_kernel`,
/// `Simple_cartesian<double>` or `Cartesian<double>`): every angle is decided exactly on those
/// doubles with the filtered predicates of `Exact_predicates_inexact_constructions_kernel`,
/// whatever the points' kernel, which is why no `geom_traits` is taken.
///
/// Throws `Bad_parameter` if a parameter is out of range, and `Bad_input` if
/// `mesh` is not certified in [30, 90] or `input` has no face, no size or is
/// not a triangle mesh; `mesh` is then unchanged.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename InputNamedParameters = CGAL::parameters::Default_named_parameters>
Deform_to_fit_statistics deform_to_fit(TriangleMesh& mesh, const TriangleMesh& input,
                                       const NamedParameters& np = CGAL::parameters::default_values(),
                                       const InputNamedParameters& np_input = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  int rings = 0;
  const internal::Deform_to_fit_options o = internal::deform_to_fit_options(np, rings);
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, mesh));
  const auto input_vpm = choose_parameter(get_parameter(np_input, CGAL::internal_np::vertex_point),
                                          get_const_property_map(CGAL::vertex_point, input));
  // a visitor given by value is copied, one given with std::ref is used in place
  auto given = choose_parameter(get_parameter(np, internal_np::fit_visitor), Default_deform_to_fit_visitor());
  return internal::deform_to_fit_with(mesh, vpm, input, input_vpm, o, rings,
                                      internal::keep_going_function<Deform_to_fit_statistics>(
                                          internal::visitor_reference(given)));
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

// With NonobtuseRemeshing::Compiled (compiled_surface_mesh.h): the declarations
// of its instantiations; src/compiled/deform_to_fit.cpp defines
// CGAL_NONOBTUSE_REMESHING_INSTANTIATE_FIT, and there they are the instantiations.
#ifdef CGAL_NONOBTUSE_REMESHING_COMPILED
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
#ifndef CGAL_NONOBTUSE_REMESHING_INSTANTIATE_FIT
extern
#endif
template Deform_to_fit_statistics deform_to_fit_with(Compiled_mesh&, Compiled_point_map, const Compiled_mesh&,
                                                     Compiled_point_map, const Deform_to_fit_options&, int,
                                                     const Keep_going_function<Deform_to_fit_statistics>&);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
#endif

#endif // CGAL_NONOBTUSE_REMESHING_DEFORM_TO_FIT_H
