// SPDX-License-Identifier: GPL-3.0-or-later
//
// Phase 2 of the nonobtuse Marching Cubes (thesis, section 4.2.2): the
// triangles met by a cube are grouped into edge-connected patches, and each
// patch gives the cube's eight corners a sign of its own.
//
// For a corner and one of its three cube edges, the patch triangle that
// crosses the edge closest to the corner votes: '+' when the corner is on the
// side its normal points to (outside), '-' otherwise; an edge the patch does
// not cross abstains. A corner voted both ways is a conflict and the patch is
// ignored. Corners left without a vote take their neighbours' signs along the
// cube edges (sign flooding); a corner offered both signs in the same round
// is a conflict too. A patch that votes nowhere produces no triangle (a
// "black" patch) but still connects its neighbours in phase 3.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_PATCHES_AND_SIGNS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_PATCHES_AND_SIGNS_H

#include <CGAL/Nonobtuse_remeshing/internal/grid.h>
#include <CGAL/Nonobtuse_remeshing/internal/index_tools.h>
#include <CGAL/Nonobtuse_remeshing/internal/marching_cubes_table.h>
#include <CGAL/Nonobtuse_remeshing/internal/mesh_cube_intersection.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

/// A patch: the input triangles of one cube that are edge-connected there.
struct Patch
{
  enum State { triangulated, black, ignored };
  std::int64_t cube = 0;
  std::vector<std::size_t> triangles;  // sorted input triangle indices
  State state = black;
  bool voted = false;                  // some corner got a vote (not ignored)
  unsigned config = 0;                 // bit c set: corner c is inside ('-'), when voted
};

/// The input as phase 2 needs it: triangles and, per triangle, the three
/// edge-adjacent triangles (or `none`).
struct Input_triangles
{
  static constexpr std::size_t none = std::size_t(-1);
  std::vector<Epick::Triangle_3> triangles;
  std::vector<std::array<std::size_t, 3> > neighbours;
};

