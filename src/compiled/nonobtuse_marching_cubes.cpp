// SPDX-License-Identifier: GPL-3.0-or-later
//
// NonobtuseRemeshing::Compiled: the initial mesh's core for Surface_mesh<Epick::Point_3>.

#define CGAL_NONOBTUSE_REMESHING_INSTANTIATE_MARCHING_CUBES
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
template Marching_cubes_result nonobtuse_marching_cubes_with(const Compiled_mesh&, Compiled_point_map,
                                                             Compiled_mesh&, Compiled_point_map, int, Sign_source,
                                                             int, double);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
