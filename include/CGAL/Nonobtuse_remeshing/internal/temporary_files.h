// SPDX-License-Identifier: GPL-3.0-or-later
//
// The temporary files of the atomic writes in progress (mesh_io.h): their
// names, and a table a signal handler can read to remove them.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_TEMPORARY_FILES_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_TEMPORARY_FILES_H

#include <atomic>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// The temporary files of the writes in progress, kept where a signal handler
// can read them without allocating: a fixed table of slots, each free (0),
// being filled (1) or holding a path (2).
// A number of this process for the names of its temporary files (the
// folder may be shared with other processes; the counter tells this
// process's files apart).
inline unsigned long process_token()
{
  static const unsigned long token = [] {
    std::random_device device;
    return (static_cast<unsigned long>(device()) << 16) ^ static_cast<unsigned long>(device());
  }();
  return token;
}

struct Temporary_files
{
  static constexpr int slots = 16;
  static constexpr std::size_t length = 4096;
  std::atomic<int> state[slots] = {};
  char paths[slots][length] = {};

  static Temporary_files& instance()
  {
    static Temporary_files files;
    return files;
  }

  // returns the slot, or -1 when the path is too long or every slot is taken
  int add(const std::string& path)
  {
    if(path.size() >= length) return -1;
    for(int i = 0; i < slots; ++i) {
      int expected = 0;
      if(state[i].compare_exchange_strong(expected, 1)) {
        std::memcpy(paths[i], path.c_str(), path.size() + 1);
        state[i].store(2);
        return i;
      }
    }
    return -1;
  }

  void remove(int slot)
  {
    if(slot >= 0) state[slot].store(0);
  }
};

// Removes the file `path` from a signal handler: POSIX lists unlink, not
// std::remove, as async-signal-safe; elsewhere std::remove is what there is.
inline void remove_file_in_signal_handler(const char* path) noexcept
{
#if defined(__unix__) || defined(__APPLE__)
  ::unlink(path);
#else
  std::remove(path);
#endif
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_TEMPORARY_FILES_H
