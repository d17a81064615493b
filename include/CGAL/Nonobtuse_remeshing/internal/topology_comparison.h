// SPDX-License-Identifier: GPL-3.0-or-later
//
// The topology of a remeshed surface against its input's, per input
// connected component (beyond the thesis: a Marching Cubes grid coarser than
// a part of the input cuts it off or opens holes in it). Each output
// component belongs to the input component nearest to it (a vote of about
// 32 of its faces' centroids). An input component's topology is kept when exactly one
// output component belongs to it, with the same number of border cycles and
// the same Euler characteristic.
//
// Input components that cross themselves or each other are compared as one
// group: the Marching Cubes make the surface of their union (the winding
// number signs of nonobtuse_marching_cubes()), which is one component with
// the borders the group has, but whose genus may legitimately differ (two
// crossing tubes enclose a handle), so the Euler characteristic of such a
// group is not compared.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_TOPOLOGY_COMPARISON_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_TOPOLOGY_COMPARISON_H

#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>
#include <CGAL/Nonobtuse_remeshing/internal/parallel.h>
#include <CGAL/Nonobtuse_remeshing/internal/winding_number_signs.h>
#include <CGAL/Nonobtuse_remeshing/remeshing_stages.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <chrono>
#include <map>
#include <cstddef>
#include <numeric>
#include <set>
#include <utility>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// Counts of one part of a mesh.
struct Part_topology
{
  std::size_t components = 0;
  std::size_t border_cycles = 0;
  long long euler_characteristic = 0;  // V - E + F of the vertices, edges and faces of its faces
};

// The face-connected components of a mesh and the topology of each.
struct Mesh_components
{
  std::vector<std::size_t> face_component;  // in the order of faces(mesh)
  std::vector<Part_topology> parts;         // per component
};

template <typename TriangleMesh>
Mesh_components mesh_components(const TriangleMesh& mesh)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  std::unordered_map<face_descriptor, std::size_t> component;
  const std::size_t n = Polygon_mesh_processing::connected_components(mesh, boost::make_assoc_property_map(component));
  Mesh_components result;
  result.parts.assign(n, Part_topology());
  for(face_descriptor f : faces(mesh)) {
    result.face_component.push_back(component.at(f));
    ++result.parts[component.at(f)].euler_characteristic;
  }
  for(auto e : edges(mesh)) {
    halfedge_descriptor h = halfedge(e, mesh);
    if(is_border(h, mesh)) h = opposite(h, mesh);
    if(!is_border(h, mesh)) --result.parts[component.at(face(h, mesh))].euler_characteristic;
  }
  // a vertex counts once in each component it belongs to (twice at a pinch)
  std::set<std::pair<vertex_descriptor, std::size_t> > counted;
  for(halfedge_descriptor h : halfedges(mesh)) {
    if(is_border(h, mesh)) continue;
    const std::size_t c = component.at(face(h, mesh));
    if(counted.emplace(target(h, mesh), c).second) ++result.parts[c].euler_characteristic;
  }
  std::unordered_set<halfedge_descriptor> walked;
  for(halfedge_descriptor h : halfedges(mesh)) {
    if(!is_border(h, mesh) || walked.count(h) > 0) continue;
    ++result.parts[component.at(face(opposite(h, mesh), mesh))].border_cycles;
    for(halfedge_descriptor g : halfedges_around_face(h, mesh)) walked.insert(g);
  }
  for(Part_topology& p : result.parts) p.components = 1;
  return result;
}

// "B borders[, Euler characteristic X]", after "C components, " if `with_components`.
inline std::string topology_text(const Part_topology& t, bool with_components, bool with_euler)
{
  std::string text = std::to_string(t.border_cycles) + (t.border_cycles == 1 ? " border" : " borders");
  if(with_components)
    text = std::to_string(t.components) + (t.components == 1 ? " component, " : " components, ") + text;
  if(with_euler) text += ", Euler characteristic " + std::to_string(t.euler_characteristic);
  return text;
}

// Compares meshes with `input` as the header says; the input's components,
// groups and closest-triangle tree are built once. Points are read through
// the internal point maps. `may_cross` false skips the self-intersection test
// (the caller knows the input has none: the Marching Cubes' automatic signs
// ran it already).
template <typename TriangleMesh>
class Topology_comparator
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Triangle = Epick::Triangle_3;
  using Triangle_iterator = typename std::vector<Triangle>::const_iterator;
  using Tree = AABB_tree<AABB_traits<Epick, AABB_triangle_primitive<Epick, Triangle_iterator> > >;

