// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input surface as deform-to-fit sees it (thesis, section 5.3): the
// closest input triangle of a point, from a CGAL AABB tree (after a move, its
// search starts from the previous closest triangle), its
// fitting quadric, the closest point on the input's border, and the feature
// samples (vertices, points along sharp and border edges) that attract the
// fitted mesh.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_CLOSEST_TRIANGLE_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_CLOSEST_TRIANGLE_H

#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>
#include <CGAL/Nonobtuse_remeshing/internal/quadric.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

template <typename TriangleMesh,
          typename VertexPointMap = typename boost::property_map<TriangleMesh, vertex_point_t>::const_type>
class Closest_triangle
{
  using Point = Epick::Point_3;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Points = Epick_points_t<VertexPointMap>;
  using Face_primitive = AABB_face_graph_triangle_primitive<TriangleMesh, Points>;
  using Face_tree = AABB_tree<AABB_traits<Epick, Face_primitive> >;
  using Segment_iterator = typename std::vector<Epick::Segment_3>::const_iterator;
  using Segment_primitive = AABB_segment_primitive<Epick, Segment_iterator>;
  using Segment_tree = AABB_tree<AABB_traits<Epick, Segment_primitive> >;

public:
  Closest_triangle(const TriangleMesh& input, VertexPointMap vpm, int quadric_rings)
    : input_(input), points_(epick_points(vpm)), tree_(faces(input).first, faces(input).second, input, points_),
      rings_(quadric_rings)
  {
    tree_.accelerate_distance_queries();
    for(auto h : halfedges(input))
      if(is_border(h, input))
        border_.emplace_back(point(source(h, input)), point(target(h, input)));
    if(!border_.empty()) {
      border_tree_.insert(border_.begin(), border_.end());
      border_tree_.accelerate_distance_queries();
    }
  }

  bool has_border() const { return !border_.empty(); }
  const TriangleMesh& mesh() const { return input_; }

  face_descriptor closest(const Point& p) const { return tree_.closest_point_and_primitive(p).second; }

  /// The closest triangle, its search started from `hint`'s closest point:
  /// after a small move the old closest triangle is close, and the tree
  /// prunes everything farther than it at once.
  face_descriptor closest(const Point& p, face_descriptor hint) const
  {
    const Point on_hint = Epick().construct_projected_point_3_object()(triangle(hint), p);
    return tree_.closest_point_and_primitive(p, std::make_pair(on_hint, hint)).second;
  }

  /// The fitting quadric of `f` and its r-ring neighbours (thesis, 5.3: the
  /// planes of the closest triangle and of the triangles around it).
  Quadric quadric(face_descriptor f) const
  {
    Quadric q;
    if(rings_ == 0) {  // the default, asked for at every evaluation: no lists
      add_plane(f, q);
      return q;
    }
    std::vector<face_descriptor> chosen = {f}, ring = {f};
    for(int r = 1; r <= rings_; ++r) {
      std::vector<face_descriptor> next;
      for(face_descriptor g : ring)
        for(auto v : vertices_around_face(halfedge(g, input_), input_))
          for(face_descriptor n : faces_around_target(halfedge(v, input_), input_))
            if(n != boost::graph_traits<TriangleMesh>::null_face() &&
               std::find(chosen.begin(), chosen.end(), n) == chosen.end()) {
              chosen.push_back(n);
              next.push_back(n);
            }
      ring.swap(next);
    }
    for(face_descriptor g : chosen) add_plane(g, q);
    return q;
  }

  /// Adds the supporting plane of `f` to `q`, none for a degenerate `f`.
  void add_plane(face_descriptor f, Quadric& q) const
  {
    const Eigen::Vector3d unit = normal(f);
    if(unit.isZero()) return;
    const Point& p = point(target(halfedge(f, input_), input_));
    q.add_plane(unit, -unit.dot(Eigen::Vector3d(p.x(), p.y(), p.z())));
  }

  /// Points the fitted mesh must come close to, with whether they lie on the
  /// input's border: the input's vertices, and points `spacing` apart along
  /// its border edges and sharp edges (normals more than 45 degrees apart),
  /// where tips, creases and border corners are. At most one sample is kept
  /// per cube of side `spacing` (and per border flag), the ends of sharp and
  /// border edges first, then the points along them, then the other
  /// vertices, so that a dense input costs no more than a coarse one.
  std::vector<std::pair<Point, bool> > feature_samples(double spacing) const
  {
    std::vector<std::pair<Point, bool> > corners, along, others;
    auto feature = get(CGAL::dynamic_vertex_property_t<bool>(), input_);
    for(auto v : vertices(input_)) put(feature, v, false);
    for(auto e : edges(input_)) {
      const auto h = halfedge(e, input_);
      const bool on_border = CGAL::is_border(e, input_);
      if(!on_border && normal(face(h, input_)).dot(normal(face(opposite(h, input_), input_))) > std::sqrt(0.5))
        continue;
      put(feature, source(h, input_), true);
      put(feature, target(h, input_), true);
      const Point& a = point(source(h, input_));
      const Point& b = point(target(h, input_));
      const double length = std::sqrt(CGAL::squared_distance(a, b));
      const int pieces = int((std::min)(std::ceil(length / spacing), 1e6));
      for(int i = 1; i < pieces; ++i) along.emplace_back(a + (b - a) * (double(i) / pieces), on_border);
    }
    for(auto v : vertices(input_))
      (get(feature, v) ? corners : others)
          .emplace_back(point(v), CGAL::is_border(v, input_) != boost::none);
    std::set<std::array<double, 4> > cells;
    std::vector<std::pair<Point, bool> > samples;
    for(const auto* group : {&corners, &along, &others})
      for(const auto& sample : *group) {
        const Point& p = sample.first;
        const std::array<double, 4> cell = {std::floor(p.x() / spacing), std::floor(p.y() / spacing),
                                            std::floor(p.z() / spacing), sample.second ? 1. : 0.};
        if(cells.insert(cell).second) samples.push_back(sample);
      }
    return samples;
  }

  /// Unit normal of `f` (zero for a degenerate triangle).
  Eigen::Vector3d normal(face_descriptor f) const
  {
    const Epick::Triangle_3 t = triangle(f);
    const Epick::Vector_3 n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    const Eigen::Vector3d e(n.x(), n.y(), n.z());
    const double length = e.norm();
    return length > 0. ? Eigen::Vector3d(e / length) : Eigen::Vector3d::Zero();
  }

  /// Closest point on the input's border (thesis, equation 5.12).
  Point closest_on_border(const Point& p) const { return border_tree_.closest_point(p); }

  Point point(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v) const { return get(points_, v); }

  Epick::Triangle_3 triangle(face_descriptor f) const
  {
    const auto h = halfedge(f, input_);
    return Epick::Triangle_3(point(source(h, input_)), point(target(h, input_)),
                             point(target(next(h, input_), input_)));
  }

private:
  const TriangleMesh& input_;
  Points points_;
  Face_tree tree_;
  int rings_;
  std::vector<Epick::Segment_3> border_;
  Segment_tree border_tree_;
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_CLOSEST_TRIANGLE_H
