// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact certification of the angle bounds of a triangle mesh.

#ifndef CGAL_NONOBTUSE_REMESHING_CERTIFY_ANGLE_BOUNDS_H
#define CGAL_NONOBTUSE_REMESHING_CERTIFY_ANGLE_BOUNDS_H

#include <CGAL/Nonobtuse_remeshing/angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/angle_predicates.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// Result of `certify_angle_bounds()`.
template <typename FaceDescriptor>
struct Angle_certificate
{
  /// the bounds asked for, in degrees
  double min_bound = 30.;
  double max_bound = 90.;
  /// true when both bounds are tested exactly as asked; false when a bound
  /// whose cosine is irrational was tightened by a tiny margin (never loosened)
  bool bounds_exact = true;

  std::size_t faces = 0;
  /// corners whose angle is proven smaller than `min_bound`
  std::size_t too_small_corners = 0;
  /// corners whose angle is proven larger than `max_bound`
  std::size_t too_large_corners = 0;
  /// faces with a zero-length edge or zero area
  std::size_t degenerate_faces = 0;
  /// every face with a failing corner or a degeneracy, in face order
  std::vector<FaceDescriptor> offending_faces;

  /// smallest and largest corner angle in degrees, measured in double over the
  /// non-degenerate faces; a corner that passes is reported within the bounds.
  /// Meaningless (180 and 0) when `has_angles()` is false.
  double min_angle = 180.;
  double max_angle = 0.;
  /// corners of the non-degenerate faces in 5 degree bins, with the measured
  /// angles shown as above: bin i is [5i, 5i+5), except that bin 17 is
  /// [85, 90] and bin 18 is (90, 95), so that a right angle counts as
  /// nonobtuse; 180 falls in bin 35
  std::array<std::size_t, 36> angle_histogram{};

  bool has_angles() const { return faces > degenerate_faces; }
  bool is_certified() const { return offending_faces.empty() && faces > 0; }
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Decides exactly, for every corner of every face of the triangle mesh `mesh`,
/// whether its angle lies in [`min_angle`, `max_angle`] (degrees, default
/// [30, 90]), from the stored double coordinates.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{min_angle} lower bound in degrees (default 30)
///     \cgalParamType{`double`} \cgalParamNEnd
///   \cgalParamNBegin{max_angle} upper bound in degrees (default 90)
///     \cgalParamType{`double`} \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} CGAL's vertex point map
///     \cgalParamType{a model of `ReadWritePropertyMap` (`ReadablePropertyMap` for a mesh only read) with the vertex descriptors as keys and points with double coordinates as values} \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// Bounds of 0, 30, 45, 60, 90, 120, 135, 150 and 180 degrees are tested
/// exactly; for any other bound the cosine is moved by 1e-12 in the safe
/// direction, so the certified interval is never looser than the one
/// requested. A mesh with no face is not certified.
///
/// The points must have double coordinates. Throws `Bad_parameter` for bounds
/// outside 0 <= min <= max <= 180, and `Bad_input` if `mesh` has a face that is
/// not a triangle.
template <typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Angle_certificate<typename boost::graph_traits<TriangleMesh>::face_descriptor>
certify_angle_bounds(const TriangleMesh& mesh,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;

  const Angle_bounds bounds(choose_parameter(get_parameter(np, internal_np::min_angle), 30.),
                            choose_parameter(get_parameter(np, internal_np::max_angle), 90.));
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));

  if(!is_triangle_mesh(mesh))
    throw Bad_input("certify_angle_bounds: the mesh has a face that is not a triangle");

  Angle_certificate<face_descriptor> result;
  result.min_bound = bounds.min_degrees();
  result.max_bound = bounds.max_degrees();
  result.bounds_exact = bounds.is_exact();

  for(face_descriptor f : faces(mesh)) {
    ++result.faces;
    const halfedge_descriptor h = halfedge(f, mesh);
    const auto& a = get(vpm, source(h, mesh));
    const auto& b = get(vpm, target(h, mesh));
    const auto& c = get(vpm, target(next(h, mesh), mesh));
    const internal::Triangle_verdict verdict = internal::triangle_verdict(a, b, c, bounds);
    if(!verdict.within_bounds())
      result.offending_faces.push_back(f);
    if(verdict.degenerate) {
      ++result.degenerate_faces;
      continue;
    }
    const decltype(&a) pts[3] = {&a, &b, &c};
    for(int i = 0; i < 3; ++i) {
      const internal::Corner_verdict& corner = verdict.corners[i];
      result.too_small_corners += corner.too_small;
      result.too_large_corners += corner.too_large;
      double angle = internal::corner_angle_degrees(*pts[i], *pts[(i + 1) % 3], *pts[(i + 2) % 3]);
      // A corner proven within the bounds is shown within them, whatever the
      // rounding of the measured value.
      if(!corner.too_small) angle = (std::max)(angle, bounds.min_degrees());
      if(!corner.too_large) angle = (std::min)(angle, bounds.max_degrees());
      result.min_angle = (std::min)(result.min_angle, angle);
      result.max_angle = (std::max)(result.max_angle, angle);
      ++result.angle_histogram[internal::angle_bin(angle)];
    }
  }
  return result;
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_CERTIFY_ANGLE_BOUNDS_H
