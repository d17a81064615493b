// SPDX-License-Identifier: GPL-3.0-or-later
//
// Robustness corpus: inputs of the kinds users really have (self-intersecting
// scans, dozens of components, genus above 100, needle and zero-area
// triangles, polygon soups, non-manifold vertices and edges, garbage) get
// either a certified output or a one-line refusal with exit code 3; never a
// crash, a hang, another exit code or a partial file.
//
// Every input is built here, at test time, from the shipped meshes or
// procedurally, and written as OFF text by the test itself (so that damaged
// content is possible); the tool then runs on it under a time limit.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <dirent.h>
#include <sys/wait.h>
#include <unistd.h>

namespace NR = CGAL::Nonobtuse_remeshing;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Vec = std::array<double, 3>;
using Face = std::vector<std::size_t>;

// ---------------------------------------------------------------------------
// Polygon soups and how to damage them

struct Soup
{
  std::vector<Vec> points;
  std::vector<Face> faces;

  // appends `other` (its indices shifted), returns the shift
  std::size_t append(const Soup& other)
  {
    const std::size_t shift = points.size();
    points.insert(points.end(), other.points.begin(), other.points.end());
    for(Face f : other.faces) {
      for(std::size_t& v : f) v += shift;
      faces.push_back(f);
    }
    return shift;
  }
};

Vec add(const Vec& a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec mul(double s, const Vec& a) { return {s * a[0], s * a[1], s * a[2]}; }
double norm(const Vec& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

using nonobtuse_test::data;

// A shipped mesh as the raw soup its file holds.
Soup shipped(const std::string& name)
{
  std::vector<Point> points;
  std::vector<Face> faces;
  std::ifstream in(data(name));
  EXPECT_TRUE(CGAL::IO::read_OFF(in, points, faces)) << name;
  Soup s;
  for(const Point& p : points) s.points.push_back({p.x(), p.y(), p.z()});
  s.faces = faces;
  return s;
}

// x -> scale * x + shift
Soup transformed(Soup s, double scale, const Vec& shift)
{
  for(Vec& p : s.points) p = add(mul(scale, p), shift);
  return s;
}

// Deterministic noise in [-1, 1] (mt19937's output is fixed by the standard).
struct Noise
{
  std::mt19937 engine;
  explicit Noise(unsigned seed) : engine(seed) {}
  double operator()() { return 2. * (double(engine()) / 4294967296.) - 1.; }
};

double mean_edge_length(const Soup& s)
{
  double sum = 0.;
  std::size_t n = 0;
  for(const Face& f : s.faces)
    for(std::size_t i = 0; i < f.size(); ++i, ++n) sum += norm(sub(s.points[f[i]], s.points[f[(i + 1) % f.size()]]));
  return sum / double(n);
}

long euler_characteristic(const Soup& s)
{
  std::set<std::pair<std::size_t, std::size_t> > edges;
  std::set<std::size_t> used;
  for(const Face& f : s.faces)
    for(std::size_t i = 0; i < f.size(); ++i) {
      const std::size_t a = f[i], b = f[(i + 1) % f.size()];
      edges.insert(std::minmax(a, b));
      used.insert(a);
    }
  return long(used.size()) - long(edges.size()) + long(s.faces.size());
}

Mesh to_mesh(const Soup& s)
{
  std::vector<Point> points;
  for(const Vec& p : s.points) points.emplace_back(p[0], p[1], p[2]);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, s.faces, mesh);
  return mesh;
}

// The opposite triangle across each directed edge of a triangle soup.
std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_to_face(const Soup& s)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> m;
  for(std::size_t f = 0; f < s.faces.size(); ++f)
    for(int i = 0; i < 3; ++i) m[{s.faces[f][i], s.faces[f][(i + 1) % 3]}] = f;
  return m;
}

