// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared pieces of the nonobtuse-remesh subcommands: exit codes, the mesh
// type, checked loading with its messages, and the error-to-exit-code policy.

#ifndef NONOBTUSE_REMESH_CLI_H
#define NONOBTUSE_REMESH_CLI_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <boost/program_options.hpp>

#include <unistd.h>

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CGAL { namespace Nonobtuse_remeshing { struct Read_log; enum class Angle_coloring; } }

namespace nonobtuse_cli {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace po = boost::program_options;

enum Exit_code : int {
  success = 0,
  certification_failed = 1,
  usage_error = 2,
  bad_input = 3,
  internal_failure = 4,
  bound_not_met = 5
};

// Reads a triangle mesh with the package's checked reader; repairs it made
// are printed to standard error as "note:" lines by run_guarded() when the
// command succeeds (a refusal only counts them) and, if `log` is given, kept
// there too.
Mesh load_mesh(const std::string& path, CGAL::Nonobtuse_remeshing::Read_log* log = nullptr);

// A path given on the command line, with the option that gave it.
struct Named_path
{
  std::string option;  // "-o", "--report", "level 1", "INPUT", ...
  std::string path;    // empty: not given
};

// Before any work: throws CGAL::Nonobtuse_remeshing::Output_error unless a
// file can be created at each output path (its folder exists and is
// writable, its name fits, it is not a folder) and no two paths, inputs and
// outputs alike, name the same file: paths are compared by what they name
// (canonical folder and file name, and device and inode where the file
// exists), not as text. The message names the two options that clash.
void check_paths(const std::vector<Named_path>& inputs, const std::vector<Named_path>& outputs);

// Parses the command line of subcommand `name`; returns false and sets
// `exit_code` when the run should stop there (help shown, or usage error).
bool parse_options(const std::string& name, const std::string& synopsis,
                   const po::options_description& options,
                   const po::positional_options_description& positional,
                   int argc, char** argv, po::variables_map& vm, int& exit_code);

// Runs `body`, mapping exceptions to one-line messages and exit codes; then,
// if it succeeded, prints the notes of load_mesh().
int run_guarded(const std::string& name, const std::function<int()>& body);

// Writes `mesh` to `path` atomically; the temporary file is re-read and
// certified in [30, 90] degrees before it replaces anything. Returns false,
// writing nothing, if the written file does not certify; `faces` gets the
// faces of the written file. With `coloring`, writes a PLY with faces
// coloured by angle. Throws Output_error when it cannot write.
bool write_certified(const std::string& path, const Mesh& mesh, std::size_t& faces,
                     std::optional<CGAL::Nonobtuse_remeshing::Angle_coloring> coloring = std::nullopt);

// A progress line on standard error, at the first call and then at most once
// a second (or at once when forced): rewritten in place on a terminal, a new
// line otherwise; nothing when quiet. Ended when it goes, so that an error
// message starts on a line of its own.
struct Progress_line
{
  bool quiet = false;
  ~Progress_line() { done(); }
  void show(const std::string& text, bool force = false);
  void done();
  // "[#########-----------]  45%" for a fraction in [0, 1]
  static std::string bar(double fraction);

private:
  bool terminal_ = isatty(2) != 0;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// Makes SIGINT, SIGTERM and SIGHUP remove the temporary files of the writes
// in progress before the program ends as the signal says (a signal the
// parent process ignores stays ignored).
void install_signal_cleanup();

int certify_command(int argc, char** argv);
int decimate_command(int argc, char** argv);
int report_command(int argc, char** argv);
int remesh_command(int argc, char** argv);

} // namespace nonobtuse_cli

#endif // NONOBTUSE_REMESH_CLI_H
