// SPDX-License-Identifier: GPL-3.0-or-later
//
// Filling the notches of a border (beyond the thesis). On an open input the
// Marching Cubes leave each border as a staircase of the grid, its notches up
// to about a cube inside the input's border, and the fit cannot pull a notch
// out: the faces along it would have to stretch beyond the angle bounds. A
// notch vertex v (the angles of its faces sum to more than 200 degrees)
// between its border neighbours a and b is filled with the face (a, v, b),
// or, where that face's angle at v would be obtuse, with two faces (a, v, w)
// and (w, v, b) around a new vertex w on the bisector of that angle, outside
// the mesh. A fill is made only towards the input's border and over the
// input (see fill_border_notches), when every new face certifies exactly in
// the bounds and crosses no face of the mesh; it adds faces along one border
// cycle, so it keeps the Euler characteristic, the border cycles and the
// components. The fit then pulls the new border towards the input's.
//
// A corner of the input's border (where it turns by 30 degrees or more)
// that the mesh's border cuts off is filled the same way, with an ear: the
// face (a, b, w) on the mesh's border edge (a, b) nearest the corner, its
// new vertex w at the corner. The fit cannot make the corner either: the
// vertices near it have too many faces to close an angle that small.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_BORDER_NOTCHES_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_BORDER_NOTCHES_H

#include <CGAL/Nonobtuse_remeshing/angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/internal/angle_predicates.h>
#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>
#include <CGAL/Nonobtuse_remeshing/internal/triangle_contact.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// What the fills of one pass changed.
template <typename vertex_descriptor, typename face_descriptor>
struct Border_fills
{
  std::size_t notches = 0;                 // notches filled
  std::size_t corners = 0;                 // corners filled with an ear
  std::vector<vertex_descriptor> added;    // the new vertices
  std::vector<vertex_descriptor> touched;  // the vertices of the new faces
  std::vector<face_descriptor> faces;      // the new faces, in the order added
};

// The sum of the angles at v of its faces, in degrees, `point` giving the
// points of `mesh`'s vertices.
template <typename Mesh, typename PointOf>
double angle_sum(const Mesh& mesh, typename boost::graph_traits<Mesh>::vertex_descriptor v, const PointOf& point)
{
  double angles = 0.;
  for(auto h : halfedges_around_target(v, mesh))
    if(!is_border(h, mesh))
      angles += CGAL::approximate_angle(point(source(h, mesh)), point(v), point(target(next(h, mesh), mesh)));
  return angles;
}

// The input's convex border corners: its border vertices whose faces'
// angles sum to at most 150 degrees, where its border turns by 30 degrees
// or more towards the surface.
template <typename Input>
std::vector<Epick::Point_3> input_border_corners(const Input& input)
{
  const auto& mesh = input.mesh();
  const auto point = [&](auto v) { return input.point(v); };
  std::vector<Epick::Point_3> corners;
  for(auto h : halfedges(mesh))
    if(is_border(h, mesh) && angle_sum(mesh, target(h, mesh), point) <= 150.)
      corners.push_back(point(target(h, mesh)));
  return corners;
}

template <typename TriangleMesh, typename VertexPointMap, typename Input>
class Border_notch_filler
{
  using Point = Epick::Point_3;
  using Vector = Epick::Vector_3;
  using Triangle = Epick::Triangle_3;
  using Segment = Epick::Segment_3;
  using Segment_tree =
      AABB_tree<AABB_traits<Epick, AABB_segment_primitive<Epick, typename std::vector<Segment>::const_iterator> > >;
  using GT = boost::graph_traits<TriangleMesh>;
  using vertex_descriptor = typename GT::vertex_descriptor;
  using halfedge_descriptor = typename GT::halfedge_descriptor;
  using face_descriptor = typename GT::face_descriptor;
  using Points = Epick_points_t<VertexPointMap>;
  using Tree = AABB_tree<AABB_traits<Epick, AABB_face_graph_triangle_primitive<TriangleMesh, Points> > >;

