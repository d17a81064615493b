// SPDX-License-Identifier: GPL-3.0-or-later
//
// Pictures of the angles of triangle meshes: an SVG histogram of the corner
// angles of several meshes, and a PLY whose faces are coloured by angle.
//
// Angles are measured in double, for the eye only; as in the certificate, a
// corner that the exact predicates prove within [30, 90] is shown within it,
// and the PLY keeps the coordinates at full precision, so it certifies as the
// mesh does. Both files are written atomically by `write_file_atomically()`.

#ifndef CGAL_NONOBTUSE_REMESHING_ANGLE_PICTURES_H
#define CGAL_NONOBTUSE_REMESHING_ANGLE_PICTURES_H

#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/angle_predicates.h>
#include <CGAL/Nonobtuse_remeshing/internal/picture_helpers.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <functional>
#include <limits>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// Corner angles of one mesh in bins of `bin_degrees`, as `angle_histogram()`
/// computes them: bin i is [i w, i w + w), except that the bin ending at 90 is
/// closed, [90 - w, 90], so that a right angle counts as nonobtuse, and 180
/// falls in the last bin (with w = 5 the bins are those of `Angle_certificate`).
struct Angle_histogram
{
  std::string name;  ///< shown in the title and legend of the picture
  int bin_degrees = 2;
  std::vector<std::size_t> counts;  ///< 180 / bin_degrees bins
  std::size_t faces = 0, degenerate_faces = 0;
  std::size_t corners = 0;  ///< corners of the non-degenerate faces, all counted
  double min_angle = 180., max_angle = 0.;  ///< as `Angle_certificate` reports them
};

/// \ingroup PkgNonobtuseRemeshingRef
/// What `write_mesh_colored_by_angle_atomically()` colours a face by.
enum class Angle_coloring { smallest_angle, largest_angle };