// Pairs of edge-adjacent triangles (f, g) sharing edge a->b in f, pairwise
// disjoint and vertex-disjoint from each other, at most `count` of them;
// returned as (f, g, i) with the shared edge f[i]->f[i+1].
std::vector<std::array<std::size_t, 3> > disjoint_edge_pairs(const Soup& s, std::size_t count)
{
  const auto opposite = edge_to_face(s);
  std::set<std::size_t> used_vertices;
  std::vector<std::array<std::size_t, 3> > pairs;
  for(std::size_t f = 0; f < s.faces.size() && pairs.size() < count; f += 7) {
    const std::size_t a = s.faces[f][0], b = s.faces[f][1];
    const auto it = opposite.find({b, a});
    if(it == opposite.end()) continue;
    const std::size_t g = it->second;
    std::set<std::size_t> touched(s.faces[f].begin(), s.faces[f].end());
    touched.insert(s.faces[g].begin(), s.faces[g].end());
    if(std::any_of(touched.begin(), touched.end(), [&](std::size_t v) { return used_vertices.count(v) > 0; }))
      continue;
    used_vertices.insert(touched.begin(), touched.end());
    pairs.push_back({f, g, 0});
  }
  return pairs;
}

// Splits edge a->b of the triangles f = (a, b, c) and g = (b, a, d) at a new
// vertex at position m: two triangles become four, (a, m, c), (m, b, c),
// (b, m, d), (m, a, d); a manifold, consistently oriented change whatever m is.
void split_edge(Soup& s, std::size_t f, std::size_t g, const Vec& m)
{
  const std::size_t a = s.faces[f][0], b = s.faces[f][1], c = s.faces[f][2];
  std::size_t d = 0;
  for(std::size_t v : s.faces[g])
    if(v != a && v != b) d = v;
  const std::size_t mi = s.points.size();
  s.points.push_back(m);
  s.faces[f] = {a, mi, c};
  s.faces[g] = {b, mi, d};
  s.faces.push_back({mi, b, c});
  s.faces.push_back({mi, a, d});
}

// Boundary of a set of unit voxels: a quad per voxel face not shared with a
// filled voxel, outward oriented, vertices shared by integer position; quads
// are split into two right isosceles triangles unless `keep_quads`.
Soup voxel_boundary(int nx, int ny, int nz, const std::function<bool(int, int, int)>& filled, bool keep_quads = false)
{
  Soup s;
  std::map<std::array<int, 3>, std::size_t> index;
  auto vertex = [&](const std::array<int, 3>& p) {
    const auto it = index.find(p);
    if(it != index.end()) return it->second;
    index[p] = s.points.size();
    s.points.push_back({double(p[0]), double(p[1]), double(p[2])});
    return s.points.size() - 1;
  };
  auto inside = [&](int x, int y, int z) {
    return x >= 0 && y >= 0 && z >= 0 && x < nx && y < ny && z < nz && filled(x, y, z);
  };
  const int corner_b[4] = {0, 1, 1, 0}, corner_c[4] = {0, 0, 1, 1};
  for(int x = 0; x < nx; ++x)
    for(int y = 0; y < ny; ++y)
      for(int z = 0; z < nz; ++z) {
        if(!inside(x, y, z)) continue;
        for(int axis = 0; axis < 3; ++axis)
          for(int sign = -1; sign <= 1; sign += 2) {
            std::array<int, 3> n = {x, y, z};
            n[axis] += sign;
            if(inside(n[0], n[1], n[2])) continue;
            // corners in the (b, c) plane, b = axis + 1, c = axis + 2: counter-
            // clockwise seen from +axis, so reversed for the -axis side
            const int b = (axis + 1) % 3, c = (axis + 2) % 3;
            Face quad;
            for(int k = 0; k < 4; ++k) {
              std::array<int, 3> p = {x, y, z};
              p[axis] += sign > 0 ? 1 : 0;
              p[b] += corner_b[k];
              p[c] += corner_c[k];
              quad.push_back(vertex(p));
            }
            if(sign < 0) std::reverse(quad.begin(), quad.end());
            if(keep_quads) {
              s.faces.push_back(quad);
            } else {
              s.faces.push_back({quad[0], quad[1], quad[2]});
              s.faces.push_back({quad[0], quad[2], quad[3]});
            }
          }
      }
  return s;
}