  // A face to add, by its corners.
  struct New_face
  {
    std::array<vertex_descriptor, 3> corners;
    Triangle triangle;
    face_descriptor face = GT::null_face();  // once added
  };

public:
  // `corners`: the input's border corners (input_border_corners()).
  Border_notch_filler(TriangleMesh& mesh, VertexPointMap vpm, const Input& input, const std::vector<Point>& corners,
                      const Angle_bounds& bounds)
    : mesh_(mesh), vpm_(vpm), points_(epick_points(vpm)), input_(input), corners_(corners), bounds_(bounds)
  {
  }

  // One pass over the mesh's border vertices: fills each notch whose vertex
  // v satisfies `fits_input_border(v)` (its border cycle follows the
  // input's) and that allows it, at most one of any three consecutive
  // border vertices (a fill changes its neighbours' faces; the next pass
  // sees them). `before_first_change()` is called once, before the pass
  // changes the mesh, if it does.
  template <typename Fits, typename Callback>
  Border_fills<vertex_descriptor, face_descriptor> operator()(const Fits& fits_input_border,
                                                              const Callback& before_first_change)
  {
    before_change_ = before_first_change;
    Border_fills<vertex_descriptor, face_descriptor> fills;
    if(!input_.has_border()) return fills;
    std::vector<halfedge_descriptor> border;
    for(halfedge_descriptor h : halfedges(mesh_))
      if(is_border(h, mesh_)) border.push_back(h);
    if(border.empty()) return fills;
    // the faces as they are before this pass, searched for crossings; the
    // faces the pass adds are checked one by one
    Tree tree(faces(mesh_).first, faces(mesh_).second, mesh_, points_);
    added_.clear();
    auto touched = get(CGAL::dynamic_vertex_property_t<bool>(), mesh_);
    for(vertex_descriptor v : vertices(mesh_)) put(touched, v, false);
    for(halfedge_descriptor h1 : border) {
      if(!is_border(h1, mesh_)) continue;  // filled this pass
      const halfedge_descriptor h2 = next(h1, mesh_);
      const vertex_descriptor a = source(h1, mesh_), v = target(h1, mesh_), b = target(h2, mesh_);
      if(get(touched, a) || get(touched, v) || get(touched, b) || !fits_input_border(v)) continue;
      const vertex_descriptor none = GT::null_vertex();
      vertex_descriptor w = none;
      if(!fill(h1, h2, tree, w)) continue;
      for(vertex_descriptor x : {a, v, b, w})
        if(x != none) {
          put(touched, x, true);
          fills.touched.push_back(x);
        }
      if(w != none) fills.added.push_back(w);
      ++fills.notches;
    }
    // then the corners, each at the mesh's border edge nearest it (as the
    // border was before this pass)
    std::vector<Segment> segments;
    if(!corners_.empty())
      for(halfedge_descriptor h : border) segments.emplace_back(point(source(h, mesh_)), point(target(h, mesh_)));
    const Segment_tree nearest(segments.begin(), segments.end());
    for(const Point& corner : corners_) {
      const halfedge_descriptor h = border[nearest.closest_point_and_primitive(corner).second - segments.begin()];
      const vertex_descriptor a = source(h, mesh_), b = target(h, mesh_);
      if(!is_border(h, mesh_) || get(touched, a) || get(touched, b) || !fits_input_border(a) || !fits_input_border(b))
        continue;
      vertex_descriptor w = GT::null_vertex();
      if(!ear(h, corner, tree, w)) continue;
      for(vertex_descriptor x : {a, b, w}) {
        put(touched, x, true);
        fills.touched.push_back(x);
      }
      fills.added.push_back(w);
      ++fills.corners;
    }
    for(const New_face& f : added_) fills.faces.push_back(f.face);
    return fills;
  }

private:
  Point point(vertex_descriptor v) const { return get(points_, v); }

  static Vector unit(const Vector& x) { return x / std::sqrt(x.squared_length()); }

  Vector face_normal(halfedge_descriptor h) const
  {
    return unit(CGAL::normal(point(source(h, mesh_)), point(target(h, mesh_)), point(target(next(h, mesh_), mesh_))));
  }

  double distance_to_input(const Point& p) const
  {
    return std::sqrt(CGAL::squared_distance(p, input_.triangle(input_.closest(p))));
  }

  double distance_to_input_border(const Point& p) const
  {
    return std::sqrt(CGAL::squared_distance(p, input_.closest_on_border(p)));
  }

