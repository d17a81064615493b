// SPDX-License-Identifier: GPL-3.0-or-later
//
// NonobtuseRemeshing::Compiled: the valence stage's core for Surface_mesh<Epick::Point_3>.

#define CGAL_NONOBTUSE_REMESHING_INSTANTIATE_VALENCE
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
#include <CGAL/Nonobtuse_remeshing/remove_bad_valence_vertices.h>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
template Bad_valence_removal_statistics remove_bad_valence_vertices_with(Compiled_mesh&, Compiled_point_map, int,
                                                                         bool);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
