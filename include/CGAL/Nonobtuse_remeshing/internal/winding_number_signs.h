// SPDX-License-Identifier: GPL-3.0-or-later
//
// Corner signs from the generalized winding number w (winding_number.h),
// beyond the thesis, whose signs come from the patches of section 4.2.2.
// The input counts as oriented outwards unless its signed volume is
// negative, in which case w is negated first. A corner is inside what the
// input encloses when w rounds to 1 or more: the union of overlapping parts
// (w = 2 where two overlap). Where w rounds below 0, a part of the surface
// has been pushed through another one and turned inside out (a dent pushed
// through the opposite wall); that pocket is outside, as the space a finger
// pushed through clay leaves is a hole.
//
// - `winding_number_patches`: every cube is one patch signed by w alone; the
//   surface is closed wherever the input is closed up to gaps smaller than
//   about a cube (larger holes are crossed by no cube that holds a triangle).
// - `sign_overlaps_and_gaps_by_winding_number`: the patches stay, except in
//   cubes where the input overlaps itself or has a gap: a patch claims a
//   corner is outside its sheet while w says the corner lies inside another
//   part (the sheet is buried in a solid), two patches claim the same corner
//   (two solids overlap), the patch's votes conflict, w is negative at a
//   corner, or the cube or one of its 26 neighbours holds a triangle that
//   intersects another one or borders a gap (near the curves where the input
//   crosses itself the wedges between the sheets are thinner than a cube and
//   look like thin parts; at a gap the patches leave a hole). A gap is a
//   border cycle whose bounding box is smaller than a cube (its diagonal);
//   larger cycles are the input's own borders, which the patches keep. Such a
//   cube is signed by w when w is clearly an integer (within 0.25) at all its
//   corners: off the input's real borders and open sheets, where w is
//   fractional. A patch that says inside where w says outside is a part
//   thinner than a cube, which the patches keep and w would lose: it stays.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_WINDING_NUMBER_SIGNS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_WINDING_NUMBER_SIGNS_H

#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>
#include <CGAL/Nonobtuse_remeshing/internal/grid.h>
#include <CGAL/Nonobtuse_remeshing/internal/index_tools.h>
#include <CGAL/Nonobtuse_remeshing/internal/marching_cubes_table.h>
#include <CGAL/Nonobtuse_remeshing/internal/mesh_cube_intersection.h>
#include <CGAL/Nonobtuse_remeshing/internal/parallel.h>
#include <CGAL/Nonobtuse_remeshing/internal/patches_and_signs.h>
#include <CGAL/Nonobtuse_remeshing/internal/winding_number.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

/// The pairs of input faces that intersect (CGAL's exact test, on the pool's
/// cores with oneTBB), as indices in the order of `faces(mesh)`, sorted so
/// that they do not depend on the number of threads.
template <typename TriangleMesh, typename VertexPointMap>
std::vector<std::pair<std::size_t, std::size_t> > crossing_face_pairs(const TriangleMesh& mesh,
                                                                     VertexPointMap points, const Thread_pool& pool)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  const auto np = CGAL::parameters::vertex_point_map(epick_points(points)).geom_traits(Epick());
  std::vector<std::pair<face_descriptor, face_descriptor> > pairs;
#ifdef CGAL_LINKED_WITH_TBB
  if(pool.workers() > 1)
    Polygon_mesh_processing::self_intersections<Parallel_tag>(faces(mesh), mesh, std::back_inserter(pairs), np);
  else
#endif
    Polygon_mesh_processing::self_intersections(faces(mesh), mesh, std::back_inserter(pairs), np);
  (void)pool;
  std::vector<std::pair<std::size_t, std::size_t> > result;
  if(pairs.empty()) return result;
  std::unordered_map<face_descriptor, std::size_t> index;
  for(face_descriptor f : faces(mesh)) index.emplace(f, index.size());
  for(const auto& pair : pairs) {
    const std::size_t a = index.at(pair.first), b = index.at(pair.second);
    result.emplace_back((std::min)(a, b), (std::max)(a, b));
  }
  std::sort(result.begin(), result.end());
  return result;
}

/// Per input face (in the order of `faces(mesh)`), whether it intersects
/// another face.
template <typename TriangleMesh, typename VertexPointMap>
std::vector<bool> crossing_faces(const TriangleMesh& mesh, VertexPointMap points, const Thread_pool& pool)
{
  std::vector<bool> crossing(faces(mesh).size(), false);
  for(const auto& pair : crossing_face_pairs(mesh, points, pool)) crossing[pair.first] = crossing[pair.second] = true;
  return crossing;
}

