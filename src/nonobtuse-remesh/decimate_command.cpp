// nonobtuse-remesh decimate INPUT -o OUTPUT (--ratio R | --target-vertices V)
//                  [--max-error PCT] [--min-valence V] [--json FILE]
// and the decimation pieces `remesh --lod` shares.

#include "decimation_cli.h"

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
  const int border = settings.min_border_valence >= 0 ? settings.min_border_valence : settings.min_valence - 1;
  return NR::parameters::combine(
      NR::parameters::max_error(settings.max_error_percent > 0. ? settings.max_error_percent / 100.
                                                                : std::numeric_limits<double>::infinity()),
      NR::parameters::min_interior_valence(std::size_t(settings.min_valence)),
      NR::parameters::min_border_valence(std::size_t((std::max)(border, 0))),
      NR::parameters::relaxation(settings.relaxation),
      NR::parameters::drum_subdivisions(settings.drum_subdivisions),
      NR::parameters::decimation_visitor(std::ref(progress)));
}

} // namespace

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
  if(vm.count("max-error") && !(max_error_percent > 0. && max_error_percent <= 100.))
    throw std::invalid_argument("--max-error must lie in (0, 100] (a percentage of the diagonal)");
  if(min_valence < 3 || min_valence > 12) throw std::invalid_argument("--min-valence must lie in [3, 12]");
  if(vm.count("min-border-valence") && (min_border_valence < 2 || min_border_valence > 12))
    throw std::invalid_argument("--min-border-valence must lie in [2, 12]");
}

NR::Angle_bounded_decimation_statistics decimate(Mesh& mesh, std::size_t target, const Decimation_settings& settings)
{
  Decimation_progress progress;
  progress.line.quiet = settings.quiet;
  progress.last_target = target;
  const auto s = NR::angle_bounded_decimation(
      mesh, NR::parameters::combine(NR::parameters::target_vertices(target), decimation_parameters(settings, progress)));
  progress.line.done();
  mesh.collect_garbage();
  return s;
}

std::vector<NR::Decimation_level<Mesh> > decimation_levels(const Mesh& full, const std::vector<double>& ratios,
                                                           const Decimation_settings& settings)
{
  Decimation_progress progress;
  progress.line.quiet = settings.quiet;
  progress.prefix = settings.progress_prefix;
  progress.last_target = std::size_t(std::llround(ratios.back() * double(vertices(full).size())));
  auto levels = NR::angle_bounded_decimation_hierarchy(full, ratios, decimation_parameters(settings, progress));
  progress.line.done();
  return levels;
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
  for(std::size_t i = 0; i < ratios.size(); ++i)
    if(!(ratios[i] > 0. && ratios[i] < 1.) || (i > 0 && !(ratios[i] < ratios[i - 1])))
      throw std::invalid_argument("the --lod ratios must decrease strictly within (0, 1) (got '" + text + "')");
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

const char* stop_reason_name(NR::Decimation_stop_reason reason)
{
  switch(reason) {
  case NR::Decimation_stop_reason::target_reached: return "target reached";
  case NR::Decimation_stop_reason::max_error: return "stopped at --max-error";
  case NR::Decimation_stop_reason::no_collapse_left: return "no certified collapse left";
  case NR::Decimation_stop_reason::round_limit: return "64 rounds ran";
  case NR::Decimation_stop_reason::cancelled: return "cancelled";
  }
  return "unknown";
}

void print_decimation(std::ostream& out, const NR::Angle_bounded_decimation_statistics& s)
{
  out << std::setprecision(4) << "decimation (angle-bounded, " << s.vertices_before << " -> " << s.vertices_after
      << " vertices, target " << s.target_vertices << "): " << stop_reason_name(s.stop_reason) << "\n"
      << "  collapses " << s.collapses << ", QP solves " << s.qp_solves << ", fallbacks to CGAL's QP solver "
      << s.qp_fallbacks << ", rounds " << s.rounds << ", relaxations " << s.relaxations << " ("
      << s.relaxation_moves << " moves, " << s.relaxation_seconds << " s)\n"
      << "  refused: empty F(u, v) " << s.empty_regions << ", valence floor " << s.valence_refusals
      << ", exact certification " << s.certification_refusals << ", topology " << s.topology_refusals << "\n"
      << "  largest collapse error " << 100. * s.largest_collapse_error << "% of the diagonal";
  if(s.stop_reason == NR::Decimation_stop_reason::max_error)
    out << ", cheapest collapse left " << 100. * s.stopping_error << "%";
  out << ", " << s.seconds << " s\n";
}

json decimation_json(const NR::Angle_bounded_decimation_statistics& s)
{
  return {{"vertices_before", s.vertices_before},
          {"vertices_after", s.vertices_after},
          {"target_vertices", s.target_vertices},
          {"stop_reason", stop_reason_name(s.stop_reason)},
          {"target_reached", s.stop_reason == NR::Decimation_stop_reason::target_reached},
          {"collapses", s.collapses},
          {"qp_solves", s.qp_solves},
          {"qp_fallbacks", s.qp_fallbacks},
          {"empty_regions", s.empty_regions},
          {"valence_refusals", s.valence_refusals},
          {"certification_refusals", s.certification_refusals},
          {"topology_refusals", s.topology_refusals},
          {"rounds", s.rounds},
          {"relaxations", s.relaxations},
          {"relaxation_moves", s.relaxation_moves},
          {"relaxation_seconds", s.relaxation_seconds},
          {"largest_collapse_error_percent", 100. * s.largest_collapse_error},
          {"stopping_error_percent", 100. * s.stopping_error},
          {"seconds", s.seconds}};
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
    if(vm.count("ratio") && !(ratio > 0. && ratio <= 1.)) throw std::invalid_argument("--ratio must lie in (0, 1]");
    if(vm.count("target-vertices") && target_vertices < 0)
      throw std::invalid_argument("--target-vertices must be at least 0");
    if(settings.drum_subdivisions < 1 || settings.drum_subdivisions > 16)
      throw std::invalid_argument("--drum-subdivisions must lie in [1, 16]");
    settings.check(vm);
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
    const std::size_t n = vertices(input).size();
    const std::size_t target =
        vm.count("ratio") ? std::size_t(std::llround(ratio * double(n))) : std::size_t(target_vertices);
    Mesh output = input;
    const NR::Angle_bounded_decimation_statistics s = decimate(output, target, settings);
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
      std::cout << "note: the target of " << target << " vertices was not reached: " << stop_reason_name(s.stop_reason)
                << "\n";
    if(!json_path.empty()) {
      json j;
      j["input"] = input_path;
      j["output"] = output_path;
      j["decimation"] = decimation_json(s);
      j["output_report"] = report_to_json(output_path, report, {});
      write_json_atomically(json_path, j);
    }
    return int(success);
  });
}

} // namespace nonobtuse_cli