  // The notch at v between the border halfedges h1 = (a, v) and h2 = (v, b):
  // filled with one face, or with two around a new vertex, then written to
  // `w`; returns whether it was filled.
  bool fill(halfedge_descriptor h1, halfedge_descriptor h2, const Tree& tree, vertex_descriptor& w)
  {
    const vertex_descriptor a = source(h1, mesh_), v = target(h1, mesh_), b = target(h2, mesh_);
    if(a == b || v == a || v == b) return false;
    const Point pa = point(a), pv = point(v), pb = point(b);
    const double length = 0.5 * (std::sqrt(CGAL::squared_distance(pa, pv)) + std::sqrt(CGAL::squared_distance(pv, pb)));
    if(!(length > 0.)) return false;
    // only a vertex a quarter of an edge or more inside the input's border,
    // and within a few edges of it
    const double inside = distance_to_input_border(pv);
    if(!(inside > 0.25 * length) || inside > 4. * length) return false;
    if(!(angle_sum(mesh_, v, [this](vertex_descriptor x) { return point(x); }) > 200.))
      return false;  // not a notch: a fill would fold over the mesh
    const double opening = CGAL::approximate_angle(pa, pv, pb);
    const Vector along_a = face_normal(opposite(h1, mesh_)), along_b = face_normal(opposite(h2, mesh_));
    // one face where its angle at v is not obtuse; a and b must not be
    // joined already (the border cycle would close, or an edge would double)
    if(opening <= bounds_.max_degrees() && !halfedge(a, b, mesh_).second &&
       distance_to_input(CGAL::midpoint(pa, pb)) < 0.5 * inside) {
      const New_face f{{a, v, b}, Triangle(pa, pv, pb)};
      if(certified(f.triangle) && acceptable(f, along_a, along_b, tree)) {
        before_change();
        add(f);
        return true;
      }
    }
    if(opening >= 170.) return false;
    // two faces: w on the bisector of the opening, about an edge from v, as
    // the fills were first made; else nearer v (a shallow notch, whose w
    // would lie too far beyond the input's border) or off the bisector (a
    // notch whose sides differ in length)
    const Vector to_a = unit(pa - pv), to_b = unit(pb - pv);
    for(double turn : {0.5, 0.45, 0.55, 0.4, 0.6})
      for(double scale : {1., 0.9, 1.1, 0.8, 1.25, 0.7, 1.4, 0.6, 0.5})
        if(two_faces(h1, h2, pv + scale * length * unit((1. - turn) * to_a + turn * to_b), inside, along_a, along_b,
                     tree, w))
          return true;
    return false;
  }

  // The fill of the notch between h1 = (a, v) and h2 = (v, b) with the two
  // faces (a, v, w) and (w, v, b), w at `pw`, if they are acceptable (the
  // faces across (a, v) and (v, b) have the unit normals `along_a` and
  // `along_b`); the new vertex is written to `w`.
  bool two_faces(halfedge_descriptor h1, halfedge_descriptor h2, const Point& pw, double inside, const Vector& along_a,
                 const Vector& along_b, const Tree& tree, vertex_descriptor& w)
  {
    const vertex_descriptor a = source(h1, mesh_), v = target(h1, mesh_), b = target(h2, mesh_);
    const Point pa = point(a), pv = point(v), pb = point(b);
    if(!(distance_to_input_border(pw) < inside) || !(distance_to_input(pw) < 0.5 * inside)) return false;
    // the new vertex's faces, as they will be; tested before w exists
    const vertex_descriptor none = GT::null_vertex();
    const New_face f1{{a, v, none}, Triangle(pa, pv, pw)}, f2{{none, v, b}, Triangle(pw, pv, pb)};
    if(!certified(f1.triangle) || !certified(f2.triangle)) return false;
    const Vector n1 = unit(f1.triangle.supporting_plane().orthogonal_vector());
    const Vector n2 = unit(f2.triangle.supporting_plane().orthogonal_vector());
    if(!(n1 * n2 >= 0.5)) return false;
    if(!acceptable(f1, along_a, n2, tree) || !acceptable(f2, n1, along_b, tree)) return false;
    before_change();
    w = add_new_vertex(pw);
    add({{a, v, w}, f1.triangle});
    add({{w, v, b}, f2.triangle});
    return true;
  }

