// SPDX-License-Identifier: GPL-3.0-or-later
//
// Nonobtuse Marching Cubes: the generated table checked exhaustively and
// exactly, phase 1 against brute force, and whole meshes at several
// resolutions, certified on the re-read file.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/nonobtuse_remeshing.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <boost/multiprecision/cpp_int.hpp>

#include <gtest/gtest.h>

#include "test_support.h"

#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <tuple>
#include <unistd.h>

namespace NR = CGAL::Nonobtuse_remeshing;
namespace MC = CGAL::Nonobtuse_remeshing::internal::marching_cubes;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

namespace {

using nonobtuse_test::data;
using nonobtuse_test::load;
using nonobtuse_test::written_and_reread;

// The grid nonobtuse_marching_cubes() builds for `mesh`.
NR::internal::Grid grid_of(const Mesh& mesh, int resolution)
{
  std::vector<Point> corners;
  for(auto f : mesh.faces())
    for(auto v : mesh.vertices_around_face(mesh.halfedge(f))) corners.push_back(mesh.point(v));
  return NR::internal::Grid(CGAL::Polygon_mesh_processing::bbox(mesh), resolution, corners);
}

std::array<long, 3> corner_position(int c) { return {2L * (c & 1), 2L * ((c >> 1) & 1), 2L * ((c >> 2) & 1)}; }

std::array<long, 3> position(int slot)
{
  const std::array<int, 3> p = MC::slot_position(slot);
  return {p[0], p[1], p[2]};
}

std::array<long, 3> minus(const std::array<long, 3>& a, const std::array<long, 3>& b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

long dot(const std::array<long, 3>& a, const std::array<long, 3>& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The edge between corners a and b, found geometrically (not with the
// table's numbering helpers): the slot whose position is their midpoint.
int slot_between(int a, int b)
{
  const std::array<long, 3> pa = corner_position(a), pb = corner_position(b);
  for(int s = 0; s < 12; ++s)
    if(position(s) == std::array<long, 3>{(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2})
      return s;
  return -1;
}

// Reports that stop at the first self-intersection: double sheets at thin
// features make a full count slow, and these tests do not need it.
auto one_self_intersection() { return NR::parameters::maximum_self_intersections(std::size_t(1)); }

} // namespace

// Every configuration: angles in [acos(sqrt(2/3)), 90] exactly; vertices
// only at midpoints of crossed edges and at the centre; a manifold patch
// whose border is exactly the face contours (ambiguous faces cut off their
// outside corners); normals from inside to outside.
TEST(MarchingCubesTable, AllConfigurationsExhaustively)
{
  const auto& table = MC::table();
  std::size_t with_centre = 0;
  for(unsigned config = 0; config < 256; ++config) {
    SCOPED_TRACE("configuration " + std::to_string(config));
    const auto& triangles = table[config].triangles;
    auto inside = [&](int c) { return ((config >> c) & 1u) != 0; };
    std::set<int> crossed;
    for(int a = 0; a < 8; ++a)
      for(int axis = 0; axis < 3; ++axis) {
        const int b = a ^ (1 << axis);
        if(a < b && inside(a) != inside(b)) crossed.insert(slot_between(a, b));
      }
    EXPECT_EQ(triangles.empty(), crossed.empty());

    // angles, exactly (integers)
    for(const auto& t : triangles)
      for(int i = 0; i < 3; ++i) {
        const auto u = minus(position(t[(i + 1) % 3]), position(t[i]));
        const auto v = minus(position(t[(i + 2) % 3]), position(t[i]));
        const long d = dot(u, v), l = dot(u, u) * dot(v, v);
        EXPECT_GE(d, 0) << "obtuse";
        EXPECT_LE(3 * d * d, 2 * l) << "below 35.26 degrees";
        EXPECT_GT(l, 0);
      }

    // vertices, edges, fans
    std::set<int> used;
    std::map<std::pair<int, int>, int> directed;
    for(const auto& t : triangles)
      for(int i = 0; i < 3; ++i) {
        used.insert(t[i]);
        ++directed[{t[i], t[(i + 1) % 3]}];
      }
    for(int s : used) EXPECT_TRUE(s == MC::centre_slot || crossed.count(s)) << "slot " << s;
    for(int s : crossed) EXPECT_TRUE(used.count(s)) << "crossed edge without vertex " << s;
    with_centre += used.count(MC::centre_slot);
    std::map<std::pair<int, int>, int> border;  // directed border edges
    for(const auto& e : directed) {
      EXPECT_EQ(e.second, 1) << "edge used twice in one direction";
      if(!directed.count({e.first.second, e.first.first})) border[e.first] = 1;
    }
    for(int s : used) {
      std::vector<std::size_t> around;
      for(std::size_t f = 0; f < triangles.size(); ++f)
        if(std::count(triangles[f].begin(), triangles[f].end(), s)) around.push_back(f);
      std::vector<std::size_t> root(around.size());
      std::iota(root.begin(), root.end(), 0);
      std::function<std::size_t(std::size_t)> find = [&](std::size_t x) { return root[x] == x ? x : root[x] = find(root[x]); };
      for(std::size_t i = 0; i < around.size(); ++i)
        for(std::size_t j = i + 1; j < around.size(); ++j) {
          int shared = 0;
          for(int a : triangles[around[i]]) shared += std::count(triangles[around[j]].begin(), triangles[around[j]].end(), a);
          if(shared == 2) root[find(i)] = find(j);
        }
      std::set<std::size_t> fans;
      for(std::size_t i = 0; i < around.size(); ++i) fans.insert(find(i));
      EXPECT_EQ(fans.size(), 1u) << "non-manifold at slot " << s;
    }

    // the border is the union of the face contours
    std::set<std::pair<int, int> > expected;
    for(int face = 0; face < 6; ++face) {
      const int axis = face / 2, side = face % 2;
      std::vector<int> q;  // the face's corners in cyclic order, found geometrically
      for(int c = 0; c < 8; ++c)
        if(((c >> axis) & 1) == side) q.push_back(c);
      std::swap(q[2], q[3]);  // (00, 10, 01, 11) -> (00, 10, 11, 01)
      std::vector<int> cut;
      for(int i = 0; i < 4; ++i)
        if(inside(q[i]) != inside(q[(i + 1) % 4])) cut.push_back(i);
      auto edge = [&](int i) { return slot_between(q[i % 4], q[(i + 1) % 4]); };
      if(cut.size() == 2) {
        expected.insert({std::min(edge(cut[0]), edge(cut[1])), std::max(edge(cut[0]), edge(cut[1]))});
      } else if(cut.size() == 4) {  // ambiguous: each outside corner is cut off
        for(int i = 0; i < 4; ++i)
          if(!inside(q[i]))
            expected.insert({std::min(edge(i + 3), edge(i)), std::max(edge(i + 3), edge(i))});
      }
    }
    std::set<std::pair<int, int> > actual;
    for(const auto& e : border) actual.insert({std::min(e.first.first, e.first.second), std::max(e.first.first, e.first.second)});
    EXPECT_EQ(actual, expected);

    // orientation: around each crossed edge's midpoint the normal points
    // from the inside corner to the outside one
    for(int s : crossed) {
      std::array<long, 3> normal = {0, 0, 0};
      for(const auto& t : triangles)
        if(std::count(t.begin(), t.end(), s)) {
          const auto u = minus(position(t[1]), position(t[0])), v = minus(position(t[2]), position(t[0]));
          normal[0] += u[1] * v[2] - u[2] * v[1];
          normal[1] += u[2] * v[0] - u[0] * v[2];
          normal[2] += u[0] * v[1] - u[1] * v[0];
        }
      int a = -1, b = -1;
      for(int c = 0; c < 8 && a < 0; ++c)
        for(int axis = 0; axis < 3; ++axis)
          if(slot_between(c, c ^ (1 << axis)) == s) { a = c; b = c ^ (1 << axis); break; }
      const int from = inside(a) ? a : b, to = inside(a) ? b : a;
      EXPECT_GT(dot(normal, minus(corner_position(to), corner_position(from))), 0) << "slot " << s;
    }
  }
  EXPECT_GT(with_centre, 0u);
  // The thesis's cases by configuration (bit c set: corner c inside): the
  // centre where the original Marching Cubes is obtuse, case 5 (three inside
  // corners of a face) and case 9 (a corner and its three neighbours, six
  // equilateral triangles); none in cases 1, 2 and 8, where a centre vertex
  // would have valence 3 or 4.
  auto uses_centre = [&](unsigned config) {
    for(const auto& t : table[config].triangles)
      if(std::count(t.begin(), t.end(), MC::centre_slot)) return true;
    return false;
  };
  EXPECT_TRUE(uses_centre(0x07));   // case 5: corners 0, 1, 2
  EXPECT_TRUE(uses_centre(0x17));   // case 9: corner 0 and its neighbours 1, 2, 4
  EXPECT_EQ(table[0x17].triangles.size(), 6u);
  EXPECT_FALSE(uses_centre(0x01));  // case 1
  EXPECT_FALSE(uses_centre(0x03));  // case 2
  EXPECT_FALSE(uses_centre(0x0f));  // case 8
}

TEST(MarchingCubesTable, FlatSheetsGetValenceSix)
{
  // A plane z = const cuts every cube through its vertical edges (case 8, a
  // square): the same diagonal everywhere gives valence 6, not 4 and 8.
  Mesh plane;
  const double s = 1.;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j <= 1; ++j)
    for(int i = 0; i <= 1; ++i) v.push_back(plane.add_vertex(Point(i * s, j * s, 0.3)));
  plane.add_face(v[0], v[1], v[3]);
  plane.add_face(v[0], v[3], v[2]);
  Mesh out;
  NR::nonobtuse_marching_cubes(plane, out, NR::parameters::resolution(12));
  const NR::Quality_report r = NR::quality_report(out);
  ASSERT_FALSE(r.interior_valences.empty());
  EXPECT_EQ(r.interior_valences.size(), 1u);
  EXPECT_EQ(r.interior_valences.begin()->first, 6u);
}

// Phase 1 against testing every cube of the grid.
TEST(MarchingCubes, MeshCubeIntersectionMatchesBruteForce)
{
  for(const std::string name : {"sphere.off", "pig.off"})
    for(int resolution : {7, 16}) {
      const Mesh mesh = load(name);
      const NR::internal::Grid grid = grid_of(mesh, resolution);
      const NR::internal::Input_triangles in = NR::internal::input_triangles(mesh, get(CGAL::vertex_point, mesh));
      const std::vector<bool> usable(in.triangles.size(), true);
      NR::internal::Cube_triangles cubes;
      ASSERT_TRUE(NR::internal::mesh_cube_intersection(grid, in.triangles, usable, std::size_t(-1), cubes));
      std::set<std::pair<std::int64_t, std::size_t> > fast, brute;
      for(std::size_t c = 0; c < cubes.size(); ++c)
        for(std::size_t i = cubes.first[c]; i < cubes.first[c + 1]; ++i) fast.insert({cubes.cube_ids[c], cubes.triangles[i]});
      for(std::size_t t = 0; t < in.triangles.size(); ++t)
        for(int k = 0; k < grid.cubes(2); ++k)
          for(int j = 0; j < grid.cubes(1); ++j)
            for(int i = 0; i < grid.cubes(0); ++i)
              if(CGAL::do_intersect(in.triangles[t], grid.cube_box(i, j, k))) brute.insert({grid.cube_id(i, j, k), t});
      EXPECT_EQ(fast, brute) << name << " at " << resolution;
      EXPECT_FALSE(fast.empty());
    }
}

TEST(MarchingCubes, GridCoordinatesAreExact)
{
  const Mesh mesh = load("pig.off");
  const NR::internal::Grid grid = grid_of(mesh, 100);
  Mesh out;
  NR::nonobtuse_marching_cubes(mesh, out, NR::parameters::resolution(100));
  // every coordinate is exactly origin + p h/2 for an integer p (rationals)
  using Rational = boost::multiprecision::cpp_rational;
  const Rational half = Rational(grid.cube_size()) / 2;
  for(auto v : out.vertices())
    for(int a = 0; a < 3; ++a) {
      const Rational steps = (Rational(out.point(v)[a]) - Rational(grid.origin(a))) / half;
      ASSERT_EQ(boost::multiprecision::denominator(steps), 1) << out.point(v);
    }
  // about N cubes along the longest side
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double longest = std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  EXPECT_GT(longest / grid.cube_size(), 99.);
  EXPECT_LE(longest / grid.cube_size(), 100.);
}

// Every sample mesh at N = 10, 40, 70, 100: a manifold mesh, certified in
// [35.26, 90] on the file written and re-read; closed inputs closed with
// their Euler characteristic at N >= 40; open ones keep their borders at 100.
class MarchingCubesOnMesh : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(MarchingCubesOnMesh, ManifoldCertifiedAndFaithful)
{
  const std::string name = std::get<0>(GetParam());
  const int resolution = std::get<1>(GetParam());
  const Mesh input = load(name);
  const NR::Quality_report in = NR::quality_report(input, nullptr, one_self_intersection());
  Mesh out;
  const NR::Marching_cubes_result r = NR::nonobtuse_marching_cubes(input, out, NR::parameters::resolution(resolution));
  ASSERT_GT(num_faces(out), 0u);
  EXPECT_EQ(r.face_patch.size(), num_faces(out));

  const std::string path = ::testing::TempDir() + "nonobtuse_mc_" + std::to_string(::getpid()) + ".off";
  NR::write_mesh_atomically(path, out);
  Mesh back;
  NR::Read_log log;
  NR::read_triangle_mesh(path, back, log);
  std::remove(path.c_str());
  EXPECT_TRUE(log.repairs.empty()) << "the written file is a valid mesh as it is";
  ASSERT_EQ(num_faces(back), num_faces(out));

  const auto strict = NR::certify_angle_bounds(back, NR::parameters::min_angle(35.26));
  EXPECT_TRUE(strict.is_certified()) << strict.offending_faces.size() << " faces out of [35.26, 90]";
  EXPECT_GE(strict.min_angle, 35.26);
  EXPECT_TRUE(NR::certify_angle_bounds(back).is_certified());
  const NR::Quality_report q = NR::quality_report(back, nullptr, one_self_intersection());
  EXPECT_EQ(q.non_manifold_vertices, 0u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(back));
  EXPECT_EQ(q.border_cycles, r.borders_out);
  // At N = 10 thin parts (an elephant's tusks) come apart as closed pieces,
  // which are kept; from N = 40 on the components are those of the input.
  if(resolution >= 40) {
    EXPECT_EQ(q.connected_components, in.connected_components) << "components";
  } else {
    EXPECT_GE(q.connected_components, in.connected_components) << "components";
  }
  if(in.border_cycles == 0 && resolution >= 40) {
    EXPECT_EQ(q.border_cycles, 0u) << "a closed input gives a closed output";
  }
  // The topology holds once the grid resolves the handles: at N = 40 one of
  // the elephant's handles is narrower than two cubes and closes.
  if(in.border_cycles == 0 && resolution >= 70) {
    EXPECT_EQ(q.euler_characteristic, in.euler_characteristic);
  }
  if(in.border_cycles > 0 && resolution == 100 && in.self_intersections == 0) {
    EXPECT_EQ(q.border_cycles, in.border_cycles);
  }
  // every output face lies in (or on) the cube of its patch
  const NR::internal::Grid grid = grid_of(input, resolution);
  const auto in_faces = input.faces();
  const std::vector<Mesh::Face_index> all(in_faces.begin(), in_faces.end());
  std::size_t f = 0;
  for(auto face : out.faces()) {
    ASSERT_LT(r.face_patch[f], r.patch_faces.size());
    const auto& patch = r.patch_faces[r.face_patch[f]];
    ASSERT_FALSE(patch.empty());
    Point c = CGAL::centroid(out.point(out.source(out.halfedge(face))), out.point(out.target(out.halfedge(face))),
                             out.point(out.target(out.next(out.halfedge(face)))));
    // the patch's input triangles pass within a cube diagonal of the face
    double nearest = 1e300;
    for(std::size_t t : patch) {
      const auto h = input.halfedge(all[t]);
      const Kernel::Triangle_3 tri(input.point(input.source(h)), input.point(input.target(h)),
                                   input.point(input.target(input.next(h))));
      nearest = std::min(nearest, CGAL::squared_distance(c, tri));
    }
    EXPECT_LE(std::sqrt(nearest), 2 * grid.cube_size());
    ++f;
  }
}

INSTANTIATE_TEST_SUITE_P(SampleMeshes, MarchingCubesOnMesh,
                         ::testing::Combine(::testing::Values("sphere.off", "cube-meshed.off", "rotor.off", "elephant.off",
                                                              "pig.off", "nefertiti.off", "mesh_with_border.off"),
                                            ::testing::Values(10, 40, 70, 100)),
                         [](const auto& info) {
                           std::string name = std::get<0>(info.param);
                           name = name.substr(0, name.find('.'));
                           for(char& ch : name) if(ch == '-') ch = '_';
                           return name + "_" + std::to_string(std::get<1>(info.param));
                         });

TEST(MarchingCubes, SeveralComponentsAreKept)
{
  Mesh two = load("sphere.off");
  const Mesh copy = two;
  std::map<Mesh::Vertex_index, Mesh::Vertex_index> to_new;
  for(auto v : copy.vertices()) to_new[v] = two.add_vertex(copy.point(v) + Kernel::Vector_3(3, 0.5, 0));
  for(auto f : copy.faces()) {
    std::vector<Mesh::Vertex_index> corners;
    for(auto v : copy.vertices_around_face(copy.halfedge(f))) corners.push_back(to_new[v]);
    two.add_face(corners);
  }
  for(auto source : {NR::Sign_source::automatic, NR::Sign_source::patches, NR::Sign_source::winding_number,
                      NR::Sign_source::inside_test}) {
    Mesh out;
    const auto r = NR::nonobtuse_marching_cubes(
        two, out, NR::parameters::combine(NR::parameters::resolution(60), NR::parameters::sign_source(source)));
    EXPECT_EQ(r.components_out, 2u);
    EXPECT_EQ(r.borders_out, 0u);
    const NR::Quality_report q = NR::quality_report(written_and_reread(out, "two.off"), nullptr, one_self_intersection());
    EXPECT_EQ(q.euler_characteristic, 4);
    EXPECT_TRUE(q.certified);
  }
}

TEST(MarchingCubes, AllSignSourcesAgreeOnClosedInputs)
{
  // rotor.off is left out: its blades are thinner than a cube, so a global
  // inside test cannot keep its topology (the patches keep it, as double
  // sheets that deform-to-fit later pulls apart).
  for(const std::string name : {"sphere.off", "elephant.off", "cube-meshed.off"}) {
    const Mesh input = load(name);
    const long euler = NR::quality_report(input).euler_characteristic;
    for(auto source : {NR::Sign_source::patches, NR::Sign_source::winding_number, NR::Sign_source::inside_test}) {
      Mesh out;
      NR::nonobtuse_marching_cubes(input, out, NR::parameters::combine(NR::parameters::resolution(70),
                                                                       NR::parameters::sign_source(source)));
      const NR::Quality_report q = NR::quality_report(written_and_reread(out, "closed.off"), nullptr,
                                                      one_self_intersection());
      EXPECT_TRUE(q.certified) << name;
      EXPECT_EQ(q.non_manifold_vertices, 0u) << name;
      EXPECT_EQ(q.border_cycles, 0u) << name;
      EXPECT_EQ(q.euler_characteristic, euler) << name;
    }
  }
  Mesh open = load("pig.off"), out;
  EXPECT_THROW(NR::nonobtuse_marching_cubes(open, out, NR::parameters::sign_source(NR::Sign_source::inside_test)),
               NR::Bad_input);
}

TEST(MarchingCubes, OrientedLikeTheInput)
{
  Mesh input = load("elephant.off");
  for(bool flipped : {false, true}) {
    if(flipped) CGAL::Polygon_mesh_processing::reverse_face_orientations(input);
    const double input_volume = CGAL::Polygon_mesh_processing::volume(input);
    for(auto source : {NR::Sign_source::patches, NR::Sign_source::winding_number, NR::Sign_source::inside_test}) {
      Mesh out;
      NR::nonobtuse_marching_cubes(input, out, NR::parameters::combine(NR::parameters::resolution(50),
                                                                       NR::parameters::sign_source(source)));
      const double volume = CGAL::Polygon_mesh_processing::volume(out);
      EXPECT_GT(volume * input_volume, 0.) << (flipped ? "flipped input" : "input");
      EXPECT_NEAR(volume / input_volume, 1., 0.1);
    }
  }
}

// Re-meshing an output of this package: its vertices are dyadic and could
// lie on the new grid's planes, where votes abstain; the grid is shifted off
// them, and the closed input stays closed.
TEST(MarchingCubes, RemeshingAnOutputKeepsItClosed)
{
  Mesh first;
  NR::nonobtuse_marching_cubes(load("sphere.off"), first, NR::parameters::resolution(30));
  for(int resolution : {60, 120}) {
    Mesh second;
    const auto r = NR::nonobtuse_marching_cubes(first, second, NR::parameters::resolution(resolution));
    EXPECT_EQ(r.borders_out, 0u) << resolution;
    EXPECT_EQ(r.patches_ignored, 0u) << resolution;
    EXPECT_EQ(NR::quality_report(second, nullptr, one_self_intersection()).euler_characteristic, 2);
  }
}

// A dumbbell whose bar is thinner than a cube: the bar is lost, but both
// boxes are real geometry and stay (closed pieces are never removed).
TEST(MarchingCubes, ClosedPiecesAreNeverRemoved)
{
  const std::string path = ::testing::TempDir() + "nonobtuse_dumbbell_" + std::to_string(::getpid()) + ".off";
  std::ofstream(path) << "OFF\n24 22 0\n"
      "0 0 0\n10 0 0\n10 10 0\n0 10 0\n0 0 10\n10 0 10\n10 10 10\n0 10 10\n"
      "10 4.9 4.9\n10 5.1 4.9\n10 5.1 5.1\n10 4.9 5.1\n20 4.9 4.9\n20 5.1 4.9\n20 5.1 5.1\n20 4.9 5.1\n"
      "20 0 0\n30 0 0\n30 10 0\n20 10 0\n20 0 10\n30 0 10\n30 10 10\n20 10 10\n"
      "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 3 7 6 2\n4 0 4 7 3\n"
      "4 1 2 9 8\n4 2 6 10 9\n4 6 5 11 10\n4 5 1 8 11\n"
      "4 8 9 13 12\n4 9 10 14 13\n4 10 11 15 14\n4 11 8 12 15\n"
      "4 16 19 18 17\n4 20 21 22 23\n4 16 17 21 20\n4 19 23 22 18\n4 17 18 22 21\n"
      "4 16 19 13 12\n4 19 23 14 13\n4 23 20 15 14\n4 20 16 12 15\n";
  Mesh dumbbell;
  NR::read_triangle_mesh(path, dumbbell);
  std::remove(path.c_str());
  ASSERT_TRUE(CGAL::is_closed(dumbbell));
  for(int resolution : {10, 30}) {
    Mesh out;
    const auto r = NR::nonobtuse_marching_cubes(dumbbell, out, NR::parameters::resolution(resolution));
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(out);
    EXPECT_LT(box.xmin(), 1.) << resolution;
    EXPECT_GT(box.xmax(), 29.) << resolution;
    EXPECT_EQ(r.borders_out, 0u) << resolution;
    EXPECT_EQ(r.islands_removed, 0u) << resolution;
  }
}

namespace {

// `mesh` and a copy moved by `offset`, as one mesh of two components.
Mesh with_moved_copy(const Mesh& mesh, const Kernel::Vector_3& offset)
{
  Mesh two = mesh;
  std::map<Mesh::Vertex_index, Mesh::Vertex_index> to_new;
  for(auto v : mesh.vertices()) to_new[v] = two.add_vertex(mesh.point(v) + offset);
  for(auto f : mesh.faces()) {
    std::vector<Mesh::Vertex_index> corners;
    for(auto v : mesh.vertices_around_face(mesh.halfedge(f))) corners.push_back(to_new[v]);
    two.add_face(corners);
  }
  return two;
}

// A closed unit sphere of revolution whose profile curls through itself at
// the equator: a fold of the surface pushed through the surface beside it.
// What it encloses is the ball with a small bulge, a sphere topologically.
Mesh curled_sphere()
{
  const double pi = 3.14159265358979323846, r = 0.22, alpha = 0.4;
  const int n = 48, loop = 40, segments = 64;
  std::vector<std::array<double, 2> > profile;
  for(int i = 1; i <= n; ++i) profile.push_back({std::cos(-pi / 2 + pi / 2 * i / n), std::sin(-pi / 2 + pi / 2 * i / n)});
  const std::array<double, 2> centre{1 - r * std::cos(alpha), r * std::sin(alpha)};
  const double start = std::atan2(-centre[1], 1 - centre[0]);
  for(int i = 1; i < loop; ++i)
    profile.push_back({centre[0] + r * std::cos(start + 2 * pi * i / loop), centre[1] + r * std::sin(start + 2 * pi * i / loop)});
  for(int i = 0; i < n; ++i) profile.push_back({std::cos(pi / 2 * i / n), std::sin(pi / 2 * i / n)});
  Mesh mesh;
  const auto south = mesh.add_vertex(Point(0, 0, -1));
  std::vector<std::vector<Mesh::Vertex_index> > rings;
  for(const auto& p : profile) {
    rings.emplace_back();
    for(int k = 0; k < segments; ++k)
      rings.back().push_back(mesh.add_vertex(
          Point(p[0] * std::cos(2 * pi * k / segments), p[0] * std::sin(2 * pi * k / segments), p[1])));
  }
  const auto north = mesh.add_vertex(Point(0, 0, 1));
  for(int k = 0; k < segments; ++k) {
    const int l = (k + 1) % segments;
    mesh.add_face(south, rings.front()[l], rings.front()[k]);
    for(std::size_t i = 0; i + 1 < rings.size(); ++i) {
      mesh.add_face(rings[i][k], rings[i][l], rings[i + 1][l]);
      mesh.add_face(rings[i][k], rings[i + 1][l], rings[i + 1][k]);
    }
    mesh.add_face(north, rings.back()[k], rings.back()[l]);
  }
  if(CGAL::Polygon_mesh_processing::volume(mesh) < 0) CGAL::Polygon_mesh_processing::reverse_face_orientations(mesh);
  return mesh;
}

} // namespace

// The tree's far-field sums against the exact sum over all triangles, at
// grid corners in and around a closed, a self-intersecting and an open mesh.
TEST(WindingNumber, TreeIsCloseToTheExactSum)
{
  for(const std::string name : {"sphere.off", "cow.off", "pig.off"}) {
    const Mesh mesh = load(name);
    const auto input = NR::internal::input_triangles(mesh, get(CGAL::vertex_point, mesh));
    const NR::internal::Winding_number w(input.triangles, std::vector<bool>(input.triangles.size(), true));
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
    double worst = 0.;
    std::size_t integral = 0;
    for(int i = 0; i <= 16; ++i)
      for(int j = 0; j <= 16; ++j)
        for(int k = 0; k <= 16; ++k) {
          std::array<double, 3> q;
          for(int a = 0; a < 3; ++a) {
            const int t = a == 0 ? i : a == 1 ? j : k;
            q[a] = box.min(a) - 0.1 * (box.max(a) - box.min(a)) + 1.2 * (box.max(a) - box.min(a)) * (t + 0.31) / 16.;
          }
          const double exact = w.brute_force(q), fast = w(q);
          worst = (std::max)(worst, std::abs(exact - fast));
          if(std::abs(exact - std::round(exact)) < 0.2) {
            ++integral;
            EXPECT_EQ(std::lround(exact), std::lround(fast)) << name;
          }
        }
    EXPECT_LT(worst, 0.05) << name;
    EXPECT_GT(integral, 4000u) << name;
  }
  const Mesh sphere = load("sphere.off");
  const auto input = NR::internal::input_triangles(sphere, get(CGAL::vertex_point, sphere));
  const NR::internal::Winding_number w(input.triangles, std::vector<bool>(input.triangles.size(), true));
  EXPECT_NEAR(w({0.01, 0.02, 0.03}), 1., 0.01);
  EXPECT_NEAR(w({3., 2., 1.}), 0., 0.01);
}

// Parts that overlap come out as the closed surface of their union; the
// initial mesh keeps its [35.26, 90] bound, checked on the written file.
TEST(MarchingCubes, OverlappingPartsComeOutAsTheirUnion)
{
  const Mesh sphere = load("sphere.off");
  const double diameter = CGAL::Polygon_mesh_processing::bbox(sphere).xmax() -
                          CGAL::Polygon_mesh_processing::bbox(sphere).xmin();
  const std::vector<std::pair<std::string, Mesh> > inputs{
      {"two overlapping spheres", with_moved_copy(sphere, Kernel::Vector_3(0.35, 0.1, 0.05) * diameter)},
      {"curled sphere", curled_sphere()}};
  for(const auto& input : inputs)
    for(int resolution : {50, 100, 200}) {
      Mesh out;
      const auto r = NR::nonobtuse_marching_cubes(input.second, out, NR::parameters::resolution(resolution));
      EXPECT_TRUE(r.self_intersecting_input) << input.first;
      EXPECT_GT(r.cubes_signed_by_winding_number, 0u) << input.first;
      EXPECT_EQ(r.cubes_signed_by_winding_number + r.cubes_signed_by_patches, r.cubes_intersected);
      const Mesh back = written_and_reread(out, "union.off");
      EXPECT_TRUE(NR::certify_angle_bounds(back, NR::parameters::min_angle(35.26)).is_certified()) << input.first;
      const NR::Quality_report q = NR::quality_report(back, nullptr, one_self_intersection());
      EXPECT_EQ(q.border_cycles, 0u) << input.first << " at " << resolution;
      EXPECT_EQ(q.connected_components, 1u) << input.first << " at " << resolution;
      EXPECT_EQ(q.euler_characteristic, 2) << input.first << " at " << resolution;
    }
  const Mesh elephant = load("elephant.off");
  const Mesh two = with_moved_copy(elephant, Kernel::Vector_3(0.1, 0.03, 0.02));
  for(int resolution : {50, 100}) {
    Mesh out;
    NR::nonobtuse_marching_cubes(two, out, NR::parameters::resolution(resolution));
    const NR::Quality_report q = NR::quality_report(written_and_reread(out, "elephants.off"), nullptr, one_self_intersection());
    EXPECT_TRUE(q.certified);
    EXPECT_EQ(q.border_cycles, 0u) << resolution;
  }
}

// cow.off is closed and crosses itself (101 face pairs): the patches alone
// open holes where it does, the automatic signs keep it closed (a horn tip
// or the tail tip, thinner than a cube, may still leave the octahedron
// around one grid corner apart, with any sign source). pig.off is open (7
// borders) and crosses itself (3 pairs): its own borders, no more.
TEST(MarchingCubes, SelfIntersectingShippedMeshesKeepTheirBorders)
{
  const Mesh cow = load("cow.off");
  for(int resolution : {100, 200}) {
    Mesh out, thesis;
    const auto r = NR::nonobtuse_marching_cubes(cow, out, NR::parameters::resolution(resolution));
    EXPECT_TRUE(r.self_intersecting_input);
    const NR::Quality_report q = NR::quality_report(written_and_reread(out, "cow.off"), nullptr, one_self_intersection());
    EXPECT_TRUE(q.certified);
    EXPECT_EQ(q.border_cycles, 0u) << resolution;
    EXPECT_LE(q.connected_components, 2u) << resolution;
    const auto patches = NR::nonobtuse_marching_cubes(
        cow, thesis, NR::parameters::combine(NR::parameters::resolution(resolution),
                                             NR::parameters::sign_source(NR::Sign_source::patches)));
    EXPECT_GT(patches.borders_out, 0u) << resolution;
  }
  Mesh out;
  NR::nonobtuse_marching_cubes(load("pig.off"), out, NR::parameters::resolution(100));
  EXPECT_EQ(NR::quality_report(written_and_reread(out, "pig.off"), nullptr, one_self_intersection()).border_cycles, 7u);
}

// Without self-intersections and gaps the automatic signs are the thesis's
// patches: the same mesh, and no winding number is computed (open inputs
// too: their border cycles are larger than a cube).
TEST(MarchingCubes, AutomaticSignsArePatchesWithoutSelfIntersectionsOrGaps)
{
  for(const std::string name : {"elephant.off", "mesh_with_border.off", "nefertiti.off"}) {
    const Mesh input = load(name);
    Mesh automatic, patches;
    const auto r = NR::nonobtuse_marching_cubes(input, automatic, NR::parameters::resolution(60));
    NR::nonobtuse_marching_cubes(input, patches, NR::parameters::combine(NR::parameters::resolution(60),
                                                                         NR::parameters::sign_source(NR::Sign_source::patches)));
    EXPECT_FALSE(r.self_intersecting_input) << name;
    EXPECT_EQ(r.cubes_signed_by_winding_number, 0u) << name;
    EXPECT_EQ(r.cubes_signed_by_patches, r.cubes_intersected) << name;
    ASSERT_EQ(automatic.number_of_vertices(), patches.number_of_vertices()) << name;
    ASSERT_EQ(automatic.number_of_faces(), patches.number_of_faces()) << name;
    for(auto v : automatic.vertices()) EXPECT_EQ(automatic.point(v), patches.point(v)) << name;
    for(auto f : automatic.faces()) {
      std::vector<Mesh::Vertex_index> a, b;
      for(auto v : automatic.vertices_around_face(automatic.halfedge(f))) a.push_back(v);
      for(auto v : patches.vertices_around_face(patches.halfedge(f))) b.push_back(v);
      EXPECT_EQ(a, b) << name;
    }
  }
}

// A gap (a border cycle smaller than a cube) is closed by the automatic
// signs; at a resolution where it is larger than a cube, it is a border.
TEST(MarchingCubes, AutomaticSignsCloseGapsSmallerThanACube)
{
  Mesh holed = load("elephant.off");
  const auto f = *holed.faces().begin();
  CGAL::Bbox_3 hole;
  for(auto v : holed.vertices_around_face(holed.halfedge(f))) hole += holed.point(v).bbox();
  const double diagonal = std::sqrt(CGAL::square(hole.xmax() - hole.xmin()) + CGAL::square(hole.ymax() - hole.ymin()) +
                                    CGAL::square(hole.zmax() - hole.zmin()));
  CGAL::Euler::remove_face(holed.halfedge(f), holed);
  holed.collect_garbage();
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(holed);
  const double longest = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  // cubes 1.5 times the hole, then a fifth of it
  const int coarse = int(longest / (1.5 * diagonal)), fine = int(5 * longest / diagonal);
  ASSERT_GE(coarse, 4);
  ASSERT_LE(fine, 1024);
  Mesh closed, open;
  const auto r = NR::nonobtuse_marching_cubes(holed, closed, NR::parameters::resolution(coarse));
  EXPECT_FALSE(r.self_intersecting_input);
  EXPECT_EQ(NR::quality_report(written_and_reread(closed, "gap.off"), nullptr, one_self_intersection()).border_cycles, 0u);
  NR::nonobtuse_marching_cubes(holed, open, NR::parameters::resolution(fine));
  const NR::Quality_report q = NR::quality_report(written_and_reread(open, "hole.off"), nullptr, one_self_intersection());
  EXPECT_TRUE(q.certified);
  EXPECT_EQ(q.border_cycles, 1u);
}

// The winding number alone: the union of overlapping parts and of a
// self-intersecting closed input, closed, and a gap smaller than a cube closed.
TEST(MarchingCubes, WindingNumberSignsGiveTheUnion)
{
  const Mesh sphere = load("sphere.off");
  const double diameter = CGAL::Polygon_mesh_processing::bbox(sphere).xmax() -
                          CGAL::Polygon_mesh_processing::bbox(sphere).xmin();
  Mesh holed = load("elephant.off");
  CGAL::Euler::remove_face(holed.halfedge(*holed.faces().begin()), holed);
  holed.collect_garbage();
  const std::vector<std::tuple<std::string, Mesh, int, std::size_t> > inputs{
      {"two overlapping spheres", with_moved_copy(sphere, Kernel::Vector_3(0.35, 0.1, 0.05) * diameter), 60, 1},
      {"cow.off", load("cow.off"), 100, 2},  // 2: a horn tip thinner than a cube
      {"holed elephant", holed, 23, 4}};     // 4: thin parts at this coarse resolution
  for(const auto& input : inputs) {
    Mesh out;
    const auto r = NR::nonobtuse_marching_cubes(
        std::get<1>(input), out, NR::parameters::combine(NR::parameters::resolution(std::get<2>(input)),
                                                         NR::parameters::sign_source(NR::Sign_source::winding_number)));
    EXPECT_EQ(r.cubes_signed_by_winding_number, r.cubes_intersected) << std::get<0>(input);
    const NR::Quality_report q = NR::quality_report(written_and_reread(out, "union.off"), nullptr, one_self_intersection());
    EXPECT_TRUE(q.certified) << std::get<0>(input);
    EXPECT_EQ(q.border_cycles, 0u) << std::get<0>(input);
    EXPECT_LE(q.connected_components, std::get<3>(input)) << std::get<0>(input);
  }
}
