// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality report fields against values computed independently, and the
// checked reader / atomic writer.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <cstdio>
#include <dirent.h>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace NR = CGAL::Nonobtuse_remeshing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Mesh = CGAL::Surface_mesh<Point>;

namespace {

using nonobtuse_test::data;
using nonobtuse_test::load;
using nonobtuse_test::folder_entries;
using nonobtuse_test::scratch_folder;



void write_text(const std::string& path, const std::string& text)
{
  std::ofstream out(path);
  out << text;
}

// Independent topology: union-find over faces sharing an edge, border cycles
// by following border halfedges, valences by counting outgoing halfedges.
struct Independent_topology
{
  std::size_t components = 0, border_cycles = 0;
  std::map<std::size_t, std::size_t> interior, boundary;
};

Independent_topology independent_topology(const Mesh& m)
{
  Independent_topology t;
  std::vector<std::size_t> parent(m.number_of_faces());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<std::size_t(std::size_t)> find = [&](std::size_t x) {
    return parent[x] == x ? x : parent[x] = find(parent[x]);
  };
  for(auto e : m.edges()) {
    const auto f = m.face(m.halfedge(e)), g = m.face(m.opposite(m.halfedge(e)));
    if(f != Mesh::null_face() && g != Mesh::null_face()) parent[find(std::size_t(f))] = find(std::size_t(g));
  }
  for(auto f : m.faces()) t.components += (find(std::size_t(f)) == std::size_t(f));

  std::set<Mesh::Halfedge_index> seen;
  for(auto h : m.halfedges()) {
    if(!m.is_border(h) || seen.count(h)) continue;
    ++t.border_cycles;
    for(auto g = h; seen.insert(g).second; g = m.next(g)) {}
  }
  for(auto v : m.vertices()) {
    std::size_t valence = 0;
    bool on_border = false;
    for(auto h : m.halfedges()) {
      if(m.source(h) != v) continue;
      ++valence;
      on_border = on_border || m.is_border(h) || m.is_border(m.opposite(h));
    }
    ++(on_border ? t.boundary : t.interior)[valence];
  }
  return t;
}

} // namespace

class ReportOnSampleMesh : public ::testing::TestWithParam<std::tuple<std::string, long, std::size_t>> {};

TEST_P(ReportOnSampleMesh, FieldsAgreeWithIndependentComputation)
{
  const std::string name = std::get<0>(GetParam());
  const Mesh mesh = load(name);
  const NR::Quality_report r = NR::quality_report(mesh);
  const Independent_topology t = independent_topology(mesh);

  EXPECT_EQ(r.vertices, mesh.number_of_vertices());
  EXPECT_EQ(r.faces, mesh.number_of_faces());
  EXPECT_EQ(r.edges, mesh.number_of_edges());
  EXPECT_EQ(r.euler_characteristic, std::get<1>(GetParam()));  // shared/meshes/README.md
  EXPECT_EQ(r.border_cycles, std::get<2>(GetParam()));
  EXPECT_EQ(r.border_cycles, t.border_cycles);
  EXPECT_EQ(r.connected_components, t.components);
  EXPECT_EQ(r.interior_valences, t.interior);
  EXPECT_EQ(r.boundary_valences, t.boundary);
  EXPECT_EQ(r.non_manifold_vertices, 0u);
  EXPECT_EQ(std::accumulate(r.angle_histogram.begin(), r.angle_histogram.end(), std::size_t(0)),
            3 * r.faces);
  EXPECT_TRUE(r.has_angles);
  const auto cert = NR::certify_angle_bounds(mesh);
  EXPECT_EQ(r.certified, cert.is_certified());
  EXPECT_EQ(r.too_small_corners, cert.too_small_corners);
  EXPECT_EQ(r.too_large_corners, cert.too_large_corners);
  EXPECT_FALSE(r.distance);
}

INSTANTIATE_TEST_SUITE_P(SampleMeshes, ReportOnSampleMesh,
                         ::testing::Values(std::make_tuple("sphere.off", 2L, std::size_t(0)),
                                           std::make_tuple("cube-meshed.off", 2L, std::size_t(0)),
                                           std::make_tuple("pig.off", -5L, std::size_t(7)),
                                           std::make_tuple("nefertiti.off", 1L, std::size_t(1)),
                                           std::make_tuple("rotor.off", 0L, std::size_t(0))),
                         [](const auto& info) {
                           std::string name = std::get<0>(info.param);
                           name = name.substr(0, name.find('.'));
                           for(char& ch : name) if(ch == '-') ch = '_';
                           return name;
                         });

