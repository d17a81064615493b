// SPDX-License-Identifier: GPL-3.0-or-later
//
// The points of any mesh as the exact predicates see them: the package
// reads a mesh's points through its vertex point map, whatever the kernel of
// their type (Epick, Simple_cartesian<double>, Cartesian<double>), and takes
// their double coordinates as points of Exact_predicates_inexact_constructions_kernel,
// so that every certification is exact on the doubles that are stored (and
// written). New positions are stored back through the same map, as points
// of the map's own type made from the same doubles.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_EPICK_POINTS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_EPICK_POINTS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <type_traits>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

using Epick = Exact_predicates_inexact_constructions_kernel;

// A point type whose coordinates are doubles, as the certification needs.
template <typename Point>
constexpr bool has_double_coordinates =
    std::is_same<std::decay_t<decltype(std::declval<const Point&>().x())>, double>::value;

// Reads the points of `VertexPointMap` as Epick points.
template <typename VertexPointMap>
struct Epick_point_map
{
  using key_type = typename boost::property_traits<VertexPointMap>::key_type;
  using value_type = Epick::Point_3;
  using reference = Epick::Point_3;
  using category = boost::readable_property_map_tag;

  VertexPointMap vpm;

  friend Epick::Point_3 get(const Epick_point_map& map, const key_type& key)
  {
    const auto& p = get(map.vpm, key);
    return Epick::Point_3(p.x(), p.y(), p.z());
  }
};

// The map itself when its points are Epick's, else the reading adaptor.
template <typename VertexPointMap,
          bool = std::is_same<typename boost::property_traits<VertexPointMap>::value_type, Epick::Point_3>::value>
struct Epick_points
{
  using type = VertexPointMap;
  static type of(const VertexPointMap& vpm) { return vpm; }
};

template <typename VertexPointMap>
struct Epick_points<VertexPointMap, false>
{
  using type = Epick_point_map<VertexPointMap>;
  static type of(const VertexPointMap& vpm)
  {
    static_assert(has_double_coordinates<typename boost::property_traits<VertexPointMap>::value_type>,
                  "the package needs points with double coordinates");
    return type{vpm};
  }
};

template <typename VertexPointMap>
using Epick_points_t = typename Epick_points<VertexPointMap>::type;

template <typename VertexPointMap>
Epick_points_t<VertexPointMap> epick_points(const VertexPointMap& vpm)
{
  return Epick_points<VertexPointMap>::of(vpm);
}

// Stores the Epick point `p` at `key` as a point of the map's type.
template <typename VertexPointMap, typename Key>
void put_point(const VertexPointMap& vpm, const Key& key, const Epick::Point_3& p)
{
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  if constexpr(std::is_same<Point, Epick::Point_3>::value)
    put(vpm, key, p);
  else
    put(vpm, key, Point(p.x(), p.y(), p.z()));
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_EPICK_POINTS_H
