// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every stage and the whole pipeline on other models of FaceGraph than the
// reference CGAL::Surface_mesh<Epick::Point_3>: CGAL::Polyhedron_3<Epick>,
// a Surface_mesh of Simple_cartesian<double> points, and points held in a
// vertex property map of the user's. What they write must certify, re-read
// from the file; the Simple_cartesian mesh, which has the same connectivity
// as the reference and the same doubles, must give the same files.

#include "test_support.h"

#include <CGAL/nonobtuse_remeshing.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <unistd.h>

namespace {

namespace NR = CGAL::Nonobtuse_remeshing;
using nonobtuse_test::data;
using nonobtuse_test::slurp;
using Reference_mesh = nonobtuse_test::Mesh;
using Polyhedron = CGAL::Polyhedron_3<CGAL::Exact_predicates_inexact_constructions_kernel>;
using Cartesian_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

template <typename Mesh>
void collect_garbage(Mesh& mesh)
{
  if constexpr(!std::is_same<Mesh, Polyhedron>::value) mesh.collect_garbage();
}

// Writes `mesh` as the tool does (certified on the temporary file before the
// rename), reads the file back into the reference mesh type, certifies it
// there and returns the file's bytes.
template <typename Mesh>
std::string written_and_certified(const Mesh& mesh, const std::string& name)
{
  const std::string path = ::testing::TempDir() + std::to_string(::getpid()) + "_generic_" + name + ".off";
  NR::write_mesh_atomically(path, mesh, NR::certifying_check(mesh));
  Reference_mesh reread;
  NR::read_triangle_mesh(path, reread);
  EXPECT_TRUE(NR::certify_angle_bounds(reread).is_certified()) << name;
  EXPECT_EQ(faces(reread).size(), faces(mesh).size()) << name;
  const std::string bytes = slurp(path);
  std::remove(path.c_str());
  return bytes;
}

// The stages one by one, then the pipeline and a hierarchy of its output,
// each written and certified; returns the files' bytes, in that order.
template <typename Mesh>
std::vector<std::string> run_stages(const std::string& input_name)
{
  std::vector<std::string> files;
  Mesh input;
  NR::read_triangle_mesh(data(input_name), input);

  Mesh mesh;
  const NR::Marching_cubes_result mc = NR::nonobtuse_marching_cubes(input, mesh, NR::parameters::resolution(16));
  EXPECT_GT(mc.triangles_out, 0u);
  files.push_back(written_and_certified(mesh, "initial"));

  NR::remove_bad_valence_vertices(mesh);
  collect_garbage(mesh);
  files.push_back(written_and_certified(mesh, "valence"));

  const NR::Deform_to_fit_statistics fit = NR::deform_to_fit(mesh, input, NR::parameters::max_moves(3000));
  EXPECT_GT(fit.moves, 0u);
  files.push_back(written_and_certified(mesh, "fit"));

  Mesh decimated;
  CGAL::copy_face_graph(mesh, decimated);
  const NR::Angle_bounded_decimation_statistics d =
      NR::angle_bounded_decimation(decimated, NR::parameters::vertex_ratio(0.6));
  EXPECT_GT(d.collapses, 0u);
  collect_garbage(decimated);
  files.push_back(written_and_certified(decimated, "decimated"));

  Mesh remeshed;
  const NR::Nonobtuse_remeshing_statistics s =
      NR::nonobtuse_remesh(input, remeshed, NR::parameters::combine(NR::parameters::resolution(16),
                                                                   NR::parameters::max_moves(3000)));
  EXPECT_TRUE(s.fit_run);
  files.push_back(written_and_certified(remeshed, "remeshed"));
  for(const auto& level : NR::angle_bounded_decimation_hierarchy(remeshed, {0.5}))
    files.push_back(written_and_certified(level.mesh, "level"));

  const auto report = NR::quality_report(remeshed, &input);
  EXPECT_TRUE(report.certified);
  EXPECT_TRUE(report.distance && report.distance->hausdorff_symmetric < 10.)  // % of the diagonal, at N = 16
      << (report.distance ? report.distance->hausdorff_symmetric : -1.);
  return files;
}

TEST(GenericMeshes, PolyhedronRunsEveryStageAndCertifies)
{
  const std::vector<std::string> files = run_stages<Polyhedron>("mesh_with_border.off");
  EXPECT_EQ(files.size(), 6u);
}

TEST(GenericMeshes, SimpleCartesianSurfaceMeshGivesTheReferenceFiles)
{
  const std::vector<std::string> cartesian = run_stages<Cartesian_mesh>("mesh_with_border.off");
  const std::vector<std::string> reference = run_stages<Reference_mesh>("mesh_with_border.off");
  ASSERT_EQ(cartesian.size(), reference.size());
  for(std::size_t i = 0; i < reference.size(); ++i) EXPECT_EQ(cartesian[i], reference[i]) << "file " << i;
}

TEST(GenericMeshes, PointsInAPropertyMapOfTheUser)
{
  // The input's points shifted along x by twice its diagonal into a property
  // map of their own: every stage must read that map, and write the output's
  // own map (its bounding box is then the shifted input's, up to the fit).
  Reference_mesh input = nonobtuse_test::load("mesh_with_border.off");
  using Point = Reference_mesh::Point;
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  auto shifted = input.add_property_map<Reference_mesh::Vertex_index, Point>("v:shifted").first;
  for(auto v : vertices(input)) {
    const Point& p = input.point(v);
    put(shifted, v, Point(p.x() + 2. * diagonal, p.y(), p.z()));
  }
  Reference_mesh output;
  auto written = output.add_property_map<Reference_mesh::Vertex_index, Point>("v:written").first;
  NR::nonobtuse_remesh(input, output,
                       NR::parameters::combine(NR::parameters::resolution(16), NR::parameters::max_moves(3000),
                                               CGAL::parameters::vertex_point_map(shifted)),
                       CGAL::parameters::vertex_point_map(written));
  ASSERT_GT(faces(output).size(), 0u);
  EXPECT_TRUE(NR::certify_angle_bounds(output, CGAL::parameters::vertex_point_map(written)).is_certified());
  CGAL::Bbox_3 out_box, in_box;
  for(auto v : vertices(output)) out_box += get(written, v).bbox();
  for(auto v : vertices(input)) in_box += get(shifted, v).bbox();
  for(int a = 0; a < 3; ++a) {
    EXPECT_NEAR(out_box.min(a), in_box.min(a), 0.05 * diagonal) << "axis " << a;
    EXPECT_NEAR(out_box.max(a), in_box.max(a), 0.05 * diagonal) << "axis " << a;
  }

  // The decimation and the fit through the same maps.
  const NR::Angle_bounded_decimation_statistics d =
      NR::angle_bounded_decimation(output, NR::parameters::combine(NR::parameters::vertex_ratio(0.7),
                                                                   CGAL::parameters::vertex_point_map(written)));
  EXPECT_GT(d.collapses, 0u);
  EXPECT_TRUE(NR::certify_angle_bounds(output, CGAL::parameters::vertex_point_map(written)).is_certified());
  NR::deform_to_fit(output, input,
                    NR::parameters::combine(NR::parameters::max_moves(500), CGAL::parameters::vertex_point_map(written)),
                    CGAL::parameters::vertex_point_map(shifted));
  EXPECT_TRUE(NR::certify_angle_bounds(output, CGAL::parameters::vertex_point_map(written)).is_certified());
}

} // namespace