TEST(QualityReport, AngleHistogramBins)
{
  // 45-45-90: the right angle in [85, 90], two corners in [45, 50)
  Mesh m;
  m.add_face(m.add_vertex(Point(0, 0, 0)), m.add_vertex(Point(1, 0, 0)), m.add_vertex(Point(0, 1, 0)));
  NR::Quality_report r = NR::quality_report(m);
  EXPECT_EQ(r.angle_histogram[17], 1u);
  EXPECT_EQ(r.angle_histogram[9], 2u);
  EXPECT_EQ(r.boundary_valences.at(2), 3u);
  // The exact 30-60-90 triangle (see test_certification.cpp): its 30 degree
  // corner measures 29.999999999999996 in double, but it is certified, so it
  // is shown as 30 and counted in [30, 35).
  Mesh t;
  t.add_face(t.add_vertex(Point(0, 0, 0)), t.add_vertex(Point(1.5, 1.5, 0)), t.add_vertex(Point(1, 2, 1)));
  r = NR::quality_report(t);
  EXPECT_TRUE(r.certified);
  EXPECT_GE(r.min_angle, 30.);
  EXPECT_NEAR(r.min_angle, 30., 1e-12);
  EXPECT_EQ(r.max_angle, 90.);
  EXPECT_EQ(r.angle_histogram[6], 1u);   // 30
  EXPECT_EQ(r.angle_histogram[12], 1u);  // 60
  EXPECT_EQ(r.angle_histogram[17], 1u);  // 90
  // degenerate faces only: no angle to show
  Mesh flat;
  flat.add_face(flat.add_vertex(Point(0, 0, 0)), flat.add_vertex(Point(1, 0, 0)), flat.add_vertex(Point(2, 0, 0)));
  r = NR::quality_report(flat);
  EXPECT_FALSE(r.has_angles);
  EXPECT_EQ(std::accumulate(r.angle_histogram.begin(), r.angle_histogram.end(), std::size_t(0)), 0u);
}

TEST(QualityReport, DistanceToATranslatedCube)
{
  // cube-meshed.off is the cube [-1,1]^3 (diagonal 2 sqrt 3). Shifted by delta
  // along x, both one-sided Hausdorff distances are delta, and the mean is
  // about delta/3 (the two x faces are delta away, the others almost 0).
  const Mesh reference = load("cube-meshed.off");
  Mesh shifted = reference;
  const double delta = 0.01;
  for(auto v : shifted.vertices()) shifted.point(v) = shifted.point(v) + Vector(delta, 0, 0);
  const NR::Quality_report r = NR::quality_report(shifted, &reference);
  ASSERT_TRUE(r.distance);
  const double diagonal = 2 * std::sqrt(3.);
  const double expected = 100 * delta / diagonal;
  EXPECT_NEAR(r.distance->reference_diagonal, diagonal, 1e-12);
  EXPECT_NEAR(r.distance->hausdorff_to_reference, expected, r.distance->hausdorff_error_bound + 1e-12);
  EXPECT_NEAR(r.distance->hausdorff_from_reference, expected, r.distance->hausdorff_error_bound + 1e-12);
  EXPECT_DOUBLE_EQ(r.distance->hausdorff_symmetric,
                   std::max(r.distance->hausdorff_to_reference, r.distance->hausdorff_from_reference));
  EXPECT_NEAR(r.distance->hausdorff_error_bound, 1e-2, 1e-12);  // 1e-4 of the diagonal, in percent
  EXPECT_GT(r.distance->mean_to_reference, 0.3 * expected);
  EXPECT_LT(r.distance->mean_to_reference, 0.34 * expected);
  EXPECT_GT(r.distance->mean_from_reference, 0.3 * expected);
  EXPECT_LT(r.distance->mean_from_reference, 0.34 * expected);

  const NR::Quality_report same = NR::quality_report(reference, &reference);
  EXPECT_EQ(same.distance->hausdorff_symmetric, 0.);
  EXPECT_LT(same.distance->mean_to_reference, 1e-12);
}