namespace signs {

inline Epick::Point_3 corner_point(const Grid& grid, const std::array<int, 3>& cube, int corner)
{
  return Epick::Point_3(grid.coordinate(0, 2 * (cube[0] + marching_cubes::corner_bit(corner, 0))),
                        grid.coordinate(1, 2 * (cube[1] + marching_cubes::corner_bit(corner, 1))),
                        grid.coordinate(2, 2 * (cube[2] + marching_cubes::corner_bit(corner, 2))));
}

// Signs of the eight corners for one patch; false on a conflict. `voted` is
// set when at least one corner got a vote.
inline bool patch_signs(const Grid& grid, const std::array<int, 3>& cube, const Input_triangles& input,
                        const std::vector<std::size_t>& patch, unsigned& config, bool& voted)
{
  std::array<Epick::Point_3, 8> corners;
  for(int c = 0; c < 8; ++c) corners[c] = corner_point(grid, cube, c);
  // per corner: 0 no vote, 1 '+', 2 '-', 3 both
  std::array<int, 8> vote{};
  for(int edge = 0; edge < 12; ++edge) {
    const std::array<int, 2> ends = marching_cubes::edge_corners(edge);
    const int axis = edge / 4;
    const Epick::Point_3& p = corners[ends[0]];
    const Epick::Point_3& q = corners[ends[1]];
    const Epick::Segment_3 segment(p, q);
    // closest crossings to each end; on an exact tie (the edge meets an input
    // edge or vertex) the tied triangles must agree, else the edge abstains
    double best_near_p = 2., best_near_q = -1.;
    std::size_t near_p = Input_triangles::none, near_q = Input_triangles::none;
    bool tie_p = false, tie_q = false;
    for(std::size_t t : patch) {
      const Epick::Triangle_3& tri = input.triangles[t];
      // quick rejection: the edge is axis-parallel
      const Bbox_3 box = tri.bbox();
      bool apart = false;
      for(int a = 0; a < 3 && !apart; ++a) {
        if(a == axis) apart = box.max(a) < p[a] || box.min(a) > q[a];
        else apart = box.max(a) < p[a] || box.min(a) > p[a];
      }
      if(apart || !CGAL::do_intersect(segment, tri)) continue;
      // crossing parameter along p -> q, in double: used only to order crossings
      const Epick::Vector_3 n = CGAL::cross_product(tri[1] - tri[0], tri[2] - tri[0]);
      const double dp = n * (p - tri[0]), dq = n * (q - tri[0]);
      if(dp == dq) continue;  // the edge lies in the triangle's plane
      const double lambda = dp / (dp - dq);
      auto side = [&](std::size_t s, int corner) {
        const Epick::Triangle_3& u = input.triangles[s];
        return CGAL::orientation(u[0], u[1], u[2], corners[corner]);
      };
      if(lambda < best_near_p) { best_near_p = lambda; near_p = t; tie_p = false; }
      else if(lambda == best_near_p && side(t, ends[0]) != side(near_p, ends[0])) tie_p = true;
      if(lambda > best_near_q) { best_near_q = lambda; near_q = t; tie_q = false; }
      else if(lambda == best_near_q && side(t, ends[1]) != side(near_q, ends[1])) tie_q = true;
    }
    auto cast = [&](std::size_t t, bool tied, int corner) {
      if(t == Input_triangles::none || tied) return;
      const Epick::Triangle_3& tri = input.triangles[t];
      const Orientation o = CGAL::orientation(tri[0], tri[1], tri[2], corners[corner]);
      if(o == POSITIVE) vote[corner] |= 1;
      else if(o == NEGATIVE) vote[corner] |= 2;
    };
    cast(near_p, tie_p, ends[0]);
    cast(near_q, tie_q, ends[1]);
  }
  voted = false;
  for(int c = 0; c < 8; ++c) {
    if(vote[c] == 3) return false;
    voted = voted || vote[c] != 0;
  }
  if(!voted) return true;
  // Sign flooding along cube edges, one round at a time.
  for(bool changed = true; changed;) {
    changed = false;
    std::array<int, 8> next = vote;
    for(int c = 0; c < 8; ++c) {
      if(vote[c] != 0) continue;
      int offered = 0;
      for(int a = 0; a < 3; ++a) offered |= vote[c ^ (1 << a)];
      if(offered == 3) return false;
      if(offered != 0) { next[c] = offered; changed = true; }
    }
    vote = next;
  }
  config = 0;
  for(int c = 0; c < 8; ++c)
    if(vote[c] == 2) config |= 1u << c;
  return true;
}

} // namespace signs

/// Splits each cube's triangles into patches and signs them.
inline std::vector<Patch> patches_and_signs(const Grid& grid, const Cube_triangles& cubes,
                                            const Input_triangles& input)
{
  std::vector<Patch> patches;
  Index_sets sets;
  for(std::size_t c = 0; c < cubes.size(); ++c) {
    const std::size_t* begin = cubes.triangles.data() + cubes.first[c];
    const std::size_t* end = cubes.triangles.data() + cubes.first[c + 1];
    const std::size_t n = std::size_t(end - begin);
    sets.reset(n);
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t neighbour : input.neighbours[begin[i]]) {
        if(neighbour == Input_triangles::none) continue;
        const std::size_t* at = std::lower_bound(begin, end, neighbour);
        if(at != end && *at == neighbour) sets.join(i, std::size_t(at - begin));
      }
    const std::size_t first_patch = patches.size();
    std::vector<std::size_t> patch_of_root(n, std::size_t(-1));
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t root = sets.find(i);
      if(patch_of_root[root] == std::size_t(-1)) {
        patch_of_root[root] = patches.size();
        patches.emplace_back();
        patches.back().cube = cubes.cube_ids[c];
      }
      patches[patch_of_root[root]].triangles.push_back(begin[i]);  // stays sorted
    }
    const std::array<int, 3> cube = grid.cube_index(cubes.cube_ids[c]);
    for(std::size_t p = first_patch; p < patches.size(); ++p) {
      bool voted = false;
      unsigned config = 0;
      if(!signs::patch_signs(grid, cube, input, patches[p].triangles, config, voted)) {
        patches[p].state = Patch::ignored;
        continue;
      }
      patches[p].voted = voted;
      patches[p].config = config;
      if(voted && config != 0 && config != 255 && !marching_cubes::table()[config].triangles.empty())
        patches[p].state = Patch::triangulated;
    }
  }
  return patches;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_PATCHES_AND_SIGNS_H
