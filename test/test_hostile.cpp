// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hostile inputs: files that lie about their sizes, outputs that name each
// other, signals during the write, memory a resolution would exhaust, files
// that only look certified; a fuzz test of the readers; and `certify` against
// an independent exact evaluation of every file of this corpus.
//
// Every input is built here, at test time.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>

#include "test_support.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace NR = CGAL::Nonobtuse_remeshing;

namespace {

using nonobtuse_test::Mesh;
using nonobtuse_test::folder_entries;
using nonobtuse_test::scratch_folder;

using nonobtuse_test::data;
using nonobtuse_test::lines;
using nonobtuse_test::slurp;

void spit(const std::string& path, const std::string& contents) { std::ofstream(path, std::ios::binary) << contents; }

struct Tool_run
{
  int code = -1;
  std::string out, err;
  double peak_mib = 0.;  // the child's peak resident memory
};

// Runs the tool with `arguments` (a shell fragment) in its own process and
// measures its peak memory.
Tool_run tool(const std::string& arguments, int time_limit = 120)
{
  static int counter = 0;
  const std::string base = ::testing::TempDir() + "nonobtuse_hostile_" + std::to_string(::getpid()) + "_" +
                           std::to_string(counter++);
  const std::string command = "exec timeout -k 5 " + std::to_string(time_limit) + " " + NONOBTUSE_TOOL + " " +
                              arguments + " >'" + base + ".out' 2>'" + base + ".err'";
  Tool_run r;
  const nonobtuse_test::Shell_run run = nonobtuse_test::run_shell(command);
  r.code = run.code;
  r.peak_mib = run.peak_mib;
  r.out = slurp(base + ".out");
  r.err = slurp(base + ".err");
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
  return r;
}

// ---------------------------------------------------------------------------
// An independent exact evaluation of a file: its own OFF parser, and every
// corner decided in exact rationals (GMP), from the definitions: a corner
// with edge vectors u, v is at most 90 degrees iff u.v >= 0 and at least 30
// iff u.v <= 0 or 4 (u.v)^2 <= 3 |u|^2 |v|^2; a face that is not a triangle of
// three distinct vertices, with nonzero area, is not certified, nor is a
// file without faces.
bool certified_by_hand(const std::string& path)
{
  std::istringstream in(slurp(path));
  std::string header;
  in >> header;
  if(header != "OFF") return false;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> nv >> nf >> ne;
  if(!in || nf == 0) return false;
  using Q = CGAL::Exact_rational;
  std::vector<std::array<Q, 3> > points;
  for(std::size_t i = 0; i < nv; ++i) {
    double x, y, z;
    if(!(in >> x >> y >> z)) return false;
    points.push_back({Q(x), Q(y), Q(z)});
  }
  for(std::size_t f = 0; f < nf; ++f) {
    std::size_t n = 0;
    if(!(in >> n) || n != 3) return false;
    std::size_t v[3];
    for(std::size_t& i : v)
      if(!(in >> i) || i >= nv) return false;
    if(v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return false;
    const auto sub = [&](std::size_t a, std::size_t b) {
      return std::array<Q, 3>{Q(points[a][0] - points[b][0]), Q(points[a][1] - points[b][1]),
                              Q(points[a][2] - points[b][2])};
    };
    const auto dot = [](const std::array<Q, 3>& a, const std::array<Q, 3>& b) -> Q {  // not an expression template
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    const std::array<Q, 3> e1 = sub(v[1], v[0]), e2 = sub(v[2], v[0]);
    const std::array<Q, 3> cross = {Q(e1[1] * e2[2] - e1[2] * e2[1]), Q(e1[2] * e2[0] - e1[0] * e2[2]),
                                    Q(e1[0] * e2[1] - e1[1] * e2[0])};
    if(dot(cross, cross) == 0) return false;
    for(int c = 0; c < 3; ++c) {
      const std::array<Q, 3> u = sub(v[(c + 1) % 3], v[c]), w = sub(v[(c + 2) % 3], v[c]);
      const Q d = dot(u, w);
      if(d < 0) return false;
      if(d > 0 && 4 * d * d > 3 * dot(u, u) * dot(w, w)) return false;
    }
  }
  return true;
}

std::string off(const std::vector<std::array<double, 3> >& points, const std::vector<std::vector<int> >& faces)
{
  std::ostringstream out;
  out << std::setprecision(17) << "OFF\n" << points.size() << " " << faces.size() << " 0\n";
  for(const auto& p : points) out << p[0] << " " << p[1] << " " << p[2] << "\n";
  for(const auto& f : faces) {
    out << f.size();
    for(int v : f) out << " " << v;
    out << "\n";
  }
  return out.str();
}

// A certified mesh written by the tool: the sphere at resolution 10.
std::string certified_sphere(const std::string& folder)
{
  const std::string path = folder + "/sphere10.off";
  if(::access(path.c_str(), F_OK) != 0)
    EXPECT_EQ(tool("remesh " + data("sphere.off") + " -o " + path + " -N 10 -q").code, 0);
  return path;
}

// `contents` plus one more face line, with the face count in the header raised.
std::string with_extra_face(const std::string& contents, const std::string& face)
{
  std::istringstream in(contents);
  std::string first, counts, rest;
  std::getline(in, first);
  std::getline(in, counts);
  std::istringstream c(counts);
  std::size_t nv = 0, nf = 0, ne = 0;
  c >> nv >> nf >> ne;
  std::ostringstream out;
  out << first << "\n" << nv << " " << nf + 1 << " " << ne << "\n" << in.rdbuf() << face << "\n";
  return out.str();
}

} // namespace

// ---------------------------------------------------------------------------
// 1. A certificate is about the file as written.

TEST(Hostile, CertifyJudgesTheFileAsWritten)
{
  const std::string folder = scratch_folder("certify_as_written");
  // a rhombus with two 120-degree corners: its triangulation is two
  // equilateral triangles, the file is not nonobtuse
  const double s = std::sqrt(3.) / 2.;
  spit(folder + "/rhombus.off", off({{0, 0, 0}, {1, 0, 0}, {1.5, s, 0}, {0.5, s, 0}}, {{0, 1, 2, 3}}));
  Tool_run r = tool("certify " + folder + "/rhombus.off");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("1 non-triangle face(s)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("certified: no"), std::string::npos) << r.out;
  r = tool("report " + folder + "/rhombus.off");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("not certified as written"), std::string::npos) << r.out;

  // a certified mesh, then the same plus a face that repeats a vertex, and
  // plus a duplicate face
  const std::string sphere = certified_sphere(folder);
  EXPECT_EQ(tool("certify " + sphere).code, 0);
  spit(folder + "/repeated.off", with_extra_face(slurp(sphere), "3 0 0 1"));
  spit(folder + "/duplicate.off", with_extra_face(slurp(sphere), "3 " + [&] {
         Mesh m;
         NR::read_triangle_mesh(sphere, m);
         std::string f;
         for(auto v : vertices_around_face(halfedge(*faces(m).begin(), m), m)) f += std::to_string(std::size_t(v)) + " ";
         return f;
       }()));
  for(const std::string name : {"repeated.off", "duplicate.off"}) {
    r = tool("certify " + folder + "/" + name);
    EXPECT_EQ(r.code, 1) << name << "\n" << r.out;
    EXPECT_NE(r.out.find("not read as written"), std::string::npos) << r.out;
    r = tool("decimate " + folder + "/" + name + " -o " + folder + "/decimated.off --ratio 0.5 -q");
    EXPECT_EQ(r.code, 1) << name;
    EXPECT_EQ(lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find("not certified as written"), std::string::npos) << r.err;
    EXPECT_EQ(::access((folder + "/decimated.off").c_str(), F_OK), -1) << name;
  }
  // remesh repairs what it reads and certifies what it writes
  r = tool("remesh " + folder + "/rhombus.off -o " + folder + "/remeshed.off -N 10 -q");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(tool("certify " + folder + "/remeshed.off").code, 0);
}

// ---------------------------------------------------------------------------
// 2. No output overwrites another, however the paths are spelled.

TEST(Hostile, OutputsAreComparedByWhatTheyName)
{
  const std::string folder = scratch_folder("path_clashes");
  ::mkdir((folder + "/out").c_str(), 0755);
  spit(folder + "/in.off", slurp(data("sphere.off")));
  const std::string sphere = certified_sphere(folder);
  const std::string in = folder + "/in.off", o = folder + "/out/o.off";
  struct Case
  {
    std::string arguments, first, second;
  };
  const std::vector<Case> cases = {
      {"remesh " + in + " -o " + o + " --report " + folder + "/out/./o.off", "-o", "--report"},
      {"remesh " + in + " -o " + o + " --lod 0.5 --report " + folder + "/out/../out/o_lod1.off", "--report", "level 1"},
      {"remesh " + in + " -o " + o + " --angle-histogram " + folder + "/out//o.off", "-o", "--angle-histogram"},
      {"remesh " + in + " -o " + folder + "/out/../in.off", "-o", "over the input"},
      {"decimate " + sphere + " -o " + o + " --ratio 0.5 --json " + folder + "/./out/o.off", "-o", "--json"},
      {"remesh " + in + " -o " + o + " --report " + o, "-o", "--report"}};
  for(const Case& c : cases) {
    const Tool_run r = tool(c.arguments + " -q");
    EXPECT_EQ(r.code, 3) << c.arguments << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1u) << c.arguments << "\n" << r.err;
    EXPECT_NE(r.err.find(c.first), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.second), std::string::npos) << r.err;
    EXPECT_TRUE(folder_entries(folder + "/out").empty()) << c.arguments;
  }
  EXPECT_EQ(slurp(in), slurp(data("sphere.off")));
  // a symbolic link to the output's folder names the same file
  ASSERT_EQ(::symlink((folder + "/out").c_str(), (folder + "/link").c_str()), 0);
  const Tool_run r = tool("remesh " + in + " -o " + o + " --report " + folder + "/link/o.off -q");
  EXPECT_EQ(r.code, 3) << r.err;
  // --report and --json are one option: giving both is a usage error
  const Tool_run both = tool("remesh " + in + " -o " + o + " --report " + folder + "/a.json --json " + folder + "/b.json");
  EXPECT_EQ(both.code, 2) << both.err;
  EXPECT_TRUE(folder_entries(folder + "/out").empty());
}