/// \ingroup PkgNonobtuseRemeshingRef
/// The histogram of the corner angles of the triangle mesh `mesh` (double
/// coordinates), degenerate faces left out. `bin_degrees` must divide 90.
template <typename TriangleMesh>
Angle_histogram angle_histogram(const TriangleMesh& mesh, const std::string& name, int bin_degrees = 2)
{
  if(bin_degrees < 1 || 90 % bin_degrees != 0)
    throw Bad_parameter("angle_histogram: the bin width must divide 90 degrees");
  Angle_histogram h;
  h.name = name;
  h.bin_degrees = bin_degrees;
  h.counts.assign(180 / bin_degrees, 0);
  const int right = 90 / bin_degrees;  // first bin above 90
  internal::for_each_triangle(mesh, [&](auto, const auto& a, const auto& b, const auto& c) {
    ++h.faces;
    std::array<double, 3> angles;
    if(internal::shown_angles(a, b, c, angles).degenerate) { ++h.degenerate_faces; return; }
    for(double angle : angles) {
      const int bin = int(angle / bin_degrees);
      ++h.counts[angle <= 90. ? (std::max)(0, (std::min)(right - 1, bin))
                              : (std::max)(right, (std::min)(2 * right - 1, bin))];
      h.min_angle = (std::min)(h.min_angle, angle);
      h.max_angle = (std::max)(h.max_angle, angle);
      ++h.corners;
    }
  });
  return h;
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Writes an SVG 1.1 picture of the histograms `series` to `path`, one panel
/// each, stacked on a shared axis 0-180 degrees: bars give the percentage of
/// the mesh's corners in each bin, the band [30, 90] is shaded, and the
/// legend of each panel gives its corner count and min and max angle. Written
/// atomically; throws `Output_error` with a one-line message on failure.
inline void write_angle_histogram_svg(const std::string& path, const std::vector<Angle_histogram>& series)
{
  using internal::fixed;
  const char* colors[] = {"#3b6fb6", "#d9542b", "#4c9f50", "#8e5ab5", "#b59a2b"};
  const double left = 70, plot_w = 900, top = 80, plot_h = 200, gap = 70;  // 5 px per degree
  const double height = top + series.size() * (plot_h + gap) + 10;
  auto x_of = [&](double degrees) { return fixed(left + degrees * plot_w / 180., 2); };
  std::ostringstream svg;
  svg.imbue(std::locale::classic());
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"1000\" height=\"" << fixed(height, 0)
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  std::string title = "Corner angles: ";
  for(std::size_t s = 0; s < series.size(); ++s)
    title += (s ? " vs " : "") + series[s].name + " (" + std::to_string(series[s].faces) + " faces)";
  svg << "<text x=\"500\" y=\"28\" text-anchor=\"middle\" font-size=\"17\" font-weight=\"bold\">"
      << internal::xml_escaped(title) << "</text>\n<text x=\"500\" y=\"48\" text-anchor=\"middle\" fill=\"#444\">"
      << "% of corner angles per " << (series.empty() ? 2 : series[0].bin_degrees)
      << "\xC2\xB0 bin, measured in double (corners certified within [30\xC2\xB0, 90\xC2\xB0] shown within);"
      << " shaded: [30\xC2\xB0, 90\xC2\xB0]</text>\n";
  for(std::size_t s = 0; s < series.size(); ++s) {
    const Angle_histogram& h = series[s];
    const double y0 = top + s * (plot_h + gap), base = y0 + plot_h;
    const double total = double((std::max)(h.corners, std::size_t(1)));
    double highest = 0.;
    for(std::size_t n : h.counts) highest = (std::max)(highest, 100. * n / total);
    double step = 50.;  // y tick step: the smallest giving at most 5 ticks
    for(double candidate : {0.5, 1., 2., 5., 10., 20., 25.})
      if(highest <= 5. * candidate) { step = candidate; break; }
    const double y_max = (std::max)(step, std::ceil(highest / step - 1e-9) * step);
    auto y_of = [&](double percent) { return base - percent * plot_h / y_max; };
    std::string legend = h.name + ": " + std::to_string(h.corners) + " angles";
    if(h.corners > 0)
      legend += ", min " + fixed(h.min_angle, 2) + "\xC2\xB0, max " + fixed(h.max_angle, 2) + "\xC2\xB0";
    if(h.degenerate_faces > 0) legend += ", " + std::to_string(h.degenerate_faces) + " degenerate faces not shown";
    svg << "<g class=\"panel\">\n<rect class=\"band\" x=\"" << x_of(30) << "\" y=\"" << y0 << "\" width=\""
        << fixed(60 * plot_w / 180., 2) << "\" height=\"" << plot_h << "\" fill=\"#dff2df\"/>\n"
        << "<rect x=\"" << left - 6 << "\" y=\"" << y0 - 17 << "\" width=\"12\" height=\"12\" fill=\"" << colors[s % 5]
        << "\"/>\n<text x=\"" << left + 12 << "\" y=\"" << y0 - 7 << "\">" << internal::xml_escaped(legend) << "</text>\n";
    for(double p = 0.; p <= y_max + 1e-9; p += step)
      svg << "<line x1=\"" << left - 5 << "\" x2=\"" << left + plot_w << "\" y1=\"" << fixed(y_of(p), 2) << "\" y2=\""
          << fixed(y_of(p), 2) << "\" stroke=\"#ddd\"/>\n<text x=\"" << left - 8 << "\" y=\"" << fixed(y_of(p) + 4, 2)
          << "\" text-anchor=\"end\">" << fixed(p, step < 1. ? 1 : 0) << "</text>\n";
    svg << "<text transform=\"translate(" << left - 45 << "," << y0 + plot_h / 2 << ") rotate(-90)\" "
        << "text-anchor=\"middle\">% of angles</text>\n<g class=\"series\" fill=\"" << colors[s % 5] << "\">\n";
    for(std::size_t i = 0; i < h.counts.size(); ++i) {
      if(h.counts[i] == 0) continue;
      const double lo = double(i * h.bin_degrees), hi = lo + h.bin_degrees, percent = 100. * h.counts[i] / total;
      svg << "<rect x=\"" << x_of(lo + 0.1 * h.bin_degrees) << "\" y=\"" << fixed(y_of(percent), 2) << "\" width=\""
          << fixed(0.8 * h.bin_degrees * plot_w / 180., 2) << "\" height=\"" << fixed(base - y_of(percent), 2)
          << "\"><title>" << (lo == 90. ? "(" : "[") << lo << ", " << hi << (hi == 90. || hi == 180. ? "]" : ")")
          << ": " << fixed(percent, 3) << "% (" << h.counts[i] << ")</title></rect>\n";
    }
    svg << "</g>\n<rect x=\"" << left << "\" y=\"" << y0 << "\" width=\"" << plot_w << "\" height=\"" << plot_h
        << "\" fill=\"none\" stroke=\"#333\"/>\n";
    for(int d = 0; d <= 180; d += 10)
      svg << "<line x1=\"" << x_of(d) << "\" x2=\"" << x_of(d) << "\" y1=\"" << base << "\" y2=\"" << base + (d % 30 ? 4 : 7)
          << "\" stroke=\"#333\"/>\n<text x=\"" << x_of(d) << "\" y=\"" << base + 19 << "\" text-anchor=\"middle\">" << d
          << "</text>\n";
    svg << "<text x=\"" << x_of(90) << "\" y=\"" << base + 35 << "\" text-anchor=\"middle\">angle (degrees)</text>\n</g>\n";
  }
  svg << "</svg>\n";
  write_text_atomically(path, svg.str());
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Writes the angle histograms of `input` and `output` (2 degree bins) to
/// `path` as `write_angle_histogram_svg()` above, the input's panel on top.
template <typename TriangleMesh>
void write_angle_histogram_svg(const std::string& path, const TriangleMesh& input, const TriangleMesh& output,
                               const std::string& input_name = "input", const std::string& output_name = "output")
{
  write_angle_histogram_svg(path, {angle_histogram(input, input_name), angle_histogram(output, output_name)});
}

/// \ingroup PkgNonobtuseRemeshingRef
/// The colormap of `write_mesh_colored_by_angle_atomically()`, as RGB: the
/// smallest angle over [30, 60] or the largest over [60, 90] (clamped) is
/// mapped from the equilateral 60 degrees, blue (0, 0, 255), through cyan,
/// green (at 45 or 75) and yellow to the bound, red (255, 0, 0), linearly
/// between these five colours.
inline std::array<unsigned char, 3> angle_color(double degrees, Angle_coloring what)
{
  const double t = (std::max)(0., (std::min)(1., (what == Angle_coloring::smallest_angle ? 60. - degrees
                                                                                         : degrees - 60.) / 30.));
  auto channel = [](double v) { return (unsigned char)(std::lround(255. * (std::max)(0., (std::min)(1., v)))); };
  return {channel(4. * t - 2.), channel(t < 0.75 ? 4. * t : 4. - 4. * t), channel(2. - 4. * t)};
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Colour of the faces that `angle_color()` does not colour: degenerate, or
/// with a corner proven below 30 (smallest angle) or above 90 (largest angle).
constexpr std::array<unsigned char, 3> out_of_bounds_color{{255, 0, 255}};

/// \ingroup PkgNonobtuseRemeshingRef
/// Writes the triangle mesh `mesh` (double coordinates) to `path` as an ASCII
/// PLY with max_digits10 digits and a colour per face (`property uchar red,
/// green, blue` on `element face`, as MeshLab reads it) by `angle_color()` of
/// its smallest or largest angle, faces in the order of `faces(mesh)`. The
/// file reads back to the same coordinates and certifies as `mesh` does.
/// Written atomically; `check`, if given, sees the temporary file before the
/// rename and may reject it, as in `write_mesh_atomically()`. Throws
/// `Output_error` with a one-line message on failure.
template <typename TriangleMesh>
void write_mesh_colored_by_angle_atomically(const std::string& path, const TriangleMesh& mesh, Angle_coloring what,
                                            const std::function<bool(const std::string&)>& check = nullptr)
{
  const bool smallest = (what == Angle_coloring::smallest_angle);
  std::ostringstream faces_out, vertices_out;
  faces_out.imbue(std::locale::classic());
  vertices_out.imbue(std::locale::classic());
  vertices_out.precision(std::numeric_limits<double>::max_digits10);
  std::unordered_map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, std::size_t> index;
  const auto vpm = get(CGAL::vertex_point, mesh);
  for(auto v : vertices(mesh)) {
    const auto& p = get(vpm, v);
    static_assert(std::is_same<typename std::decay<decltype(p.x())>::type, double>::value,
                  "the coloured PLY keeps double coordinates exactly");
    index.emplace(v, index.size());
    vertices_out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  internal::for_each_triangle(mesh, [&](auto face, const auto& a, const auto& b, const auto& c) {
    std::array<double, 3> angles;
    const internal::Triangle_verdict verdict = internal::shown_angles(a, b, c, angles);
    bool out = verdict.degenerate;
    for(int i = 0; i < 3 && !out; ++i) out = smallest ? verdict.corners[i].too_small : verdict.corners[i].too_large;
    const auto color = out ? out_of_bounds_color
                           : angle_color(smallest ? *std::min_element(angles.begin(), angles.end())
                                                  : *std::max_element(angles.begin(), angles.end()), what);
    const auto h = halfedge(face, mesh);
    faces_out << "3 " << index.at(source(h, mesh)) << ' ' << index.at(target(h, mesh)) << ' '
              << index.at(target(next(h, mesh), mesh)) << ' ' << int(color[0]) << ' ' << int(color[1]) << ' '
              << int(color[2]) << '\n';
  });
  std::ostringstream ply;
  ply << "ply\nformat ascii 1.0\ncomment face colour by " << (smallest ? "smallest angle: blue 60, green 45, red 30"
                                                                       : "largest angle: blue 60, green 75, red 90")
      << " degrees, magenta out of [30, 90] or degenerate\nelement vertex " << vertices(mesh).size()
      << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << faces(mesh).size()
      << "\nproperty list uchar int vertex_indices\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "end_header\n" << vertices_out.str() << faces_out.str();
  write_text_atomically(path, ply.str(), check);
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_ANGLE_PICTURES_H
