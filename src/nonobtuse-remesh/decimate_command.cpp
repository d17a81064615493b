// SPDX-License-Identifier: GPL-3.0-or-later
//
// nonobtuse-remesh decimate INPUT -o OUTPUT (--ratio R | --target-vertices V)
//                  [--max-error PCT] [--min-valence V] [--json FILE]
// and the decimation pieces `remesh --lod` shares.

#include "decimation_cli.h"
#include "statistics_output.h"

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>
#include <CGAL/Nonobtuse_remeshing/quality_report.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace nonobtuse_cli {

namespace NR = CGAL::Nonobtuse_remeshing;

namespace {

// The decimation's progress line, with a bar towards the last target.
struct Decimation_progress
{
  Progress_line line;
  std::string prefix;
  std::size_t last_target = 0;

  bool keep_going(const NR::Angle_bounded_decimation_statistics& s)
  {
    const double to_remove = double(s.vertices_before) - double(last_target);
    line.show(prefix + "decimate " + Progress_line::bar(to_remove > 0. ? double(s.collapses) / to_remove : 1.) + " " +
              std::to_string(s.vertices_before - s.collapses) + " vertices, round " + std::to_string(s.rounds) +
              ", " + std::to_string(s.relaxations) + " relaxations");
    return true;
  }
};

auto decimation_parameters(const Decimation_settings& settings, Decimation_progress& progress)
{
  return NR::parameters::combine(
      NR::parameters::max_error(settings.max_error_given ? settings.max_error_percent / 100.
                                                         : std::numeric_limits<double>::infinity()),
      NR::parameters::min_interior_valence(std::size_t(settings.min_valence)),
      NR::parameters::min_border_valence(settings.border_valence()),
      NR::parameters::relaxation(settings.relaxation),
      NR::parameters::drum_subdivisions(settings.drum_subdivisions),
      NR::parameters::number_of_threads(settings.threads),
      NR::parameters::decimation_visitor(std::ref(progress)));
}

} // namespace

std::size_t Decimation_settings::border_valence() const
{
  return std::size_t((std::max)(min_border_valence >= 0 ? min_border_valence : min_valence - 1, 0));
}

void Decimation_settings::add_options(po::options_description& options)
{
  options.add_options()
    ("max-error", po::value<double>(&max_error_percent),
     "decimation: stop when the cheapest collapse would move a vertex farther than PCT % of the "
     "bounding-box diagonal from the planes and points its quadric sums (default: no limit)")
    ("min-valence", po::value<int>(&min_valence)->default_value(4),
     "decimation: no collapse makes an interior vertex of lower valence")
    ("min-border-valence", po::value<int>(&min_border_valence),
     "decimation: the same for border vertices (default: min-valence - 1)")
    ("no-relaxation", "decimation: the thesis's single greedy run, no deform-to-fit between rounds");
}

void Decimation_settings::check(const po::variables_map& vm)
{
  relaxation = vm.count("no-relaxation") == 0;
  max_error_given = vm.count("max-error") > 0;
}

void Decimation_settings::check_parameters(const std::vector<double>& ratios) const
{
  Decimation_progress progress;
  NR::internal::decimation_options(decimation_parameters(*this, progress));
  if(!ratios.empty()) NR::internal::check_level_ratios(ratios);
}

NR::Angle_bounded_decimation_statistics decimate(Mesh& mesh, std::optional<double> ratio, std::size_t target,
                                                 const Decimation_settings& settings)
{
  Decimation_progress progress;
  progress.line.quiet = settings.quiet;
  progress.last_target = ratio ? std::size_t(std::llround(*ratio * double(vertices(mesh).size()))) : target;
  const auto s =
      ratio ? NR::angle_bounded_decimation(mesh, NR::parameters::combine(NR::parameters::vertex_ratio(*ratio),
                                                                         decimation_parameters(settings, progress)))
            : NR::angle_bounded_decimation(mesh, NR::parameters::combine(NR::parameters::target_vertices(target),
                                                                         decimation_parameters(settings, progress)));
  progress.line.done();
  mesh.collect_garbage();
  return s;
}

