// SPDX-License-Identifier: GPL-3.0-or-later
//
// The other sign source of the nonobtuse Marching Cubes, for closed inputs
// (beyond the thesis, whose signs come from the patches of section 4.2.2):
// one sign per grid corner from CGAL's exact inside test, and the
// orientation of the result taken from the input's.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_INSIDE_TEST_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_INSIDE_TEST_H

#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>
#include <CGAL/Nonobtuse_remeshing/internal/grid.h>
#include <CGAL/Nonobtuse_remeshing/internal/marching_cubes_table.h>
#include <CGAL/Nonobtuse_remeshing/internal/mesh_cube_intersection.h>
#include <CGAL/Nonobtuse_remeshing/internal/patches_and_signs.h>
#include <CGAL/Nonobtuse_remeshing/internal/stitching.h>

#include <CGAL/Side_of_triangle_mesh.h>

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// One patch per cube, signed by an exact inside test at the grid corners.
template <typename TriangleMesh, typename VertexPointMap>
std::vector<Patch> inside_test_patches(const TriangleMesh& mesh, VertexPointMap points, const Grid& grid,
                                       const Cube_triangles& cubes)
{
  const Side_of_triangle_mesh<TriangleMesh, Epick, Epick_points_t<VertexPointMap> > side(mesh, epick_points(points));
  std::unordered_map<std::int64_t, bool> inside;
  std::vector<Patch> patches;
  for(std::size_t c = 0; c < cubes.size(); ++c) {
    Patch patch;
    patch.cube = cubes.cube_ids[c];
    patch.triangles.assign(cubes.triangles.begin() + cubes.first[c], cubes.triangles.begin() + cubes.first[c + 1]);
    const std::array<int, 3> cube = grid.cube_index(patch.cube);
    for(int corner = 0; corner < 8; ++corner) {
      const int i = cube[0] + marching_cubes::corner_bit(corner, 0), j = cube[1] + marching_cubes::corner_bit(corner, 1),
                k = cube[2] + marching_cubes::corner_bit(corner, 2);
      auto found = inside.find(grid.corner_id(i, j, k));
      if(found == inside.end())
        found = inside.emplace(grid.corner_id(i, j, k),
                               side(signs::corner_point(grid, cube, corner)) != ON_UNBOUNDED_SIDE).first;
      if(found->second) patch.config |= 1u << corner;
    }
    patch.state = (patch.config != 0 && patch.config != 255) ? Patch::triangulated : Patch::black;
    patches.push_back(std::move(patch));
  }
  return patches;
}

// The inside test ignores the input's orientation, so its triangles point
// out of the solid. Each output component is flipped when the input
// component it mostly comes from is oriented inwards (negative signed volume).
inline void orient_like_input(const Input_triangles& input, const std::vector<std::size_t>& input_component,
                              const std::vector<Patch>& patches, Marching_cubes_soup& soup)
{
  std::unordered_map<std::size_t, double> volume;  // six times the signed volume
  for(std::size_t t = 0; t < input.triangles.size(); ++t) {
    const Epick::Triangle_3& tri = input.triangles[t];
    volume[input_component[t]] += CGAL::determinant(tri[0] - ORIGIN, tri[1] - ORIGIN, tri[2] - ORIGIN);
  }
  const std::vector<std::size_t> root = edge_connected_components(soup.triangles);
  std::unordered_map<std::size_t, long> vote;
  for(std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const std::size_t t = patches[soup.triangle_patch[f]].triangles.front();
    vote[root[f]] += volume[input_component[t]] < 0 ? -1 : 1;
  }
  for(std::size_t f = 0; f < soup.triangles.size(); ++f)
    if(vote[root[f]] < 0) std::swap(soup.triangles[f][1], soup.triangles[f][2]);
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_INSIDE_TEST_H
