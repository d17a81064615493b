// SPDX-License-Identifier: GPL-3.0-or-later
//
// Angle-bounded decimation in the tool: the options `decimate` and
// `remesh --lod` share, the statistics as text and JSON, and the levels of
// detail of `remesh`.

#ifndef NONOBTUSE_REMESH_DECIMATION_CLI_H
#define NONOBTUSE_REMESH_DECIMATION_CLI_H

#include "cli.h"
#include "json_output.h"

#include <CGAL/Nonobtuse_remeshing/angle_bounded_decimation.h>
#include <CGAL/Nonobtuse_remeshing/levels_of_detail.h>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace nonobtuse_cli {

struct Decimation_settings
{
  double max_error_percent = 0.;
  bool max_error_given = false;  // false: no maximum error
  int min_valence = 4;
  int min_border_valence = -1;    // -1: min_valence - 1
  bool relaxation = true;
  int drum_subdivisions = 2;
  int threads = 0;                // --threads, 0: one per core
  bool quiet = false;
  std::string progress_prefix;    // e.g. "[4/4] " when a stage of remesh

  // The border valence floor: --min-border-valence, or min_valence - 1 (at least 0).
  std::size_t border_valence() const;
  // --max-error, --min-valence, --min-border-valence, --no-relaxation
  void add_options(po::options_description& options);
  // Reads the switches.
  void check(const po::variables_map& vm);
  // The library's checks of these settings and of the levels' `ratios`
  // (none if empty), before any work: throws Bad_parameter.
  void check_parameters(const std::vector<double>& ratios) const;
};

// Decimates `mesh` in place to `ratio` of its vertices if given, else to
// `target` vertices.
CGAL::Nonobtuse_remeshing::Angle_bounded_decimation_statistics decimate(Mesh& mesh, std::optional<double> ratio,
                                                                        std::size_t target,
                                                                        const Decimation_settings& settings);

// The hierarchy of `full` at `ratios`, one decimation; with `rebuild`, each
// level against a rebuild of `full` at its vertex count, the closer kept
// (levels_of_detail()).
std::vector<CGAL::Nonobtuse_remeshing::Level_of_detail<Mesh> > decimation_levels(
    const Mesh& full, const std::vector<double>& ratios, const Decimation_settings& settings, bool rebuild);

// One line on the choice between a level's decimation and its rebuild.
void print_level_choice(std::ostream& out, std::size_t i, const CGAL::Nonobtuse_remeshing::Level_of_detail<Mesh>& level);

// "0.5,0.1" -> {0.5, 0.1}; throws std::invalid_argument unless the text is
// a list of numbers.
std::vector<double> parse_ratios(const std::string& text);

// The file of level i (from 1) of `output`: "dir/name.off" -> "dir/name_lod1.off".
std::string level_path(const std::string& output, std::size_t i);

void print_decimation(std::ostream& out, const CGAL::Nonobtuse_remeshing::Angle_bounded_decimation_statistics& s);

} // namespace nonobtuse_cli

#endif // NONOBTUSE_REMESH_DECIMATION_CLI_H