public:
  Topology_comparator(const TriangleMesh& input, Thread_pool& pool, bool may_cross)
    : pool_(pool), in_(mesh_components(input)), group_(in_.parts.size()), crossing_(in_.parts.size(), false),
      expected_(in_.parts.size())
  {
    const auto start = std::chrono::steady_clock::now();
    // groups of input components that cross themselves or each other
    std::iota(group_.begin(), group_.end(), std::size_t(0));
    if(may_cross)
      for(const auto& pair : crossing_face_pairs(input, get(CGAL::vertex_point, input), pool)) {
        const std::size_t a = root(in_.face_component[pair.first]), b = root(in_.face_component[pair.second]);
        group_[a] = b;
        crossing_[b] = true;
      }
    for(std::size_t c = 0; c < in_.parts.size(); ++c) group_[c] = root(c);  // flat: read-only from here on
    for(std::size_t c = 0; c < in_.parts.size(); ++c) {
      Part_topology& e = expected_[group_[c]];
      e.components = 1;
      e.border_cycles += in_.parts[c].border_cycles;
      e.euler_characteristic += in_.parts[c].euler_characteristic;
    }
    const auto points = epick_points(get(CGAL::vertex_point, input));
    triangles_.reserve(in_.face_component.size());
    for(face_descriptor f : faces(input)) {
      const auto h = halfedge(f, input);
      triangles_.emplace_back(get(points, source(h, input)), get(points, target(h, input)),
                              get(points, target(next(h, input), input)));
    }
    tree_.insert(triangles_.cbegin(), triangles_.cend());
    tree_.accelerate_distance_queries();
    setup_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // Seconds the constructor took (the components are counted before it starts timing).
  double setup_seconds() const { return setup_seconds_; }

  Topology_comparison compare(const TriangleMesh& output)
  {
    const auto start = std::chrono::steady_clock::now();
    const Mesh_components out = mesh_components(output);
    // Each output component goes to the group of the input triangle nearest
    // to the majority of (about 32 of) its faces' centroids.
    std::vector<std::vector<face_descriptor> > members(out.parts.size());
    std::size_t i = 0;
    for(face_descriptor f : faces(output)) members[out.face_component[i++]].push_back(f);
    const auto points = epick_points(get(CGAL::vertex_point, output));
    std::vector<std::size_t> owner(out.parts.size());
    pool_.for_each(members.size(), [&](std::size_t c, int) {
      std::map<std::size_t, std::size_t> votes;
      const std::size_t step = (std::max)(std::size_t(1), members[c].size() / 32);
      for(std::size_t j = 0; j < members[c].size(); j += step) {
        const auto h = halfedge(members[c][j], output);
        const auto p = centroid(get(points, source(h, output)), get(points, target(h, output)),
                                get(points, target(next(h, output), output)));
        ++votes[group_[in_.face_component[std::size_t(tree_.closest_point_and_primitive(p).second - triangles_.cbegin())]]];
      }
      owner[c] = std::max_element(votes.begin(), votes.end(), [](const auto& a, const auto& b) {
                   return a.second < b.second;
                 })->first;
    });
    std::vector<Part_topology> found(in_.parts.size());
    for(std::size_t c = 0; c < out.parts.size(); ++c) {
      Part_topology& f = found[owner[c]];
      ++f.components;
      f.border_cycles += out.parts[c].border_cycles;
      f.euler_characteristic += out.parts[c].euler_characteristic;
    }

    Topology_comparison r;
    r.compared = true;
    r.input_components = in_.parts.size();
    r.output_components = out.parts.size();
    for(const Part_topology& p : in_.parts) {
      r.input_border_cycles += p.border_cycles;
      r.input_euler_characteristic += p.euler_characteristic;
    }
    for(const Part_topology& p : out.parts) {
      r.output_border_cycles += p.border_cycles;
      r.output_euler_characteristic += p.euler_characteristic;
    }
    for(std::size_t g = 0; g < in_.parts.size(); ++g) {
      if(group_[g] != g) continue;
      ++r.input_groups;
      r.crossing_groups += crossing_[g];
      const bool same = found[g].components == 1 && found[g].border_cycles == expected_[g].border_cycles &&
                        (crossing_[g] || found[g].euler_characteristic == expected_[g].euler_characteristic);
      if(same) continue;
      ++r.groups_differing;
      const auto gap = [](long long a, long long b) { return std::size_t(a > b ? a - b : b - a); };
      const std::size_t borders = gap((long long)found[g].border_cycles, (long long)expected_[g].border_cycles);
      r.border_mismatch += borders;
      r.mismatch += gap((long long)found[g].components, 1) + borders +
                    (crossing_[g] ? 0 : (gap(found[g].euler_characteristic, expected_[g].euler_characteristic) + 1) / 2);
      if(!r.difference.empty()) continue;
      std::size_t size = 0;
      for(std::size_t c = 0; c < in_.parts.size(); ++c) size += group_[c] == g;
      r.difference = (size > 1       ? std::to_string(size) + " crossing input components"
                      : crossing_[g] ? std::string("a self-crossing input component")
                                     : std::string("an input component")) +
                     " with " + topology_text(expected_[g], false, !crossing_[g]) + " became " +
                     topology_text(found[g], true, !crossing_[g]);
    }
    r.matches = r.groups_differing == 0;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }

private:
  std::size_t root(std::size_t c)
  {
    while(group_[c] != c) c = group_[c] = group_[group_[c]];
    return c;
  }

  Thread_pool& pool_;
  Mesh_components in_;
  std::vector<std::size_t> group_;  // union-find over the input components
  std::vector<bool> crossing_;      // per group root
  std::vector<Part_topology> expected_;
  std::vector<Triangle> triangles_;
  Tree tree_;
  double setup_seconds_ = 0.;
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_TOPOLOGY_COMPARISON_H