TEST(Hostile, LongOutputNames)
{
  const std::string folder = scratch_folder("long_names");
  const std::string fits = std::string(251, 'n') + ".off", too_long = std::string(252, 'n') + ".off";
  Tool_run r = tool("remesh " + data("sphere.off") + " -o " + folder + "/" + fits + " -N 8 -q");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(folder_entries(folder), std::set<std::string>{fits});
  r = tool("remesh " + data("sphere.off") + " -o " + folder + "/" + too_long + " -N 8 -q");
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("file name has 256 bytes"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << "refused before any work";
  EXPECT_EQ(folder_entries(folder), std::set<std::string>{fits});
}

// ---------------------------------------------------------------------------
// 3. Bounded memory and time.

TEST(Hostile, MemoryBudgetRefusesAtOnce)
{
  const std::string folder = scratch_folder("memory_budget");
  // N = 1024 on the sphere needs about 9 GiB: refused with the estimate
  Tool_run r = tool("remesh " + data("sphere.off") + " -o " + folder + "/out.off -N 1024 -q");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("memory budget of 4 GiB"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--memory-limit"), std::string::npos) << r.err;
  EXPECT_LT(r.peak_mib, 1500.) << "the estimate comes before the mesh";
  std::cout << "[ memory   ] N = 1024 refused at a peak of " << r.peak_mib << " MiB" << std::endl;
  // the same through a vertex target, and a small budget at the default resolution
  r = tool("remesh " + data("sphere.off") + " -o " + folder + "/out.off --target-vertices 100000000 -q");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("memory budget"), std::string::npos) << r.err;
  r = tool("remesh " + data("sphere.off") + " -o " + folder + "/out.off --memory-limit 0.01 -q");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("memory budget of 0.01 GiB"), std::string::npos) << r.err;
  // N = 30 needs about 8 MiB: refused under 0.005 GiB, built under 0.02
  r = tool("remesh " + data("sphere.off") + " -o " + folder + "/out.off -N 30 --memory-limit 0.005 --stop-after init -q");
  EXPECT_EQ(r.code, 3) << r.err;
  r = tool("remesh " + data("sphere.off") + " -o " + folder + "/out.off -N 30 --memory-limit 0.02 --stop-after init -q");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(folder_entries(folder) == std::set<std::string>{"out.off"});
}

