// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether two triangles of a mesh (or of a mesh to be) meet beyond the
// corners and the side they share, decided exactly: the test behind the
// Marching Cubes table's embedded triangulations and the border fills'
// crossing test.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_TRIANGLE_CONTACT_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_TRIANGLE_CONTACT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <array>
#include <cstddef>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// Triangles s and t, with corner ids (equal ids: a shared corner) and
// points, meet elsewhere than in what they share:
// - nothing shared: they intersect;
// - one corner c: the side of one opposite c meets the other (two triangles
//   sharing only c that meet beyond c, coplanar or not, meet at a point of
//   such a side);
// - one side: they are coplanar and on the same side of it (folded onto
//   each other);
// - three corners: the same triangle twice.
template <typename Id>
bool meet_beyond_shared(const std::array<Id, 3>& s_ids,
                        const std::array<Exact_predicates_inexact_constructions_kernel::Point_3, 3>& s,
                        const std::array<Id, 3>& t_ids,
                        const std::array<Exact_predicates_inexact_constructions_kernel::Point_3, 3>& t)
{
  using K = Exact_predicates_inexact_constructions_kernel;
  int shared = 0;
  std::array<bool, 3> s_shared{false, false, false}, t_shared{false, false, false};
  for(std::size_t i = 0; i < 3; ++i)
    for(std::size_t j = 0; j < 3; ++j)
      if(s_ids[i] == t_ids[j]) {
        ++shared;
        s_shared[i] = t_shared[j] = true;
      }
  const K::Triangle_3 ts(s[0], s[1], s[2]), tt(t[0], t[1], t[2]);
  if(shared == 0) return CGAL::do_intersect(ts, tt);
  if(shared >= 3) return true;
  // the corners of each that are not shared, in order
  std::array<std::size_t, 2> only_s{}, only_t{};
  for(std::size_t i = 0, m = 0, n = 0; i < 3; ++i) {
    if(!s_shared[i] && m < 2) only_s[m++] = i;
    if(!t_shared[i] && n < 2) only_t[n++] = i;
  }
  if(shared == 1)
    return CGAL::do_intersect(ts, K::Segment_3(t[only_t[0]], t[only_t[1]])) ||
           CGAL::do_intersect(tt, K::Segment_3(s[only_s[0]], s[only_s[1]]));
  // one side shared: the apexes s[only_s[0]] and t[only_t[0]]
  std::array<K::Point_3, 2> side;
  for(std::size_t i = 0, k = 0; i < 3; ++i)
    if(s_shared[i]) side[k++] = s[i];
  const K::Point_3 &apex_s = s[only_s[0]], &apex_t = t[only_t[0]];
  return CGAL::coplanar(side[0], side[1], apex_s, apex_t) && !CGAL::collinear(side[0], side[1], apex_s) &&
         CGAL::coplanar_orientation(side[0], side[1], apex_s, apex_t) == CGAL::POSITIVE;
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_TRIANGLE_CONTACT_H
