// SPDX-License-Identifier: GPL-3.0-or-later
//
// nonobtuse-remesh remesh INPUT -o OUTPUT [--resolution N | --target-vertices V | --max-distance PCT]
//                  [--topology keep|ignore] [--max-resolution N]
//                  [--stop-after init|valence|fit|decimation] [--signs auto|patches|winding-number|inside-test] [stage options]
//                  [--lod R,R...] [--report FILE.json] [--angle-histogram FILE.svg]
//                  [--color-by-angle smallest|largest]

#include "cli.h"
#include "decimation_cli.h"
#include "json_output.h"
#include "statistics_output.h"

#include <CGAL/Nonobtuse_remeshing/angle_pictures.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_remesh.h>
#include <CGAL/Nonobtuse_remeshing/quality_report.h>

#include <chrono>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>


namespace nonobtuse_cli {

namespace NR = CGAL::Nonobtuse_remeshing;

namespace {

void print_initial_mesh(std::ostream& out, const NR::Marching_cubes_result& r)
{
  print_fields(out, std::string("init (") + NR::stage_description(NR::Remeshing_stage::initial_mesh) + ")", r);
  if(r.degenerate_input_triangles > 0)
    out << "  note: " << r.degenerate_input_triangles << " degenerate input triangle(s) ignored\n";
}

void print_valence(std::ostream& out, const NR::Bad_valence_removal_statistics& s)
{
  print_fields(out, std::string("valence (") + NR::stage_description(NR::Remeshing_stage::valence) + ")", s);
}

void print_fit(std::ostream& out, const NR::Deform_to_fit_statistics& s)
{
  print_fields(out, std::string("fit (") + NR::stage_description(NR::Remeshing_stage::fit) + ")", s);
  if(s.budget_exhausted) out << "  note: the budget ran out before the fit converged\n";
}

// What the refinement for the topology did, and whether the topology matched.
void print_topology(std::ostream& out, const NR::Nonobtuse_remeshing_statistics& s)
{
  const NR::Topology_comparison& t = s.topology;
  if(s.refinements > 0)
    out << "topology: refined the initial mesh " << s.refinements << " time(s) from resolution "
        << s.budget_resolution << " (cap " << s.max_resolution << "); kept resolution " << s.resolution << "\n";
  if(s.target_vertices == 0 && s.decimation_target > 0)
    out << "topology: " << (s.decimation_run ? "after the fit, decimated back to the " : "not decimated back to the ")
        << s.decimation_target << " vertices of resolution " << s.budget_resolution << "'s initial mesh"
        << (s.decimation_run ? "" : " (the decimation stage did not run)") << "\n";
  if(t.matches)
    out << "topology: the input's, per input component (" << t.input_components << " component(s), "
        << t.input_border_cycles << " border(s)"
        << (t.crossing_groups > 0 ? ", " + std::to_string(t.crossing_groups) +
                                        " crossing group(s) compared without their Euler characteristic"
                                  : ", Euler characteristic " + std::to_string(t.input_euler_characteristic))
        << ")\n";
  else
    out << "topology: differs from the input's in " << t.groups_differing << " of " << t.input_groups
        << " input component group(s): " << t.difference
        << (s.keep_topology ? " (--max-resolution raises the cap of the refinement)"
                            : " (--topology keep, the default, refines the grid until it matches)")
        << "\n";
}

void print_decimation_stage(std::ostream& out, const NR::Angle_bounded_decimation_statistics& s, bool bounded)
{
  print_fields(out, std::string("decimation (") + NR::stage_description(NR::Remeshing_stage::decimation) + ")", s);
  if(bounded)
    out << "  the coarsest level within the distance bound: " << s.vertices_after << " of "
        << s.vertices_before << " vertices\n";
  else if(s.stop_reason != NR::Decimation_stop_reason::target_reached)
    out << "  note: the decimation stopped at " << s.vertices_after << " vertices, before the target "
        << s.target_vertices << ": " << NR::stop_reason_name(s.stop_reason)
        << (s.stop_reason == NR::Decimation_stop_reason::max_error
                ? " (its ceiling: one cube of the grid the target alone gives)"
                : s.stop_reason == NR::Decimation_stop_reason::cancelled ? "" : " (keeping the topology needs more)")
        << "\n";
}

// The columns of the thesis's tables, under its names.
// NM is counted on the output: the later stages keep it manifold.
json table_4_1_json(const NR::Quality_report& input, const NR::Quality_report& output,
                    const NR::Marching_cubes_result& r)
{
  return {{"caption", "initial mesh statistics (thesis, Table 4.1)"},
          {"triangles_in", input.faces},
          {"B_in", input.border_cycles},
          {"grid", r.resolution},
          {"triangles_out", r.triangles_out},
          {"B_out", r.borders_out},
          {"NM", output.non_manifold_vertices},
          {"non_manifold_faces_removed", r.non_manifold_faces_removed},
          {"MP", r.cubes_with_several_patches},
          {"SF", r.faces_stitched},
          {"PI", r.patches_ignored},
          {"VR", {r.min_valence, r.max_valence}},
          {"AR", {r.min_angle, r.max_angle}},
          {"t", r.seconds}};
}

json table_7_1_json(const NR::Bad_valence_removal_statistics& s)
{
  return {{"caption", "removal of bad-valence vertices (thesis, Table 7.1)"},
          {"V_in", s.vertices_before},
          {"V_out", s.vertices_after},
          {"v2", s.before.valence_2},
          {"v3", s.before.valence_3()},
          {"int_v4", s.before.interior_valence_4},
          {"v2*", s.after.valence_2},
          {"v3*", s.after.valence_3()},
          {"int_v4*", s.after.interior_valence_4}};
}

json table_7_2_json(const NR::Quality_report& input, const NR::Quality_report& output,
                    const NR::Deform_to_fit_statistics& s, bool lazy, bool early)
{
  return {{"caption", "optimization time and error (thesis, Table 7.2)"},
          {"triangles_in", input.faces},
          {"triangles_out", output.faces},
          {"lazy_evaluation", lazy},
          {"early_smoothing", early},
          {"t", s.seconds},
          {"epsilon_percent", output.distance ? json(output.distance->hausdorff_symmetric) : json(nullptr)}};
}

// One progress line per stage, "[i/n] stage ...": a bar where the stage's
// fraction is known, the fit's moves and distance where it is not.
struct Pipeline_progress
{
  Progress_line line;
  int stages = 3;
  int index = 0;