/// Per input face (in the order of `faces(mesh)`), whether it borders a gap:
/// a border cycle whose bounding box has a diagonal shorter than `size` (a
/// cube). Longer border cycles are the input's own borders.
template <typename TriangleMesh, typename VertexPointMap>
std::vector<bool> gap_faces(const TriangleMesh& mesh, VertexPointMap points, double size)
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  const auto vpm = epick_points(points);
  std::vector<bool> gap(faces(mesh).size(), false);
  std::vector<halfedge_descriptor> cycles;
  Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  std::unordered_map<face_descriptor, std::size_t> index;
  for(halfedge_descriptor start : cycles) {
    Bbox_3 box;
    for(halfedge_descriptor h : halfedges_around_face(start, mesh)) box += get(vpm, target(h, mesh)).bbox();
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    if(!(diagonal < size)) continue;
    if(index.empty())
      for(face_descriptor f : faces(mesh)) index.emplace(f, index.size());
    for(halfedge_descriptor h : halfedges_around_face(start, mesh)) gap[index.at(face(opposite(h, mesh), mesh))] = true;
  }
  return gap;
}

/// The winding number at every corner of the cubes met by the input.
class Corner_winding_numbers
{
public:
  Corner_winding_numbers(const Grid& grid, const Cube_triangles& cubes, const Input_triangles& input,
                         const std::vector<bool>& usable, Thread_pool& pool)
    : grid_(grid)
  {
    for(std::int64_t id : cubes.cube_ids) {
      const std::array<int, 3> cube = grid.cube_index(id);
      for(int corner = 0; corner < 8; ++corner) ids_.push_back(corner_id(cube, corner));
    }
    std::sort(ids_.begin(), ids_.end());
    ids_.erase(std::unique(ids_.begin(), ids_.end()), ids_.end());
    double volume = 0.;  // six times the input's signed volume
    for(const Epick::Triangle_3& t : input.triangles)
      volume += CGAL::determinant(t[0] - ORIGIN, t[1] - ORIGIN, t[2] - ORIGIN);
    inwards_ = volume < 0.;
    const Winding_number winding_number(input.triangles, usable);
    values_.resize(ids_.size());
    const std::int64_t nx = grid.cubes(0) + 1, ny = grid.cubes(1) + 1;
    pool.for_each(ids_.size(), [&](std::size_t i, int) {
      const std::int64_t id = ids_[i];
      const std::int64_t x = id % nx, y = (id / nx) % ny, z = id / (nx * ny);
      const double w = winding_number({grid.coordinate(0, 2 * x), grid.coordinate(1, 2 * y), grid.coordinate(2, 2 * z)});
      values_[i] = inwards_ ? -w : w;
    });
  }

  /// Whether the input is oriented inwards (negative signed volume).
  bool inwards() const { return inwards_; }

  /// The winding number at a corner of a cube, negated when the input is
  /// oriented inwards.
  double at(const std::array<int, 3>& cube, int corner) const
  {
    return values_[std::size_t(std::lower_bound(ids_.begin(), ids_.end(), corner_id(cube, corner)) - ids_.begin())];
  }

  /// Inside what the input encloses.
  static bool inside(double w) { return std::lround(w) >= 1; }
  /// In a pocket turned inside out.
  static bool inverted(double w) { return std::lround(w) < 0; }
  /// Clearly an integer: off the input's borders and gaps.
  static bool decisive(double w) { return std::abs(w - double(std::lround(w))) <= 0.25; }

private:
  std::int64_t corner_id(const std::array<int, 3>& cube, int corner) const
  {
    return grid_.corner_id(cube[0] + marching_cubes::corner_bit(corner, 0), cube[1] + marching_cubes::corner_bit(corner, 1),
                           cube[2] + marching_cubes::corner_bit(corner, 2));
  }

  const Grid& grid_;
  std::vector<std::int64_t> ids_;
  std::vector<double> values_;
  bool inwards_ = false;
};

namespace signs {

// One patch holding all triangles of cube c, with the given configuration.
inline Patch whole_cube_patch(const Cube_triangles& cubes, std::size_t c, unsigned config)
{
  Patch patch;
  patch.cube = cubes.cube_ids[c];
  patch.triangles.assign(cubes.triangles.begin() + std::ptrdiff_t(cubes.first[c]),
                         cubes.triangles.begin() + std::ptrdiff_t(cubes.first[c + 1]));
  patch.config = config;
  patch.state = (config != 0 && config != 255 && !marching_cubes::table()[config].triangles.empty())
                    ? Patch::triangulated : Patch::black;
  return patch;
}

// Input components that meet in a cube signed by the winding number are one
// solid there (their union): they become one component (for the islands of
// the stitching and the orientation).
// `signed_by_w`: indices of those patches.
inline void join_components(const std::vector<Patch>& patches, const std::vector<std::size_t>& signed_by_w,
                            std::vector<std::size_t>& component)
{
  Index_sets sets(component.size());
  for(std::size_t p : signed_by_w)
    for(std::size_t t : patches[p].triangles) sets.join(component[t], component[patches[p].triangles.front()]);
  for(std::size_t& c : component) c = sets.find(c);
}

} // namespace signs

