// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checked reading and atomic, full-precision writing of triangle meshes.
//
// Reading goes through a polygon soup so that nothing is repaired silently:
// the soup is checked, repaired only when it is not a valid polygon mesh, and
// every repair is reported. Writing goes to a temporary file in the target's
// folder, with max_digits10 digits (or binary PLY), and is renamed over the
// target only once complete, so the file holds exactly the doubles in memory.

#ifndef CGAL_NONOBTUSE_REMESHING_MESH_IO_H
#define CGAL_NONOBTUSE_REMESHING_MESH_IO_H

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/soup_checks.h>
#include <CGAL/Nonobtuse_remeshing/internal/temporary_files.h>
#include <CGAL/Nonobtuse_remeshing/read_log.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// Reads an OFF, OBJ, PLY or STL file into the triangle mesh `mesh` (cleared
/// first). Throws `Bad_input` with a one-line message when the file is
/// missing, unreadable, empty, has non-finite coordinates, bad face indices,
/// or is a polygon soup that cannot be made a polygon mesh. Non-triangle faces
/// are triangulated and invalid soups repaired; `log` says what was done.
template <typename PolygonMesh>
void read_triangle_mesh(const std::string& path, PolygonMesh& mesh, Read_log& log)
{
  using Point = typename boost::property_traits<
      typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type;
  log = Read_log();
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  internal::read_soup(path, points, polygons, log.ignored_elements);
  if(log.ignored_elements > 0)
    log.repairs.push_back("ignored " + std::to_string(log.ignored_elements) +
                          " polyline or point element(s) (OBJ 'l' and 'p' lines)");
  internal::check_and_repair_soup(path, points, polygons, log);

  // vertices used by no face are dropped, the others renumbered
  std::vector<std::size_t> index(points.size(), std::size_t(-1));
  for(const auto& polygon : polygons)
    for(std::size_t v : polygon) index[v] = 0;
  std::size_t kept = 0;
  for(std::size_t v = 0; v < points.size(); ++v)
    if(index[v] == 0) {
      points[kept] = points[v];
      index[v] = kept++;
    }
  if(kept < points.size()) {
    log.repairs.push_back("ignored " + std::to_string(points.size() - kept) + " vertex(es) used by no face");
    points.resize(kept);
    for(auto& polygon : polygons)
      for(std::size_t& v : polygon) v = index[v];
  }

  clear(mesh);
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(!is_triangle_mesh(mesh)) {
    if(!Polygon_mesh_processing::triangulate_faces(mesh))
      throw Bad_input("'" + path + "': a non-triangle face could not be triangulated");
    log.repairs.push_back("triangulated " + std::to_string(log.non_triangle_faces) +
                          " non-triangle face(s)");
  }
}

