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
#include <CGAL/Nonobtuse_remeshing/internal/soup_readers.h>

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
#include <fstream>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// What `read_triangle_mesh()` found in the file and had to do to it.
struct Read_log
{
  /// each repair, one line
  std::vector<std::string> repairs;
  /// faces in the file, as written
  std::size_t faces_in_file = 0;
  /// faces with more than three vertices, triangulated
  std::size_t non_triangle_faces = 0;
  /// faces that repeat a vertex, dropped
  std::size_t faces_with_repeated_vertex = 0;
  /// faces that repeat another face (either orientation), merged into it
  std::size_t duplicate_faces = 0;
  /// OBJ `l` and `p` elements, ignored
  std::size_t ignored_elements = 0;

  /// True when the mesh holds every face of the file, each a triangle of three
  /// distinct vertices, as written (faces may have been reoriented and
  /// vertices duplicated or dropped, which changes no angle). A certificate of
  /// the mesh is a certificate of the file only then.
  bool faces_as_written() const
  {
    return non_triangle_faces == 0 && faces_with_repeated_vertex == 0 && duplicate_faces == 0;
  }

  /// Why `faces_as_written()` is false, as a phrase ("2 non-triangle faces, ...").
  std::string faces_changed() const
  {
    std::string text;
    const auto add = [&text](std::size_t n, const char* what) {
      if(n == 0) return;
      text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + what;
    };
    add(non_triangle_faces, "non-triangle face(s)");
    add(faces_with_repeated_vertex, "face(s) that repeat a vertex");
    add(duplicate_faces, "duplicate face(s)");
    return text;
  }
};

namespace internal {

inline std::string file_extension(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

inline bool is_mesh_extension(const std::string& ext)
{
  return ext == "off" || ext == "obj" || ext == "ply" || ext == "stl";
}

// True when the file holds a whitespace-separated token that reads as a
// non-finite number (nan, inf, 1e400): text readers stop there, and the user
// should hear the real reason.
inline bool has_non_finite_token(const std::string& path)
{
  std::ifstream in(path);
  std::string token;
  while(in >> token) {
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if(end != token.c_str() && *end == '\0' && !std::isfinite(value))
      return true;
  }
  return false;
}

template <typename Point>
void read_soup(const std::string& path, std::vector<Point>& points,
               std::vector<std::vector<std::size_t> >& polygons, std::size_t& ignored_elements)
{
  const std::string ext = file_extension(path);
  if(!is_mesh_extension(ext))
    throw Bad_input("unsupported file format '" + path + "' (expected .off, .obj, .ply or .stl)");
  struct stat status;
  if(::stat(path.c_str(), &status) != 0)
    throw Bad_input("cannot open '" + path + "': no such file");
  if(!S_ISREG(status.st_mode))
    throw Bad_input("cannot read '" + path + "': not a regular file");
  if(!std::ifstream(path, std::ios::binary))
    throw Bad_input("cannot open '" + path + "': permission denied");
  if(status.st_size == 0)
    throw Bad_input("'" + path + "' is empty");
  bool ok = false;
  try {
    if(ext == "stl") {
      check_STL_size(slurp_file(path));
      ok = CGAL::IO::read_STL(path, points, polygons);
    } else {
      const std::string contents = slurp_file(path);
      if(ext == "off") read_OFF_soup(contents, points, polygons);
      else if(ext == "obj") read_OBJ_soup(contents, points, polygons, ignored_elements);
      else read_PLY_soup(contents, points, polygons);
      ok = true;
    }
  } catch(const Format_error& e) {
    throw Bad_input("cannot parse '" + path + "' as " + ext + ": " + e.what());
  } catch(const std::bad_alloc&) {
    throw;  // not the file's fault: an internal failure
  } catch(const std::exception&) {
    ok = false;
  }
  if(!ok) {
    if(has_non_finite_token(path))
      throw Bad_input("'" + path + "' has a non-finite (nan or inf) coordinate");
    throw Bad_input("cannot parse '" + path + "' as " + ext + ": unreadable or malformed file");
  }
}

// Checks the soup read from `path`; drops faces that repeat a vertex, and
// repairs a soup that is not a valid polygon mesh, logging each repair.
template <typename Point>
void check_and_repair_soup(const std::string& path, std::vector<Point>& points,
                           std::vector<std::vector<std::size_t> >& polygons, Read_log& log)
{
  if(polygons.empty())
    throw Bad_input("'" + path + "' holds no face (empty mesh)");
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int k = 0; k < 3; ++k)
      if(!std::isfinite(CGAL::to_double(points[i][k])))
        throw Bad_input("'" + path + "': vertex " + std::to_string(i) +
                        " has a non-finite (nan or inf) coordinate");
  std::size_t repeated = 0;
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    const std::vector<std::size_t>& polygon = polygons[f];
    if(polygon.size() < 3)
      throw Bad_input("'" + path + "': face " + std::to_string(f) + " has fewer than 3 vertices");
    for(std::size_t v : polygon)
      if(v >= points.size())
        throw Bad_input("'" + path + "': face " + std::to_string(f) + " refers to vertex " +
                        std::to_string(v) + " but there are only " + std::to_string(points.size()));
  }
  polygons.erase(std::remove_if(polygons.begin(), polygons.end(),
                                [&](const std::vector<std::size_t>& polygon) {
                                  const std::set<std::size_t> distinct(polygon.begin(), polygon.end());
                                  const bool bad = distinct.size() != polygon.size();
                                  repeated += bad;
                                  return bad;
                                }),
                 polygons.end());
  log.faces_in_file = polygons.size() + repeated;
  log.faces_with_repeated_vertex = repeated;
  for(const auto& polygon : polygons) log.non_triangle_faces += (polygon.size() > 3);
  if(repeated > 0)
    log.repairs.push_back("removed " + std::to_string(repeated) +
                          " face(s) that repeat a vertex");
  if(polygons.empty())
    throw Bad_input("'" + path + "' holds no valid face (empty mesh)");

