// SPDX-License-Identifier: GPL-3.0-or-later
//
// What reading a mesh file found and did (mesh_io.h): the faces as written,
// and every repair.

#ifndef CGAL_NONOBTUSE_REMESHING_READ_LOG_H
#define CGAL_NONOBTUSE_REMESHING_READ_LOG_H

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
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

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_READ_LOG_H