/// One patch per cube, signed by the winding number; the output is oriented
/// out of the enclosed region (`orient_like_input` restores the input's).
/// `input_component` (per input triangle) is joined where components meet.
inline std::vector<Patch> winding_number_patches(const Grid& grid, const Cube_triangles& cubes,
                                                 const Corner_winding_numbers& w,
                                                 std::vector<std::size_t>& input_component)
{
  std::vector<Patch> patches;
  patches.reserve(cubes.size());
  for(std::size_t c = 0; c < cubes.size(); ++c) {
    const std::array<int, 3> cube = grid.cube_index(cubes.cube_ids[c]);
    unsigned config = 0;
    for(int corner = 0; corner < 8; ++corner)
      if(Corner_winding_numbers::inside(w.at(cube, corner))) config |= 1u << corner;
    patches.push_back(signs::whole_cube_patch(cubes, c, config));
  }
  std::vector<std::size_t> all(patches.size());
  std::iota(all.begin(), all.end(), std::size_t(0));
  signs::join_components(patches, all, input_component);
  return patches;
}

/// Replaces the patches of the cubes where the input overlaps itself or has
/// a gap (see the file comment) by one patch signed by the winding number.
/// `defect[t]`: input triangle t crosses another one or borders a gap.
/// The input's orientation is kept: when it is oriented inwards the enclosed
/// region is the patches' outside. `input_component` is joined where
/// components meet. Returns the number of cubes signed by the winding number.
inline std::size_t sign_overlaps_and_gaps_by_winding_number(const Grid& grid, const Cube_triangles& cubes,
                                                            const Corner_winding_numbers& w,
                                                            const std::vector<bool>& defect, std::vector<Patch>& patches,
                                                            std::vector<std::size_t>& input_component)
{
  const bool inwards = w.inwards();
  std::vector<std::int64_t> defect_cubes;  // cubes holding a defect triangle
  for(std::size_t c = 0; c < cubes.size(); ++c)
    for(std::size_t i = cubes.first[c]; i < cubes.first[c + 1]; ++i)
      if(defect[cubes.triangles[i]]) {
        defect_cubes.push_back(cubes.cube_ids[c]);
        break;
      }
  std::sort(defect_cubes.begin(), defect_cubes.end());
  const auto near_defect = [&](const std::array<int, 3>& cube) {
    for(int dx = -1; dx <= 1; ++dx)
      for(int dy = -1; dy <= 1; ++dy)
        for(int dz = -1; dz <= 1; ++dz)
          if(grid.valid_cube(cube[0] + dx, cube[1] + dy, cube[2] + dz) &&
             std::binary_search(defect_cubes.begin(), defect_cubes.end(),
                                grid.cube_id(cube[0] + dx, cube[1] + dy, cube[2] + dz)))
            return true;
    return false;
  };
  // the patches [begin, end) of a cube whose corners enclose `enclosed`
  const auto patches_overlap = [&](std::size_t begin, std::size_t end, unsigned enclosed) {
    unsigned claimed = 0;  // corners some patch puts inside its sheet
    for(std::size_t p = begin; p < end; ++p) {
      if(patches[p].state == Patch::ignored) return true;
      if(!patches[p].voted) continue;
      const unsigned patch_inside = inwards ? ~patches[p].config & 255u : patches[p].config;
      // outside its sheet but inside another part, or inside two sheets
      // (the two sides of a thin part each claim the corners beyond the other)
      if((enclosed & ~patch_inside) != 0 || (claimed & patch_inside) != 0) return true;
      claimed |= patch_inside;
    }
    return false;
  };
  std::vector<Patch> result;
  result.reserve(patches.size());
  std::vector<std::size_t> signed_by_w;  // indices into result
  for(std::size_t c = 0, begin = 0; c < cubes.size(); ++c) {
    std::size_t end = begin;
    while(end < patches.size() && patches[end].cube == cubes.cube_ids[c]) ++end;
    const std::array<int, 3> cube = grid.cube_index(cubes.cube_ids[c]);
    bool decisive = true, inverted = false;
    unsigned enclosed = 0;  // corners inside the enclosed region
    for(int corner = 0; corner < 8; ++corner) {
      const double value = w.at(cube, corner);
      decisive = decisive && Corner_winding_numbers::decisive(value);
      inverted = inverted || Corner_winding_numbers::inverted(value);
      if(Corner_winding_numbers::inside(value)) enclosed |= 1u << corner;
    }
    if(decisive && (inverted || near_defect(cube) || patches_overlap(begin, end, enclosed))) {
      signed_by_w.push_back(result.size());
      result.push_back(signs::whole_cube_patch(cubes, c, inwards ? ~enclosed & 255u : enclosed));
    } else {
      result.insert(result.end(), std::make_move_iterator(patches.begin() + std::ptrdiff_t(begin)),
                    std::make_move_iterator(patches.begin() + std::ptrdiff_t(end)));
    }
    begin = end;
  }
  signs::join_components(result, signed_by_w, input_component);
  patches.swap(result);
  return signed_by_w.size();
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_WINDING_NUMBER_SIGNS_H