TEST(QualityReport, SelfIntersectionsAndTheirCap)
{
  Mesh two = load("sphere.off");
  EXPECT_EQ(NR::quality_report(two).self_intersections, 0u);
  const Mesh copy = two;
  std::map<Mesh::Vertex_index, Mesh::Vertex_index> to_new;
  for(auto v : copy.vertices()) to_new[v] = two.add_vertex(copy.point(v) + Vector(0.3, 0.1, 0.05));
  for(auto f : copy.faces()) {
    std::vector<Mesh::Vertex_index> corners;
    for(auto v : copy.vertices_around_face(copy.halfedge(f))) corners.push_back(to_new[v]);
    two.add_face(corners);
  }
  const NR::Quality_report all = NR::quality_report(two);
  EXPECT_GT(all.self_intersections, 10u);
  EXPECT_FALSE(all.self_intersections_capped);
  EXPECT_EQ(all.connected_components, 2u);
  EXPECT_EQ(all.euler_characteristic, 4);
  const NR::Quality_report capped =
      NR::quality_report(two, nullptr, NR::parameters::maximum_self_intersections(std::size_t(5)));
  EXPECT_EQ(capped.self_intersections, 5u);
  EXPECT_TRUE(capped.self_intersections_capped);
  // a cap equal to the true count is reached but not exceeded
  const NR::Quality_report exact = NR::quality_report(
      two, nullptr, NR::parameters::maximum_self_intersections(all.self_intersections));
  EXPECT_EQ(exact.self_intersections, all.self_intersections);
  EXPECT_FALSE(exact.self_intersections_capped);
  EXPECT_THROW(NR::quality_report(two, nullptr, NR::parameters::maximum_self_intersections(std::size_t(0))),
               NR::Bad_parameter);
}

TEST(QualityReport, NonManifoldVertexIsCounted)
{
  // two triangles that share one vertex only
  Mesh m;
  const auto o = m.add_vertex(Point(0, 0, 0));
  m.add_face(o, m.add_vertex(Point(1, 0, 0)), m.add_vertex(Point(0, 1, 0)));
  ASSERT_NE(m.add_face(o, m.add_vertex(Point(-1, 0, 0)), m.add_vertex(Point(0, -1, 0))), Mesh::null_face());
  const NR::Quality_report r = NR::quality_report(m);
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  EXPECT_EQ(r.connected_components, 2u);
}

