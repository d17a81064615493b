// SPDX-License-Identifier: GPL-3.0-or-later
//
// What differs between mesh types and the package must do alike on all of
// them: removing garbage, and emptying a mesh without removing its property
// maps.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_MESH_HELPERS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_MESH_HELPERS_H

#include <CGAL/boost/graph/helpers.h>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// Removes a Surface_mesh's garbage; meshes without garbage have nothing to do.
template <typename Mesh>
auto collect_garbage_of(Mesh& mesh, int) -> decltype(mesh.collect_garbage(), void())
{
  mesh.collect_garbage();
}
template <typename Mesh>
void collect_garbage_of(Mesh&, long) {}

// Empties `mesh` but keeps the property maps a user added to it (a
// Surface_mesh's clear() removes them, and a point map among them would dangle).
template <typename Mesh>
auto clear_keeping_maps(Mesh& mesh, int) -> decltype(mesh.clear_without_removing_property_maps(), void())
{
  mesh.clear_without_removing_property_maps();
}
template <typename Mesh>
void clear_keeping_maps(Mesh& mesh, long)
{
  clear(mesh);
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_MESH_HELPERS_H