std::string off_text(const Soup& s)
{
  std::ostringstream out;
  out << std::setprecision(17) << "OFF\n" << s.points.size() << " " << s.faces.size() << " 0\n";
  for(const Vec& p : s.points) out << p[0] << " " << p[1] << " " << p[2] << "\n";
  for(const Face& f : s.faces) {
    out << f.size();
    for(std::size_t v : f) out << " " << v;
    out << "\n";
  }
  return out.str();
}

// ---------------------------------------------------------------------------
// Running the tool and checking its promise

struct Topology
{
  std::size_t components = 0, borders = 0;
  long euler = 0;
  long genus() const { return (2 * long(components) - long(borders) - euler) / 2; }  // summed over components
  bool operator==(const Topology& o) const { return components == o.components && borders == o.borders && euler == o.euler; }
};

std::ostream& operator<<(std::ostream& out, const Topology& t)
{
  return out << t.components << " components, " << t.borders << " borders, euler " << t.euler << " (genus " << t.genus()
             << ")";
}

// What a success must keep: the input's topology, when remeshing cannot
// reasonably change it. `none` when anything certified will do.
const Topology none{std::size_t(-1), 0, 0};
const Topology closed_sphere{1, 0, 2};  // one closed genus-0 component

Topology topology(const Mesh& mesh)
{
  Topology t;
  std::map<Mesh::Face_index, std::size_t> component;
  t.components = PMP::connected_components(mesh, boost::make_assoc_property_map(component));
  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(cycles));
  t.borders = cycles.size();
  t.euler = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
  return t;
}

struct Outcome
{
  int code = -1;
  std::string out, err;
  double seconds = 0.;
  double peak_mib = 0.;  // peak resident memory of the run
  bool certified = false;
  Mesh mesh;  // the written output, re-read, when code == 0
};

using nonobtuse_test::slurp;


