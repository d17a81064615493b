// SPDX-License-Identifier: GPL-3.0-or-later
//
// Phase 3 of the nonobtuse Marching Cubes (thesis, section 4.2.3): the
// per-patch triangulations of phase 2 share nothing yet; this joins them.
//
// Two patches are linked when they lie in face-adjacent cubes and share an
// input triangle (a triangle touching the common face belongs to both
// cubes); chains of links may pass through black or ignored patches, as the
// thesis's stitching rule asks.
// 1. Welding: copies of a cube-edge midpoint made by linked patches of the
//    cubes around that grid edge become one vertex (never two copies from
//    the same cube: that would pinch two sheets together).
// 2. Stitching: on each grid face, the open edges of linked patches that do
//    not match are closed: opposite open edges are zipped, and open cycles of
//    three or four face midpoints are filled with flat triangles in the face
//    (right isosceles, angles 45, 45, 90).
// 3. Clean-up (beyond the thesis, which assumes stitching leaves a
//    manifold): whatever is still not manifold (an edge with more than two
//    triangles or two of the same direction, a vertex with several fans, a
//    face twice) is removed and counted, never left in the output
//    (soup_cleanup.h, as 4).
// 4. Islands (beyond the thesis): near open borders and self-intersections,
//    ignored patches can cut small open fragments off the surface. A piece is removed (and
//    counted) only when it is open, is not the largest piece made from its
//    input component, and has at most max(8, 1%) of that largest piece's
//    triangles; closed pieces and large pieces are real geometry and stay.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_STITCHING_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_STITCHING_H

#include <CGAL/Nonobtuse_remeshing/internal/grid.h>
#include <CGAL/Nonobtuse_remeshing/internal/index_tools.h>
#include <CGAL/Nonobtuse_remeshing/internal/marching_cubes_table.h>
#include <CGAL/Nonobtuse_remeshing/internal/patches_and_signs.h>
#include <CGAL/Nonobtuse_remeshing/internal/soup_cleanup.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

/// The initial mesh as a soup: positions in half-cube units of the grid.
struct Marching_cubes_soup
{
  std::vector<std::array<std::int64_t, 3> > positions;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::size_t> triangle_patch;  // index into the patches
  std::size_t faces_stitched = 0;           // grid faces where stitching acted
  std::size_t welds_refused = 0;            // midpoint groups left apart (same cube)
  std::size_t removed_non_manifold = 0;     // triangles removed by the clean-up
  std::size_t islands_removed = 0;          // small pieces cut off the surface
};


class Stitcher
{
public:
  // `input_component[t]`: the connected component of input triangle t.
  Stitcher(const Grid& grid, const std::vector<std::int64_t>& cube_ids, const std::vector<Patch>& patches,
           std::vector<std::size_t> input_component)
    : grid_(grid), cube_ids_(cube_ids), patches_(patches), input_component_(std::move(input_component))
  {
    // patches of one cube are contiguous and in cube order
    patch_begin_.reserve(cube_ids.size() + 1);
    std::size_t p = 0;
    for(std::int64_t id : cube_ids) {
      patch_begin_.push_back(p);
      while(p < patches.size() && patches[p].cube == id) ++p;
    }
    patch_begin_.push_back(p);
  }

  Marching_cubes_soup run()
  {
    build_soup();
    weld();
    stitch();
    clean_up();
    remove_islands();
    return compact();
  }

private:
  using Position = std::array<std::int64_t, 3>;

  // ---- soup ----------------------------------------------------------------

  void build_soup()
  {
    for(std::size_t p = 0; p < patches_.size(); ++p) {
      const Patch& patch = patches_[p];
      if(patch.state != Patch::triangulated) continue;
      const std::array<int, 3> cube = grid_.cube_index(patch.cube);
      std::array<std::size_t, 13> vertex_of_slot;
      vertex_of_slot.fill(std::size_t(-1));
      for(const std::array<int, 3>& t : marching_cubes::table()[patch.config].triangles) {
        std::array<std::size_t, 3> triangle;
        for(int i = 0; i < 3; ++i) {
          std::size_t& v = vertex_of_slot[t[i]];
          if(v == std::size_t(-1)) {
            const std::array<int, 3> s = marching_cubes::slot_position(t[i]);
            v = positions_.size();
            positions_.push_back({2 * std::int64_t(cube[0]) + s[0], 2 * std::int64_t(cube[1]) + s[1],
                                  2 * std::int64_t(cube[2]) + s[2]});
            vertex_patch_.push_back(p);
          }
          triangle[i] = v;
        }
        triangles_.push_back(triangle);
        triangle_patch_.push_back(p);
      }
    }
    welded_.reset(positions_.size());
  }