TEST(Hostile, AnnouncedCountsAreBoundedByTheFile)
{
  const std::string folder = scratch_folder("lying_counts");
  std::vector<std::pair<std::string, std::string> > files = {
      {"face_count.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n300000000 0 1 2\n"},
      {"header.off", "OFF\n300000000 300000000 0\n0 0 0\n"}};
  const auto le32 = [](std::uint32_t v) {
    std::string s(4, '\0');
    for(int i = 0; i < 4; ++i) s[std::size_t(i)] = char((v >> (8 * i)) & 0xff);
    return s;
  };
  const auto le_float = [&](float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return le32(u);
  };
  std::string vertices;
  for(float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) vertices += le_float(c);
  const std::string ply_header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n";
  // binary OFF: big-endian counts
  const auto be32 = [](std::uint32_t v) {
    std::string s(4, '\0');
    for(int i = 0; i < 4; ++i) s[std::size_t(i)] = char((v >> (8 * (3 - i))) & 0xff);
    return s;
  };
  files.push_back({"binary.off", "OFF BINARY\n" + be32(3) + be32(200000000) + be32(0)});
  files.push_back({"binary_face.off", "OFF BINARY\n" + be32(3) + be32(1) + be32(0) + std::string(36, '\0') +
                                          be32(300000000) + be32(0) + be32(1) + be32(2)});
  // vertices packed on one line, then a lying face
  files.push_back({"packed.off", "OFF\n3 1 0\n0 0 0 1 0 0 0 1 0\n500000000 0 1 2\n"});
  files.push_back({"skeleton.off", "SKEL\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"});
  files.push_back({"four_d.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n"});
  files.push_back({"list_count.ply", ply_header + vertices + le32(300000000) + le32(0) + le32(1) + le32(2)});
  files.push_back({"element_count.ply",
                   "ply\nformat ascii 1.0\nelement vertex 300000000\nproperty float x\nproperty float y\n"
                   "property float z\nend_header\n0 0 0\n"});
  // a binary STL whose header says 2 triangles and which holds 4
  std::string stl(80, '\0');
  stl += le32(2);
  const float tetra[4][3][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}, {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
                                {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}}};
  for(const auto& t : tetra) {
    for(int i = 0; i < 3; ++i) stl += le_float(0.f);
    for(const auto& p : t)
      for(float c : p) stl += le_float(c);
    stl += std::string(2, '\0');
  }
  files.push_back({"count_mismatch.stl", stl});
  for(const auto& [name, contents] : files) {
    spit(folder + "/" + name, contents);
    const Tool_run r = tool("remesh " + folder + "/" + name + " -o " + folder + "/out.off -q");
    EXPECT_EQ(r.code, 3) << name << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1u) << name << "\n" << r.err;
    EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
    EXPECT_LT(r.peak_mib, 100.) << name << ": nothing is allocated from a lying count";
    std::cout << "[ counts   ] " << name << ": peak " << r.peak_mib << " MiB: " << r.err;
  }
  EXPECT_NE(tool("report " + folder + "/count_mismatch.stl").err.find("announces 2 triangles"), std::string::npos);
  // the same STL with a truthful header is a closed tetrahedron
  stl.replace(80, 4, le32(4));
  spit(folder + "/truthful.stl", stl);
  const Tool_run r = tool("report " + folder + "/truthful.stl");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("border cycles: 0"), std::string::npos) << r.out;
}

