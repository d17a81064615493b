// Helpers shared by the library tests: the shipped sample meshes.

#ifndef NONOBTUSE_TEST_SUPPORT_H
#define NONOBTUSE_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>

#include <string>

namespace nonobtuse_test {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

inline std::string data(const std::string& name) { return std::string(NONOBTUSE_TEST_DATA) + "/" + name; }

inline Mesh load(const std::string& name)
{
  Mesh mesh;
  CGAL::Nonobtuse_remeshing::read_triangle_mesh(data(name), mesh);
  return mesh;
}

} // namespace nonobtuse_test

#endif // NONOBTUSE_TEST_SUPPORT_H
