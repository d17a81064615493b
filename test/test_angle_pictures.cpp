// SPDX-License-Identifier: GPL-3.0-or-later
//
// Angle pictures: the histogram agrees with the certificate, the SVG has a
// band, one bar series per mesh whose percentages sum to 100 and the min and
// max angles in its legend; the PLY coloured by angle reads back to the same
// coordinates bit for bit, certifies, and its face colours are the colormap's
// (also as CGAL reads them); failed writes throw Output_error and leave nothing.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>
#include <CGAL/Nonobtuse_remeshing/angle_pictures.h>
#include <CGAL/IO/PLY.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

namespace NR = CGAL::Nonobtuse_remeshing;
using nonobtuse_test::Mesh;
using nonobtuse_test::Point;
using nonobtuse_test::folder_entries;
using nonobtuse_test::scratch_folder;
using Color = std::array<unsigned char, 3>;

namespace {



std::string contents(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::size_t occurrences(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::uint64_t bits(double x)
{
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// The shipped sphere and its nonobtuse Marching Cubes mesh (certified).
const Mesh& sphere() { static const Mesh m = nonobtuse_test::load("sphere.off"); return m; }
const Mesh& remeshed_sphere()
{
  static const Mesh m = [] {
    Mesh out;
    NR::nonobtuse_marching_cubes(sphere(), out, NR::parameters::resolution(30));
    return out;
  }();
  return m;
}

// The smallest or largest corner angle of the face, shown within [30, 90]
// when the mesh is certified.
double extreme_angle(const Mesh& mesh, Mesh::Face_index f, NR::Angle_coloring what)
{
  std::vector<Point> p;
  for(auto v : vertices_around_face(mesh.halfedge(f), mesh)) p.push_back(mesh.point(v));
  double lo = 180., hi = 0.;
  for(int i = 0; i < 3; ++i) {
    const double a = NR::internal::corner_angle_degrees(p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
    lo = std::min(lo, a);
    hi = std::max(hi, a);
  }
  return what == NR::Angle_coloring::smallest_angle ? std::max(lo, 30.) : std::min(hi, 90.);
}

} // namespace

TEST(AnglePictures, HistogramAgreesWithTheCertificate)
{
  for(const Mesh* mesh : {&sphere(), &remeshed_sphere()}) {
    const auto certificate = NR::certify_angle_bounds(*mesh);
    const NR::Angle_histogram five = NR::angle_histogram(*mesh, "mesh", 5);
    ASSERT_EQ(five.counts.size(), 36u);
    for(std::size_t i = 0; i < 36; ++i) EXPECT_EQ(five.counts[i], certificate.angle_histogram[i]) << "bin " << i;
    const NR::Angle_histogram two = NR::angle_histogram(*mesh, "mesh");
    EXPECT_EQ(two.counts.size(), 90u);
    EXPECT_EQ(two.corners, 3 * num_faces(*mesh));
    EXPECT_EQ(two.min_angle, certificate.min_angle);
    EXPECT_EQ(two.max_angle, certificate.max_angle);
  }
  EXPECT_GE(NR::angle_histogram(remeshed_sphere(), "mc").min_angle, 35.26);
  EXPECT_THROW(NR::angle_histogram(sphere(), "bad", 7), NR::Bad_parameter);
}

TEST(AnglePictures, SvgHasTheBandOneSeriesPerMeshAndTheExtremes)
{
  const std::string folder = scratch_folder("pictures_svg");
  const std::string path = folder + "/hist.svg";
  NR::write_angle_histogram_svg(path, sphere(), remeshed_sphere(), "sphere.off", "remeshed <MC>");
  EXPECT_EQ(folder_entries(folder).size(), 1u) << "no temporary file left";
  const std::string svg = contents(path);
  EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
  EXPECT_EQ(svg.substr(svg.find_last_not_of(" \n") - 5, 6), "</svg>");
  EXPECT_EQ(occurrences(svg, "<g"), occurrences(svg, "</g>"));
  EXPECT_NE(svg.find("remeshed &lt;MC&gt;"), std::string::npos) << "names are escaped";
  EXPECT_EQ(occurrences(svg, "class=\"band\" x=\"220.00\""), 2u) << "the band starts at 30 degrees in both panels";

  const NR::Angle_histogram expected[2] = {NR::angle_histogram(sphere(), "sphere.off"),
                                           NR::angle_histogram(remeshed_sphere(), "remeshed <MC>")};
  ASSERT_EQ(occurrences(svg, "<g class=\"series\""), 2u);
  std::size_t at = 0;
  for(const NR::Angle_histogram& h : expected) {
    EXPECT_NE(svg.find("min " + NR::internal::fixed(h.min_angle, 2) + "\xC2\xB0, max " +
                       NR::internal::fixed(h.max_angle, 2) + "\xC2\xB0"), std::string::npos);
    at = svg.find("<g class=\"series\"", at);
    const std::size_t end = svg.find("</g>", at);
    double percent = 0.;
    std::size_t corners = 0, bars = 0;
    for(std::size_t t = svg.find("<title>", at); t < end; t = svg.find("<title>", t + 1), ++bars) {
      const std::size_t colon = svg.find(": ", t);  // <title>[40, 42): 12.500% (120)</title>
      percent += std::atof(svg.c_str() + colon + 2);
      corners += std::strtoul(svg.c_str() + svg.find("% (", colon) + 3, nullptr, 10);
    }
    EXPECT_NEAR(percent, 100., 0.05);
    EXPECT_EQ(corners, h.corners);
    EXPECT_GT(bars, 1u);
    at = end;
  }
}

TEST(AnglePictures, ColoredPlyRereadsBitForBitCertifiesAndHasTheColormap)
{
  const std::string folder = scratch_folder("pictures_ply");
  const Mesh& mesh = remeshed_sphere();
  ASSERT_TRUE(NR::certify_angle_bounds(mesh).is_certified());
  for(NR::Angle_coloring what : {NR::Angle_coloring::smallest_angle, NR::Angle_coloring::largest_angle}) {
    const std::string path = folder + "/colored.ply";
    NR::write_mesh_colored_by_angle_atomically(path, mesh, what);
    EXPECT_EQ(folder_entries(folder).size(), 1u) << "no temporary file left";

    Mesh back;
    NR::Read_log log;
    NR::read_triangle_mesh(path, back, log);
    EXPECT_TRUE(log.repairs.empty());
    ASSERT_EQ(num_vertices(back), num_vertices(mesh));
    ASSERT_EQ(num_faces(back), num_faces(mesh));
    for(auto v : vertices(mesh))
      for(int k = 0; k < 3; ++k)
        ASSERT_EQ(bits(back.point(v)[k]), bits(mesh.point(v)[k])) << "vertex " << v;
    const auto certificate = NR::certify_angle_bounds(back);
    EXPECT_TRUE(certificate.is_certified());
    EXPECT_EQ(certificate.min_angle, NR::certify_angle_bounds(mesh).min_angle);

    // the faces as written: vertex indices of the mesh, and the colormap's colour
    std::istringstream in(contents(path));
    std::string line;
    bool has_colors = false;
    while(std::getline(in, line) && line != "end_header") has_colors |= (line == "property uchar blue");
    EXPECT_TRUE(has_colors);
    for(std::size_t i = 0; i < num_vertices(mesh); ++i) std::getline(in, line);
    std::vector<Color> colors;
    for(Mesh::Face_index f : faces(mesh)) {
      int n = 0, r = 0, g = 0, b = 0;
      std::size_t ids[3];
      ASSERT_TRUE(in >> n >> ids[0] >> ids[1] >> ids[2] >> r >> g >> b);
      EXPECT_EQ(n, 3);
      const auto h = mesh.halfedge(f);
      EXPECT_EQ(ids[0], std::size_t(mesh.source(h)));
      EXPECT_EQ(ids[1], std::size_t(mesh.target(h)));
      EXPECT_EQ(ids[2], std::size_t(mesh.target(mesh.next(h))));
      const Color expected = NR::angle_color(extreme_angle(mesh, f, what), what);
      EXPECT_EQ(Color({(unsigned char)r, (unsigned char)g, (unsigned char)b}), expected) << "face " << f;
      colors.push_back(expected);
    }
    EXPECT_FALSE(in >> line) << "nothing after the faces";

    // CGAL's own reader sees the same colours
    std::vector<Point> points;
    std::vector<std::vector<std::size_t> > polygons;
    std::vector<CGAL::IO::Color> cgal_colors, vertex_colors;
    ASSERT_TRUE(CGAL::IO::read_PLY(path, points, polygons,
                                   CGAL::parameters::face_color_output_iterator(std::back_inserter(cgal_colors))
                                       .vertex_color_output_iterator(std::back_inserter(vertex_colors))));
    EXPECT_TRUE(vertex_colors.empty());
    ASSERT_EQ(cgal_colors.size(), colors.size());
    for(std::size_t i = 0; i < colors.size(); ++i)
      EXPECT_EQ(Color({cgal_colors[i].red(), cgal_colors[i].green(), cgal_colors[i].blue()}), colors[i]);
  }
}

TEST(AnglePictures, ColormapAndOutOfBoundsFaces)
{
  const auto smallest = NR::Angle_coloring::smallest_angle, largest = NR::Angle_coloring::largest_angle;
  EXPECT_EQ(NR::angle_color(60., smallest), Color({0, 0, 255}));
  EXPECT_EQ(NR::angle_color(52.5, smallest), Color({0, 255, 255}));
  EXPECT_EQ(NR::angle_color(45., smallest), Color({0, 255, 0}));
  EXPECT_EQ(NR::angle_color(37.5, smallest), Color({255, 255, 0}));
  EXPECT_EQ(NR::angle_color(30., smallest), Color({255, 0, 0}));
  EXPECT_EQ(NR::angle_color(10., smallest), Color({255, 0, 0}));
  EXPECT_EQ(NR::angle_color(60., largest), Color({0, 0, 255}));
  EXPECT_EQ(NR::angle_color(75., largest), Color({0, 255, 0}));
  EXPECT_EQ(NR::angle_color(90., largest), Color({255, 0, 0}));
  EXPECT_EQ(NR::angle_color(41.25, smallest), Color({128, 255, 0}));

  // a triangle with angles 35, 35 and 110: its largest angle is out of bounds
  Mesh obtuse;
  obtuse.add_face(obtuse.add_vertex(Point(0, 0, 0)), obtuse.add_vertex(Point(2, 0, 0)),
                  obtuse.add_vertex(Point(1, 0.7, 0)));
  const std::string folder = scratch_folder("pictures_obtuse");
  auto face_color = [&](NR::Angle_coloring what) {
    NR::write_mesh_colored_by_angle_atomically(folder + "/t.ply", obtuse, what);
    std::istringstream in(contents(folder + "/t.ply"));
    std::string line;
    while(std::getline(in, line) && line != "end_header") {}
    for(int i = 0; i < 3; ++i) std::getline(in, line);
    int n, a, b, c, r, g, bl;
    in >> n >> a >> b >> c >> r >> g >> bl;
    return Color({(unsigned char)r, (unsigned char)g, (unsigned char)bl});
  };
  EXPECT_EQ(face_color(largest), NR::out_of_bounds_color);
  EXPECT_EQ(face_color(smallest), NR::angle_color(extreme_angle(obtuse, *faces(obtuse).begin(), smallest), smallest));
  EXPECT_NE(face_color(smallest), NR::out_of_bounds_color);
}

TEST(AnglePictures, FailedWritesThrowAndLeaveNothing)
{
  const std::string folder = scratch_folder("pictures_fail");
  const Mesh& mesh = sphere();
  ::mkdir((folder + "/a_folder.svg").c_str(), 0755);
  ::mkdir((folder + "/a_folder.ply").c_str(), 0755);
  for(const std::string& target : {folder + "/missing/h.svg", folder + "/a_folder.svg"}) {
    try {
      NR::write_angle_histogram_svg(target, mesh, mesh);
      ADD_FAILURE() << target << " was written";
    } catch(const NR::Output_error& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
    }
  }
  EXPECT_THROW(NR::write_mesh_colored_by_angle_atomically(folder + "/missing/c.ply", mesh,
                                                          NR::Angle_coloring::smallest_angle),
               NR::Output_error);
  EXPECT_THROW(NR::write_mesh_colored_by_angle_atomically(folder + "/a_folder.ply", mesh,
                                                          NR::Angle_coloring::largest_angle),
               NR::Output_error);
  EXPECT_EQ(folder_entries(folder).size(), 2u) << "only the two folders, no temporary file";
  EXPECT_TRUE(folder_entries(folder + "/a_folder.svg").empty());
}