// A flat disk given as one polygon of 20,000 sides: its triangulation is all
// needles. The fit's closest-triangle search used to visit a large part of
// them per query (108 s for the fit); its cost now depends on the output.
TEST(Hostile, NeedleTrianglesDoNotSlowTheFit)
{
  const std::string folder = scratch_folder("needles");
  const int sides = 20000;
  std::vector<std::array<double, 3> > points;
  std::vector<int> polygon;
  for(int i = 0; i < sides; ++i) {
    const double a = 2. * M_PI * double(i) / double(sides);
    points.push_back({std::cos(a), std::sin(a), 0.});
    polygon.push_back(i);
  }
  spit(folder + "/disk.off", off(points, {polygon}));
  const Tool_run r = tool("remesh " + folder + "/disk.off -o " + folder + "/out.off -N 60 -q", 60);
  EXPECT_EQ(r.code, 0) << "exit " << r.code << (r.code == 124 ? " (timed out)" : "") << "\n" << r.err;
  EXPECT_NE(r.err.find("triangulated 1 non-triangle face(s)"), std::string::npos) << r.err;
  EXPECT_TRUE(certified_by_hand(folder + "/out.off"));
}

// One strip folded into 40 layers 1e-6 apart: every cube holds 40 patches
// of the same configuration, whose triangles would coincide (82 s, and an
// output overlapping itself 3.7 million times): refused at once, saying why.
TEST(Hostile, StackedSheetsAreRefusedWithTheReason)
{
  const std::string folder = scratch_folder("accordion");
  std::vector<std::array<double, 2> > polyline;  // (x, z), extruded along y
  for(int layer = 0; layer < 40; ++layer)
    for(int k = 0; k <= 8; ++k) {
      const double x = double(layer % 2 == 0 ? k : 8 - k) / 8.;
      polyline.push_back({x, 1e-6 * double(layer)});
    }
  std::vector<std::array<double, 3> > points;
  std::vector<std::vector<int> > faces_;
  for(const auto& q : polyline) {
    points.push_back({q[0], 0., q[1]});
    points.push_back({q[0], 0.2, q[1]});
  }
  for(int k = 0; k + 1 < int(polyline.size()); ++k) {
    faces_.push_back({2 * k, 2 * k + 2, 2 * k + 3});
    faces_.push_back({2 * k, 2 * k + 3, 2 * k + 1});
  }
  spit(folder + "/accordion.off", off(points, faces_));
  const Tool_run r = tool("remesh " + folder + "/accordion.off -o " + folder + "/out.off -q", 60);
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("sheets closer together than a cube"), std::string::npos) << r.err;
  EXPECT_EQ(folder_entries(folder), std::set<std::string>{"accordion.off"});
  // one layer of the same strip is meshed
  spit(folder + "/layer.off", off(std::vector<std::array<double, 3> >(points.begin(), points.begin() + 18),
                                  std::vector<std::vector<int> >(faces_.begin(), faces_.begin() + 16)));
  EXPECT_EQ(tool("remesh " + folder + "/layer.off -o " + folder + "/layer_out.off -N 40 -q").code, 0);
}

