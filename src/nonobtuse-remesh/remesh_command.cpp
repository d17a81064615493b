// nonobtuse-remesh remesh INPUT -o OUTPUT [--resolution N] [--stop-after init]
//                  [--signs patches|inside-test] [--json FILE]

#include "cli.h"
#include "json_output.h"

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>
#include <CGAL/Nonobtuse_remeshing/quality_report.h>

#include <fstream>
#include <iomanip>
#include <iostream>

namespace nonobtuse_cli {

namespace NR = CGAL::Nonobtuse_remeshing;

namespace {

json initial_mesh_json(const NR::Marching_cubes_result& r)
{
  return {{"resolution", r.resolution},
          {"cube_size", r.cube_size},
          {"input_triangles", r.input_triangles},
          {"degenerate_input_triangles", r.degenerate_input_triangles},
          {"cubes_intersected", r.cubes_intersected},
          {"cubes_with_several_patches", r.cubes_with_several_patches},
          {"patches", r.patches},
          {"patches_ignored", r.patches_ignored},
          {"cube_faces_stitched", r.faces_stitched},
          {"welds_refused", r.welds_refused},
          {"non_manifold_faces_removed", r.non_manifold_faces_removed},
          {"islands_removed", r.islands_removed},
          {"vertices_out", r.vertices_out},
          {"triangles_out", r.triangles_out},
          {"borders_out", r.borders_out},
          {"components_out", r.components_out},
          {"valence_range", {r.min_valence, r.max_valence}},
          {"angle_range", {r.min_angle, r.max_angle}},
          {"seconds", r.seconds}};
}

void print_initial_mesh(std::ostream& out, const NR::Marching_cubes_result& r)
{
  out << std::setprecision(6) << "init (nonobtuse Marching Cubes, N = " << r.resolution
      << ", cube size " << r.cube_size << "):\n"
      << "  triangles out " << r.triangles_out << ", vertices out " << r.vertices_out << ", borders out "
      << r.borders_out << ", components out " << r.components_out << "\n"
      << "  cubes intersected " << r.cubes_intersected << ", with several patches "
      << r.cubes_with_several_patches << ", patches " << r.patches << ", ignored " << r.patches_ignored
      << "\n"
      << "  cube faces stitched " << r.faces_stitched << ", welds refused " << r.welds_refused
      << ", non-manifold faces removed " << r.non_manifold_faces_removed << ", islands removed "
      << r.islands_removed << "\n"
      << "  valence range [" << r.min_valence << ", " << r.max_valence << "], angle range ["
      << std::setprecision(10) << r.min_angle << ", " << r.max_angle << "], " << std::setprecision(3)
      << r.seconds << " s\n";
  if(r.degenerate_input_triangles > 0)
    out << "  note: " << r.degenerate_input_triangles << " degenerate input triangle(s) ignored\n";
}

} // namespace

int remesh_command(int argc, char** argv)
{
  std::string input_path, output_path, json_path, stop_after = "init", signs = "patches";
  int resolution = 100;
  po::options_description options("options");
  options.add_options()
    ("help,h", "show this help")
    ("input", po::value<std::string>(&input_path)->required(), "the mesh to remesh")
    ("output,o", po::value<std::string>(&output_path)->required(),
     "where to write the result (.off, .obj, .ply, .stl)")
    ("resolution,N", po::value<int>(&resolution)->default_value(100),
     "Marching Cubes cubes along the longest side of the input's bounding box")
    ("stop-after", po::value<std::string>(&stop_after)->default_value("init"),
     "last stage to run: init (the only stage so far)")
    ("signs", po::value<std::string>(&signs)->default_value("patches"),
     "corner signs: patches (open inputs too) or inside-test (closed inputs)")
    ("json", po::value<std::string>(&json_path), "also write statistics and the quality report as JSON");
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map vm;
  int exit_code = success;
  if(!parse_options("remesh", "INPUT -o OUTPUT [--resolution N] [--stop-after init] [options]\n\n"
                    "Remeshes INPUT into a mesh whose angles all lie in [30, 90] degrees, certified\n"
                    "exactly on the written file. Stages: init (nonobtuse Marching Cubes).",
                    options, positional, argc, argv, vm, exit_code))
    return exit_code;

  return run_guarded("remesh", [&]() {
    if(stop_after != "init")
      throw std::invalid_argument("--stop-after must be one of: init (got '" + stop_after + "')");
    if(signs != "patches" && signs != "inside-test")
      throw std::invalid_argument("--signs must be patches or inside-test (got '" + signs + "')");
    if(resolution < 1 || resolution > 1024)
      throw std::invalid_argument("--resolution must be between 1 and 1024");
    check_output_path(output_path, {input_path});
    if(!NR::internal::is_mesh_extension(NR::internal::file_extension(output_path)))
      throw NR::Output_error("cannot write '" + output_path + "': unsupported extension (expected .off, .obj, .ply or .stl)");
    if(!json_path.empty()) check_output_path(json_path, {input_path, output_path});

    const Mesh input = load_mesh(input_path);
    const NR::Sign_source source = signs == "patches" ? NR::Sign_source::patches : NR::Sign_source::inside_test;
    if(source == NR::Sign_source::inside_test && !CGAL::is_closed(input))
      throw NR::Bad_input("--signs inside-test needs a closed input, and '" + input_path + "' has borders");
    Mesh output;
    NR::Marching_cubes_result init;
    try {
      init = NR::nonobtuse_marching_cubes(input, output,
                                          NR::parameters::combine(NR::parameters::resolution(resolution),
                                                                  NR::parameters::sign_source(source)));
    } catch(const std::invalid_argument& e) {  // the arguments were checked: it is the input
      throw NR::Bad_input("'" + input_path + "': " + e.what());
    }
    if(num_faces(output) == 0)
      throw NR::Bad_input("'" + input_path + "' is too small or too thin for resolution " +
                          std::to_string(resolution) + ": the initial mesh is empty");
    print_initial_mesh(std::cout, init);

    // The file itself must certify: it is re-read and certified before it
    // replaces anything.
    std::size_t written_faces = 0;
    bool written_certified = false;
    try {
      NR::write_mesh_atomically(output_path, output, [&](const std::string& temporary) {
        Mesh reread;
        NR::read_triangle_mesh(temporary, reread);
        const auto certificate = NR::certify_angle_bounds(reread);
        written_faces = certificate.faces;
        written_certified = certificate.is_certified() && written_faces == num_faces(output);
        return written_certified;
      });
    } catch(const NR::Output_error& e) {
      if(written_faces > 0 && !written_certified) {
        std::cerr << "nonobtuse-remesh remesh: certification of the written file failed; nothing written\n";
        return int(certification_failed);
      }
      throw;
    }
    std::cout << "wrote " << output_path << ": " << written_faces
              << " faces, certified in [30, 90] degrees on the written file\n";

    if(!json_path.empty()) {
      const NR::Quality_report report = NR::quality_report(output, &input);
      json j;
      j["input"] = input_path;
      j["output"] = output_path;
      j["init"] = initial_mesh_json(init);
      j["output_report"] = report_to_json(output_path, report, {});
      write_json_atomically(json_path, j);
    }
    return int(success);
  });
}

} // namespace nonobtuse_cli
