// SPDX-License-Identifier: GPL-3.0-or-later
//
// nonobtuse-remesh: command-line front end of the Nonobtuse_remeshing package.
// Each subcommand is a small file of its own over the library.

#include "cli.h"

#include <cstring>
#include <iostream>
#include <string>

namespace {

struct Command
{
  const char* name;
  int (*run)(int, char**);
  const char* summary;
};

const Command commands[] = {
  {"certify", &nonobtuse_cli::certify_command,
   "decide exactly whether every angle of a mesh lies within the bounds"},
  {"decimate", &nonobtuse_cli::decimate_command,
   "decimate a certified mesh by angle-bounded edge collapses"},
  {"remesh", &nonobtuse_cli::remesh_command,
   "remesh a surface into a certified well-shaped nonobtuse mesh"},
  {"report", &nonobtuse_cli::report_command,
   "quality report: angles, valences, topology, defects, distance to a reference"},
};

void print_help(std::ostream& out)
{
  out << "usage: nonobtuse-remesh <command> [options]\n\n"
         "Well-shaped nonobtuse remeshing with exactly certified angle bounds.\n\n"
         "commands:\n";
  for(const Command& c : commands)
    out << "  " << c.name << std::string(10 - std::strlen(c.name), ' ') << c.summary << "\n";
  out << "\n'nonobtuse-remesh <command> --help' describes a command.\n"
         "exit codes: 0 success, 1 certification failed, 2 usage error,\n"
         "            3 bad input (or unwritable output), 4 internal failure,\n"
         "            5 the --max-distance bound not met (the closest mesh found is written)\n";
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2) {
    print_help(std::cerr);
    return nonobtuse_cli::usage_error;
  }
  const std::string name = argv[1];
  if(name == "--help" || name == "-h" || name == "help") {
    print_help(std::cout);
    return nonobtuse_cli::success;
  }
  nonobtuse_cli::install_signal_cleanup();
  for(const Command& c : commands)
    if(name == c.name)
      return c.run(argc - 1, argv + 1);
  std::cerr << "nonobtuse-remesh: usage error: unknown command '" << name << "' (see --help)\n";
  return nonobtuse_cli::usage_error;
}