std::vector<NR::Level_of_detail<Mesh> > decimation_levels(const Mesh& full, const std::vector<double>& ratios,
                                                          const Decimation_settings& settings, bool rebuild)
{
  Decimation_progress progress;
  progress.line.quiet = settings.quiet;
  progress.prefix = settings.progress_prefix;
  progress.last_target = std::size_t(std::llround(ratios.back() * double(vertices(full).size())));
  std::vector<NR::Level_of_detail<Mesh> > levels;
  if(rebuild) {
    levels = NR::levels_of_detail(full, ratios, decimation_parameters(settings, progress));
  } else {
    for(auto& d : NR::angle_bounded_decimation_hierarchy(full, ratios, decimation_parameters(settings, progress))) {
      levels.emplace_back();
      static_cast<NR::Decimation_level<Mesh>&>(levels.back()) = std::move(d);
      levels.back().rebuild_refused = "not asked (--no-level-rebuild)";
    }
  }
  progress.line.done();
  return levels;
}

void print_level_choice(std::ostream& out, std::size_t i, const NR::Level_of_detail<Mesh>& level)
{
  out << std::setprecision(4) << "level " << i << ": ";
  if(level.rebuilt)
    out << "the rebuild of the full mesh at its vertex count (" << 100. * level.rebuilt_distance
        << "% from it) is closer than the decimation's level (" << 100. * level.decimated_distance << "%)";
  else if(level.rebuilt_distance >= 0.)
    out << "the decimation's level (" << 100. * level.decimated_distance << "% from the full mesh) is closer than "
        << "the rebuild at its vertex count (" << 100. * level.rebuilt_distance << "%)";
  else
    out << "the decimation's level; no rebuild: " << level.rebuild_refused;
  if(level.seconds > 0.) out << "; " << std::setprecision(3) << level.seconds << " s for the rebuild and distances";
  out << "\n";
}

std::vector<double> parse_ratios(const std::string& text)
{
  std::vector<double> ratios;
  std::istringstream in(text);
  std::string item;
  while(std::getline(in, item, ',')) {
    std::size_t used = 0;
    double r = 0.;
    try {
      r = std::stod(item, &used);
    } catch(const std::exception&) {
      used = 0;
    }
    if(used == 0 || used != item.size())
      throw std::invalid_argument("--lod takes ratios separated by commas, like 0.5,0.1 (got '" + text + "')");
    ratios.push_back(r);
  }
  if(ratios.empty()) throw std::invalid_argument("--lod needs at least one ratio");
  return ratios;
}

std::string level_path(const std::string& output, std::size_t i)
{
  const std::size_t slash = output.find_last_of('/');
  const std::size_t dot = output.find_last_of('.');
  const std::size_t cut = (dot == std::string::npos || (slash != std::string::npos && dot < slash)) ? output.size()
                                                                                                      : dot;
  return output.substr(0, cut) + "_lod" + std::to_string(i) + output.substr(cut);
}

void print_decimation(std::ostream& out, const NR::Angle_bounded_decimation_statistics& s)
{
  print_fields(out, "decimation (angle-bounded edge collapses)", s);
}