// ---------------------------------------------------------------------------
// 4. Signals during the write leave no temporary file.

TEST(Hostile, SignalsLeaveNoTemporaryFile)
{
  for(int signal_number : {SIGINT, SIGTERM}) {
    const std::string folder = scratch_folder("signals_" + std::to_string(signal_number));
    spit(folder + "/out.off", "previous contents\n");
    const pid_t child = ::fork();
    if(child == 0) {
      ::signal(SIGINT, SIG_DFL);
      ::signal(SIGTERM, SIG_DFL);
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1);
      ::dup2(null, 2);
      ::execl(NONOBTUSE_TOOL, NONOBTUSE_TOOL, "remesh", data("sphere.off").c_str(), "-o", (folder + "/out.off").c_str(),
              "-N", "90", "--stop-after", "init", "-q", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // wait for the temporary file to appear, then interrupt
    bool seen = false;
    for(int i = 0; i < 200000 && !seen; ++i) {
      for(const std::string& name : folder_entries(folder))
        if(name.find(".tmp-") != std::string::npos) seen = true;
      if(!seen) ::usleep(100);
    }
    ::kill(child, signal_number);
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_TRUE(seen) << "the write was not caught in progress";
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << "ends as the signal says";
    EXPECT_EQ(folder_entries(folder), std::set<std::string>{"out.off"}) << "signal " << signal_number;
    // interrupted in the write, the previous output stays; interrupted just
    // after the rename (the signal can land there), the new one is complete
    const std::string now = slurp(folder + "/out.off");
    EXPECT_TRUE(now == "previous contents\n" || certified_by_hand(folder + "/out.off")) << "signal " << signal_number;
  }
}

// ---------------------------------------------------------------------------
// 5.-10. Silent wrong answers and valid files that were refused.

TEST(Hostile, ObjFacesByWhitespaceIndexZeroRefused)
{
  const std::string folder = scratch_folder("obj");
  const std::string tetra_v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  spit(folder + "/zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  Tool_run r = tool("certify " + folder + "/zero.obj");
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("index 0"), std::string::npos) << r.err;
  // a tab between indices: a quad, not a triangle
  spit(folder + "/tab.obj", tetra_v + "f 1 2 3\t4\n");
  r = tool("certify " + folder + "/tab.obj");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("1 non-triangle face(s)"), std::string::npos) << r.out;
  // a byte order mark, tabs, polylines, points, texture references, negative indices
  spit(folder + "/valid.obj", "\xEF\xBB\xBF# a tetrahedron\nv\t0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nl 1 2\np 3\n"
                              "f 1/1 3/1 2/1\nf\t1//1\t2//1\t4//1\nf -3 -2 -1\nf 1 4 3\n");
  r = tool("report " + folder + "/valid.obj");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("faces: 4"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Euler characteristic: 2"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("ignored 2 polyline or point element(s)"), std::string::npos) << r.err;
}

TEST(Hostile, PlyWithSmallIntegerLists)
{
  const std::string folder = scratch_folder("ply");
  const char* types[][2] = {{"uchar", "char"}, {"ushort", "ushort"}, {"char", "uchar"}, {"uint", "short"}};
  for(const auto& t : types)
    for(const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
      const std::string name = folder + "/" + t[0] + "_" + t[1] + "_" + format + ".ply";
      std::ostringstream out;
      out << "ply\nformat " << format << " 1.0\ncomment hostile\nelement vertex 4\nproperty double x\n"
          << "property double y\nproperty double z\nproperty uchar red\nelement face 4\nproperty list " << t[0] << " "
          << t[1] << " vertex_indices\nproperty float quality\nend_header\n";
      const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
      const auto bytes = [&](const std::string& type) {
        return type == "char" || type == "uchar" ? 1 : type == "short" || type == "ushort" ? 2 : 4;
      };
      const auto put = [&](std::uint64_t value, int size) {
        for(int i = 0; i < size; ++i)
          out.put(char((value >> (8 * (format == "binary_little_endian" ? i : size - 1 - i))) & 0xff));
      };
      for(const auto& v : p) {
        if(format == "ascii") {
          out << v[0] << " " << v[1] << " " << v[2] << " 7\n";
          continue;
        }
        for(double c : v) {
          std::uint64_t u;
          std::memcpy(&u, &c, 8);
          put(u, 8);
        }
        put(7, 1);
      }
      for(const auto& face : f) {
        if(format == "ascii") {
          out << "3 " << face[0] << " " << face[1] << " " << face[2] << " 0.5\n";
          continue;
        }
        put(3, bytes(t[0]));
        for(int i : face) put(std::uint64_t(i), bytes(t[1]));
        const float q = 0.5f;
        std::uint32_t u;
        std::memcpy(&u, &q, 4);
        put(u, 4);
      }
      spit(name, out.str());
      const Tool_run r = tool("report " + name);
      EXPECT_EQ(r.code, 0) << name << "\n" << r.err;
      EXPECT_NE(r.out.find("faces: 4"), std::string::npos) << name << "\n" << r.out;
      EXPECT_NE(r.out.find("Euler characteristic: 2"), std::string::npos) << name << "\n" << r.out;
    }
}

TEST(Hostile, MissingComponentsAreReported)
{
  const std::string folder = scratch_folder("missing_components");
  // the sphere and a copy a thousand times smaller, far from it
  Mesh sphere = nonobtuse_test::load("sphere.off");
  std::vector<std::array<double, 3> > points;
  std::vector<std::vector<int> > faces_;
  for(int copy = 0; copy < 2; ++copy) {
    const int shift = int(points.size());
    for(auto v : vertices(sphere)) {
      const auto& p = sphere.point(v);
      const double s = copy == 0 ? 1. : 1e-3;
      points.push_back({s * p.x() + (copy == 0 ? 0. : 3.), s * p.y(), s * p.z()});
    }
    for(auto f : faces(sphere)) {
      std::vector<int> face;
      for(auto v : vertices_around_face(halfedge(f, sphere), sphere)) face.push_back(shift + int(std::size_t(v)));
      faces_.push_back(face);
    }
  }
  spit(folder + "/two.off", off(points, faces_));
  const Tool_run r = tool("remesh " + folder + "/two.off -o " + folder + "/out.off -N 30 --report " + folder + "/out.json -q");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("note: 1 of the input's 2 connected component(s) do not appear"), std::string::npos) << r.out;
  const nlohmann::json j = nlohmann::json::parse(slurp(folder + "/out.json"));
  EXPECT_EQ(j["input_components"]["components"], 2);
  EXPECT_EQ(j["input_components"]["missing"], 1);
  EXPECT_TRUE(certified_by_hand(folder + "/out.off"));
}

