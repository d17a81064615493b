// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the angle pictures (angle_pictures.h) share: the corner angles of a
// triangle as certify_angle_bounds() shows them, a loop over the triangles,
// and number and text formatting for SVG.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_PICTURE_HELPERS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_PICTURE_HELPERS_H

#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/angle_predicates.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cstdio>
#include <locale>
#include <sstream>
#include <string>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// The corner angles of the triangle (a, b, c) in degrees, measured in double
// and shown within [30, 90] where the exact verdict proves them so, as
// `certify_angle_bounds()` does; the verdict is returned.
template <typename Point>
Triangle_verdict shown_angles(const Point& a, const Point& b, const Point& c, std::array<double, 3>& angles)
{
  static const Angle_bounds bounds(30., 90.);
  const Triangle_verdict verdict = triangle_verdict(a, b, c, bounds);
  const Point* p[3] = {&a, &b, &c};
  for(int i = 0; i < 3 && !verdict.degenerate; ++i) {
    angles[i] = corner_angle_degrees(*p[i], *p[(i + 1) % 3], *p[(i + 2) % 3]);
    if(!verdict.corners[i].too_small) angles[i] = (std::max)(angles[i], 30.);
    if(!verdict.corners[i].too_large) angles[i] = (std::min)(angles[i], 90.);
  }
  return verdict;
}

// Calls f(face, a, b, c) with the points of each face, in the order of faces(mesh).
template <typename TriangleMesh, typename F>
void for_each_triangle(const TriangleMesh& mesh, F f)
{
  if(!is_triangle_mesh(mesh))
    throw Bad_input("angle pictures: the mesh has a face that is not a triangle");
  const auto vpm = get(CGAL::vertex_point, mesh);
  for(auto face : faces(mesh)) {
    const auto h = halfedge(face, mesh);
    f(face, get(vpm, source(h, mesh)), get(vpm, target(h, mesh)), get(vpm, target(next(h, mesh), mesh)));
  }
}

// A number in fixed notation with `decimals` digits, whatever the global locale.
inline std::string fixed(double value, int decimals)
{
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.setf(std::ios::fixed);
  out.precision(decimals);
  out << value;
  return out.str();
}

// `text` with the XML special characters escaped.
inline std::string xml_escaped(const std::string& text)
{
  std::string out;
  for(char c : text)
    out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '"' ? "&quot;" : std::string(1, c);
  return out;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_PICTURE_HELPERS_H
