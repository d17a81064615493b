// SPDX-License-Identifier: GPL-3.0-or-later
//
// Feature attraction in deform-to-fit (beyond the thesis): the input's
// vertices and points along its sharp and border edges (the feature samples
// of closest_triangle.h) each attract their nearest mesh vertex, so that the
// fitted mesh keeps the input's tips, creases and border corners. This finds
// the owner of each sample; the optimizer adds the attraction to the owner's
// objective (fit_objective.h).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_FEATURE_ATTRACTION_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_FEATURE_ATTRACTION_H

#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// (vertex, sample) for every sample, sorted: a sample's vertex is the nearest
// of `points`, or, for a border sample, the nearest of those flagged in
// `on_border` (a border sample is left out when none is flagged).
inline std::vector<std::pair<std::size_t, std::size_t> > feature_sample_owners(
    const std::vector<Epick::Point_3>& points, const std::vector<bool>& on_border_flags,
    const std::vector<std::pair<Epick::Point_3, bool> >& samples)
{
  using Point = Epick::Point_3;
  using Traits = Search_traits_3<Epick>;
  using Point_map = typename Pointer_property_map<Point>::const_type;
  using Adapter = Search_traits_adapter<std::size_t, Point_map, Traits>;
  using Distance = Distance_adapter<std::size_t, Point_map, Euclidean_distance<Traits> >;
  using Search = Orthogonal_k_neighbor_search<Adapter, Distance>;
  using Tree = typename Search::Tree;
  std::vector<std::size_t> everywhere, on_border;
  for(std::size_t i = 0; i < points.size(); ++i) {
    everywhere.push_back(i);
    if(on_border_flags[i]) on_border.push_back(i);
  }
  const Point_map map = make_property_map(points);
  const Tree all(everywhere.begin(), everywhere.end(), typename Tree::Splitter(), Adapter(map));
  const Tree border(on_border.begin(), on_border.end(), typename Tree::Splitter(), Adapter(map));
  std::vector<std::pair<std::size_t, std::size_t> > owner;
  owner.reserve(samples.size());
  for(std::size_t s = 0; s < samples.size(); ++s) {
    const bool at_border = samples[s].second;
    if(at_border && on_border.empty()) continue;
    const Search search(at_border ? border : all, samples[s].first, 1, 0., true, Distance(map));
    owner.emplace_back(search.begin()->first, s);
  }
  std::sort(owner.begin(), owner.end());
  return owner;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_FEATURE_ATTRACTION_H