int decimate_command(int argc, char** argv)
{
  std::string input_path, output_path, json_path;
  double ratio = 0.;
  long long target_vertices = 0;
  Decimation_settings settings;
  po::options_description options("options");
  options.add_options()
    ("help,h", "show this help")
    ("input", po::value<std::string>(&input_path)->required(), "a mesh certified in [30, 90] degrees")
    ("output,o", po::value<std::string>(&output_path)->required(),
     "where to write the result (.off, .obj, .ply, .stl)")
    ("ratio", po::value<double>(&ratio), "fraction of the vertices to keep, in (0, 1]")
    ("target-vertices", po::value<long long>(&target_vertices), "vertices to keep (instead of --ratio)")
    ("drum-subdivisions,k", po::value<int>(&settings.drum_subdivisions)->default_value(2),
     "drum planes per side in the feasible regions, in [1, 16]")
    ("threads", po::value<int>(&settings.threads)->default_value(0),
     "threads of the relaxation (0: one per core); the result is the same for any number")
    ("quiet,q", po::bool_switch(&settings.quiet), "no progress line")
    ("json", po::value<std::string>(&json_path), "also write statistics and the quality report as JSON");
  settings.add_options(options);
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map vm;
  int exit_code = success;
  if(!parse_options("decimate", "INPUT -o OUTPUT (--ratio R | --target-vertices V) [--max-error PCT] [options]\n\n"
                    "Decimates INPUT, whose angles must all lie in [30, 90] degrees, by angle-bounded\n"
                    "edge collapses (thesis, chapter 6); the result is certified in [30, 90] degrees\n"
                    "on the written file and keeps the topology.",
                    options, positional, argc, argv, vm, exit_code))
    return exit_code;

  return run_guarded("decimate", [&]() {
    if(vm.count("ratio") == vm.count("target-vertices"))
      throw std::invalid_argument("give one of --ratio and --target-vertices");
    if(vm.count("target-vertices") && target_vertices < 0)
      throw std::invalid_argument("--target-vertices must be at least 0");
    settings.check(vm);
    settings.check_parameters({});
    check_paths({{"INPUT", input_path}}, {{"-o", output_path}, {"--json", json_path}});
    if(!NR::internal::is_mesh_extension(NR::internal::file_extension(output_path)))
      throw NR::Output_error("cannot write '" + output_path + "': unsupported extension (expected .off, .obj, .ply or .stl)");

    NR::Read_log log;
    const Mesh input = load_mesh(input_path, &log);
    if(!log.faces_as_written()) {
      std::cerr << "nonobtuse-remesh decimate: '" << input_path << "' is not certified as written: it has "
                << log.faces_changed() << "; decimate needs a nonobtuse triangle mesh, such as the output of remesh\n";
      return int(certification_failed);
    }
    const auto certificate = NR::certify_angle_bounds(input);
    if(!certificate.is_certified()) {
      std::cerr << "nonobtuse-remesh decimate: '" << input_path << "' does not certify in [30, 90] degrees ("
                << certificate.too_small_corners << " corners below 30, " << certificate.too_large_corners
                << " above 90, " << certificate.degenerate_faces
                << " degenerate faces); decimate needs a nonobtuse mesh, such as the output of remesh\n";
      return int(certification_failed);
    }
    Mesh output = input;
    const NR::Angle_bounded_decimation_statistics s =
        decimate(output, vm.count("ratio") ? std::optional<double>(ratio) : std::nullopt,
                 std::size_t(target_vertices), settings);
    const std::size_t target = s.target_vertices;
    print_decimation(std::cout, s);

    std::size_t written_faces = 0;
    if(!write_certified(output_path, output, written_faces)) {
      std::cerr << "nonobtuse-remesh decimate: certification of the written file failed; nothing written\n";
      return int(certification_failed);
    }
    const NR::Quality_report report = NR::quality_report(output, &input);
    std::cout << "wrote " << output_path << ": " << vertices(output).size() << " vertices, " << written_faces
              << " faces, certified in [30, 90] degrees on the written file; Hausdorff distance to the input "
              << std::setprecision(4) << report.distance->hausdorff_symmetric << "% of its diagonal\n";
    if(s.stop_reason != NR::Decimation_stop_reason::target_reached)
      std::cout << "note: the target of " << target << " vertices was not reached: " << NR::stop_reason_name(s.stop_reason)
                << "\n";
    if(!json_path.empty()) {
      json j;
      j["input"] = input_path;
      j["output"] = output_path;
      j["decimation"] = fields_json(s);
      j["output_report"] = report_to_json(output_path, report, {});
      write_json_atomically(json_path, j);
    }
    return int(success);
  });
}

} // namespace nonobtuse_cli
