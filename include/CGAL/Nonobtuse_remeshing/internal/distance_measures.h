// SPDX-License-Identifier: GPL-3.0-or-later
//
// The measures of the quality report (quality_report.h): Hausdorff
// distances (CGAL's bounded-error one, both ways), area-weighted mean
// distances (the four at the same time with oneTBB), the bounding-box
// diagonal, and a counter of self-intersections.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_MEASURES_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_MEASURES_H

#include <CGAL/Nonobtuse_remeshing/exceptions.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_invoke.h>
#endif

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// An AABB tree of the faces of `TriangleMesh`, in the kernel of its points.
template <typename TriangleMesh>
using Face_tree = AABB_tree<AABB_traits<
    typename Kernel_traits<typename boost::property_traits<
        typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel,
    AABB_face_graph_triangle_primitive<TriangleMesh> > >;

// Area-weighted mean distance from `mesh` to the triangles in `tree`: each
// face is integrated with the degree-3 rule that weighs the vertices 1/20,
// the edge midpoints 2/15 and the centroid 9/20.
template <typename TriangleMesh, typename Tree>
double mean_distance(const TriangleMesh& mesh, const Tree& tree)
{
  using Point = typename boost::property_traits<
      typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type;
  const auto vpm = get(CGAL::vertex_point, mesh);
  double integral = 0., area = 0.;
  for(auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    const Point& a = get(vpm, source(h, mesh));
    const Point& b = get(vpm, target(h, mesh));
    const Point& c = get(vpm, target(next(h, mesh), mesh));
    const double fa = std::sqrt(to_double(CGAL::squared_area(a, b, c)));
    auto d = [&](const Point& p) { return std::sqrt(to_double(tree.squared_distance(p))); };
    const double corners = d(a) + d(b) + d(c);
    const double midpoints = d(CGAL::midpoint(a, b)) + d(CGAL::midpoint(b, c)) + d(CGAL::midpoint(c, a));
    const double mean = corners / 20. + midpoints * 2. / 15. + d(CGAL::centroid(a, b, c)) * 9. / 20.;
    integral += fa * mean;
    area += fa;
  }
  return area > 0. ? integral / area : 0.;
}

template <typename TriangleMesh>
double bbox_diagonal(const TriangleMesh& mesh)
{
  const Bbox_3 box = Polygon_mesh_processing::bbox(mesh);
  const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(), dz = box.zmax() - box.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// The distances of `mesh` to `reference` and back, as a `Report`
// (quality_report.h's Distance_report), in % of the reference's diagonal.
template <typename Report, typename TriangleMesh>
Report distance_report(const TriangleMesh& mesh, const TriangleMesh& reference, double relative_error)
{
  namespace PMP = Polygon_mesh_processing;

  Report r;
  r.reference_diagonal = bbox_diagonal(reference);
  if(!(r.reference_diagonal > 0.))
    throw Bad_input("the reference mesh has a zero-size bounding box");
  const double scale = r.reference_diagonal > 0. ? 100. / r.reference_diagonal : 0.;
  const double error = relative_error * r.reference_diagonal;
  // four measures, each sequential, side by side on the cores there are
  const auto hausdorff_to = [&] {
    r.hausdorff_to_reference = scale * PMP::bounded_error_Hausdorff_distance<Sequential_tag>(mesh, reference, error);
  };
  const auto hausdorff_from = [&] {
    r.hausdorff_from_reference = scale * PMP::bounded_error_Hausdorff_distance<Sequential_tag>(reference, mesh, error);
  };
  const auto mean_to = [&] {
    Face_tree<TriangleMesh> to_reference(faces(reference).first, faces(reference).second, reference);
    to_reference.accelerate_distance_queries();
    r.mean_to_reference = scale * mean_distance(mesh, to_reference);
  };
  const auto mean_from = [&] {
    Face_tree<TriangleMesh> to_mesh(faces(mesh).first, faces(mesh).second, mesh);
    to_mesh.accelerate_distance_queries();
    r.mean_from_reference = scale * mean_distance(reference, to_mesh);
  };
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_invoke(hausdorff_to, hausdorff_from, mean_to, mean_from);
#else
  hausdorff_to();
  hausdorff_from();
  mean_to();
  mean_from();
#endif
  r.hausdorff_symmetric = (std::max)(r.hausdorff_to_reference, r.hausdorff_from_reference);
  r.hausdorff_error_bound = scale * error;
  return r;
}

// An upper bound of the symmetric Hausdorff distance between `mesh` and
// `reference`: CGAL's bounded-error estimate plus its error bound `error`
// (absolute); both ways side by side unless `threads` is 1 (CGAL 5.5's
// Parallel_tag there needs METIS too).
template <typename TriangleMesh>
double hausdorff_distance_bound(const TriangleMesh& mesh, const TriangleMesh& reference, double error, int threads)
{
  namespace PMP = Polygon_mesh_processing;
#ifdef CGAL_LINKED_WITH_TBB
  if(threads != 1) {
    double to = 0., from = 0.;
    tbb::parallel_invoke([&] { to = PMP::bounded_error_Hausdorff_distance<Sequential_tag>(mesh, reference, error); },
                         [&] { from = PMP::bounded_error_Hausdorff_distance<Sequential_tag>(reference, mesh, error); });
    return (std::max)(to, from) + error;
  }
#endif
  (void)threads;
  return PMP::bounded_error_symmetric_Hausdorff_distance<Sequential_tag>(mesh, reference, error) + error;
}

// Output iterator that only counts the face pairs it is given.
struct Counting_iterator
{
  std::size_t* count;
  Counting_iterator& operator*() { return *this; }
  Counting_iterator& operator++() { return *this; }
  Counting_iterator operator++(int) { return *this; }
  template <typename T> Counting_iterator& operator=(const T&) { ++*count; return *this; }
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_DISTANCE_MEASURES_H
