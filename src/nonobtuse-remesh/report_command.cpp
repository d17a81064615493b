// SPDX-License-Identifier: GPL-3.0-or-later
//
// nonobtuse-remesh report MESH [--reference INPUT] [--json FILE]

#include "cli.h"
#include "json_output.h"

#include <CGAL/Nonobtuse_remeshing/mesh_io.h>
#include <CGAL/Nonobtuse_remeshing/quality_report.h>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace nonobtuse_cli {

namespace NR = CGAL::Nonobtuse_remeshing;

namespace {

void print_valences(std::ostream& out, const char* label,
                    const std::map<std::size_t, std::size_t>& valences)
{
  out << label << ":";
  if(valences.empty()) out << " none";
  for(const auto& entry : valences) out << " " << entry.first << ":" << entry.second;
  out << "\n";
}

void print_report(std::ostream& out, const std::string& path, const NR::Quality_report& r)
{
  out << std::setprecision(10) << "mesh: " << path << "\n"
      << "vertices: " << r.vertices << "  edges: " << r.edges << "  faces: " << r.faces << "\n"
      << "angles: ";
  if(r.has_angles) out << "min " << r.min_angle << "  max " << r.max_angle << "\n";
  else out << "n/a (every face is degenerate)\n";
  out << "certified in [" << r.min_bound << ", " << r.max_bound << "]: "
      << (r.certified ? "yes" : "no") << " (corners below: " << r.too_small_corners
      << ", above: " << r.too_large_corners << ", degenerate faces: " << r.degenerate_faces << ")\n"
      << "angle histogram (5 degree bins from 0; a right angle counts in [85, 90]):";
  for(std::size_t count : r.angle_histogram) out << " " << count;
  out << "\n";
  print_valences(out, "interior valences", r.interior_valences);
  print_valences(out, "boundary valences", r.boundary_valences);
  out << "border cycles: " << r.border_cycles << "  components: " << r.connected_components
      << "  Euler characteristic: " << r.euler_characteristic
      << "  non-manifold vertices: " << r.non_manifold_vertices << "\n"
      << "self-intersecting face pairs: " << r.self_intersections
      << (r.self_intersections_capped ? " (capped)" : "") << "\n";
  if(r.distance) {
    const NR::Distance_report& d = *r.distance;
    out << "distance to reference (% of its bbox diagonal " << d.reference_diagonal << "):\n"
        << "  Hausdorff mesh->reference " << d.hausdorff_to_reference << ", reference->mesh "
        << d.hausdorff_from_reference << ", symmetric " << d.hausdorff_symmetric << " (+/- "
        << d.hausdorff_error_bound << ")\n"
        << "  mean mesh->reference " << d.mean_to_reference << ", reference->mesh "
        << d.mean_from_reference << "\n";
  }
}

} // namespace

int report_command(int argc, char** argv)
{
  std::string path, reference_path, json_path;
  double min_angle = 30., max_angle = 90., hausdorff_error = 1e-4;
  std::size_t max_self_intersections = 1000;
  po::options_description options("options");
  options.add_options()
    ("help,h", "show this help")
    ("mesh", po::value<std::string>(&path)->required(), "the mesh to report on")
    ("reference", po::value<std::string>(&reference_path), "reference mesh for the distances")
    ("json", po::value<std::string>(&json_path), "also write the report as JSON to this file")
    ("min-angle", po::value<double>(&min_angle)->default_value(30.), "lower angle bound, degrees")
    ("max-angle", po::value<double>(&max_angle)->default_value(90.), "upper angle bound, degrees")
    ("hausdorff-error", po::value<double>(&hausdorff_error)->default_value(1e-4),
     "Hausdorff error bound, as a fraction of the reference's bbox diagonal")
    ("max-self-intersections", po::value<std::size_t>(&max_self_intersections)->default_value(1000),
     "stop counting self-intersecting face pairs there (at least 1)");
  po::positional_options_description positional;
  positional.add("mesh", 1);
  po::variables_map vm;
  int exit_code = success;
  if(!parse_options("report", "MESH [--reference INPUT] [--json FILE] [options]\n\n"
                    "Quality report of MESH: exact angle certification, angle histogram,\n"
                    "valences, borders, components, defects, and distances to a reference.",
                    options, positional, argc, argv, vm, exit_code))
    return exit_code;

  return run_guarded("report", [&]() {
    const NR::Angle_bounds bounds(min_angle, max_angle);
    check_paths({{"MESH", path}, {"--reference", reference_path}}, {{"--json", json_path}});

    NR::Read_log log;
    const Mesh mesh = load_mesh(path, &log);
    Mesh reference;
    if(!reference_path.empty()) {
      reference = load_mesh(reference_path);
      if(!(NR::internal::bbox_diagonal(reference) > 0.))
        throw NR::Bad_input("the reference '" + reference_path + "' has a zero-size bounding box");
    }

    NR::Quality_report r = NR::quality_report(
        mesh, reference_path.empty() ? nullptr : &reference,
        NR::parameters::combine(NR::parameters::min_angle(bounds.min_degrees()),
                                NR::parameters::max_angle(bounds.max_degrees()),
                                NR::parameters::hausdorff_relative_error(hausdorff_error),
                                NR::parameters::maximum_self_intersections(max_self_intersections)));
    // the certificate is about the file as written: a face the reader had to
    // triangulate, drop or merge is not certified by the mesh's certificate
    if(!log.faces_as_written()) {
      r.certified = false;
      std::cout << "note: '" << path << "' is not certified as written: it has " << log.faces_changed() << "\n";
    }
    print_report(std::cout, path, r);
    if(!json_path.empty()) write_json_atomically(json_path, report_to_json(path, r, log.repairs));
    return int(success);
  });
}

} // namespace nonobtuse_cli