std::vector<std::string> split_lines(const std::string& text)
{
  std::vector<std::string> result;
  std::istringstream in(text);
  for(std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

const int time_limit_seconds = 120;
// Every case of the corpus stays under this peak memory (the README's budget
// for the corpus).
const double peak_memory_budget_mib = 1024.;

// Writes `contents` as `name`/in.off in a fresh folder, runs
// `remesh in.off -o out.off -N resolution -q` under a time limit, and checks
// the promise: exit 0 with a certified out.off of the `expected` topology and
// nothing else written, or exit 3 with one line on standard error naming the
// input and nothing written. The folder is removed unless something failed.
Outcome remesh(const std::string& name, const std::string& contents, int resolution, const Topology& expected = none)
{
  const std::string folder = ::testing::TempDir() + "nonobtuse_robust_" + std::to_string(::getpid()) + "_" + name;
  std::system(("rm -rf '" + folder + "' '" + folder + ".stdout' '" + folder + ".stderr' && mkdir -p '" + folder + "'").c_str());
  const std::string input = folder + "/in.off", output = folder + "/out.off";
  std::ofstream(input, std::ios::binary) << contents;
  const std::string command = "timeout -k 10 " + std::to_string(time_limit_seconds) + " " + std::string(NONOBTUSE_TOOL) +
                              " remesh '" + input + "' -o '" + output + "' -N " + std::to_string(resolution) +
                              " -q >'" + folder + ".stdout' 2>'" + folder + ".stderr'";
  Outcome r;
  const auto start = std::chrono::steady_clock::now();
  const nonobtuse_test::Shell_run run = nonobtuse_test::run_shell(command);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.code = run.code;
  r.peak_mib = run.peak_mib;
  EXPECT_LT(r.peak_mib, peak_memory_budget_mib) << name << ": peak memory";
  r.out = slurp(folder + ".stdout");
  r.err = slurp(folder + ".stderr");
  const std::string what = name + " (" + command + ")";

  EXPECT_TRUE(r.code == 0 || r.code == 3)
      << what << "\nexit " << r.code << (r.code == 124 ? ": timed out" : r.code > 128 ? ": killed by a signal" : "")
      << "\nstderr:\n" << r.err;
  const std::set<std::string> entries = nonobtuse_test::folder_entries(folder);
  if(r.code == 0) {
    EXPECT_EQ(entries, (std::set<std::string>{"in.off", "out.off"})) << what << ": only the output is written";
    NR::Read_log log;
    try {
      NR::read_triangle_mesh(output, r.mesh, log);
      r.certified = NR::certify_angle_bounds(r.mesh).is_certified();
    } catch(const std::exception& e) {
      ADD_FAILURE() << what << ": the output cannot be re-read: " << e.what();
    }
    EXPECT_TRUE(r.certified) << what << ": the written file does not certify in [30, 90]";
    EXPECT_TRUE(log.repairs.empty()) << what << ": the output needed repairs when re-read";
    EXPECT_NE(r.out.find("certified in [30, 90] degrees on the written file"), std::string::npos) << what;
    for(const std::string& line : split_lines(r.err))
      EXPECT_EQ(line.rfind("note: ", 0), 0u) << what << ": standard error has more than notes:\n" << r.err;
    if(!(expected == none)) EXPECT_EQ(topology(r.mesh), expected) << what << ": the output's topology";
  } else {
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << ": not one line:\n" << r.err;
    if(r.code == 3) {
      EXPECT_NE(r.err.find("bad input: "), std::string::npos) << what << ": " << r.err;
      EXPECT_NE(r.err.find(input), std::string::npos) << what << ": the message does not name the input: " << r.err;
    }
    EXPECT_EQ(entries, std::set<std::string>{"in.off"}) << what << ": a refused input leaves no file";
  }

  std::cout << "[ robust   ] " << name << ": exit " << r.code;
  if(r.code == 0)
    std::cout << ", " << num_faces(r.mesh) << " faces, " << topology(r.mesh) << (r.certified ? ", certified" : ", NOT CERTIFIED");
  else
    std::cout << ": " << r.err.substr(0, r.err.find('\n'));
  std::cout << std::fixed << std::setprecision(2) << " (" << r.seconds << " s, peak " << std::setprecision(0)
            << r.peak_mib << " MiB)" << std::defaultfloat << std::setprecision(6) << std::endl;
  if(!::testing::Test::HasFailure())
    std::system(("rm -rf '" + folder + "' '" + folder + ".stdout' '" + folder + ".stderr'").c_str());
  return r;
}

Outcome remesh(const std::string& name, const Soup& soup, int resolution, const Topology& expected = none)
{
  return remesh(name, off_text(soup), resolution, expected);
}

} // namespace

// ---------------------------------------------------------------------------
// 1. Self-intersecting inputs

// Two copies of a closed mesh overlapping in one file (the second shifted by
// 40% of its size), and the same for an open mesh: the surfaces cross.
TEST(Robustness, SelfIntersectingOverlappingCopies)
{
  Soup spheres = shipped("sphere.off");
  spheres.append(transformed(shipped("sphere.off"), 1., {0.4, 0.1, 0.}));
  ASSERT_TRUE(PMP::does_self_intersect(to_mesh(spheres)));
  remesh("overlapping_spheres", spheres, 30);

  Soup pigs = shipped("pig.off");
  pigs.append(transformed(shipped("pig.off"), 0.9, {0.05, 0.03, 0.02}));
  ASSERT_TRUE(PMP::does_self_intersect(to_mesh(pigs)));
  remesh("overlapping_pigs", pigs, 30);
}

// A scan with noise: every vertex moved by up to 1.5 mean edge lengths along
// each axis, enough to fold triangles through each other.
TEST(Robustness, SelfIntersectingFoldedByNoise)
{
  for(const std::string& name : {std::string("sphere.off"), std::string("pig.off")}) {
    Soup s = shipped(name);
    const double amplitude = 1.5 * mean_edge_length(s);
    Noise noise(7);
    for(Vec& p : s.points) p = add(p, {amplitude * noise(), amplitude * noise(), amplitude * noise()});
    ASSERT_TRUE(PMP::does_self_intersect(to_mesh(s))) << name;
    remesh("noisy_" + name.substr(0, name.find('.')), s, 30);
  }
}

// ---------------------------------------------------------------------------
// 2. Dozens of components

// 36 spheres of different sizes on a 4 x 3 x 3 lattice, one file: if the
// tool succeeds, the output has 36 closed sphere-like components.
TEST(Robustness, DozensOfComponents)
{
  Soup s;
  const Soup sphere = shipped("sphere.off");  // radius 0.5
  int k = 0;
  for(int x = 0; x < 4; ++x)
    for(int y = 0; y < 3; ++y)
      for(int z = 0; z < 3; ++z, ++k)
        s.append(transformed(sphere, 0.6 + 0.02 * (k % 7), {double(x), double(y), double(z)}));
  ASSERT_EQ(s.faces.size(), 36u * sphere.faces.size());
  remesh("36_spheres", s, 48, Topology{36, 0, 2 * 36});
}

// ---------------------------------------------------------------------------
// 3. Genus above 100

// The boundary of a voxel grating: a 23 x 23 x 1 block of unit voxels with
// the 11 x 11 voxels at (odd, odd) removed, genus 121; closed, manifold,
// consistently oriented. At N = 69 every bar and hole is 3 cubes wide, and
// the output must keep the genus.
TEST(Robustness, GenusAbove100)
{
  const int n = 11, side = 2 * n + 1;
  const Soup grating = voxel_boundary(side, side, 1, [](int x, int y, int) { return !(x % 2 == 1 && y % 2 == 1); });
  ASSERT_EQ(euler_characteristic(grating), 2 - 2 * n * n);
  ASSERT_TRUE(CGAL::is_closed(to_mesh(grating)));
  remesh("grating_genus_121", grating, 3 * side, Topology{1, 0, 2 - 2 * n * n});
}

// ---------------------------------------------------------------------------
// 4. Needle and zero-area triangles

namespace {

// sphere.off snapped to multiples of 2^-20, so that midpoints are exact.
Soup snapped_sphere()
{
  Soup s = shipped("sphere.off");
  for(Vec& p : s.points)
    for(double& x : p) x = std::ldexp(std::round(std::ldexp(x, 20)), -20);
  return s;
}

} // namespace

// (a) 12 edges split at a new vertex placed exactly on another edge of the
// triangle (the midpoint of a and c): one of the four triangles has zero
// area exactly, and the surface is unchanged; (b) 6 vertices moved onto a
// neighbour (coincident vertices: zero-length edges, two degenerate faces
// each); (c) a file of zero-area triangles only. Geometrically, (a) and (b)
// are still the closed sphere, so a success must be one.
TEST(Robustness, ZeroAreaTriangles)
{
  Soup split = snapped_sphere();
  const auto pairs = disjoint_edge_pairs(split, 12);
  ASSERT_EQ(pairs.size(), 12u);
  for(const auto& pair : pairs) {
    const Face f = split.faces[pair[0]];
    split_edge(split, pair[0], pair[1], mul(0.5, add(split.points[f[0]], split.points[f[2]])));
  }
  ASSERT_EQ(NR::certify_angle_bounds(to_mesh(split)).degenerate_faces, 12u);
  remesh("zero_area_splits", split, 30, closed_sphere);

  Soup collapsed = snapped_sphere();
  for(const auto& pair : disjoint_edge_pairs(collapsed, 6)) {
    const Face f = collapsed.faces[pair[0]];
    collapsed.points[f[0]] = collapsed.points[f[1]];
  }
  ASSERT_EQ(NR::certify_angle_bounds(to_mesh(collapsed)).degenerate_faces, 12u);
  remesh("coincident_vertices", collapsed, 30, closed_sphere);

  remesh("only_zero_area", "OFF\n4 2 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n3 0 1 2\n3 1 3 2\n", 30);
}

// Needles: (a) 12 edges of sphere.off split one millionth of the way along,
// two needle triangles at each split, the surface unchanged (so a success
// must be the closed sphere); (b) 3 vertices
// pulled out to three times the radius (spikes of long thin triangles);
// (c) a mesh of needles only, a closed triangular prism 1 long, 0.001 wide.
TEST(Robustness, NeedleTriangles)
{
  const Soup sphere = shipped("sphere.off");
  Soup needles = sphere;
  for(const auto& pair : disjoint_edge_pairs(needles, 12)) {
    const Face f = needles.faces[pair[0]];
    const Vec& a = needles.points[f[0]];
    split_edge(needles, pair[0], pair[1], add(a, mul(1e-6, sub(needles.points[f[1]], a))));
  }
  ASSERT_EQ(needles.faces.size(), sphere.faces.size() + 24);
  remesh("needle_splits", needles, 30, closed_sphere);

  Soup spikes = sphere;
  for(const auto& pair : disjoint_edge_pairs(spikes, 3)) {
    Vec& p = spikes.points[spikes.faces[pair[0]][0]];
    p = mul(3., p);
  }
  remesh("spikes", spikes, 30);

  const double w = 0.001;
  Soup prism;
  prism.points = {{0, 0, 0}, {0, w, 0}, {0, 0, w}, {1, 0, 0}, {1, w, 0}, {1, 0, w}};
  prism.faces = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {2, 0, 3}, {2, 3, 5}};
  ASSERT_TRUE(CGAL::is_closed(to_mesh(prism)));
  remesh("needle_prism", prism, 30);
}

