// SPDX-License-Identifier: GPL-3.0-or-later
//
// nonobtuse-remesh certify MESH [--min-angle 30] [--max-angle 90]

#include "cli.h"

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace nonobtuse_cli {

namespace NR = CGAL::Nonobtuse_remeshing;

int certify_command(int argc, char** argv)
{
  std::string path;
  double min_angle = 30., max_angle = 90.;
  po::options_description options("options");
  options.add_options()
    ("help,h", "show this help")
    ("mesh", po::value<std::string>(&path)->required(), "the mesh to certify (.off, .obj, .ply, .stl)")
    ("min-angle", po::value<double>(&min_angle)->default_value(30.), "lower angle bound, degrees")
    ("max-angle", po::value<double>(&max_angle)->default_value(90.), "upper angle bound, degrees");
  po::positional_options_description positional;
  positional.add("mesh", 1);
  po::variables_map vm;
  int exit_code = success;
  if(!parse_options("certify", "MESH [--min-angle DEG] [--max-angle DEG]\n\n"
                    "Decides exactly, from the stored coordinates, whether every angle of MESH\n"
                    "lies in [min, max]. Exit 0 if certified, 1 if not. The file is judged as\n"
                    "written: a face that is not a triangle, repeats a vertex or repeats another\n"
                    "face makes it not certified.",
                    options, positional, argc, argv, vm, exit_code))
    return exit_code;

  return run_guarded("certify", [&]() {
    const NR::Angle_bounds bounds(min_angle, max_angle);  // validates before reading
    NR::Read_log log;
    const Mesh mesh = load_mesh(path, &log);
    const auto c = NR::certify_angle_bounds(
        mesh, NR::parameters::combine(NR::parameters::min_angle(bounds.min_degrees()),
                                      NR::parameters::max_angle(bounds.max_degrees())));
    std::cout << std::setprecision(std::numeric_limits<double>::max_digits10)
              << "mesh: " << path << "\n"
              << "bounds: [" << c.min_bound << ", " << c.max_bound << "] degrees, "
              << (c.bounds_exact ? "tested exactly"
                                 : "tested exactly against a cosine tightened by 1e-12")
              << "\n"
              << "faces: " << c.faces << "\n"
              << "corners below " << c.min_bound << ": " << c.too_small_corners << "\n"
              << "corners above " << c.max_bound << ": " << c.too_large_corners << "\n"
              << "degenerate faces: " << c.degenerate_faces << "\n"
              << std::setprecision(10);
    if(c.has_angles())
      std::cout << "min angle: " << c.min_angle << "\n"
                << "max angle: " << c.max_angle << "\n";
    else
      std::cout << "min angle: n/a (every face is degenerate)\n"
                << "max angle: n/a\n";
    if(!c.offending_faces.empty()) {
      std::cout << "offending faces (" << c.offending_faces.size() << "):";
      const std::size_t shown = (std::min<std::size_t>)(10, c.offending_faces.size());
      for(std::size_t i = 0; i < shown; ++i) std::cout << " " << std::size_t(c.offending_faces[i]);
      std::cout << (shown < c.offending_faces.size() ? " ..." : "") << "\n";
    }
    // The certificate is about the file as written: a face that is not a
    // triangle, repeats a vertex or repeats another face is not certified by
    // what the reader made of it.
    const bool as_written = log.faces_as_written();
    if(!as_written)
      std::cout << "faces in the file: " << log.faces_in_file << ", not read as written: " << log.faces_changed()
                << "\n";
    const bool certified = c.is_certified() && as_written;
    std::cout << "certified: " << (certified ? "yes" : "no");
    if(c.is_certified() && !as_written) std::cout << " (the file's faces are not all triangles as written)";
    std::cout << "\n";
    return certified ? int(success) : int(certification_failed);
  });
}

} // namespace nonobtuse_cli
