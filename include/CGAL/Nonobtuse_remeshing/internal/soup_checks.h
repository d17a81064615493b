// SPDX-License-Identifier: GPL-3.0-or-later
//
// The first half of reading a mesh file (mesh_io.h): the file is read as a
// polygon soup, checked, and repaired only when it is not a valid polygon
// mesh, every repair logged; nothing is repaired silently.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_SOUP_CHECKS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_SOUP_CHECKS_H

#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/soup_readers.h>
#include <CGAL/Nonobtuse_remeshing/read_log.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
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
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if(error || !std::filesystem::exists(status))
    throw Bad_input("cannot open '" + path + "': no such file");
  if(!std::filesystem::is_regular_file(status))
    throw Bad_input("cannot read '" + path + "': not a regular file");
  if(!std::ifstream(path, std::ios::binary))
    throw Bad_input("cannot open '" + path + "': permission denied");
  if(std::filesystem::file_size(path, error) == 0 && !error)
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
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_SOUP_CHECKS_H
