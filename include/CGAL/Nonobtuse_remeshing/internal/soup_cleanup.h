// SPDX-License-Identifier: GPL-3.0-or-later
//
// The end of phase 3 of the nonobtuse Marching Cubes (stitching.h), on the
// welded and stitched soup: what is still not manifold is removed, then the
// small open islands near borders and self-intersections (both beyond the
// thesis, which assumes stitching leaves a manifold; see stitching.h).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_SOUP_CLEANUP_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_SOUP_CLEANUP_H

#include <CGAL/Nonobtuse_remeshing/internal/index_tools.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

/// Component of each triangle of a soup, triangles being joined through
/// shared edges (either orientation): a representative triangle index each.
inline std::vector<std::size_t> edge_connected_components(const std::vector<std::array<std::size_t, 3> >& triangles)
{
  Index_sets sets(triangles.size());
  std::unordered_map<std::uint64_t, std::size_t> owner;
  for(std::size_t f = 0; f < triangles.size(); ++f)
    for(int i = 0; i < 3; ++i) {
      const auto inserted = owner.emplace(edge_key(triangles[f][i], triangles[f][(i + 1) % 3]), f);
      if(!inserted.second) sets.join(f, inserted.first->second);
    }
  return sets.representatives();
}

// Keeps the triangles (and their patches) flagged in `keep`, in order.
inline void keep_triangles(std::vector<std::array<std::size_t, 3> >& triangles,
                           std::vector<std::size_t>& triangle_patch, const std::vector<bool>& keep)
{
  std::size_t kept = 0;
  for(std::size_t f = 0; f < triangles.size(); ++f)
    if(keep[f]) {
      triangles[kept] = triangles[f];
      triangle_patch[kept] = triangle_patch[f];
      ++kept;
    }
  triangles.resize(kept);
  triangle_patch.resize(kept);
}

// Clean-up: removes every triangle that makes the soup non-manifold (an edge
// with more than two triangles or two of the same direction, a vertex with
// several fans, a face twice), until none is left; returns how many.
inline std::size_t remove_non_manifold_triangles(std::vector<std::array<std::size_t, 3> >& triangles,
                                                 std::vector<std::size_t>& triangle_patch, std::size_t vertex_count)
{
  std::size_t count = 0;
  std::vector<bool> removed(triangles.size(), false);
  for(bool changed = true; changed;) {
    changed = false;
    auto remove = [&](std::size_t f) {
      if(!removed[f]) { removed[f] = true; ++count; changed = true; }
    };
    // the same face twice (either orientation): sorted by their sorted
    // corners, equal neighbours are the same face
    std::vector<std::pair<std::array<std::size_t, 3>, std::size_t> > by_vertices;
    by_vertices.reserve(triangles.size());
    for(std::size_t f = 0; f < triangles.size(); ++f) {
      if(removed[f]) continue;
      std::array<std::size_t, 3> s = triangles[f];
      std::sort(s.begin(), s.end());
      by_vertices.emplace_back(s, f);
    }
    std::sort(by_vertices.begin(), by_vertices.end());
    for(std::size_t i = 0, j = 0; i < by_vertices.size(); i = j) {
      while(j < by_vertices.size() && by_vertices[j].first == by_vertices[i].first) ++j;
      if(j - i > 1)
        for(std::size_t k = i; k < j; ++k) remove(by_vertices[k].second);
    }
    // edges: at most one triangle per direction, at most two in all (the
    // uses of an edge, sorted by its lower and higher vertex, then face)
    std::vector<std::array<std::size_t, 4> > uses;  // lower, higher, face, whether lower -> higher
    uses.reserve(3 * triangles.size());
    for(std::size_t f = 0; f < triangles.size(); ++f) {
      if(removed[f]) continue;
      for(int i = 0; i < 3; ++i) {
        const std::size_t u = triangles[f][i], v = triangles[f][(i + 1) % 3];
        uses.push_back({(std::min)(u, v), (std::max)(u, v), f, std::size_t(u < v)});
      }
    }
    std::sort(uses.begin(), uses.end());
    for(std::size_t i = 0, j = 0; i < uses.size(); i = j) {
      while(j < uses.size() && uses[j][0] == uses[i][0] && uses[j][1] == uses[i][1]) ++j;
      if(j - i > 2 || (j - i == 2 && uses[i][3] == uses[i + 1][3]))
        for(std::size_t k = i; k < j; ++k) remove(uses[k][2]);
    }
    if(changed) continue;
    // vertices: the faces around each vertex form one fan (the faces of
    // vertex v: around[first[v], first[v + 1]), in order)
    std::vector<std::size_t> first(vertex_count + 1, 0);
    for(std::size_t f = 0; f < triangles.size(); ++f)
      if(!removed[f])
        for(std::size_t v : triangles[f]) ++first[v + 1];
    for(std::size_t v = 0; v < vertex_count; ++v) first[v + 1] += first[v];
    std::vector<std::size_t> around(first.back()), next(first.begin(), first.end() - 1);
    for(std::size_t f = 0; f < triangles.size(); ++f)
      if(!removed[f])
        for(std::size_t v : triangles[f]) around[next[v]++] = f;
    Index_sets fan;
    std::vector<std::pair<std::size_t, std::size_t> > size;  // each fan's root and faces
    for(std::size_t v = 0; v < vertex_count; ++v) {
      const std::size_t* fs = around.data() + first[v];
      const std::size_t valence = first[v + 1] - first[v];
      if(valence < 2) continue;
      fan.reset(valence);
      for(std::size_t i = 0; i < valence; ++i)
        for(std::size_t j = i + 1; j < valence; ++j) {
          int shared = 0;
          for(std::size_t a : triangles[fs[i]])
            for(std::size_t b : triangles[fs[j]]) shared += (a == b);
          if(shared >= 2) fan.join(i, j);
        }
      size.clear();
      for(std::size_t i = 0; i < valence; ++i) {
        const std::size_t root = fan.find(i);
        const auto known = std::find_if(size.begin(), size.end(), [&](const auto& e) { return e.first == root; });
        if(known == size.end()) size.emplace_back(root, 1);
        else ++known->second;
      }
      if(size.size() < 2) continue;
      std::sort(size.begin(), size.end());
      std::size_t keep = size.front().first, most = size.front().second;  // the largest fan, the first root on a tie
      for(const auto& s : size)
        if(s.second > most) {
          keep = s.first;
          most = s.second;
        }
      for(std::size_t i = 0; i < valence; ++i)
        if(fan.find(i) != keep) remove(fs[i]);
    }
  }
  std::vector<bool> keep(removed.size());
  for(std::size_t f = 0; f < removed.size(); ++f) keep[f] = !removed[f];
  keep_triangles(triangles, triangle_patch, keep);
  return count;
}

