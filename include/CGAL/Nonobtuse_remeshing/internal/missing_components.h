// SPDX-License-Identifier: GPL-3.0-or-later
//
// Input components that do not appear in a remeshed output (beyond the
// thesis): a connected component of the input is missing when none of its
// vertices lies within `distance` of the output, typically because it is
// smaller or thinner than a cube of the Marching Cubes grid.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_MISSING_COMPONENTS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_MISSING_COMPONENTS_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

struct Component_accounting
{
  std::size_t input_components = 0;
  std::size_t missing = 0;
  double largest_missing_diameter = 0.;  // bounding-box diagonal of the largest missing component
};

template <typename TriangleMesh>
Component_accounting missing_components(const TriangleMesh& input, const TriangleMesh& output, double distance)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<TriangleMesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive> >;

  Component_accounting result;
  std::unordered_map<face_descriptor, std::size_t> face_component;
  result.input_components =
      Polygon_mesh_processing::connected_components(input, boost::make_assoc_property_map(face_component));
  std::vector<std::vector<vertex_descriptor> > members(result.input_components);
  for(face_descriptor f : faces(input))
    for(vertex_descriptor v : vertices_around_face(halfedge(f, input), input))
      members[face_component[f]].push_back(v);

  const auto vpm = get(CGAL::vertex_point, input);
  Tree tree(faces(output).first, faces(output).second, output);
  const bool empty = faces(output).empty();
  if(!empty) tree.accelerate_distance_queries();
  for(std::vector<vertex_descriptor>& component : members) {
    std::sort(component.begin(), component.end());
    component.erase(std::unique(component.begin(), component.end()), component.end());
    bool present = false;
    for(vertex_descriptor v : component)
      if(!empty && CGAL::to_double(tree.squared_distance(get(vpm, v))) <= distance * distance) {
        present = true;
        break;
      }
    if(present) continue;
    ++result.missing;
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for(vertex_descriptor v : component)
      for(int a = 0; a < 3; ++a) {
        lo[a] = (std::min)(lo[a], CGAL::to_double(get(vpm, v)[a]));
        hi[a] = (std::max)(hi[a], CGAL::to_double(get(vpm, v)[a]));
      }
    const double diameter = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                      (hi[2] - lo[2]) * (hi[2] - lo[2]));
    result.largest_missing_diameter = (std::max)(result.largest_missing_diameter, diameter);
  }
  return result;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_MISSING_COMPONENTS_H
