// nonobtuse-remesh remesh INPUT -o OUTPUT [--resolution N] [--stop-after init|valence|fit]
//                  [--signs patches|inside-test] [fit options] [--lod R,R...] [--json FILE]

#include "cli.h"
#include "decimation_cli.h"
#include "json_output.h"

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/deform_to_fit.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>
#include <CGAL/Nonobtuse_remeshing/quality_report.h>
#include <CGAL/Nonobtuse_remeshing/remove_bad_valence_vertices.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <unistd.h>

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

json valence_counts_json(const NR::Valence_counts& c)
{
  return {{"v2", c.valence_2},
          {"v3", c.valence_3()},
          {"v3_border", c.border_valence_3},
          {"v3_interior", c.interior_valence_3},
          {"int_v4", c.interior_valence_4},
          {"int_above_11", c.interior_valence_above_11},
          {"total", c.total()}};
}

json valence_json(const NR::Bad_valence_removal_statistics& s)
{
  return {{"before", valence_counts_json(s.before)},
          {"after", valence_counts_json(s.after)},
          {"vertices_before", s.vertices_before},
          {"vertices_after", s.vertices_after},
          {"border_valence_2_discarded", s.border_valence_2_discarded},
          {"interior_valence_3_discarded", s.interior_valence_3_discarded},
          {"interior_valence_4_discarded", s.interior_valence_4_discarded},
          {"interior_valence_4_collapsed", s.interior_valence_4_collapsed},
          {"border_valence_3_discarded", s.border_valence_3_discarded},
          {"border_valence_3_collapsed", s.border_valence_3_collapsed},
          {"border_teeth_removed", s.border_teeth_removed},
          {"splits", s.splits},
          {"refused_by_certification", s.refused},
          {"rounds", s.rounds},
          {"seconds", s.seconds}};
}

void print_valence(std::ostream& out, const NR::Bad_valence_removal_statistics& s)
{
  auto counts = [](const NR::Valence_counts& c) {
    return "v2 " + std::to_string(c.valence_2) + ", v3 " + std::to_string(c.valence_3()) + " (border " +
           std::to_string(c.border_valence_3) + "), int-v4 " + std::to_string(c.interior_valence_4) +
           ", int-v12+ " + std::to_string(c.interior_valence_above_11);
  };
  out << std::setprecision(3) << "valence (bad-valence removal and vertex split, " << s.vertices_before << " -> "
      << s.vertices_after << " vertices):\n"
      << "  before: " << counts(s.before) << "\n"
      << "  after:  " << counts(s.after) << "\n"
      << "  discarded: border v2 " << s.border_valence_2_discarded << ", interior v3 "
      << s.interior_valence_3_discarded << ", interior v4 " << s.interior_valence_4_discarded << ", border v3 "
      << s.border_valence_3_discarded << "; collapsed: interior v4 " << s.interior_valence_4_collapsed
      << ", border v3 " << s.border_valence_3_collapsed << "; border teeth " << s.border_teeth_removed
      << "; splits " << s.splits << "\n"
      << "  refused by the exact certification " << s.refused << ", rounds " << s.rounds << ", " << s.seconds
      << " s\n";
}

json fit_json(const NR::Deform_to_fit_statistics& s)
{
  return {{"vertices", s.vertices},
          {"feature_samples", s.feature_samples},
          {"moves", s.moves},
          {"smoothing_moves", s.smoothing_moves},
          {"qp_solves", s.qp_solves},
          {"qp_fallbacks", s.qp_fallbacks},
          {"infeasible_regions", s.infeasible_regions},
          {"shortened_moves", s.shortened_moves},
          {"rejected_moves", s.rejected_moves},
          {"undone_moves", s.undone_moves},
          {"full_updates", s.full_updates},
          {"smoothing_passes", s.smoothing_passes},
          {"intersecting_pairs_found", s.intersecting_pairs_found},
          {"untangling_moves", s.untangling_moves},
          {"intersecting_pairs", s.intersecting_pairs},
          {"rms_vertex_distance_percent", s.rms_distance},
          {"budget_exhausted", s.budget_exhausted},
          {"optimization_seconds", s.optimization_seconds},
          {"smoothing_seconds", s.smoothing_seconds},
          {"untangling_seconds", s.untangling_seconds},
          {"seconds", s.seconds}};
}

