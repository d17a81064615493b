// SPDX-License-Identifier: GPL-3.0-or-later
//
// Removal of bad-valence vertices before deform-to-fit (thesis, section 5.7),
// and vertex splits for those that removal cannot reach (its chapter 8).

#ifndef CGAL_NONOBTUSE_REMESHING_REMOVE_BAD_VALENCE_VERTICES_H
#define CGAL_NONOBTUSE_REMESHING_REMOVE_BAD_VALENCE_VERTICES_H

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/Bad_valence_removal.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>

#include <CGAL/boost/graph/helpers.h>

#include <chrono>
#include <stdexcept>

namespace CGAL {
namespace Nonobtuse_remeshing {

namespace internal {

// remove_bad_valence_vertices() once its parameters are read: one
// instantiation per mesh type and point map.
template <typename TriangleMesh, typename VertexPointMap>
Bad_valence_removal_statistics remove_bad_valence_vertices_with(TriangleMesh& mesh, VertexPointMap vpm, int k,
                                                                bool split)
{
  const auto start = std::chrono::steady_clock::now();
  if(!is_triangle_mesh(mesh)) throw Bad_input("remove_bad_valence_vertices: not a triangle mesh");
  if(!certify_angle_bounds(mesh, CGAL::parameters::vertex_point_map(vpm)).is_certified())
    throw Bad_input("remove_bad_valence_vertices needs a mesh certified in [30, 90] degrees");

  Bad_valence_removal_statistics stats;
  stats.before = count_bad_valences(mesh);
  stats.vertices_before = vertices(mesh).size();
  Bad_valence_removal<TriangleMesh, VertexPointMap> removal(mesh, vpm, k, split, stats);
  removal.run();
  stats.after = count_bad_valences(mesh);
  stats.vertices_after = vertices(mesh).size();
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

} // namespace internal

/// \ingroup PkgNonobtuseRemeshingRef
/// Removes bad-valence vertices from `mesh`, whose angles must lie in
/// [30, 90] degrees (the initial mesh's do), as the thesis's section 5.7
/// does before the fit: first border vertices of valence 2 and interior ones
/// of valence 3, then interior vertices of valence 4, then border vertices of
/// valence 3. Each is discarded and its ring retriangulated, or its edge to a
/// neighbour collapsed to the point of the feasible region F(u, v) closest to
/// the edge's midpoint (equation 5.18), under the neighbour valences of the
/// thesis's Figure 5.6. Then, beyond the thesis, each remaining bad vertex
/// raises its valence by splitting interior neighbours of valence 6 or more
/// (both halves keep 5 or more), the two new positions found by alternating
/// QPs in their feasible regions. Removal and split alternate while they
/// change the mesh, at most 16 rounds.
///
/// Every operation keeps the mesh manifold with the same Euler
/// characteristic, borders and components (collapses obey the link
/// condition), and is applied only when its new faces certify exactly in
/// [30, 90] degrees (and keep their orientation, tested in double): the mesh
/// is certified at every moment. Removed elements may leave garbage in a `Surface_mesh`
/// (call `collect_garbage()`).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_split} split after removal; default true
///     \cgalParamType{`bool`} \cgalParamNEnd
///   \cgalParamNBegin{drum_subdivisions} k of the feasible regions, in [1, 16]; default 2
///     \cgalParamType{`int`} \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} default: the mesh's
///     \cgalParamType{a model of `ReadWritePropertyMap` (`ReadablePropertyMap` for a mesh only read) with the vertex descriptors as keys and points with double coordinates as values} \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// Throws, leaving `mesh` unchanged, `Bad_parameter` if k is out of range and
/// `Bad_input` if `mesh` is not a triangle mesh certified in [30, 90] degrees.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Bad_valence_removal_statistics remove_bad_valence_vertices(TriangleMesh& mesh,
                                                           const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const bool split = choose_parameter(get_parameter(np, internal_np::vertex_split), true);
  const int k = choose_parameter(get_parameter(np, internal_np::drum_subdivisions), 2);
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, mesh));
  if(k < 1 || k > 16) throw Bad_parameter("the drum subdivisions k must lie in [1, 16]");
  return internal::remove_bad_valence_vertices_with(mesh, vpm, k, split);
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

// With NonobtuseRemeshing::Compiled (compiled_surface_mesh.h): the declarations
// of its instantiations; src/compiled/remove_bad_valence_vertices.cpp defines
// CGAL_NONOBTUSE_REMESHING_INSTANTIATE_VALENCE, and there they are the instantiations.
#ifdef CGAL_NONOBTUSE_REMESHING_COMPILED
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
#ifndef CGAL_NONOBTUSE_REMESHING_INSTANTIATE_VALENCE
extern
#endif
template Bad_valence_removal_statistics remove_bad_valence_vertices_with(Compiled_mesh&, Compiled_point_map,
                                                                         int, bool);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
#endif

#endif // CGAL_NONOBTUSE_REMESHING_REMOVE_BAD_VALENCE_VERTICES_H