// ---------------------------------------------------------------------------
// 5. Polygon soups

TEST(Robustness, PolygonSoups)
{
  const Soup sphere = shipped("sphere.off");

  // every other face reversed: inconsistently oriented; repairable, so a
  // success keeps one closed sphere
  Soup reversed = sphere;
  for(std::size_t f = 0; f < reversed.faces.size(); f += 2) std::reverse(reversed.faces[f].begin(), reversed.faces[f].end());
  remesh("half_reversed", reversed, 30, closed_sphere);

  // 20 faces duplicated, 10 of them reversed as well (edges with 3 and 4 faces)
  Soup duplicated = sphere;
  for(std::size_t f = 0; f < 20; ++f) {
    Face copy = sphere.faces[f * 13];
    if(f % 2) std::reverse(copy.begin(), copy.end());
    duplicated.faces.push_back(copy);
  }
  remesh("duplicated_faces", duplicated, 30);

  // 100 unreferenced vertices, far away: ignored, so they must change
  // neither the size of the grid nor the output
  Soup unreferenced = sphere;
  Noise noise(11);
  for(int i = 0; i < 100; ++i) unreferenced.points.push_back({50. * noise(), 50. * noise(), 50. * noise()});
  remesh("unreferenced_vertices", unreferenced, 30, closed_sphere);

  // faces that repeat a vertex: 5 extra (a, a, b), 5 faces turned into
  // (a, b, b, c) (these leave holes once dropped)
  Soup repeated = sphere;
  for(std::size_t f = 0; f < 5; ++f) {
    const Face g = sphere.faces[f * 31];
    repeated.faces.push_back({g[0], g[0], g[1]});
    repeated.faces[f * 31 + 7] = {repeated.faces[f * 31 + 7][0], repeated.faces[f * 31 + 7][1],
                                  repeated.faces[f * 31 + 7][1], repeated.faces[f * 31 + 7][2]};
  }
  remesh("repeated_vertex_index", repeated, 30);

  // quads: a voxel cross written with quads (planar), and sphere.off with
  // pairs of triangles merged into non-planar quads and the fans of 6
  // vertices merged into non-planar pentagons and hexagons (the centres are
  // left unreferenced)
  const Soup cross = voxel_boundary(3, 3, 3, [](int x, int y, int z) { return (x == 1) + (y == 1) + (z == 1) >= 2; }, true);
  remesh("voxel_cross_quads", cross, 30, closed_sphere);
  Soup polygons = sphere;
  {
    // fans first: a vertex's faces become its link polygon
    std::set<std::size_t> removed_faces, touched;
    std::vector<Face> added;
    for(std::size_t v = 0; v < sphere.points.size() && added.size() < 6; v += 17) {
      std::map<std::size_t, std::size_t> next;  // link edge a -> b for each face (v, a, b)
      std::vector<std::size_t> fan;
      for(std::size_t f = 0; f < sphere.faces.size(); ++f) {
        const Face& g = sphere.faces[f];
        for(int i = 0; i < 3; ++i)
          if(g[i] == v) { next[g[(i + 1) % 3]] = g[(i + 2) % 3]; fan.push_back(f); }
      }
      if(std::any_of(fan.begin(), fan.end(), [&](std::size_t f) { return touched.count(f) > 0; })) continue;
      Face link = {next.begin()->first};
      while(link.size() < next.size()) link.push_back(next[link.back()]);
      for(std::size_t f : fan) removed_faces.insert(f);
      for(std::size_t f = 0; f < sphere.faces.size(); ++f)  // keep later fans apart from this one
        for(std::size_t u : sphere.faces[f])
          if(std::find(link.begin(), link.end(), u) != link.end() || u == v) touched.insert(f);
      added.push_back(link);
    }
    ASSERT_EQ(added.size(), 6u);
    // then pairs of the remaining triangles become quads
    const auto opposite = edge_to_face(sphere);
    std::set<std::size_t> merged;
    for(std::size_t f = 0; f < sphere.faces.size(); ++f) {
      if(removed_faces.count(f) || merged.count(f)) continue;
      const Face& g = sphere.faces[f];
      const std::size_t h = opposite.at({g[1], g[0]});
      if(removed_faces.count(h) || merged.count(h) || f % 3 != 0) continue;
      std::size_t d = 0;
      for(std::size_t u : sphere.faces[h])
        if(u != g[0] && u != g[1]) d = u;
      added.push_back({g[0], d, g[1], g[2]});
      merged.insert(f);
      merged.insert(h);
    }
    polygons.faces.clear();
    for(std::size_t f = 0; f < sphere.faces.size(); ++f)
      if(!removed_faces.count(f) && !merged.count(f)) polygons.faces.push_back(sphere.faces[f]);
    polygons.faces.insert(polygons.faces.end(), added.begin(), added.end());
    ASSERT_EQ(euler_characteristic(polygons), 2);
  }
  remesh("sphere_polygons", polygons, 30, closed_sphere);

  // all of it at once, shuffled
  Soup everything = reversed;
  everything.append(transformed(duplicated, 1., {1.5, 0., 0.}));
  everything.append(transformed(unreferenced, 1., {0., 1.5, 0.}));
  everything.append(transformed(repeated, 1., {1.5, 1.5, 0.}));
  everything.append(transformed(polygons, 1., {0., 0., 1.5}));
  std::shuffle(everything.faces.begin(), everything.faces.end(), std::mt19937(3));
  remesh("soup_of_everything", everything, 40);
}