  std::size_t find(std::size_t v) { return welded_.find(v); }

  // ---- links between patches -------------------------------------------------

  std::size_t cube_slot(std::int64_t cube_id) const
  {
    const auto it = std::lower_bound(cube_ids_.begin(), cube_ids_.end(), cube_id);
    return (it != cube_ids_.end() && *it == cube_id) ? std::size_t(it - cube_ids_.begin()) : std::size_t(-1);
  }

  // Pairs of linked patches (one in each cube) across the face between a and b.
  const std::vector<std::pair<std::size_t, std::size_t> >& links(std::size_t a, std::size_t b)
  {
    if(a > b) std::swap(a, b);
    const std::uint64_t key = pair_key(a, b);
    auto found = links_.find(key);
    if(found != links_.end()) return found->second;
    std::vector<std::pair<std::size_t, std::size_t> >& result = links_[key];
    for(std::size_t p = patch_begin_[a]; p < patch_begin_[a + 1]; ++p)
      for(std::size_t q = patch_begin_[b]; q < patch_begin_[b + 1]; ++q) {
        const std::vector<std::size_t>& s = patches_[p].triangles;
        const std::vector<std::size_t>& t = patches_[q].triangles;
        std::size_t i = 0, j = 0;
        while(i < s.size() && j < t.size()) {
          if(s[i] == t[j]) { result.emplace_back(p, q); break; }
          (s[i] < t[j]) ? ++i : ++j;
        }
      }
    return result;
  }

  // Connected components of the patches of `cubes` (cube slots, -1 for none),
  // linked across the faces between the pairs of cubes in `adjacent`.
  // Returns the component of each patch index in `component`.
  void components(const std::vector<std::size_t>& cubes,
                  const std::vector<std::pair<int, int> >& adjacent,
                  std::unordered_map<std::size_t, std::size_t>& component)
  {
    component.clear();
    std::vector<std::size_t> nodes;
    for(std::size_t c : cubes)
      if(c != std::size_t(-1))
        for(std::size_t p = patch_begin_[c]; p < patch_begin_[c + 1]; ++p) {
          component[p] = nodes.size();
          nodes.push_back(nodes.size());
        }
    auto root = [&](std::size_t x) {
      while(nodes[x] != x) x = nodes[x] = nodes[nodes[x]];
      return x;
    };
    for(const auto& pair : adjacent) {
      const std::size_t a = cubes[pair.first], b = cubes[pair.second];
      if(a == std::size_t(-1) || b == std::size_t(-1)) continue;
      for(const auto& link : links(a, b)) nodes[root(component[link.first])] = root(component[link.second]);
    }
    for(auto& entry : component) entry.second = root(entry.second);
  }

  // ---- 1. welding ----------------------------------------------------------