// Islands: a piece is removed only when it is open, is not the largest piece
// made from its input component (`component`, per triangle), and has at most
// max(8, 1%) of that largest piece's triangles; returns how many pieces.
inline std::size_t remove_islands(std::vector<std::array<std::size_t, 3> >& triangles,
                                  std::vector<std::size_t>& triangle_patch, const std::vector<std::size_t>& component)
{
  const std::size_t n = triangles.size();
  const std::vector<std::size_t> root = edge_connected_components(triangles);
  // size of each output component, and the input component it mostly comes from
  std::unordered_map<std::size_t, std::size_t> size;
  std::unordered_map<std::size_t, std::unordered_map<std::size_t, std::size_t> > votes;
  for(std::size_t f = 0; f < n; ++f) {
    ++size[root[f]];
    ++votes[root[f]][component[f]];
  }
  std::unordered_map<std::size_t, std::size_t> largest;  // input component -> its largest piece
  std::unordered_map<std::size_t, std::size_t> source;
  for(const auto& entry : votes) {
    std::size_t top = 0, count = 0;
    for(const auto& v : entry.second)
      if(v.second > count || (v.second == count && v.first < top)) { top = v.first; count = v.second; }
    source[entry.first] = top;
    auto kept = largest.find(top);
    if(kept == largest.end() || size[entry.first] > size[kept->second] ||
       (size[entry.first] == size[kept->second] && entry.first < kept->second))
      largest[top] = entry.first;
  }
  // pieces with a border edge (an edge used once)
  std::unordered_map<std::uint64_t, int> uses;
  for(const auto& t : triangles)
    for(int i = 0; i < 3; ++i) {
      const std::size_t u = t[i], v = t[(i + 1) % 3];
      ++uses[edge_key(u, v)];
    }
  std::unordered_set<std::size_t> open;
  for(std::size_t f = 0; f < n; ++f)
    for(int i = 0; i < 3; ++i) {
      const std::size_t u = triangles[f][i], v = triangles[f][(i + 1) % 3];
      if(uses[edge_key(u, v)] == 1) open.insert(root[f]);
    }
  std::unordered_set<std::size_t> removed;
  for(const auto& entry : size) {
    const std::size_t main_piece = largest[source[entry.first]];
    if(entry.first != main_piece && open.count(entry.first) &&
       entry.second <= (std::max)(std::size_t(8), size[main_piece] / 100))
      removed.insert(entry.first);
  }
      std::vector<bool> keep(n);
  for(std::size_t f = 0; f < n; ++f) keep[f] = removed.count(root[f]) == 0;
  keep_triangles(triangles, triangle_patch, keep);
  return removed.size();
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_SOUP_CLEANUP_H