  // The ear (a, b, w) on the border halfedge h = (a, b), w at the input's
  // border corner `corner` or pulled towards the edge, if it is acceptable
  // (as a fill's face: certified, turning by at most 60 degrees from the
  // face across (a, b), crossing no face); the new vertex is written to `w`.
  // Only where the edge cuts the corner off by a quarter of its length or
  // more, and at most two lengths.
  bool ear(halfedge_descriptor h, const Point& corner, const Tree& tree, vertex_descriptor& w)
  {
    const vertex_descriptor a = source(h, mesh_), b = target(h, mesh_);
    const Point pa = point(a), pb = point(b);
    const double length = std::sqrt(CGAL::squared_distance(pa, pb));
    const double cut = std::sqrt(CGAL::squared_distance(corner, Segment(pa, pb)));
    if(!(cut > 0.25 * length) || cut > 2. * length) return false;
    const Vector across = face_normal(opposite(h, mesh_));
    const Point middle = CGAL::midpoint(pa, pb);
    for(double scale : {1., 0.85, 0.7}) {
      const Point pw = middle + scale * (corner - middle);
      const New_face f{{a, b, GT::null_vertex()}, Triangle(pa, pb, pw)};
      if(!certified(f.triangle) || !acceptable(f, across, across, tree)) continue;
      before_change();
      w = add_new_vertex(pw);
      add({{a, b, w}, f.triangle});
      return true;
    }
    return false;
  }

  vertex_descriptor add_new_vertex(const Point& p)
  {
    const vertex_descriptor w = add_vertex(mesh_);
    put(vpm_, w, typename boost::property_traits<VertexPointMap>::value_type(p.x(), p.y(), p.z()));
    return w;
  }

  bool certified(const Triangle& t) const
  {
    return triangle_verdict(t[0], t[1], t[2], bounds_).within_bounds();
  }

  // The new face, certified already, turns by at most 60 degrees from the
  // faces across its sides (a, v) and (v, b), or (w, v), by their unit
  // normals, and crosses no face of the mesh.
  bool acceptable(const New_face& f, const Vector& across_first, const Vector& across_second, const Tree& tree) const
  {
    const Vector n = unit(f.triangle.supporting_plane().orthogonal_vector());
    if(!(n * across_first >= 0.5) || !(n * across_second >= 0.5)) return false;
    std::vector<face_descriptor> near;
    tree.all_intersected_primitives(f.triangle.bbox(), std::back_inserter(near));
    for(face_descriptor g : near)
      if(crosses(f, face_corners(g))) return false;
    for(const New_face& g : added_)
      if(crosses(f, g.corners)) return false;
    return true;
  }

  std::array<vertex_descriptor, 3> face_corners(face_descriptor g) const
  {
    const halfedge_descriptor h = halfedge(g, mesh_);
    return {source(h, mesh_), target(h, mesh_), target(next(h, mesh_), mesh_)};
  }

  // Whether the new face f and the face with `corners` (of the mesh, or
  // added this pass) meet elsewhere than in what they share, exactly; the
  // new vertex of a two-face fill, not yet in the mesh, is the null vertex
  // in f's corners and shares nothing.
  bool crosses(const New_face& f, const std::array<vertex_descriptor, 3>& corners) const
  {
    return meet_beyond_shared(f.corners, {f.triangle[0], f.triangle[1], f.triangle[2]}, corners,
                              {point(corners[0]), point(corners[1]), point(corners[2])});
  }

  // Adds f along the border: its sides (a, v) and (v, b), or (w, v), are
  // consecutive border halfedges and its third side is new, which is all
  // that Euler::add_face needs; a refusal would be a bug here.
  void before_change()
  {
    if(before_change_) before_change_();
    before_change_ = nullptr;
  }

  void add(New_face f)
  {
    f.face = Euler::add_face(f.corners, mesh_);
    if(f.face == GT::null_face())
      throw std::logic_error("fill_border_notches: a face could not be added along the border");
    added_.push_back(f);
  }

  TriangleMesh& mesh_;
  VertexPointMap vpm_;
  Points points_;
  const Input& input_;
  const std::vector<Point>& corners_;
  const Angle_bounds bounds_;
  std::vector<New_face> added_;  // this pass's new faces
  std::function<void()> before_change_;  // until the pass's first change
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_BORDER_NOTCHES_H