TEST(MeshIO, RoundTripKeepsEveryDoubleAndTheCertificate)
{
  const std::string folder = scratch_folder("round_trip");
  Mesh mesh = load("sphere.off");
  // non-dyadic coordinates with all 17 digits significant
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  for(auto v : mesh.vertices())
    mesh.point(v) = mesh.point(v) + Vector(noise(rng), noise(rng), noise(rng));
  const auto before = NR::certify_angle_bounds(mesh);
  for(const std::string ext : {"off", "obj", "ply", "stl"}) {
    const std::string path = folder + "/sphere." + ext;
    NR::write_mesh_atomically(path, mesh);
    Mesh back;
    NR::Read_log log;
    NR::read_triangle_mesh(path, back, log);
    EXPECT_TRUE(log.repairs.empty()) << ext;
    ASSERT_EQ(back.number_of_vertices(), mesh.number_of_vertices()) << ext;
    ASSERT_EQ(back.number_of_faces(), mesh.number_of_faces()) << ext;
    std::multiset<std::array<double, 3>> a, b;
    for(auto v : mesh.vertices()) a.insert({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
    for(auto v : back.vertices()) b.insert({back.point(v).x(), back.point(v).y(), back.point(v).z()});
    EXPECT_EQ(a, b) << ext << ": coordinates changed";
    const auto after = NR::certify_angle_bounds(back);
    EXPECT_EQ(after.is_certified(), before.is_certified()) << ext;
    EXPECT_EQ(after.too_small_corners, before.too_small_corners) << ext;
    EXPECT_EQ(after.too_large_corners, before.too_large_corners) << ext;
    EXPECT_EQ(NR::quality_report(back).euler_characteristic, 2) << ext;
  }
  EXPECT_EQ(folder_entries(folder),
            (std::set<std::string>{"sphere.off", "sphere.obj", "sphere.ply", "sphere.stl"}));

  // A certified mesh written and re-read still certifies: the exact right
  // angles of cube-meshed survive the file.
  const Mesh cube = load("cube-meshed.off");
  ASSERT_TRUE(NR::certify_angle_bounds(cube).is_certified());
  const std::string cube_path = folder + "/cube.off";
  NR::write_mesh_atomically(cube_path, cube);
  Mesh cube_back;
  NR::read_triangle_mesh(cube_path, cube_back);
  EXPECT_TRUE(NR::certify_angle_bounds(cube_back).is_certified());
}

TEST(MeshIO, AtomicWriteLeavesNothingBehindOnFailure)
{
  const std::string folder = scratch_folder("atomic");
  const Mesh mesh = load("sphere.off");
  EXPECT_THROW(NR::write_mesh_atomically(folder + "/missing/out.off", mesh), NR::Output_error);
  EXPECT_THROW(NR::write_mesh_atomically(folder + "/out.xyz", mesh), NR::Output_error);
  // a check that rejects the written file: the target is never created
  EXPECT_THROW(NR::write_mesh_atomically(folder + "/out.off", mesh,
                                         [](const std::string&) { return false; }),
               NR::Output_error);
  EXPECT_TRUE(folder_entries(folder).empty());
  // an existing target is replaced whole, or kept whole
  write_text(folder + "/keep.off", "old");
  EXPECT_THROW(NR::write_mesh_atomically(folder + "/keep.off", mesh,
                                         [](const std::string&) { return false; }),
               NR::Output_error);
  std::ifstream in(folder + "/keep.off");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "old");
}

TEST(MeshIO, BadInputIsRefusedWithAReason)
{
  const std::string folder = scratch_folder("bad_input");
  auto expect_refused = [&](const std::string& file, const std::string& text, const std::string& reason) {
    if(!text.empty() || file.find("empty") != std::string::npos) write_text(folder + "/" + file, text);
    Mesh m;
    try {
      NR::read_triangle_mesh(folder + "/" + file, m);
      ADD_FAILURE() << file << " was accepted";
    } catch(const NR::Bad_input& e) {
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
    }
  };
  expect_refused("absent.off", "", "cannot open");
  expect_refused("empty.off", "", "is empty");
  expect_refused("garbage.off", "this is not a mesh\n\x01\x02\x03", "cannot parse");
  expect_refused("no_faces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "no face");
  expect_refused("nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "non-finite");
  expect_refused("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "refers to vertex 7");
  expect_refused("index.ply",
                 "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                 "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                 "0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n",
                 "refers to vertex 9");
  expect_refused("huge.off", "OFF\n1000000000 1000000000 0\n0 0 0\n", "more than its");
  expect_refused("nan.ply",
                 "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                 "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                 "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n",
                 "non-finite");
  expect_refused("overflow.off", "OFF\n3 1 0\n0 0 0\n1e400 0 0\n0 1 0\n3 0 1 2\n", "non-finite");
  ::mkdir((folder + "/folder.off").c_str(), 0755);
  expect_refused("folder.off", "", "not a regular file");
  expect_refused("mesh.txt", "OFF\n", "unsupported file format");
}

TEST(MeshIO, RepairsAreMadeOnlyWhenNeededAndReported)
{
  const std::string folder = scratch_folder("repairs");
  // a quad: triangulated
  write_text(folder + "/quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  Mesh quad;
  NR::Read_log log;
  NR::read_triangle_mesh(folder + "/quad.off", quad, log);
  EXPECT_EQ(quad.number_of_faces(), 2u);
  ASSERT_EQ(log.repairs.size(), 1u);
  EXPECT_NE(log.repairs[0].find("triangulated 1"), std::string::npos);

  // two triangles with opposite orientations across their shared edge
  write_text(folder + "/flipped.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 2 3\n");
  Mesh flipped;
  NR::Read_log flipped_log;
  NR::read_triangle_mesh(folder + "/flipped.off", flipped, flipped_log);
  EXPECT_EQ(flipped.number_of_faces(), 2u);
  ASSERT_EQ(flipped_log.repairs.size(), 1u);
  EXPECT_NE(flipped_log.repairs[0].find("orient_polygon_soup"), std::string::npos);
  EXPECT_EQ(NR::quality_report(flipped).connected_components, 1u);

  // Two closed tetrahedra touching at a point through two distinct vertices
  // with equal coordinates: a valid mesh, so nothing is merged or repaired.
  write_text(folder + "/touching.off",
             "OFF\n8 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
             "0 0 0\n-1 0 0\n0 -1 0\n0 0 -1\n"
             "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
             "3 4 5 6\n3 4 7 5\n3 4 6 7\n3 5 7 6\n");
  Mesh touching;
  NR::Read_log touching_log;
  NR::read_triangle_mesh(folder + "/touching.off", touching, touching_log);
  EXPECT_TRUE(touching_log.repairs.empty());
  const NR::Quality_report r = NR::quality_report(touching);
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.border_cycles, 0u);
  EXPECT_EQ(r.connected_components, 2u);
  EXPECT_EQ(r.euler_characteristic, 4);

  // a face that repeats a vertex is dropped and reported
  write_text(folder + "/repeat.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 1 3\n");
  Mesh repeat;
  NR::Read_log repeat_log;
  NR::read_triangle_mesh(folder + "/repeat.off", repeat, repeat_log);
  EXPECT_EQ(repeat.number_of_faces(), 1u);
  ASSERT_FALSE(repeat_log.repairs.empty());
  EXPECT_NE(repeat_log.repairs[0].find("repeat a vertex"), std::string::npos);
}