template <typename PolygonMesh>
void read_triangle_mesh(const std::string& path, PolygonMesh& mesh)
{
  Read_log log;
  read_triangle_mesh(path, mesh, log);
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Removes the temporary files of the atomic writes in progress (see
/// `write_file_atomically()`). Async-signal-safe: a program calls it from its
/// SIGINT, SIGTERM and SIGHUP handlers so that an interrupted write leaves nothing
/// behind (the target file is untouched until the final rename).
inline void remove_temporary_files() noexcept
{
  internal::Temporary_files& files = internal::Temporary_files::instance();
  for(int i = 0; i < internal::Temporary_files::slots; ++i)
    if(files.state[i].load() == 2) internal::remove_file_in_signal_handler(files.paths[i]);
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Writes `path` atomically: `write_contents(temporary_path)` fills a
/// temporary file in the same folder (its name ends with the same extension),
/// `check(temporary_path)`, if given, may reject it by returning false, and
/// only then is it renamed over `path`. On any failure the temporary file is
/// removed, `path` is left untouched and `Output_error` is thrown.
inline void write_file_atomically(const std::string& path,
                                  const std::function<bool(const std::string&)>& write_contents,
                                  const std::function<bool(const std::string&)>& check = nullptr)
{
  static std::atomic<unsigned> counter{0};
  const std::size_t slash = path.find_last_of('/');
  const std::string folder = (slash == std::string::npos) ? std::string() : path.substr(0, slash + 1);
  const std::string name = (slash == std::string::npos) ? path : path.substr(slash + 1);
  if(name.empty())
    throw Output_error("cannot write '" + path + "': not a file name");
  const std::string ext = internal::file_extension(name);
  // "." + name + ".tmp-TOKEN-N.EXT", the name cut so that the whole fits a
  // file name (255 bytes)
  const std::string suffix = ".tmp-" + std::to_string(internal::process_token()) + "-" + std::to_string(counter++) +
                             (ext.empty() ? "" : "." + ext);
  const std::size_t room = 255 - 1 - suffix.size();
  const std::string temporary = folder + "." + name.substr(0, room) + suffix;
  const int slot = internal::Temporary_files::instance().add(temporary);
  struct Unregister
  {
    int slot;
    ~Unregister() { internal::Temporary_files::instance().remove(slot); }
  } unregister{slot};
  bool written = false;
  try {
    written = write_contents(temporary);
  } catch(const std::exception&) {
    written = false;
  }
  if(!written) {
    std::remove(temporary.c_str());
    throw Output_error("cannot write '" + path + "' (folder missing or not writable?)");
  }
  bool accepted = true;
  try {
    accepted = !check || check(temporary);
  } catch(...) {
    std::remove(temporary.c_str());  // no temporary file is left behind, whatever the check throws
    throw;
  }
  if(!accepted) {
    std::remove(temporary.c_str());
    throw Output_error("refused to write '" + path + "': the written file failed its check");
  }
  if(std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw Output_error("cannot write '" + path + "': rename failed");
  }
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Writes the text `contents` to `path` atomically, as `write_file_atomically()`.
inline void write_text_atomically(const std::string& path, const std::string& contents,
                                  const std::function<bool(const std::string&)>& check = nullptr)
{
  write_file_atomically(
      path,
      [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << contents;
        out.close();
        return bool(out);
      },
      check);
}

/// \ingroup PkgNonobtuseRemeshingRef
/// Writes the triangle mesh `mesh` to `path` (format by extension: OFF, OBJ,
/// ASCII STL with max_digits10 digits, or binary PLY with doubles), atomically
/// as `write_file_atomically()`. `check`, if given, sees the temporary file
/// before the rename and may reject it.
template <typename PolygonMesh>
void write_mesh_atomically(const std::string& path, const PolygonMesh& mesh,
                           const std::function<bool(const std::string&)>& check = nullptr)
{
  const std::string ext = internal::file_extension(path);
  if(!internal::is_mesh_extension(ext))
    throw Output_error("cannot write '" + path + "': unsupported extension (expected .off, .obj, .ply or .stl)");
  write_file_atomically(
      path,
      [&](const std::string& temporary) {
        return CGAL::IO::write_polygon_mesh(
            temporary, mesh,
            CGAL::parameters::stream_precision(std::numeric_limits<double>::max_digits10)
                .use_binary_mode(ext == "ply"));
      },
      check);
}

/// \ingroup PkgNonobtuseRemeshingRef
/// A `check` for `write_mesh_atomically()` that makes the guarantee hold on
/// the file itself: it re-reads the temporary file and accepts it only if its
/// faces are read as written (see `Read_log::faces_as_written()`), certify
/// exactly in [30, 90] degrees and are as many as those of `mesh`. If
/// `file_faces` is given, it receives the faces of the file. `mesh` must outlive
/// the check.
///
///   write_mesh_atomically("out.off", mesh, certifying_check(mesh));  // throws Output_error if refused
template <typename TriangleMesh>
std::function<bool(const std::string&)> certifying_check(const TriangleMesh& mesh, std::size_t* file_faces = nullptr)
{
  return [&mesh, file_faces](const std::string& temporary) {
    TriangleMesh reread;
    Read_log log;
    try {
      read_triangle_mesh(temporary, reread, log);
    } catch(const Bad_input&) {  // e.g. a mesh without faces: it does not certify
      return false;
    }
    const Angle_certificate certificate = certify_angle_bounds(reread);
    if(file_faces) *file_faces = certificate.faces;
    return certificate.is_certified() && log.faces_as_written() && certificate.faces == faces(mesh).size();
  };
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

// With NonobtuseRemeshing::Compiled (compiled_surface_mesh.h): the declarations
// of its instantiations; src/compiled/mesh_io.cpp defines
// CGAL_NONOBTUSE_REMESHING_INSTANTIATE_MESH_IO, and there they are the instantiations.
#ifdef CGAL_NONOBTUSE_REMESHING_COMPILED
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
namespace CGAL {
namespace Nonobtuse_remeshing {
#ifndef CGAL_NONOBTUSE_REMESHING_INSTANTIATE_MESH_IO
extern
#endif
template void read_triangle_mesh(const std::string&, internal::Compiled_mesh&, Read_log&);
#ifndef CGAL_NONOBTUSE_REMESHING_INSTANTIATE_MESH_IO
extern
#endif
template void write_mesh_atomically(const std::string&, const internal::Compiled_mesh&,
                                    const std::function<bool(const std::string&)>&);
} // namespace Nonobtuse_remeshing
} // namespace CGAL
#endif

#endif // CGAL_NONOBTUSE_REMESHING_MESH_IO_H