// ---------------------------------------------------------------------------
// 6. Non-manifold inputs

TEST(Robustness, NonManifold)
{
  const Soup sphere = shipped("sphere.off");

  // two spheres sharing one vertex (a bow-tie vertex): the second is the
  // point reflection of the first through its vertex 0 (faces reversed to
  // keep them outward), with that vertex merged
  Soup bowtie = sphere;
  {
    const Vec p = sphere.points[0];
    Soup mirrored = sphere;
    for(Vec& q : mirrored.points) q = sub(mul(2., p), q);
    for(Face& f : mirrored.faces) std::reverse(f.begin(), f.end());
    const std::size_t shift = bowtie.append(mirrored);
    for(std::size_t f = sphere.faces.size(); f < bowtie.faces.size(); ++f)
      for(std::size_t& v : bowtie.faces[f])
        if(v == shift) v = 0;
  }
  remesh("bowtie_vertex", bowtie, 30);

  // a closed surface pinched at vertices: a voxel "chain" of 4 cubes meeting
  // corner to corner (3 non-manifold vertices, vertices merged by position)
  const Soup chain = voxel_boundary(4, 4, 4, [](int x, int y, int z) { return x == y && y == z; });
  remesh("voxel_corner_chain", chain, 30);

  // two voxels sharing only an edge (a non-manifold edge with 4 faces)
  const Soup edge_pair = voxel_boundary(2, 2, 1, [](int x, int y, int) { return x == y; });
  remesh("voxel_edge_pair", edge_pair, 30);

  // three faces on one edge: a fin on 8 edges of the sphere, and a second
  // fin on one of them (4 faces on that edge)
  Soup fins = sphere;
  for(std::size_t f = 0; f < 8; ++f) {
    const Face g = sphere.faces[f * 40];
    const Vec tip = mul(1.6 * 0.5, add(sphere.points[g[0]], sphere.points[g[1]]));
    fins.points.push_back(tip);
    fins.faces.push_back({g[0], g[1], fins.points.size() - 1});
  }
  {
    const Face g = sphere.faces[0];
    fins.points.push_back(mul(1.3 * 0.5, add(add(sphere.points[g[0]], sphere.points[g[1]]), {0, 0, 0.2})));
    fins.faces.push_back({g[1], g[0], fins.points.size() - 1});
  }
  remesh("fins_on_edges", fins, 30);
}