// ---------------------------------------------------------------------------
// The readers under random damage, and certify against the hand evaluation.

// Valid files of each format, then random mutations of their bytes (fixed
// seed): each is read in a child process under a 1 GiB address-space limit
// and a time limit, and must either give a mesh or be refused with Bad_input.
TEST(Hostile, FuzzedReaders)
{
  const std::string folder = scratch_folder("fuzz");
  const Mesh sphere = nonobtuse_test::load("sphere.off");
  std::vector<std::string> seeds;
  for(const std::string ext : {"off", "obj", "ply", "stl"}) {
    const std::string path = folder + "/seed." + ext;
    if(ext == "stl" || ext == "ply")
      ASSERT_TRUE(CGAL::IO::write_polygon_mesh(path, sphere, CGAL::parameters::use_binary_mode(ext == "stl")));
    else
      NR::write_mesh_atomically(path, sphere);
    seeds.push_back(path);
  }
  // the PLY above is ASCII: a binary one too, and a binary OFF
  NR::write_mesh_atomically(folder + "/seed_binary.ply", sphere);
  seeds.push_back(folder + "/seed_binary.ply");
  {
    std::ofstream out(folder + "/seed_binary.off", std::ios::binary);
    const auto be32 = [&out](std::uint32_t v) {
      for(int i = 3; i >= 0; --i) out.put(char((v >> (8 * i)) & 0xff));
    };
    out << "OFF BINARY\n";
    be32(std::uint32_t(num_vertices(sphere)));
    be32(std::uint32_t(num_faces(sphere)));
    be32(0);
    for(auto v : vertices(sphere))
      for(int a = 0; a < 3; ++a) {
        const float c = float(sphere.point(v)[a]);
        std::uint32_t u;
        std::memcpy(&u, &c, 4);
        be32(u);
      }
    for(auto f : faces(sphere)) {
      be32(3);
      for(auto v : vertices_around_face(halfedge(f, sphere), sphere)) be32(std::uint32_t(std::size_t(v)));
      be32(0);
    }
  }
  seeds.push_back(folder + "/seed_binary.off");

  std::mt19937 random(20261202);
  const int cases_per_seed = 400;
  std::size_t accepted = 0, refused = 0;
  long peak_kib = 0;
  std::vector<std::string> tool_cases;
  for(const std::string& seed : seeds) {
    const std::string original = slurp(seed);
    const std::string ext = NR::internal::file_extension(seed);
    for(int c = 0; c < cases_per_seed; ++c) {
      std::string bytes = original;
      const int mutations = 1 + int(random() % 8);
      for(int m = 0; m < mutations; ++m) {
        const std::size_t at = random() % bytes.size();
        switch(random() % 6) {
        case 0: bytes[at] = char(random() % 256); break;                                   // a random byte
        case 1: bytes[at] = "0123456789 -.e\n"[random() % 15]; break;                      // a plausible one
        case 2: bytes.erase(at, 1 + random() % 16); break;                                 // cut
        case 3: bytes.insert(at, bytes.substr(random() % bytes.size(), 1 + random() % 32)); break;  // repeat
        case 4: bytes.resize(at + 1); break;                                               // truncate
        default: bytes.insert(at, std::to_string(random()) + "0000"); break;               // a large number
        }
        if(bytes.empty()) bytes = "x";
      }
      const std::string path = folder + "/case." + ext;
      spit(path, bytes);
      const pid_t child = ::fork();
      if(child == 0) {
        struct rlimit limit = {rlim_t(1) << 30, rlim_t(1) << 30};
        ::setrlimit(RLIMIT_AS, &limit);
        ::alarm(20);
        std::cerr.setstate(std::ios::failbit);
        try {
          Mesh mesh;
          NR::Read_log log;
          NR::read_triangle_mesh(path, mesh, log);
          ::_exit(is_triangle_mesh(mesh) && num_faces(mesh) > 0 ? 0 : 5);
        } catch(const NR::Bad_input&) {
          ::_exit(3);
        } catch(...) {
          ::_exit(4);
        }
      }
      int status = 0;
      struct rusage usage;
      ::wait4(child, &status, 0, &usage);
      const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      peak_kib = std::max<long>(peak_kib, usage.ru_maxrss);
      EXPECT_LT(usage.ru_maxrss, 256 * 1024) << "peak memory reading a mutation of " << seed;
      EXPECT_TRUE(code == 0 || code == 3) << "exit " << code << " on a mutation of " << seed << ", kept as "
                                          << folder << "/failed_" << c << "." << ext;
      if(code != 0 && code != 3) spit(folder + "/failed_" + std::to_string(c) + "." + ext, bytes);
      (code == 0 ? accepted : refused)++;
      if(c % 40 == 0) {  // one case in forty also goes through the tool
        const std::string kept = folder + "/tool_" + std::to_string(tool_cases.size()) + "." + ext;
        spit(kept, bytes);
        tool_cases.push_back(kept);
      }
    }
  }
  std::cout << "[ fuzz     ] " << accepted + refused << " mutated files: " << accepted << " read, " << refused
            << " refused with Bad_input, peak memory of a reader " << peak_kib / 1024 << " MiB" << std::endl;
  EXPECT_GT(refused, 100u);

  // the tool on a sample: a certified output, or one line and exit 3, and no other file
  for(const std::string& input : tool_cases) {
    const std::string out_folder = folder + "/run";
    std::system(("rm -rf '" + out_folder + "' && mkdir '" + out_folder + "'").c_str());
    const Tool_run r = tool("remesh '" + input + "' -o " + out_folder + "/out.off -N 12 -q", 60);
    EXPECT_TRUE(r.code == 0 || r.code == 3) << input << ": exit " << r.code << "\n" << r.err;
    if(r.code == 0) {
      EXPECT_EQ(folder_entries(out_folder), std::set<std::string>{"out.off"}) << input;
      EXPECT_TRUE(certified_by_hand(out_folder + "/out.off")) << input;
    } else {
      EXPECT_EQ(lines(r.err), 1u) << input << "\n" << r.err;
      EXPECT_TRUE(folder_entries(out_folder).empty()) << input;
    }
    EXPECT_LT(r.peak_mib, 1024.) << input;
  }
}