  // (the test costs much on polygons of many sides: it runs once when it passes)
  bool valid = Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
  if(!valid) {
    const std::size_t duplicates = Polygon_mesh_processing::merge_duplicate_polygons_in_polygon_soup(points, polygons);
    log.duplicate_faces = duplicates;
    if(duplicates > 0)
      log.repairs.push_back("merged " + std::to_string(duplicates) + " duplicate face(s) (same vertices, either orientation)");
    valid = duplicates > 0 && Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
  }
  if(!valid) {
    const std::size_t before = points.size();
    Polygon_mesh_processing::orient_polygon_soup(points, polygons);
    if(!Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
      throw Bad_input("'" + path + "' is not a valid polygon mesh and could not be repaired");
    log.repairs.push_back("not a valid polygon mesh (non-manifold or inconsistently oriented): "
                          "repaired with orient_polygon_soup, " +
                          std::to_string(points.size() - before) + " vertex(es) duplicated");
  }
}

} // namespace internal

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

namespace internal {

// The temporary files of the writes in progress, kept where a signal handler
// can read them without allocating: a fixed table of slots, each free (0),
// being filled (1) or holding a path (2).
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

} // namespace internal

/// \ingroup PkgNonobtuseRemeshingRef
/// Removes the temporary files of the atomic writes in progress (see
/// `write_file_atomically()`). Async-signal-safe: a program calls it from its
/// SIGINT, SIGTERM and SIGHUP handlers so that an interrupted write leaves nothing
/// behind (the target file is untouched until the final rename).
inline void remove_temporary_files() noexcept
{
  internal::Temporary_files& files = internal::Temporary_files::instance();
  for(int i = 0; i < internal::Temporary_files::slots; ++i)
    if(files.state[i].load() == 2) ::unlink(files.paths[i]);
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
  // "." + name + ".tmp-PID-N.EXT", the name cut so that the whole fits a
  // file name (255 bytes)
  const std::string suffix = ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
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

#endif // CGAL_NONOBTUSE_REMESHING_MESH_IO_H
