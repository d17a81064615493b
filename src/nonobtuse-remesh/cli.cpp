// SPDX-License-Identifier: GPL-3.0-or-later
//
#include "cli.h"

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/angle_pictures.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>

#include <algorithm>
#include <csignal>
#include <iostream>
#include <sstream>
#include <utility>

#include <climits>
#include <cstdlib>

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace nonobtuse_cli {

namespace NR = CGAL::Nonobtuse_remeshing;

namespace {

// The readers' repairs, said when the command succeeds: a refusal is one line.
std::vector<std::string> pending_notes;

} // namespace

Mesh load_mesh(const std::string& path, NR::Read_log* log)
{
  Mesh mesh;
  NR::Read_log local;
  NR::Read_log& used = log ? *log : local;
  {
    // CGAL's readers print their own diagnostics on std::cerr (the PLY reader
    // even when not verbose); the tool says what went wrong in one line.
    std::ostringstream silenced;
    std::streambuf* const cerr_buffer = std::cerr.rdbuf(silenced.rdbuf());
    try {
      NR::read_triangle_mesh(path, mesh, used);
    } catch(...) {
      std::cerr.rdbuf(cerr_buffer);
      for(const std::string& repair : used.repairs) pending_notes.push_back("note: " + path + ": " + repair);
      throw;
    }
    std::cerr.rdbuf(cerr_buffer);
  }
  for(const std::string& repair : used.repairs) pending_notes.push_back("note: " + path + ": " + repair);
  return mesh;
}

namespace {

// What a path names: the canonical folder and the file name, and the file's
// device and inode where it exists.
struct File_identity
{
  std::string canonical;
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;

  bool same_file(const File_identity& other) const
  {
    return (!canonical.empty() && canonical == other.canonical) ||
           (exists && other.exists && device == other.device && inode == other.inode);
  }
};

// A path's folder ("." when it has none; ending with '/' otherwise) and file name.
std::pair<std::string, std::string> split_path(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  if(slash == std::string::npos) return {".", path};
  return {path.substr(0, slash + 1), path.substr(slash + 1)};
}

File_identity identify(const std::string& path)
{
  File_identity id;
  const auto [folder, name] = split_path(path);
  if(char* real = ::realpath(folder.c_str(), nullptr)) {
    id.canonical = std::string(real) + "/" + name;
    std::free(real);
  }
  struct stat status;
  if(::stat(path.c_str(), &status) == 0) {
    id.exists = true;
    id.device = status.st_dev;
    id.inode = status.st_ino;
  }
  return id;
}

} // namespace

void check_paths(const std::vector<Named_path>& inputs, const std::vector<Named_path>& outputs)
{
  std::vector<std::pair<const Named_path*, File_identity> > seen;
  for(const Named_path& input : inputs)
    if(!input.path.empty()) seen.emplace_back(&input, identify(input.path));
  const std::size_t input_count = seen.size();
  for(const Named_path& output : outputs) {
    const std::string& path = output.path;
    if(path.empty()) continue;
    const auto [folder, name] = split_path(path);
    if(name.empty() || name == "." || name == "..")
      throw NR::Output_error("cannot write '" + path + "' (" + output.option + "): not a file name");
    if(::access(folder.c_str(), W_OK) != 0)
      throw NR::Output_error("cannot write '" + path + "' (" + output.option + "): folder '" + folder +
                             "' does not exist or is not writable");
    const long name_max = ::pathconf(folder.c_str(), _PC_NAME_MAX);
    if(name.size() > std::size_t(name_max > 0 ? name_max : 255))
      throw NR::Output_error("cannot write '" + path + "' (" + output.option + "): its file name has " +
                             std::to_string(name.size()) + " bytes, more than the folder allows (" +
                             std::to_string(name_max > 0 ? name_max : 255) + ")");
    struct stat target;
    if(::stat(path.c_str(), &target) == 0 && S_ISDIR(target.st_mode))
      throw NR::Output_error("cannot write '" + path + "' (" + output.option + "): it is a folder");
    const File_identity id = identify(path);
    for(std::size_t i = 0; i < seen.size(); ++i) {
      if(!id.same_file(seen[i].second)) continue;
      const Named_path& other = *seen[i].first;
      if(i < input_count)
        throw NR::Output_error("refusing to write '" + path + "' (" + output.option + ") over the input '" +
                               other.path + "'");
      throw NR::Output_error(other.option + " '" + other.path + "' and " + output.option + " '" + path +
                             "' name the same file: give each output its own path");
    }
    seen.emplace_back(&output, id);
  }
}

bool parse_options(const std::string& name, const std::string& synopsis,
                   const po::options_description& options,
                   const po::positional_options_description& positional,
                   int argc, char** argv, po::variables_map& vm, int& exit_code)
{
  try {
    po::store(po::command_line_parser(argc, argv).options(options).positional(positional).run(), vm);
    if(vm.count("help")) {
      std::cout << "usage: nonobtuse-remesh " << name << " " << synopsis << "\n\n" << options;
      exit_code = success;
      return false;
    }
    po::notify(vm);
  } catch(const po::error& e) {
    std::cerr << "nonobtuse-remesh " << name << ": usage error: " << e.what()
              << " (see --help)\n";
    exit_code = usage_error;
    return false;
  }
  return true;
}

int run_guarded(const std::string& name, const std::function<int()>& body)
{
  // A refusal is one line: the repairs made before it are counted in it.
  const auto after_repairs = []() {
    const std::size_t n = pending_notes.size();
    pending_notes.clear();
    return n == 0 ? std::string() : " (after " + std::to_string(n) + " repair(s) of the input)";
  };
  try {
    const int code = body();
    if(code == success)
      for(const std::string& note : pending_notes) std::cerr << note << "\n";
    pending_notes.clear();
    return code;
  } catch(const NR::Bad_parameter& e) {
    std::cerr << "nonobtuse-remesh " << name << ": usage error: " << e.what() << after_repairs() << "\n";
    return usage_error;
  } catch(const NR::Bad_input& e) {
    std::cerr << "nonobtuse-remesh " << name << ": bad input: " << e.what() << after_repairs() << "\n";
    return bad_input;
  } catch(const NR::Output_error& e) {
    std::cerr << "nonobtuse-remesh " << name << ": output error: " << e.what() << after_repairs() << "\n";
    return bad_input;
  } catch(const std::invalid_argument& e) {
    std::cerr << "nonobtuse-remesh " << name << ": usage error: " << e.what() << after_repairs() << "\n";
    return usage_error;
  } catch(const std::exception& e) {
    std::cerr << "nonobtuse-remesh " << name << ": internal failure: " << e.what() << after_repairs() << "\n";
    return internal_failure;
  } catch(...) {
    std::cerr << "nonobtuse-remesh " << name << ": internal failure: unknown exception" << after_repairs() << "\n";
    return internal_failure;
  }
}

bool write_certified(const std::string& path, const Mesh& mesh, std::size_t& faces,
                     std::optional<NR::Angle_coloring> coloring)
{
  faces = 0;
  bool checked = false, accepted = false;
  const auto certifying = NR::certifying_check(mesh, &faces);
  const auto check = [&](const std::string& temporary) {
    checked = true;
    return accepted = certifying(temporary);
  };
  try {
    if(coloring) NR::write_mesh_colored_by_angle_atomically(path, mesh, *coloring, check);
    else NR::write_mesh_atomically(path, mesh, check);
  } catch(const NR::Output_error&) {
    if(checked && !accepted) return false;  // the file was written, and the check refused it
    throw;
  }
  return true;
}

namespace {

extern "C" void remove_temporaries_and_die(int signal_number)
{
  NR::remove_temporary_files();
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

} // namespace

void install_signal_cleanup()
{
  for(int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction current;
    if(::sigaction(signal_number, nullptr, &current) == 0 && current.sa_handler == SIG_IGN)
      continue;  // ignored by whoever started us (nohup, a background job): left so
    std::signal(signal_number, remove_temporaries_and_die);
  }
}

void Progress_line::show(const std::string& text, bool force)
{
  const auto now = std::chrono::steady_clock::now();
  if(quiet || (!force && shown_ && now - last_ < std::chrono::seconds(1))) return;
  last_ = now;
  shown_ = true;
  std::cerr << (terminal_ ? "\r" : "") << text << (terminal_ ? "   " : "\n") << std::flush;
}

void Progress_line::done()
{
  if(shown_ && terminal_) std::cerr << "\n";
  shown_ = false;
}

std::string Progress_line::bar(double fraction)
{
  const int width = 20;
  const double f = std::min(1., std::max(0., fraction));
  const int filled = int(f * width + 0.5);
  const std::string percent = std::to_string(int(f * 100. + 0.5));
  return "[" + std::string(std::size_t(filled), '#') + std::string(std::size_t(width - filled), '-') + "] " +
         std::string(3 - std::min<std::size_t>(3, percent.size()), ' ') + percent + "%";
}

} // namespace nonobtuse_cli