void print_fit(std::ostream& out, const NR::Deform_to_fit_statistics& s)
{
  out << std::setprecision(4) << "fit (deform-to-fit, " << s.vertices << " vertices, " << s.feature_samples
      << " feature samples):\n"
      << "  moves " << s.moves << " (smoothing " << s.smoothing_moves << "), QP solves " << s.qp_solves
      << ", fallbacks to CGAL's QP solver " << s.qp_fallbacks << ", empty regions " << s.infeasible_regions << "\n"
      << "  shortened moves " << s.shortened_moves << ", rejected " << s.rejected_moves << ", undone "
      << s.undone_moves << ", full updates " << s.full_updates << ", smoothing passes " << s.smoothing_passes
      << "\n"
      << "  self-intersecting face pairs " << s.intersecting_pairs_found << " after the fit, "
      << s.intersecting_pairs << " after " << s.untangling_moves << " untangling moves\n"
      << "  rms vertex distance " << s.rms_distance << "% of the diagonal, optimization "
      << s.optimization_seconds << " s, smoothing " << s.smoothing_seconds << " s, untangling "
      << s.untangling_seconds << " s, total " << s.seconds << " s\n";
  if(s.budget_exhausted) out << "  note: the budget ran out before the fit converged\n";
}

// The fit's progress line.
struct Fit_progress
{
  Progress_line line;

  bool keep_going(const NR::Deform_to_fit_statistics& s)
  {
    std::ostringstream text;
    text << "fit: " << (s.stage == NR::Deform_to_fit_stage::smoothing ? "smoothing" : "optimization") << ", "
         << s.moves << " moves, rms vertex distance " << std::setprecision(3) << s.rms_distance << "%";
    line.show(text.str());
    return true;
  }
};

} // namespace

