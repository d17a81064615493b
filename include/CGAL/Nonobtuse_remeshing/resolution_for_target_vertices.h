// SPDX-License-Identifier: GPL-3.0-or-later
//
// The resolution of the nonobtuse Marching Cubes (thesis, chapter 4) for a
// number of vertices.

#ifndef CGAL_NONOBTUSE_REMESHING_RESOLUTION_FOR_TARGET_VERTICES_H
#define CGAL_NONOBTUSE_REMESHING_RESOLUTION_FOR_TARGET_VERTICES_H

#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Nonobtuse_remeshing {

namespace internal {

// The longest side of the bounding box of the faces of `input`, as the
// grid's; throws Bad_input outside the range the grid accepts.
template <typename TriangleMesh, typename VertexPointMap>
double longest_side_of_faces(const TriangleMesh& input, VertexPointMap vpm)
{
  Bbox_3 box;
  for(auto f : faces(input))
    for(auto v : vertices_around_face(halfedge(f, input), input)) box += get(vpm, v).bbox();
  const double longest = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  if(longest < 1e-30 || longest > 1e30)  // as the grid refuses it
    throw Bad_input("the input's size is outside the supported range [1e-30, 1e30]: scale it");
  return longest;
}

} // namespace internal

// Vertices of the initial mesh per unit of area, times the squared cube
// size h: a plane crosses (|n_x| + |n_y| + |n_z|) / h^2 grid edges per unit
// of area, 1.5 / h^2 on average over normals, and the nonobtuse cases add
// cube centres. Measured at N = 40 and 100 on CGAL's 17 sample meshes: 1.65
// to 1.89 on curved ones, 2.07 to 2.27 on many small holes, 1.26 to 1.40 on
// mostly axis-aligned ones, 1.0 on an axis-aligned box.
/// \ingroup PkgNonobtuseRemeshingRef
/// The vertex density c of `resolution_for_target_vertices()`.
constexpr double marching_cubes_vertex_density = 1.8;

/// \ingroup PkgNonobtuseRemeshingRef
/// The resolution (cubes along the longest side of the bounding box of the
/// faces) whose initial mesh of `input` should have about `target_vertices`
/// vertices: N = L sqrt(V / (c A)), with L the longest side, A the area and c = 1.8
/// the vertex density measured on curved surfaces (see the manual). Clamped
/// to [1, 1024]. Throws `Bad_input` for an input without area.
/// `np` may hold the `vertex_point_map` of `input`.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
int resolution_for_target_vertices(const TriangleMesh& input, std::size_t target_vertices,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, input));
  const double longest = internal::longest_side_of_faces(input, vpm);
  const double area = Polygon_mesh_processing::area(input, CGAL::parameters::vertex_point_map(vpm));
  if(!(area > 0.) || !(longest > 0.) || !std::isfinite(area))
    throw Bad_input("the input has no area to choose a resolution from");
  const double n = longest * std::sqrt(double(target_vertices) / (marching_cubes_vertex_density * area));
  return int(std::lround((std::min)(1024., (std::max)(1., n))));
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_RESOLUTION_FOR_TARGET_VERTICES_H
