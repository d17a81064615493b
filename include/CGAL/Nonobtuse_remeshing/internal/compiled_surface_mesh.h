// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh type whose stage cores the library NonobtuseRemeshing::Compiled
// instantiates once (src/compiled/): CGAL::Surface_mesh with the points of
// Exact_predicates_inexact_constructions_kernel. A translation unit built
// with CGAL_NONOBTUSE_REMESHING_COMPILED (that target sets it) sees explicit
// instantiation declarations of those cores at the end of their headers and
// leaves their instantiation to the library; any other mesh or point map is
// instantiated in place, as without the library.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_COMPILED_SURFACE_MESH_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_COMPILED_SURFACE_MESH_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

using Compiled_mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
// its internal point map (const_type and type are one type for Surface_mesh)
using Compiled_point_map = boost::property_map<Compiled_mesh, CGAL::vertex_point_t>::type;

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_COMPILED_SURFACE_MESH_H
