// SPDX-License-Identifier: GPL-3.0-or-later
//
// NonobtuseRemeshing::Compiled: the pipeline's core for Surface_mesh<Epick::Point_3>
// (its stages' cores are instantiated by the other files of src/compiled).

#define CGAL_NONOBTUSE_REMESHING_INSTANTIATE_PIPELINE
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_remesh.h>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
template Nonobtuse_remeshing_statistics nonobtuse_remesh_with(const Compiled_mesh&, Compiled_mesh&,
                                                              const Remeshing_settings&);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
