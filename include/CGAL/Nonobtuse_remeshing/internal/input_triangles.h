// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input of the nonobtuse Marching Cubes (thesis, chapter 4) as its
// phases see it: the triangles, read through the vertex point map as Epick
// triangles, their edge neighbours, and their edge-connected components.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_INPUT_TRIANGLES_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_INPUT_TRIANGLES_H

#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>
#include <CGAL/Nonobtuse_remeshing/internal/index_tools.h>
#include <CGAL/Nonobtuse_remeshing/internal/patches_and_signs.h>

#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cstddef>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

template <typename TriangleMesh, typename VertexPointMap>
Input_triangles input_triangles(const TriangleMesh& mesh, VertexPointMap points)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  const auto vpm = epick_points(points);
  std::unordered_map<face_descriptor, std::size_t> index;
  std::size_t i = 0;
  for(face_descriptor f : faces(mesh)) index[f] = i++;
  Input_triangles input;
  for(face_descriptor f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    input.triangles.emplace_back(get(vpm, source(h, mesh)), get(vpm, target(h, mesh)),
                                 get(vpm, target(next(h, mesh), mesh)));
    std::array<std::size_t, 3> neighbours;
    auto g = h;
    for(int k = 0; k < 3; ++k, g = next(g, mesh)) {
      const auto o = opposite(g, mesh);
      neighbours[k] = is_border(o, mesh) ? Input_triangles::none : index.at(face(o, mesh));
    }
    input.neighbours.push_back(neighbours);
  }
  return input;
}

// Edge-connected component of each input triangle.
inline std::vector<std::size_t> input_components(const Input_triangles& input)
{
  Index_sets sets(input.triangles.size());
  for(std::size_t t = 0; t < input.triangles.size(); ++t)
    for(std::size_t n : input.neighbours[t])
      if(n != Input_triangles::none) sets.join(t, n);
  return sets.representatives();
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_INPUT_TRIANGLES_H