  void weld()
  {
    std::vector<std::size_t> order(positions_.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return positions_[a] < positions_[b]; });
    std::unordered_map<std::size_t, std::size_t> component;
    for(std::size_t first = 0; first < order.size();) {
      std::size_t last = first + 1;
      while(last < order.size() && positions_[order[last]] == positions_[order[first]]) ++last;
      const Position& x = positions_[order[first]];
      const int odd = int(x[0] & 1) + int(x[1] & 1) + int(x[2] & 1);
      if(last - first > 1 && odd == 1) {  // a grid-edge midpoint with several copies
        const int axis = (x[0] & 1) ? 0 : ((x[1] & 1) ? 1 : 2);
        const std::array<int, 2> o = marching_cubes::other_axes(axis);
        // the four cubes around the grid edge, in cyclic order
        std::vector<std::size_t> cubes;
        const int around[4][2] = {{-1, -1}, {0, -1}, {0, 0}, {-1, 0}};
        for(const auto& d : around) {
          std::array<int, 3> c;
          c[axis] = int((x[axis] - 1) / 2);
          c[o[0]] = int(x[o[0]] / 2) + d[0];
          c[o[1]] = int(x[o[1]] / 2) + d[1];
          cubes.push_back(grid_.valid_cube(c[0], c[1], c[2]) ? cube_slot(grid_.cube_id(c[0], c[1], c[2]))
                                                            : std::size_t(-1));
        }
        components(cubes, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, component);
        std::map<std::size_t, std::vector<std::size_t> > groups;
        for(std::size_t i = first; i < last; ++i)
          groups[component.at(vertex_patch_[order[i]])].push_back(order[i]);
        for(const auto& group : groups) {
          const std::vector<std::size_t>& copies = group.second;
          if(copies.size() < 2) continue;
          std::vector<std::int64_t> owners;
          for(std::size_t v : copies) owners.push_back(patches_[vertex_patch_[v]].cube);
          std::sort(owners.begin(), owners.end());
          if(std::adjacent_find(owners.begin(), owners.end()) != owners.end()) {
            ++welds_refused_;
            continue;
          }
          for(std::size_t v : copies) welded_.join(v, copies[0]);
        }
      }
      first = last;
    }
  }

  // ---- 2. stitching --------------------------------------------------------

  // The grid face holding two face midpoints, as (axis, lower corner), or
  // false when they are not on a common face.
  static bool common_face(const Position& a, const Position& b, int& axis, Position& corner)
  {
    for(int k = 0; k < 3; ++k) {
      if(a[k] != b[k] || (a[k] & 1)) continue;
      Position low;
      for(int m = 0; m < 3; ++m) {
        if(m == k) { low[m] = a[m]; continue; }
        // the square's lower corner along m: an even value within 2 of both
        const std::int64_t lo = (std::max)(a[m], b[m]) - 2, hi = (std::min)(a[m], b[m]);
        std::int64_t l = lo + (lo & 1);
        if(l > hi) return false;
        // a midpoint is odd along its edge's axis and even elsewhere; pick the
        // corner so that both lie in [l, l + 2]
        if(!((a[m] & 1) || (b[m] & 1))) l = (std::min)(a[m], b[m]);
        if((std::max)(a[m], b[m]) > l + 2) return false;
        low[m] = l;
      }
      axis = k;
      corner = low;
      return true;
    }
    return false;
  }

  struct Open_edge
  {
    std::size_t from, to, patch;
  };

  void stitch()
  {
    // directed edges of the current soup, with canonical vertex ids
    std::unordered_map<std::uint64_t, std::size_t> count;
    for(auto& t : triangles_)
      for(int i = 0; i < 3; ++i) ++count[pair_key(find(t[i]), find(t[(i + 1) % 3]))];
    std::map<std::pair<int, Position>, std::vector<Open_edge> > open;
    for(std::size_t f = 0; f < triangles_.size(); ++f)
      for(int i = 0; i < 3; ++i) {
        const std::size_t u = find(triangles_[f][i]), v = find(triangles_[f][(i + 1) % 3]);
        if(count[pair_key(u, v)] != 1 || count.count(pair_key(v, u))) continue;
        const Position &a = positions_[u], &b = positions_[v];
        if(((a[0] & 1) + (a[1] & 1) + (a[2] & 1)) != 1 || ((b[0] & 1) + (b[1] & 1) + (b[2] & 1)) != 1)
          continue;  // a centre is not on a face
        int axis;
        Position corner;
        if(!common_face(a, b, axis, corner)) continue;
        open[{axis, corner}].push_back({u, v, triangle_patch_[f]});
      }
    std::unordered_map<std::size_t, std::size_t> component;
    for(auto& entry : open) {
      std::vector<Open_edge>& edges = entry.second;
      if(edges.size() < 2) continue;
      const int axis = entry.first.first;
      const Position& corner = entry.first.second;
      // the two cubes sharing the face
      std::array<int, 3> below = {int(corner[0] / 2), int(corner[1] / 2), int(corner[2] / 2)};
      std::array<int, 3> above = below;
      below[axis] -= 1;
      std::vector<std::size_t> cubes;
      for(const auto& c : {below, above})
        cubes.push_back(grid_.valid_cube(c[0], c[1], c[2]) ? cube_slot(grid_.cube_id(c[0], c[1], c[2]))
                                                          : std::size_t(-1));
      components(cubes, {{0, 1}}, component);
      std::map<std::size_t, std::vector<Open_edge> > groups;
      for(const Open_edge& e : edges) groups[component.at(e.patch)].push_back(e);
      bool acted = false;
      for(auto& group : groups) acted = close_open_edges(group.second) || acted;
      faces_stitched_ += acted;
    }
  }

  // Zips opposite open edges and fills open 3- and 4-cycles of one group.
  bool close_open_edges(std::vector<Open_edge>& edges)
  {
    bool acted = false;
    std::vector<bool> used(edges.size(), false);
    auto at = [&](std::size_t v) { return positions_[v]; };
    // zip: u -> v against v' -> u' at the same positions
    for(std::size_t i = 0; i < edges.size(); ++i)
      for(std::size_t j = i + 1; j < edges.size() && !used[i]; ++j)
        if(!used[j] && at(edges[i].from) == at(edges[j].to) && at(edges[i].to) == at(edges[j].from)) {
          welded_.join(edges[j].to, edges[i].from);
          welded_.join(edges[j].from, edges[i].to);
          used[i] = used[j] = true;
          acted = true;
        }
    // cycles: follow open edges head to tail by position
    for(std::size_t start = 0; start < edges.size(); ++start) {
      if(used[start]) continue;
      std::vector<std::size_t> cycle = {start};
      while(cycle.size() <= 4) {
        const Position head = at(edges[cycle.back()].to);
        if(head == at(edges[start].from) && cycle.size() >= 3) break;
        std::size_t next = std::size_t(-1);
        for(std::size_t j = 0; j < edges.size(); ++j)
          if(!used[j] && std::find(cycle.begin(), cycle.end(), j) == cycle.end() && at(edges[j].from) == head) {
            next = j;
            break;
          }
        if(next == std::size_t(-1)) { cycle.clear(); break; }
        cycle.push_back(next);
      }
      if(cycle.size() < 3 || cycle.size() > 4 || at(edges[cycle.back()].to) != at(edges[start].from)) continue;
      for(std::size_t k = 0; k < cycle.size(); ++k) {
        const Open_edge& e = edges[cycle[k]];
        const Open_edge& f = edges[cycle[(k + 1) % cycle.size()]];
        welded_.join(f.from, e.to);
        used[cycle[k]] = true;
      }
      // reversed cycle x1 <- x2 <- ... : triangles (x1, xn, x(n-1)), ..., (x1, x3, x2)
      const std::size_t patch = edges[start].patch;
      for(std::size_t k = cycle.size() - 1; k >= 2; --k) {
        triangles_.push_back({edges[cycle[0]].from, edges[cycle[k]].from, edges[cycle[k - 1]].from});
        triangle_patch_.push_back(patch);
      }
      acted = true;
    }
    return acted;
  }

  // ---- 3. clean-up ---------------------------------------------------------

  void clean_up()
  {
    for(auto& t : triangles_)
      for(auto& v : t) v = find(v);
    removed_non_manifold_ = remove_non_manifold_triangles(triangles_, triangle_patch_, positions_.size());
  }

  // ---- 4. islands ----------------------------------------------------------

  void remove_islands()
  {
    std::vector<std::size_t> component(triangles_.size());
    for(std::size_t f = 0; f < triangles_.size(); ++f)
      component[f] = input_component_[patches_[triangle_patch_[f]].triangles.front()];
    islands_removed_ = internal::remove_islands(triangles_, triangle_patch_, component);
  }

  Marching_cubes_soup compact()
  {
    Marching_cubes_soup soup;
    std::vector<std::size_t> index(positions_.size(), std::size_t(-1));
    for(auto& t : triangles_) {
      std::array<std::size_t, 3> out;
      for(int i = 0; i < 3; ++i) {
        if(index[t[i]] == std::size_t(-1)) {
          index[t[i]] = soup.positions.size();
          soup.positions.push_back(positions_[t[i]]);
        }
        out[i] = index[t[i]];
      }
      soup.triangles.push_back(out);
    }
    soup.triangle_patch = triangle_patch_;
    soup.faces_stitched = faces_stitched_;
    soup.welds_refused = welds_refused_;
    soup.removed_non_manifold = removed_non_manifold_;
    soup.islands_removed = islands_removed_;
    return soup;
  }

  const Grid& grid_;
  const std::vector<std::int64_t>& cube_ids_;
  const std::vector<Patch>& patches_;
  const std::vector<std::size_t> input_component_;
  std::vector<std::size_t> patch_begin_;
  std::unordered_map<std::uint64_t, std::vector<std::pair<std::size_t, std::size_t> > > links_;

  std::vector<Position> positions_;
  std::vector<std::size_t> vertex_patch_;
  Index_sets welded_;  // copies of a vertex welded into one
  std::vector<std::array<std::size_t, 3> > triangles_;
  std::vector<std::size_t> triangle_patch_;
  std::size_t faces_stitched_ = 0, welds_refused_ = 0, removed_non_manifold_ = 0, islands_removed_ = 0;
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_STITCHING_H