int remesh_command(int argc, char** argv)
{
  std::string input_path, output_path, json_path, stop_after = "fit", signs = "patches", lod;
  Decimation_settings decimation;
  int resolution = 100, drum_subdivisions = 2, quadric_rings = 0, smoothing_steps = 2;
  double alpha = 0.5, fit_tolerance = 1e-4, max_seconds = 0.;
  long long max_moves = 0;
  bool quiet = false;
  po::options_description options("options");
  options.add_options()
    ("help,h", "show this help")
    ("input", po::value<std::string>(&input_path)->required(), "the mesh to remesh")
    ("output,o", po::value<std::string>(&output_path)->required(),
     "where to write the result (.off, .obj, .ply, .stl)")
    ("resolution,N", po::value<int>(&resolution)->default_value(100),
     "Marching Cubes cubes along the longest side of the input's bounding box")
    ("stop-after", po::value<std::string>(&stop_after)->default_value("fit"),
     "last stage to run: init, valence or fit")
    ("no-valence-cleanup", "skip the removal of bad-valence vertices between init and fit")
    ("no-vertex-split", "valence: removal only, as in the thesis (no vertex splits)")
    ("signs", po::value<std::string>(&signs)->default_value("patches"),
     "corner signs: patches (open inputs too) or inside-test (closed inputs)")
    ("alpha", po::value<double>(&alpha)->default_value(0.5), "fit: weight of the distance term, in [0, 1]")
    ("drum-subdivisions,k", po::value<int>(&drum_subdivisions)->default_value(2),
     "fit: drum planes per side in the feasible regions, in [1, 16]")
    ("quadric-rings,r", po::value<int>(&quadric_rings)->default_value(0),
     "fit: rings of input triangles around the closest one in the distance quadric, in [0, 4]")
    ("smoothing-steps", po::value<int>(&smoothing_steps)->default_value(2),
     "fit: constrained Laplacian smoothing passes between optimizations")
    ("fit-tolerance", po::value<double>(&fit_tolerance)->default_value(1e-4),
     "fit: stop when no move improves the cost by (tolerance * diagonal)^2")
    ("max-moves", po::value<long long>(&max_moves), "fit: budget in moves (default: none)")
    ("max-seconds", po::value<double>(&max_seconds), "fit: budget in seconds (default: none)")
    ("no-lazy-evaluation", "fit: re-evaluate the neighbours of a moved vertex at once")
    ("no-early-smoothing", "fit: complete each optimization phase before smoothing")
    ("no-tangential-smoothing", "fit: smoothing term in every direction, as in the thesis")
    ("no-feature-attraction", "fit: no attraction of the input's vertices and sharp edges")
    ("quiet,q", po::bool_switch(&quiet), "no progress line")
    ("lod", po::value<std::string>(&lod),
     "levels of detail: decreasing fractions of the vertices to keep, like 0.5,0.1; level i is written "
     "next to OUTPUT as NAME_lodi.EXT")
    ("json", po::value<std::string>(&json_path), "also write statistics and the quality report as JSON");
  decimation.add_options(options);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map vm;
  int exit_code = success;
  if(!parse_options("remesh", "INPUT -o OUTPUT [--resolution N] [--stop-after init|valence|fit] [options]\n\n"
                    "Remeshes INPUT into a mesh whose angles all lie in [30, 90] degrees, certified\n"
                    "exactly on the written file. Stages: init (nonobtuse Marching Cubes), valence\n"
                    "(removal of bad-valence vertices, vertex splits), fit (deform-to-fit with\n"
                    "constrained Laplacian smoothing); then, with --lod, levels of detail by\n"
                    "angle-bounded decimation, each certified on its written file.",
                    options, positional, argc, argv, vm, exit_code))
    return exit_code;

  return run_guarded("remesh", [&]() {
    if(stop_after != "init" && stop_after != "valence" && stop_after != "fit")
      throw std::invalid_argument("--stop-after must be one of: init, valence, fit (got '" + stop_after + "')");
    const bool valence_cleanup = vm.count("no-valence-cleanup") == 0;
    if(stop_after == "valence" && !valence_cleanup)
      throw std::invalid_argument("--stop-after valence contradicts --no-valence-cleanup");
    if(!(alpha >= 0. && alpha <= 1.)) throw std::invalid_argument("--alpha must lie in [0, 1]");
    if(drum_subdivisions < 1 || drum_subdivisions > 16)
      throw std::invalid_argument("--drum-subdivisions must lie in [1, 16]");
    if(quadric_rings < 0 || quadric_rings > 4) throw std::invalid_argument("--quadric-rings must lie in [0, 4]");
    if(smoothing_steps < 0 || smoothing_steps > 100)
      throw std::invalid_argument("--smoothing-steps must lie in [0, 100]");
    if(!(fit_tolerance > 0. && fit_tolerance < 1.)) throw std::invalid_argument("--fit-tolerance must lie in (0, 1)");
    if(vm.count("max-seconds") && !(max_seconds >= 0.)) throw std::invalid_argument("--max-seconds must be at least 0");
    if(vm.count("max-moves") && max_moves < 0) throw std::invalid_argument("--max-moves must be at least 0");
    if(signs != "patches" && signs != "inside-test")
      throw std::invalid_argument("--signs must be patches or inside-test (got '" + signs + "')");
    if(resolution < 1 || resolution > 1024)
      throw std::invalid_argument("--resolution must be between 1 and 1024");
    check_output_path(output_path, {input_path});
    if(!NR::internal::is_mesh_extension(NR::internal::file_extension(output_path)))
      throw NR::Output_error("cannot write '" + output_path + "': unsupported extension (expected .off, .obj, .ply or .stl)");
    if(!json_path.empty()) check_output_path(json_path, {input_path, output_path});
    decimation.check(vm);
    decimation.quiet = quiet;
    decimation.drum_subdivisions = drum_subdivisions;
    const std::vector<double> ratios = lod.empty() ? std::vector<double>() : parse_ratios(lod);
    if(!ratios.empty() && stop_after != "fit") throw std::invalid_argument("--lod needs the whole pipeline (no --stop-after)");
    for(std::size_t i = 1; i <= ratios.size(); ++i)
      check_output_path(level_path(output_path, i), {input_path, output_path, json_path});

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

    if(!NR::certify_angle_bounds(output).is_certified()) {  // cannot happen: chapter 4's guarantee
      std::cerr << "nonobtuse-remesh remesh: the initial mesh does not certify; nothing written\n";
      return int(certification_failed);
    }
    NR::Bad_valence_removal_statistics valence;
    if(stop_after != "init" && valence_cleanup) {
      valence = NR::remove_bad_valence_vertices(
          output, NR::parameters::combine(NR::parameters::vertex_split(vm.count("no-vertex-split") == 0),
                                          NR::parameters::drum_subdivisions(drum_subdivisions)));
      output.collect_garbage();
      print_valence(std::cout, valence);
    }

    NR::Deform_to_fit_statistics fit;
    if(stop_after == "fit") {
      Fit_progress progress;
      progress.line.quiet = quiet;
      fit = NR::deform_to_fit(
          output, input,
          NR::parameters::combine(
              NR::parameters::alpha(alpha), NR::parameters::drum_subdivisions(drum_subdivisions),
              NR::parameters::quadric_rings(quadric_rings), NR::parameters::smoothing_steps(smoothing_steps),
              NR::parameters::fit_tolerance(fit_tolerance),
              NR::parameters::max_moves(vm.count("max-moves") ? std::size_t(max_moves) : std::size_t(-1)),
              NR::parameters::max_seconds(vm.count("max-seconds") ? max_seconds : 1e300),
              NR::parameters::lazy_evaluation(vm.count("no-lazy-evaluation") == 0),
              NR::parameters::early_smoothing(vm.count("no-early-smoothing") == 0),
              NR::parameters::tangential_smoothing(vm.count("no-tangential-smoothing") == 0),
              NR::parameters::attract_features(vm.count("no-feature-attraction") == 0),
              NR::parameters::fit_visitor(std::ref(progress))));
      progress.line.done();
      print_fit(std::cout, fit);
    }

    // The file itself must certify: it is re-read and certified before it
    // replaces anything.
    std::size_t written_faces = 0;
    if(!write_certified(output_path, output, written_faces)) {
      std::cerr << "nonobtuse-remesh remesh: certification of the written file failed; nothing written\n";
      return int(certification_failed);
    }
    std::cout << "wrote " << output_path << ": " << written_faces
              << " faces, certified in [30, 90] degrees on the written file\n";

    // Levels of detail: one decimation of the output, each level certified
    // on its written file and measured against the full-resolution mesh.
    json levels_json = json::array();
    if(!ratios.empty()) {
      const auto levels = decimation_levels(output, ratios, decimation);
      for(std::size_t i = 0; i < levels.size(); ++i) {
        const auto& level = levels[i];
        const std::string path = level_path(output_path, i + 1);
        print_decimation(std::cout, level.statistics);
        std::size_t faces = 0;
        if(!write_certified(path, level.mesh, faces)) {
          std::cerr << "nonobtuse-remesh remesh: certification of the written level " << path
                    << " failed; it is not written\n";
          return int(certification_failed);
        }
        const NR::Quality_report report = NR::quality_report(level.mesh, &output);
        std::cout << "wrote level " << i + 1 << " " << path << ": " << vertices(level.mesh).size() << " vertices ("
                  << "target " << level.target_vertices << "), " << faces
                  << " faces, certified in [30, 90] degrees on the written file; Hausdorff distance to the "
                     "full-resolution mesh "
                  << std::setprecision(4) << report.distance->hausdorff_symmetric << "% of its diagonal\n";
        if(!level.reached)
          std::cout << "note: level " << i + 1 << " did not reach its target: "
                    << stop_reason_name(level.statistics.stop_reason) << "; the levels after it are not written\n";
        json l;
        l["ratio"] = ratios[i];
        l["output"] = path;
        l["reached"] = level.reached;
        l["decimation"] = decimation_json(level.statistics);
        l["report_against_full_resolution"] = report_to_json(path, report, {});
        levels_json.push_back(l);
      }
    }

    if(!json_path.empty()) {
      const NR::Quality_report report = NR::quality_report(output, &input);
      json j;
      j["input"] = input_path;
      j["output"] = output_path;
      j["init"] = initial_mesh_json(init);
      if(stop_after != "init" && valence_cleanup) j["valence"] = valence_json(valence);
      if(stop_after == "fit") j["fit"] = fit_json(fit);
      j["output_report"] = report_to_json(output_path, report, {});
      if(!ratios.empty()) j["levels"] = levels_json;
      write_json_atomically(json_path, j);
    }
    return int(success);
  });
}

} // namespace nonobtuse_cli
