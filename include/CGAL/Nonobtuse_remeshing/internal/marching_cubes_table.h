// SPDX-License-Identifier: GPL-3.0-or-later
//
// The nonobtuse Marching Cubes table (thesis, section 4.1), derived rather
// than typed in: for each of the 256 sign configurations, the contour cycles
// are built on the cube faces, and each cycle is triangulated, with or
// without the cube centre, by a search for a triangulation whose angles all
// lie in [35.26, 90] degrees (the thesis's bound; 35.26 = acos(sqrt(2/3)) is
// the small angle of the right triangle with sides sqrt(2)/2, 1, sqrt(6)/2).
//
// Output vertices sit at cube-edge midpoints and the cube centre only, so in
// half-cube units every position is an integer vector in {0, 1, 2}^3 and the
// angle tests below are exact integer arithmetic.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_MARCHING_CUBES_TABLE_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_MARCHING_CUBES_TABLE_H

#include <CGAL/Nonobtuse_remeshing/internal/triangle_contact.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/assertions.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
namespace marching_cubes {

// Corner c of the unit cube has coordinates ((c>>0)&1, (c>>1)&1, (c>>2)&1).
// Edge 4a+k runs along axis a; k's two bits give the coordinates along the two
// other axes (lower axis first). Slot 12 is the cube centre.
constexpr int centre_slot = 12;

inline int corner_bit(int corner, int axis) { return (corner >> axis) & 1; }

inline std::array<int, 2> other_axes(int axis)
{
  return axis == 0 ? std::array<int, 2>{1, 2} : (axis == 1 ? std::array<int, 2>{0, 2} : std::array<int, 2>{0, 1});
}

inline std::array<int, 2> edge_corners(int edge)
{
  const int axis = edge / 4, k = edge % 4;
  const std::array<int, 2> o = other_axes(axis);
  const int c0 = ((k & 1) << o[0]) | (((k >> 1) & 1) << o[1]);
  return {c0, c0 | (1 << axis)};
}

inline int edge_between(int c0, int c1)
{
  const int diff = c0 ^ c1;
  const int axis = diff == 1 ? 0 : (diff == 2 ? 1 : 2);
  const std::array<int, 2> o = other_axes(axis);
  const int low = c0 & ~(1 << axis);
  return 4 * axis + (corner_bit(low, o[0]) | (corner_bit(low, o[1]) << 1));
}

/// Position of a slot in half-cube units.
inline std::array<int, 3> slot_position(int slot)
{
  if(slot == centre_slot) return {1, 1, 1};
  const std::array<int, 2> c = edge_corners(slot);
  std::array<int, 3> p;
  for(int a = 0; a < 3; ++a) p[a] = corner_bit(c[0], a) + corner_bit(c[1], a);
  return p;
}

/// The four corners of face 2a+s (the face where axis a is s), in cyclic order.
inline std::array<int, 4> face_corners(int face)
{
  const int axis = face / 2, side = face % 2;
  const std::array<int, 2> o = other_axes(axis);
  const int base = side << axis;
  return {base, base | (1 << o[0]), base | (1 << o[0]) | (1 << o[1]), base | (1 << o[1])};
}

/// True when corner c is inside ('-') in configuration `config`.
inline bool inside(unsigned config, int corner) { return (config >> corner) & 1u; }

/// Contour segments of a face, as pairs of edge slots. An ambiguous face
/// (signs alternating around it) is resolved by one fixed rule that depends
/// on the face's signs only: the inside corners are joined, each outside
/// corner is cut off. Two cubes sharing the face therefore always agree.
inline std::vector<std::array<int, 2> > face_segments(unsigned config, int face)
{
  const std::array<int, 4> q = face_corners(face);
  std::vector<int> crossed;
  for(int i = 0; i < 4; ++i)
    if(inside(config, q[i]) != inside(config, q[(i + 1) % 4])) crossed.push_back(i);
  std::vector<std::array<int, 2> > segments;
  auto edge = [&](int i) { return edge_between(q[i % 4], q[(i + 1) % 4]); };
  if(crossed.size() == 2) {
    segments.push_back({edge(crossed[0]), edge(crossed[1])});
  } else if(crossed.size() == 4) {
    for(int i = 0; i < 4; ++i)
      if(!inside(config, q[i])) segments.push_back({edge(i + 3), edge(i)});
  }
  return segments;
}

// Exact integer geometry on half-unit positions.
using Vec = std::array<long, 3>;
inline Vec sub(const std::array<int, 3>& a, const std::array<int, 3>& b)
{
  return {long(a[0]) - b[0], long(a[1]) - b[1], long(a[2]) - b[2]};
}
inline long dot(const Vec& u, const Vec& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
inline Vec cross(const Vec& u, const Vec& v)
{
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

/// Every angle of the slot triangle lies in [acos(sqrt(2/3)), 90] degrees:
/// at each corner d = u.v >= 0 and 3 d^2 <= 2 |u|^2 |v|^2.
inline bool well_shaped(const std::array<int, 3>& t)
{
  for(int i = 0; i < 3; ++i) {
    const std::array<int, 3> a = slot_position(t[i]), b = slot_position(t[(i + 1) % 3]),
                             c = slot_position(t[(i + 2) % 3]);
    const Vec u = sub(b, a), v = sub(c, a);
    const Vec n = cross(u, v);
    if(dot(n, n) == 0) return false;
    const long d = dot(u, v);
    if(d < 0 || 3 * d * d > 2 * dot(u, u) * dot(v, v)) return false;
  }
  return true;
}

// Geometric validity of a set of slot triangles: no two triangles overlap
// beyond the vertices and edges they share (exact predicates).
inline bool embedded(const std::vector<std::array<int, 3> >& triangles)
{
  using K = Exact_predicates_inexact_constructions_kernel;
  auto point = [](int slot) {
    const std::array<int, 3> p = slot_position(slot);
    return K::Point_3(p[0], p[1], p[2]);
  };
  for(std::size_t i = 0; i < triangles.size(); ++i)
    for(std::size_t j = i + 1; j < triangles.size(); ++j) {
      const std::array<int, 3>& s = triangles[i];
      const std::array<int, 3>& t = triangles[j];
      if(meet_beyond_shared(s, {point(s[0]), point(s[1]), point(s[2])}, t, {point(t[0]), point(t[1]), point(t[2])}))
        return false;
    }
  return true;
}

/// One table entry: triangles over slots, oriented so that normals point from
/// the inside corners to the outside ones.
struct Entry
{
  std::vector<std::array<int, 3> > triangles;
};

struct Cycle_triangulation
{
  std::vector<std::array<int, 3> > triangles;
  bool uses_centre = false;
};

// All triangulations of the polygon cycle[i..j] (no new vertex) whose
// triangles are well shaped; appended to `out`.
inline void polygon_triangulations(const std::vector<int>& cycle, int i, int j,
                                   std::vector<std::vector<std::array<int, 3> > >& out)
{
  if(j - i < 2) { out.emplace_back(); return; }
  for(int m = i + 1; m < j; ++m) {
    const std::array<int, 3> t = {cycle[i], cycle[m], cycle[j]};
    if(!well_shaped(t)) continue;
    std::vector<std::vector<std::array<int, 3> > > left, right;
    polygon_triangulations(cycle, i, m, left);
    if(left.empty()) continue;
    polygon_triangulations(cycle, m, j, right);
    for(const auto& l : left)
      for(const auto& r : right) {
        std::vector<std::array<int, 3> > all = l;
        all.insert(all.end(), r.begin(), r.end());
        all.push_back(t);
        out.push_back(std::move(all));
      }
  }
}

// Side of the surface at each crossed edge of the cycle: the sign of the
// normal (summed over the triangles at the edge's midpoint) along the
// direction from the edge's inside corner to its outside corner. A
// triangulation that folds over has both signs; a good one has one sign,
// and is flipped if that sign is negative.
inline int orientation_along_crossings(unsigned config, const std::vector<int>& cycle,
                                       const std::vector<std::array<int, 3> >& triangles)
{
  int positive = 0, negative = 0;
  for(int slot : cycle) {
    Vec normal = {0, 0, 0};
    for(const auto& t : triangles)
      if(std::count(t.begin(), t.end(), slot)) {
        const Vec n = cross(sub(slot_position(t[1]), slot_position(t[0])),
                            sub(slot_position(t[2]), slot_position(t[0])));
        for(int a = 0; a < 3; ++a) normal[a] += n[a];
      }
    const std::array<int, 2> c = edge_corners(slot);
    const int from = inside(config, c[0]) ? c[0] : c[1];
    const int to = from == c[0] ? c[1] : c[0];
    const std::array<int, 3> pf = {2 * corner_bit(from, 0), 2 * corner_bit(from, 1), 2 * corner_bit(from, 2)};
    const std::array<int, 3> pt = {2 * corner_bit(to, 0), 2 * corner_bit(to, 1), 2 * corner_bit(to, 2)};
    const long side = dot(normal, sub(pt, pf));
    positive += side > 0;
    negative += side <= 0;
  }
  return negative == 0 ? 1 : (positive == 0 ? -1 : 0);
}

// Key that makes the choice among equally good triangulations depend on the
// directions of their diagonals only, so that congruent configurations in
// different cubes are triangulated alike (a flat sheet then gets parallel
// diagonals and valence 6, not a pattern of valence-4 and valence-8 vertices,
// the thesis's concern for cases 2, 6, 8, 10).
inline std::vector<Vec> diagonal_directions(const std::vector<int>& cycle,
                                            const std::vector<std::array<int, 3> >& triangles)
{
  std::vector<Vec> directions;
  const int k = int(cycle.size());
  auto is_polygon_edge = [&](int a, int b) {
    for(int i = 0; i < k; ++i)
      if((cycle[i] == a && cycle[(i + 1) % k] == b) || (cycle[i] == b && cycle[(i + 1) % k] == a))
        return true;
    return false;
  };
  for(const auto& t : triangles)
    for(int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      if(is_polygon_edge(a, b)) continue;
      Vec d = sub(slot_position(b), slot_position(a));
      const long first = d[0] != 0 ? d[0] : (d[1] != 0 ? d[1] : d[2]);
      if(first < 0) d = {-d[0], -d[1], -d[2]};
      directions.push_back(d);
    }
  std::sort(directions.begin(), directions.end());
  directions.erase(std::unique(directions.begin(), directions.end()), directions.end());
  return directions;
}

// Chooses the triangulation of one contour cycle: without the centre when a
// well-shaped, unfolded one exists (the direction key breaks ties), otherwise
// the fan around the centre (the thesis's one-ring patch of cases 5, 9, 11,
// 12, 14). The result is oriented from inside to outside.
inline bool triangulate_cycle(unsigned config, const std::vector<int>& cycle, Cycle_triangulation& result)
{
  const int k = int(cycle.size());
  std::vector<std::vector<std::array<int, 3> > > candidates;
  polygon_triangulations(cycle, 0, k - 1, candidates);
  bool found = false;
  std::vector<Vec> best_key;
  for(const auto& c : candidates) {
    if(orientation_along_crossings(config, cycle, c) == 0 || !embedded(c)) continue;
    std::vector<Vec> key = diagonal_directions(cycle, c);
    if(!found || key < best_key) {
      result.triangles = c;
      result.uses_centre = false;
      best_key = std::move(key);
      found = true;
    }
  }
  if(!found) {
    std::vector<std::array<int, 3> > fan;
    for(int i = 0; i < k; ++i) {
      const std::array<int, 3> t = {centre_slot, cycle[i], cycle[(i + 1) % k]};
      if(!well_shaped(t)) return false;
      fan.push_back(t);
    }
    if(orientation_along_crossings(config, cycle, fan) == 0 || !embedded(fan)) return false;
    result.triangles = fan;
    result.uses_centre = true;
  }
  if(orientation_along_crossings(config, cycle, result.triangles) < 0)
    for(auto& t : result.triangles) std::swap(t[1], t[2]);
  return true;
}

/// Contour cycles of a configuration: every crossed edge lies on exactly two
/// faces and on one segment of each, so the segments close into cycles.
inline std::vector<std::vector<int> > contour_cycles(unsigned config)
{
  std::array<std::vector<int>, 12> neighbours;
  for(int face = 0; face < 6; ++face)
    for(const auto& s : face_segments(config, face)) {
      neighbours[s[0]].push_back(s[1]);
      neighbours[s[1]].push_back(s[0]);
    }
  std::vector<std::vector<int> > cycles;
  std::array<bool, 12> used{};
  for(int start = 0; start < 12; ++start) {
    if(used[start] || neighbours[start].empty()) continue;
    if(neighbours[start].size() != 2)
      CGAL_error_msg("nonobtuse marching cubes: contour vertex without two segments");
    std::vector<int> cycle;
    int previous = -1, current = start;
    while(!used[current]) {
      used[current] = true;
      cycle.push_back(current);
      const int next = neighbours[current][0] != previous ? neighbours[current][0] : neighbours[current][1];
      previous = current;
      current = next;
    }
    cycles.push_back(cycle);
  }
  return cycles;
}

inline Entry generate_entry(unsigned config)
{
  Entry entry;
  const std::vector<std::vector<int> > cycles = contour_cycles(config);
  bool centre_taken = false;
  for(const auto& cycle : cycles) {
    Cycle_triangulation t;
    if(!triangulate_cycle(config, cycle, t))
      CGAL_error_msg(("nonobtuse marching cubes: no well-shaped triangulation for configuration " + std::to_string(config)).c_str());
    if(t.uses_centre) {
      if(centre_taken)
        CGAL_error_msg(("nonobtuse marching cubes: two cycles need the centre in configuration " + std::to_string(config)).c_str());
      centre_taken = true;
    }
    entry.triangles.insert(entry.triangles.end(), t.triangles.begin(), t.triangles.end());
  }
  if(!embedded(entry.triangles))
    CGAL_error_msg(("nonobtuse marching cubes: overlapping cycles in configuration " + std::to_string(config)).c_str());
  return entry;
}

/// The 256-entry table, generated once on first use.
inline const std::array<Entry, 256>& table()
{
  static const std::array<Entry, 256> entries = [] {
    std::array<Entry, 256> t;
    for(unsigned config = 0; config < 256; ++config) t[config] = generate_entry(config);
    return t;
  }();
  return entries;
}

} // namespace marching_cubes
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_MARCHING_CUBES_TABLE_H