// `certify` and the independent evaluation agree on every OFF file of this
// corpus: certified outputs, shipped meshes, damaged and near-miss files.
TEST(Hostile, CertifyAgreesWithAnIndependentEvaluation)
{
  const std::string folder = scratch_folder("certify_agrees");
  std::vector<std::string> corpus;
  for(const std::string name : {"sphere.off", "pig.off", "cube-meshed.off", "mesh_with_border.off"})
    corpus.push_back(data(name));
  const std::string sphere = certified_sphere(folder);
  corpus.push_back(sphere);
  const std::string content = slurp(sphere);
  // near misses: one coordinate of the certified mesh moved by one ulp, both
  // ways, at several vertices; a face that repeats a vertex; a quad of two
  // 120-degree corners; triangles of 45-45-90 and 60-60-60 degrees (both
  // certified), of 29.99 degrees and of just over 90 (neither)
  Mesh m;
  NR::read_triangle_mesh(sphere, m);
  int variant = 0;
  for(auto v : vertices(m)) {
    if(std::size_t(v) % 37 != 0) continue;
    for(double direction : {-1., 1.}) {
      Mesh moved = m;
      const auto p = moved.point(v);
      moved.point(v) = {std::nextafter(p.x(), direction * 1e300), p.y(), p.z()};
      const std::string path = folder + "/ulp_" + std::to_string(variant++) + ".off";
      std::ofstream out(path);
      out << std::setprecision(17);
      CGAL::IO::write_OFF(out, moved, CGAL::parameters::stream_precision(17));
      out.close();
      corpus.push_back(path);
    }
  }
  spit(folder + "/repeated.off", with_extra_face(content, "3 1 1 2"));
  corpus.push_back(folder + "/repeated.off");
  const double s = std::sqrt(3.) / 2.;
  spit(folder + "/quad.off", off({{0, 0, 0}, {1, 0, 0}, {1.5, s, 0}, {0.5, s, 0}}, {{0, 1, 2, 3}}));
  spit(folder + "/right.off", off({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
  spit(folder + "/equilateral.off", off({{0, 0, 0}, {1, 0, 0}, {0.5, s, 0}}, {{0, 1, 2}}));
  spit(folder + "/thin.off", off({{0, 0, 0}, {1, 0, 0}, {0.5, std::tan(29.99 * M_PI / 180.) / 2., 0}}, {{0, 1, 2}}));
  spit(folder + "/obtuse.off", off({{0, 0, 0}, {1, 0, 0}, {0.5, 0.4999999, 0}}, {{0, 1, 2}}));
  for(const std::string name : {"quad.off", "right.off", "equilateral.off", "thin.off", "obtuse.off"})
    corpus.push_back(folder + "/" + name);
  std::size_t agreed = 0, certified = 0;
  for(const std::string& path : corpus) {
    const Tool_run r = tool("certify " + path);
    ASSERT_TRUE(r.code == 0 || r.code == 1) << path << "\n" << r.err;
    const bool by_hand = certified_by_hand(path);
    EXPECT_EQ(r.code == 0, by_hand) << path << "\n" << r.out;
    agreed += (r.code == 0) == by_hand;
    certified += by_hand;
  }
  std::cout << "[ certify  ] agrees with the exact evaluation by hand on " << agreed << " of " << corpus.size()
            << " files (" << certified << " certified)" << std::endl;
  EXPECT_GT(certified, 3u);
  EXPECT_LT(certified, corpus.size());
}
