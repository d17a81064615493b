// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality report of a triangle mesh: angles (certified exactly), valences,
// topology, defects, and the distance to a reference mesh.

#ifndef CGAL_NONOBTUSE_REMESHING_QUALITY_REPORT_H
#define CGAL_NONOBTUSE_REMESHING_QUALITY_REPORT_H

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/distance_measures.h>
#include <CGAL/Nonobtuse_remeshing/internal/angle_predicates.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/property_map.h>

#include <boost/optional.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <unordered_map>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// Distances between a mesh and a reference, in percent of the reference's
/// bounding-box diagonal.
struct Distance_report
{
  double reference_diagonal = 0.;
  /// one-sided Hausdorff distance from the mesh to the reference
  double hausdorff_to_reference = 0.;
  /// one-sided Hausdorff distance from the reference to the mesh
  double hausdorff_from_reference = 0.;
  /// max of the two
  double hausdorff_symmetric = 0.;
  /// each Hausdorff value is within this of the true distance
  /// (CGAL's bounded-error Hausdorff distance)
  double hausdorff_error_bound = 0.;
  /// area-weighted mean distance from the mesh to the reference, and back
  double mean_to_reference = 0.;
  double mean_from_reference = 0.;
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Result of `quality_report()`.
struct Quality_report
{
  std::size_t vertices = 0, edges = 0, faces = 0;
  /// exact certification summary (see `certify_angle_bounds()`)
  double min_bound = 30., max_bound = 90.;
  bool bounds_exact = true;
  bool certified = false;
  std::size_t too_small_corners = 0, too_large_corners = 0, degenerate_faces = 0;
  std::size_t offending_faces = 0;
  /// false when every face is degenerate: min and max angle are meaningless
  bool has_angles = false;
  double min_angle = 0., max_angle = 0.;
  /// corner angles in 5 degree bins, as in `Angle_certificate`: bin i counts
  /// [5i, 5i+5), except bin 17 = [85, 90] and bin 18 = (90, 95)
  std::array<std::size_t, 36> angle_histogram{};
  /// valence (number of incident edges) to number of vertices
  std::map<std::size_t, std::size_t> interior_valences, boundary_valences;
  std::size_t border_cycles = 0;
  std::size_t connected_components = 0;
  long euler_characteristic = 0;
  std::size_t non_manifold_vertices = 0;
  /// intersecting face pairs (beyond shared vertices and edges; a degenerate
  /// face counts as a pair with itself), counted up to `self_intersections_cap`
  std::size_t self_intersections = 0;
  std::size_t self_intersections_cap = 0;
  bool self_intersections_capped = false;
  double bbox_diagonal = 0.;
  boost::optional<Distance_report> distance;
};

namespace internal {

// quality_report() once its parameters are read and `mesh` certified: one
// instantiation per mesh type.
template <typename TriangleMesh>
Quality_report quality_report_with(
    const TriangleMesh& mesh, const TriangleMesh* reference, std::size_t cap, double hausdorff_error,
    const Angle_certificate<typename boost::graph_traits<TriangleMesh>::face_descriptor>& certificate)
{
  namespace PMP = Polygon_mesh_processing;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  Quality_report r;
  r.vertices = vertices(mesh).size();  // live elements: num_*() of a Surface_mesh count removed ones
  r.edges = edges(mesh).size();
  r.faces = faces(mesh).size();
  r.euler_characteristic = long(r.vertices) - long(r.edges) + long(r.faces);

  r.min_bound = certificate.min_bound;
  r.max_bound = certificate.max_bound;
  r.bounds_exact = certificate.bounds_exact;
  r.certified = certificate.is_certified();
  r.too_small_corners = certificate.too_small_corners;
  r.too_large_corners = certificate.too_large_corners;
  r.degenerate_faces = certificate.degenerate_faces;
  r.offending_faces = certificate.offending_faces.size();
  r.has_angles = certificate.has_angles();
  r.min_angle = certificate.min_angle;
  r.max_angle = certificate.max_angle;
  r.angle_histogram = certificate.angle_histogram;

  // one halfedge per umbrella of each non-manifold vertex (linear time;
  // is_non_manifold_vertex() would be linear per vertex)
  std::vector<halfedge_descriptor> umbrellas;
  PMP::non_manifold_vertices(mesh, std::back_inserter(umbrellas));
  std::set<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> pinched;
  for(halfedge_descriptor h : umbrellas) pinched.insert(target(h, mesh));
  r.non_manifold_vertices = pinched.size();
  for(auto v : vertices(mesh)) {
    const std::size_t valence = degree(v, mesh);
    if(is_border(v, mesh)) ++r.boundary_valences[valence];
    else ++r.interior_valences[valence];
  }

  std::vector<halfedge_descriptor> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  r.border_cycles = cycles.size();

  std::unordered_map<face_descriptor, std::size_t> component;
  r.connected_components =
      PMP::connected_components(mesh, boost::make_assoc_property_map(component));

  r.self_intersections_cap = cap;
  // ask for one more than the cap: finding it is what proves the cap was hit
  PMP::self_intersections(faces(mesh), mesh, Counting_iterator{&r.self_intersections},
                          CGAL::parameters::maximum_number(unsigned(r.self_intersections_cap + 1)));
  r.self_intersections_capped = (r.self_intersections > r.self_intersections_cap);
  r.self_intersections = (std::min)(r.self_intersections, r.self_intersections_cap);

  r.bbox_diagonal = bbox_diagonal(mesh);
  if(reference != nullptr)
    r.distance = distance_report<Distance_report>(mesh, *reference, hausdorff_error);
  return r;
}

} // namespace internal

/// \ingroup PkgNonobtuseRemeshingRef
/// Computes the quality report of the triangle mesh `mesh` (a
/// `CGAL::Surface_mesh` or any model of `FaceListGraph`). If `reference` is
/// not null, the distances to it are computed too.
///
/// Throws `Bad_parameter` for a parameter out of range, and `Bad_input`
/// unless `mesh` and `reference` are triangle meshes and the reference's
/// bounding box is not a point.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{min_angle, max_angle} the bounds to certify (default 30, 90) \cgalParamNEnd
///   \cgalParamNBegin{maximum_self_intersections} cap on the counted self-intersecting
///     face pairs (default 1000)
///     \cgalParamType{`std::size_t`} \cgalParamNEnd
///   \cgalParamNBegin{hausdorff_relative_error} error bound of the Hausdorff distances,
///     as a fraction of the reference's bounding-box diagonal (default 1e-4)
///     \cgalParamType{`double`} \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Quality_report quality_report(const TriangleMesh& mesh,
                              const std::common_type_t<TriangleMesh>* reference = nullptr,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::size_t cap =
      choose_parameter(get_parameter(np, internal_np::maximum_self_intersections), std::size_t(1000));
  if(cap < 1 || cap >= (std::numeric_limits<unsigned>::max)())
    throw Bad_parameter("maximum_self_intersections must be between 1 and 2^32 - 2");
  const double hausdorff_error = choose_parameter(get_parameter(np, internal_np::hausdorff_relative_error), 1e-4);
  if(!(hausdorff_error > 0.)) throw Bad_parameter("the Hausdorff error bound must be positive");
  return internal::quality_report_with(mesh, reference, cap, hausdorff_error, certify_angle_bounds(mesh, np));
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

// With NonobtuseRemeshing::Compiled (compiled_surface_mesh.h): the declarations
// of its instantiations; src/compiled/quality_report.cpp defines
// CGAL_NONOBTUSE_REMESHING_INSTANTIATE_QUALITY_REPORT, and there they are the instantiations.
#ifdef CGAL_NONOBTUSE_REMESHING_COMPILED
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
#ifndef CGAL_NONOBTUSE_REMESHING_INSTANTIATE_QUALITY_REPORT
extern
#endif
template Quality_report quality_report_with(const Compiled_mesh&, const Compiled_mesh*, std::size_t, double,
                                            const Angle_certificate<Compiled_mesh::Face_index>&);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
#endif

#endif // CGAL_NONOBTUSE_REMESHING_QUALITY_REPORT_H