// ---------------------------------------------------------------------------
// 7. Garbage: always exit 3 with one line

TEST(Robustness, GarbageIsRefusedInOneLine)
{
  const std::string sphere = off_text(shipped("sphere.off"));
  std::string nan = sphere;
  nan.replace(nan.find('\n', nan.find('\n', nan.find('\n') + 1) + 1) + 1, 1, "nan ");  // first coordinate
  std::string binary;
  Noise noise(5);
  for(int i = 0; i < 4000; ++i) binary.push_back(char(int(128 * (noise() + 1.)) & 0xff));
  const std::string cases[][3] = {
    {"empty", "", "is empty"},
    {"blank", "\n\n  \n", "cannot parse"},
    {"header_only", "OFF\n", "cannot parse"},
    {"no_faces", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "no face"},
    {"nan_coordinate", nan, "non-finite"},
    {"inf_coordinate", "OFF\n3 1 0\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n", "non-finite"},
    {"truncated_in_vertices", sphere.substr(0, sphere.size() / 4), "cannot parse"},
    {"truncated_in_faces", sphere.substr(0, sphere.size() - 200), "cannot parse"},
    {"truncated_mid_face", sphere.substr(0, sphere.size() - 3), ""},
    {"index_out_of_range", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "cannot parse|refers to vertex"},
    {"negative_index", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", ""},
    {"two_vertex_face", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", ""},
    {"header_lies_hugely", "OFF\n300 500 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "more than its"},
    {"header_lies", "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", ""},
    {"binary_junk", binary, ""},
  };
  for(const auto& c : cases) {
    const Outcome r = remesh(c[0], c[1], 40);
    EXPECT_EQ(r.code, 3) << c[0] << ": " << r.err;
    const std::string& wanted = c[2];  // alternatives separated by '|'
    bool named = false;
    for(std::size_t from = 0, bar; !named && from <= wanted.size(); from = bar + 1) {
      bar = std::min(wanted.find('|', from), wanted.size());
      named = r.err.find(wanted.substr(from, bar - from)) != std::string::npos;
    }
    EXPECT_TRUE(named) << c[0] << ": expected '" << wanted << "' in: " << r.err;
  }
}

// Coordinates far from the origin, huge or tiny scales. The sphere is 30
// cubes wide at N = 30 whatever its scale, so a success must keep one closed
// sphere, and a refusal must not blame its size.
TEST(Robustness, ExtremeCoordinates)
{
  const Soup sphere = shipped("sphere.off");
  remesh("far_from_origin", transformed(sphere, 1., {1e12, -3e12, 5e11}), 30);
  for(const double scale : {1e-150, 1e-110, 1e104, 1e150}) {
    std::ostringstream name;
    name << "scale_" << scale;
    const Outcome r = remesh(name.str(), transformed(sphere, scale, {0., 0., 0.}), 30, closed_sphere);
    if(r.code != 0) {
      EXPECT_EQ(r.err.find("too small or too thin"), std::string::npos) << name.str() << ": " << r.err;
    }
  }
  remesh("subnormal_scale", transformed(sphere, 1e-310, {0., 0., 0.}), 30);
}
