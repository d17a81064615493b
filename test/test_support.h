// SPDX-License-Identifier: GPL-3.0-or-later
//
// Helpers shared by the library tests: the shipped sample meshes.

#ifndef NONOBTUSE_TEST_SUPPORT_H
#define NONOBTUSE_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <set>
#include <string>
#include <system_error>
#include <vector>
#include <dirent.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace nonobtuse_test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

inline std::string data(const std::string& name) { return std::string(NONOBTUSE_TEST_DATA) + "/" + name; }

// The whole file, bytes as they are.
inline std::string slurp(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The number of lines of `text` (its newlines).
inline std::size_t lines(const std::string& text)
{
  return std::size_t(std::count(text.begin(), text.end(), '\n'));
}

inline Mesh load(const std::string& name)
{
  Mesh mesh;
  CGAL::Nonobtuse_remeshing::read_triangle_mesh(data(name), mesh);
  return mesh;
}

// Writes `mesh` as the tool does and reads it back: what the checks see is
// the file.
inline Mesh written_and_reread(const Mesh& mesh, const std::string& name)
{
  const std::string path = ::testing::TempDir() + std::to_string(::getpid()) + "_" + name;
  CGAL::Nonobtuse_remeshing::write_mesh_atomically(path, mesh);
  Mesh reread;
  CGAL::Nonobtuse_remeshing::read_triangle_mesh(path, reread);
  std::remove(path.c_str());
  return reread;
}

// Runs `command` with /bin/sh in a child process; returns its exit code
// (128 + the signal when a signal ended it) and its peak resident memory.
struct Shell_run
{
  int code = -1;
  double peak_mib = 0.;
};

inline Shell_run run_shell(const std::string& command)
{
  Shell_run r;
  const pid_t child = ::fork();
  if(child == 0) {
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  struct rusage usage;
  ::wait4(child, &status, 0, &usage);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.peak_mib = double(usage.ru_maxrss) / 1024.;
  return r;
}

// Every test process writes its files under a folder of its own:
// ::testing::TempDir() returns TEST_TMPDIR, set here to a fresh folder in
// the one it named before (or TMPDIR, or /tmp) when the tests start. The
// folder is removed when the process ends with every test passed; after a
// failure it stays, and its path is printed.
class Scratch_root : public ::testing::EmptyTestEventListener
{
public:
  void OnTestProgramStart(const ::testing::UnitTest&) override
  {
    const std::string base = ::testing::TempDir();
    std::vector<char> name(base.begin(), base.end());
    for(char c : std::string("nonobtuse_tests_XXXXXX")) name.push_back(c);
    name.push_back('\0');
    if(::mkdtemp(name.data()) == nullptr) return;  // the tests then write where TempDir() said
    root_ = name.data();
    ::setenv("TEST_TMPDIR", root_.c_str(), 1);
  }
  void OnTestProgramEnd(const ::testing::UnitTest& unit) override
  {
    if(root_.empty()) return;
    std::error_code ignored;
    if(unit.Passed())
      std::filesystem::remove_all(root_, ignored);
    else
      std::cerr << "the tests' files are kept in " << root_ << "\n";
  }

private:
  std::string root_;
};

inline const bool scratch_root_registered = [] {
  ::testing::UnitTest::GetInstance()->listeners().Append(new Scratch_root);
  return true;
}();

// A fresh scratch folder per test.
inline std::string scratch_folder(const std::string& test)
{
  const std::string folder = ::testing::TempDir() + "nonobtuse_" + test + "_" + std::to_string(::getpid());
  std::system(("rm -rf '" + folder + "' && mkdir -p '" + folder + "'").c_str());
  return folder;
}

// The names in `folder`, without "." and "..".
inline std::set<std::string> folder_entries(const std::string& folder)
{
  std::set<std::string> names;
  if(DIR* dir = ::opendir(folder.c_str())) {
    while(const dirent* e = ::readdir(dir))
      if(std::string(e->d_name) != "." && std::string(e->d_name) != "..") names.insert(e->d_name);
    ::closedir(dir);
  }
  return names;
}

} // namespace nonobtuse_test

#endif // NONOBTUSE_TEST_SUPPORT_H