  std::string prefix() const { return "[" + std::to_string(index) + "/" + std::to_string(stages) + "] "; }
  void stage_started(NR::Remeshing_stage stage)
  {
    ++index;
    stages = (std::max)(stages, index);  // the decimation runs only over the target
    line.show(prefix() + NR::stage_name(stage) + " " + Progress_line::bar(0.), true);
  }
  void stage_finished(NR::Remeshing_stage stage, double seconds)
  {
    std::ostringstream text;
    text << prefix() << NR::stage_name(stage) << " " << Progress_line::bar(1.) << " done in " << std::setprecision(3)
         << seconds << " s";
    line.show(text.str(), true);
    line.done();
  }
  bool keep_going(const NR::Remeshing_progress& p)
  {
    if(p.fit) {
      std::ostringstream text;
      text << prefix() << "fit: " << (p.fit->stage == NR::Deform_to_fit_stage::smoothing ? "smoothing" : "optimization")
           << ", " << p.fit->moves << " moves, rms vertex distance " << std::setprecision(3) << p.fit->rms_distance
           << "%";
      line.show(text.str());
    } else if(p.decimation) {
      line.show(prefix() + "decimation: " + std::to_string(p.decimation->vertices_after) + " vertices, target " +
                std::to_string(p.decimation->target_vertices));
    }
    return true;
  }
};

} // namespace

int remesh_command(int argc, char** argv)
{
  std::string input_path, output_path, report_path, stop_after = "decimation", signs = "patches", lod, histogram_path,
      coloring_name, topology;
  Decimation_settings decimation;
  int resolution = 100, drum_subdivisions = 2, quadric_rings = 0, smoothing_steps = 2, max_resolution = 0;
  long long target_vertices = 0;
  double alpha = 0.5, fit_tolerance = 1e-4, max_seconds = 0., memory_limit = 4., oversampling = 1., max_distance = 0.;
  long long max_moves = 0;
  bool quiet = false;
  po::options_description options("options");
  options.add_options()
    ("help,h", "show this help")
    ("input", po::value<std::string>(&input_path)->required(), "the mesh to remesh")
    ("output,o", po::value<std::string>(&output_path)->required(),
     "where to write the result (.off, .obj, .ply, .stl)")
    ("resolution,N", po::value<int>(&resolution)->default_value(100),
     "Marching Cubes cubes along the longest side of the input's bounding box (the first grid: --topology "
     "keep refines it while the topology differs)")
    ("target-vertices,V", po::value<long long>(&target_vertices),
     "instead of --resolution: about this many output vertices (the resolution is chosen from the input's "
     "area and bounding box)")
    ("max-distance", po::value<double>(&max_distance),
     "instead of --resolution or --target-vertices: the fewest vertices (the decimation's coarsest level, "
     "levels 10% apart) whose symmetric Hausdorff distance to INPUT is at most PCT % of its bounding-box "
     "diagonal. The first grid's cube is 5 PCT (at least 16 cubes), refined while the fitted mesh is over "
     "0.8 PCT (up to --max-resolution, default 4 times the resolution of cubes of 1.25 PCT). The distance is measured on the written file (CGAL's bounded-error Hausdorff "
     "distance plus its error bound, PCT / 50); exit code 5 when the bound is not met, the closest mesh "
     "found written")
    ("oversampling", po::value<double>(&oversampling)->default_value(1.),
     "with --target-vertices: build the initial mesh for this many times V vertices, fit it, then decimate "
     "it to V, which keeps the vertices where the surface needs them (2 fits curved inputs closer; CAD "
     "parts' regular grids decimate badly); in [1, 16]")
    ("topology", po::value<std::string>(&topology),
     "keep (the default): while the initial mesh's topology differs from the input's (per input component: "
     "components, borders, Euler characteristic), rebuild it at 1.25 times the resolution, up to "
     "--max-resolution; with --target-vertices the fitted mesh is then decimated to V. ignore: the grid of "
     "--resolution, or of the budget alone")
    ("max-resolution", po::value<int>(&max_resolution),
     "cap of that refinement (and of --max-distance's), in [1, 1024] (default: twice the first resolution; "
     "with --max-distance, 4 times the resolution of cubes of 1.25 PCT)")
    ("stop-after", po::value<std::string>(&stop_after)->default_value("decimation"),
     "last stage to run: init, valence, fit or decimation (which runs only when the fitted mesh is over "
     "--target-vertices, or over the vertex count of the grid --resolution gives after a refinement for "
     "the topology, by more than 10%)")
    ("no-valence-cleanup", "skip the removal of bad-valence vertices between init and fit")
    ("no-vertex-split", "valence: removal only, as in the thesis (no vertex splits)")
    ("signs", po::value<std::string>(&signs)->default_value("auto"),
     "corner signs: auto (patches, and the winding number where the input overlaps itself or has a gap "
     "smaller than a cube), patches (the thesis's), winding-number (everywhere) or inside-test (closed "
     "inputs)")
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
    ("no-distance-guard", "fit: do not move back where the fit ended farther from the input than the mesh it "
                          "started from")
    ("no-border-fill", "fit: do not fill the notches of the borders of an open input, nor the corners of the "
                       "input's border they cut off (faces added where the border lies inside the input's, then "
                       "fitted again)")
    ("no-stuck-vertices", "fit: do not free the vertices left farthest from the input by moving each together "
                          "with its one-ring")
    ("no-distance-balance", "fit: leave the vertices on the input instead of moving them along their normals "
                            "until the mesh straddles it")
    ("threads", po::value<int>(&decimation.threads)->default_value(0),
     "threads of the fit and of the levels' relaxation (0: one per core); the result is the same for any "
     "number")
    ("memory-limit", po::value<double>(&memory_limit)->default_value(4.),
     "GiB the run may use, estimated before the initial mesh is built (about 2 KiB per patch of input "
     "triangles in a grid cube); a larger run is refused at once")
    ("quiet,q", po::bool_switch(&quiet), "no progress lines")
    ("lod", po::value<std::string>(&lod),
     "levels of detail: decreasing fractions of the vertices to keep, like 0.5,0.1; level i is written "
     "next to OUTPUT as NAME_lodi.EXT")
    ("no-level-rebuild", "levels of detail by decimation alone: no rebuild of the output at a level's vertex "
     "count, kept where it is closer (the default; see the manual)")
    ("report", po::value<std::string>(&report_path),
     "also write a JSON report: certification, quality against the input, the statistics of every stage "
     "(the thesis's Tables 4.1, 7.1, 7.2) and timings")
    ("json", po::value<std::string>(&report_path), "the same as --report (the name the other commands use)")
    ("angle-histogram", po::value<std::string>(&histogram_path),
     "also write an SVG picture of the angle distributions of input and output, the [30, 90] band marked")
    ("color-by-angle", po::value<std::string>(&coloring_name),
     "smallest or largest: colour the faces of OUTPUT (and of the levels) by that angle; needs a .ply OUTPUT");
  decimation.add_options(options);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map vm;
  int exit_code = success;
  if(!parse_options("remesh", "INPUT -o OUTPUT [--resolution N | --target-vertices V] [--lod R,R...] [options]\n\n"
                    "Remeshes INPUT into a mesh whose angles all lie in [30, 90] degrees, certified\n"
                    "exactly on the written file. Stages: init (nonobtuse Marching Cubes), valence\n"
                    "(removal of bad-valence vertices, vertex splits), fit (deform-to-fit with\n"
                    "constrained Laplacian smoothing), decimation (with --target-vertices, down to\n"
                    "V when the fitted mesh is over it: refined for the input's topology, or\n"
                    "oversampled; with --resolution N, down to the vertices of the grid N when\n"
                    "it was refined for the topology); then, with --lod, levels of detail by\n"
                    "angle-bounded decimation or, where closer to the output, by rebuilding the\n"
                    "output at the level's vertex count, each certified on its written file. --max-error\n"
                    "applies to the levels only; the decimation stage stops at one cube of the\n"
                    "grid V or N alone gives.",
                    options, positional, argc, argv, vm, exit_code))
    return exit_code;

  return run_guarded("remesh", [&]() {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const auto seconds_since = [](Clock::time_point t) {
      return std::chrono::duration<double>(Clock::now() - t).count();
    };
    const NR::Remeshing_stage last = NR::stage_from_name(stop_after);
    const bool valence_cleanup = vm.count("no-valence-cleanup") == 0;
    if(vm.count("max-moves") && max_moves < 0) throw std::invalid_argument("--max-moves must be at least 0");
    const std::map<std::string, NR::Sign_source> sign_sources{{"auto", NR::Sign_source::automatic},
                                                              {"patches", NR::Sign_source::patches},
                                                              {"winding-number", NR::Sign_source::winding_number},
                                                              {"inside-test", NR::Sign_source::inside_test}};
    if(sign_sources.count(signs) == 0)
      throw std::invalid_argument("--signs must be auto, patches, winding-number or inside-test (got '" + signs + "')");
    if(int(vm.count("target-vertices")) + int(!vm["resolution"].defaulted()) + int(vm.count("max-distance")) > 1)
      throw std::invalid_argument("give one of --resolution, --target-vertices and --max-distance");
    if(vm.count("max-distance") && !(max_distance > 0. && max_distance <= 100.))
      throw std::invalid_argument("--max-distance must lie in (0, 100], a percentage of the input's diagonal");
    if(vm.count("max-distance") && (last == NR::Remeshing_stage::initial_mesh || last == NR::Remeshing_stage::valence))
      throw std::invalid_argument("--max-distance needs the fit (--stop-after fit or decimation)");
    if(vm.count("target-vertices") && (target_vertices < 4 || target_vertices > 100000000))
      throw std::invalid_argument("--target-vertices must lie in [4, 100000000]");
    if(vm.count("report") && vm.count("json"))
      throw std::invalid_argument("--report and --json are one option under two names: give one");
    std::optional<NR::Angle_coloring> coloring;
    if(vm.count("color-by-angle")) {
      if(coloring_name != "smallest" && coloring_name != "largest")
        throw std::invalid_argument("--color-by-angle must be smallest or largest (got '" + coloring_name + "')");
      if(NR::internal::file_extension(output_path) != "ply")
        throw std::invalid_argument("--color-by-angle needs a .ply OUTPUT (got '" + output_path + "')");
      coloring = coloring_name == "smallest" ? NR::Angle_coloring::smallest_angle : NR::Angle_coloring::largest_angle;
    }
    decimation.check(vm);
    decimation.quiet = quiet;
    decimation.drum_subdivisions = drum_subdivisions;
    const std::vector<double> ratios = lod.empty() ? std::vector<double>() : parse_ratios(lod);
    if(!ratios.empty()) decimation.check_parameters(ratios);
    if(vm.count("topology") && topology != "keep" && topology != "ignore")
      throw std::invalid_argument("--topology must be keep or ignore (got '" + topology + "')");
    if(!(oversampling >= 1. && oversampling <= 16.)) throw std::invalid_argument("--oversampling must lie in [1, 16]");
    if(vm.count("max-resolution") && (max_resolution < 1 || max_resolution > 1024))
      throw std::invalid_argument("--max-resolution must lie in [1, 1024]");
    const bool keep_topology = !vm.count("topology") || topology == "keep";
    if(!ratios.empty() && (last == NR::Remeshing_stage::initial_mesh || last == NR::Remeshing_stage::valence))
      throw std::invalid_argument("--lod needs the fit (--stop-after fit or decimation)");
    std::vector<Named_path> outputs{{"-o", output_path},
                                    {vm.count("json") ? "--json" : "--report", report_path},
                                    {"--angle-histogram", histogram_path}};
    for(std::size_t i = 1; i <= ratios.size(); ++i)
      outputs.push_back({"level " + std::to_string(i) + " of --lod", level_path(output_path, i)});
    check_paths({{"INPUT", input_path}}, outputs);
    if(!NR::internal::is_mesh_extension(NR::internal::file_extension(output_path)))
      throw NR::Output_error("cannot write '" + output_path + "': unsupported extension (expected .off, .obj, .ply or .stl)");

    const Mesh input = load_mesh(input_path);
    const NR::Sign_source source = sign_sources.at(signs);
    Pipeline_progress progress;
    progress.line.quiet = quiet;
    progress.stages = 1 + int(last != NR::Remeshing_stage::initial_mesh && valence_cleanup) +
                      int(last == NR::Remeshing_stage::fit || last == NR::Remeshing_stage::decimation) +
                      int(!ratios.empty());
    Mesh output;
    NR::Nonobtuse_remeshing_statistics stats;
    try {
      stats = NR::nonobtuse_remesh(
          input, output,
          NR::parameters::combine(
              vm.count("target-vertices") ? NR::parameters::target_vertices(std::size_t(target_vertices))
                                          : NR::parameters::target_vertices(std::size_t(0)),
              NR::parameters::resolution(resolution), NR::parameters::sign_source(source),
              NR::parameters::keep_topology(keep_topology), NR::parameters::max_resolution(max_resolution),
              NR::parameters::oversampling(oversampling), NR::parameters::max_distance(max_distance / 100.),
              NR::parameters::min_interior_valence(std::size_t(decimation.min_valence)),
              NR::parameters::min_border_valence(decimation.border_valence()),
              NR::parameters::relaxation(decimation.relaxation),
              NR::parameters::stop_after(last), NR::parameters::valence_cleanup(valence_cleanup),
              NR::parameters::vertex_split(vm.count("no-vertex-split") == 0),
              NR::parameters::alpha(alpha), NR::parameters::drum_subdivisions(drum_subdivisions),
              NR::parameters::quadric_rings(quadric_rings), NR::parameters::smoothing_steps(smoothing_steps),
              NR::parameters::fit_tolerance(fit_tolerance),
              NR::parameters::max_moves(vm.count("max-moves") ? std::size_t(max_moves) : std::size_t(-1)),
              NR::parameters::max_seconds(vm.count("max-seconds") ? max_seconds : 1e300),
              NR::parameters::lazy_evaluation(vm.count("no-lazy-evaluation") == 0),
              NR::parameters::early_smoothing(vm.count("no-early-smoothing") == 0),
              NR::parameters::tangential_smoothing(vm.count("no-tangential-smoothing") == 0),
              NR::parameters::attract_features(vm.count("no-feature-attraction") == 0),
              NR::parameters::distance_guard(vm.count("no-distance-guard") == 0),
              NR::parameters::fill_border_notches(vm.count("no-border-fill") == 0),
              NR::parameters::free_stuck_vertices(vm.count("no-stuck-vertices") == 0),
              NR::parameters::balance_distance(vm.count("no-distance-balance") == 0),
              NR::parameters::number_of_threads(decimation.threads),
              NR::parameters::remeshing_visitor(std::ref(progress)),
              NR::parameters::memory_budget(memory_limit * 1024. * 1024. * 1024.)));
    } catch(const NR::Memory_budget_exceeded& e) {
      throw NR::Bad_input("'" + input_path + "': " + e.what() + " (--memory-limit, in GiB)");
    } catch(const NR::Bad_input& e) {
      throw NR::Bad_input("'" + input_path + "': " + e.what());
    }
    if(stats.target_vertices > 0) {
      std::cout << "resolution " << stats.budget_resolution << " for about ";
      if(stats.oversampling > 1.) std::cout << stats.oversampling << " x ";
      std::cout << stats.target_vertices << " vertices";
      if(stats.trial_resolution > 0)
        std::cout << " (resolution " << stats.trial_resolution << " from the area gave a mesh too far from it)";
      std::cout << "\n";
    }
    if(stats.degenerate_faces_removed > 0)
      std::cout << "note: " << stats.degenerate_faces_removed
                << " zero-area input face(s) removed first (CGAL's remove_degenerate_faces, on a copy)\n";
    print_initial_mesh(std::cout, stats.initial_mesh);
    if(stats.input_components_missing > 0)
      std::cout << "note: " << stats.input_components_missing << " of the input's " << stats.input_components
                << " connected component(s) do not appear in the output: none of their vertices lies within a "
                   "cube diagonal of it (the largest is "
                << std::setprecision(3) << stats.largest_missing_component << " across, the cube size "
                << stats.initial_mesh.cube_size << "): they are below the resolution\n";
    print_topology(std::cout, stats);
    if(stats.valence_run) print_valence(std::cout, stats.valence);
    if(stats.fit_run) print_fit(std::cout, stats.fit);
    if(stats.decimation_run) print_decimation_stage(std::cout, stats.decimation, max_distance > 0.);

    // The file itself must certify: it is re-read and certified before it
    // replaces anything.
    const auto write_start = Clock::now();
    std::size_t written_faces = 0;
    if(!write_certified(output_path, output, written_faces, coloring)) {
      std::cerr << "nonobtuse-remesh remesh: certification of the written file failed; nothing written\n";
      return int(certification_failed);
    }
    double write_seconds = seconds_since(write_start);
    std::cout << "wrote " << output_path << ": " << vertices(output).size() << " vertices, " << written_faces
              << " faces, certified in [30, 90] degrees on the written file\n";

    // The distance bound is claimed only as measured on the written file.
    std::optional<double> written_distance;
    double measure_seconds = 0.;
    if(max_distance > 0.) {
      const auto measure_start = Clock::now();
      Mesh written;
      NR::Read_log log;
      NR::read_triangle_mesh(output_path, written, log);
      const double diagonal = NR::internal::bbox_diagonal(input);
      written_distance = 100. * NR::internal::hausdorff_distance_bound(written, input,
                                                                      stats.distance.measurement_error * diagonal,
                                                                      decimation.threads) / diagonal;
      measure_seconds = seconds_since(measure_start);
      std::cout << "distance: the written file is within " << std::setprecision(4) << *written_distance
                << "% of the input's diagonal (symmetric Hausdorff, CGAL's bounded-error estimate plus its error "
                << 100. * stats.distance.measurement_error << "%) after " << stats.distance.measurements
                << " measurement(s) in the pipeline: the bound " << max_distance << "% "
                << (*written_distance <= max_distance ? "holds" : "is NOT met") << "\n";
    }

    // Levels of detail: one decimation of the output, each level certified
    // on its written file and measured against the full-resolution mesh.
    json levels_json = json::array();
    double levels_seconds = 0.;
    if(!ratios.empty()) {
      const auto levels_start = Clock::now();
      decimation.progress_prefix = "[" + std::to_string(progress.stages) + "/" + std::to_string(progress.stages) + "] ";
      const auto levels = decimation_levels(output, ratios, decimation, vm.count("no-level-rebuild") == 0);
      for(std::size_t i = 0; i < levels.size(); ++i) {
        const auto& level = levels[i];
        const std::string path = level_path(output_path, i + 1);
        print_decimation(std::cout, level.statistics);
        print_level_choice(std::cout, i + 1, level);
        std::size_t faces = 0;
        if(!write_certified(path, level.mesh, faces, coloring)) {
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
                    << NR::stop_reason_name(level.statistics.stop_reason) << "; the levels after it are not written\n";
        json l;
        l["ratio"] = ratios[i];
        l["output"] = path;
        l["reached"] = level.reached;
        l["rebuilt"] = level.rebuilt;
        if(level.decimated_distance >= 0.) l["decimated_hausdorff_percent"] = 100. * level.decimated_distance;
        if(level.rebuilt_distance >= 0.) l["rebuilt_hausdorff_percent"] = 100. * level.rebuilt_distance;
        l["rebuilt_vertices"] = level.rebuilt_vertices;
        if(!level.rebuild_refused.empty()) l["rebuild_refused"] = level.rebuild_refused;
        l["rebuild_seconds"] = level.seconds;
        l["decimation"] = fields_json(level.statistics);
        l["report_against_full_resolution"] = report_to_json(path, report, {});
        levels_json.push_back(l);
      }
      levels_seconds = seconds_since(levels_start);
    }

    if(!histogram_path.empty()) {
      const auto base_name = [](const std::string& path) { return path.substr(path.find_last_of('/') + 1); };
      NR::write_angle_histogram_svg(histogram_path, input, output, "input " + base_name(input_path),
                                    "output " + base_name(output_path));
      std::cout << "wrote " << histogram_path << ": angle histograms of input and output\n";
    }

    if(!report_path.empty()) {
      const auto report_start = Clock::now();
      const NR::Quality_report report = NR::quality_report(output, &input);
      const NR::Quality_report input_report = NR::quality_report(input);
      json j;
      j["input"] = input_path;
      j["output"] = output_path;
      j["resolution"] = stats.resolution;
      if(stats.target_vertices > 0) {
        j["target_vertices"] = stats.target_vertices;
        if(stats.trial_resolution > 0) j["trial_resolution"] = stats.trial_resolution;
        j["oversampling"] = stats.oversampling;
      }
      j["certification"] = {{"written_file", output_path},
                            {"certified", report.certified},
                            {"faces", report.faces},
                            {"min_angle", report.min_angle},
                            {"max_angle", report.max_angle},
                            {"levels_certified", std::size_t(levels_json.size())}};
      j["table_4_1"] = table_4_1_json(input_report, report, stats.initial_mesh);
      if(stats.valence_run) j["table_7_1"] = table_7_1_json(stats.valence);
      if(stats.fit_run)
        j["table_7_2"] = table_7_2_json(input_report, report, stats.fit, vm.count("no-lazy-evaluation") == 0,
                                        vm.count("no-early-smoothing") == 0);
      j["init"] = fields_json(stats.initial_mesh);
      j["topology"] = fields_json(stats.topology);
      j["topology"]["keep_topology"] = stats.keep_topology;
      j["topology"]["budget_resolution"] = stats.budget_resolution;
      j["topology"]["max_resolution"] = stats.max_resolution;
      j["topology"]["refinements"] = stats.refinements;
      j["topology"]["resolution"] = stats.resolution;
      j["topology"]["decimation_target"] = stats.decimation_target;
      j["input_components"] = {{"components", stats.input_components},
                               {"missing", stats.input_components_missing},
                               {"largest_missing_diameter", stats.largest_missing_component},
                               {"missing_means", "no vertex of the component lies within a cube diagonal of the "
                                                 "output: it is below the resolution"}};
      if(stats.valence_run) j["valence"] = fields_json(stats.valence);
      if(stats.fit_run) j["fit"] = fields_json(stats.fit);
      if(stats.decimation_run) j["decimation"] = fields_json(stats.decimation);
      if(written_distance) {
        j["max_distance"] = fields_json(stats.distance);
        j["max_distance"]["requested_percent"] = max_distance;
        j["max_distance"]["written_file_percent"] = *written_distance;
        j["max_distance"]["met"] = *written_distance <= max_distance;
        j["max_distance"]["fractions_of"] = "the input's bounding-box diagonal (the *_percent fields: percent)";
      }
      j["output_report"] = report_to_json(output_path, report, {});
      if(!ratios.empty()) j["levels"] = levels_json;
      j["timings"] = {{"init", stats.initial_mesh.seconds},
                      {"valence", stats.valence_run ? stats.valence.seconds : 0.},
                      {"fit", stats.fit_run ? stats.fit.seconds : 0.},
                      {"decimation", stats.decimation_run ? stats.decimation.seconds : 0.},
                      {"distance_measurements", stats.distance.seconds},
                      {"topology", stats.topology.seconds},
                      {"pipeline", stats.seconds},
                      {"write_and_certify", write_seconds},
                      {"distance_of_written_file", measure_seconds},
                      {"levels", levels_seconds},
                      {"report", seconds_since(report_start)},
                      {"total", seconds_since(start)}};
      write_json_atomically(report_path, j);
    }
    if(written_distance && *written_distance > max_distance) {
      std::cerr << "nonobtuse-remesh remesh: the distance bound " << max_distance << "% is not met: the closest mesh "
                << "found, written to " << output_path << ", is within " << std::setprecision(4) << *written_distance
                << "% (resolution " << stats.resolution << ", cap " << stats.max_resolution
                << "; --max-resolution raises it)\n";
      return int(bound_not_met);
    }
    return int(success);
  });
}

} // namespace nonobtuse_cli
