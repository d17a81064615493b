// SPDX-License-Identifier: GPL-3.0-or-later
//
// NonobtuseRemeshing::Compiled: reading and writing Surface_mesh<Epick::Point_3>.

#define CGAL_NONOBTUSE_REMESHING_INSTANTIATE_MESH_IO
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>

namespace CGAL {
namespace Nonobtuse_remeshing {
template void read_triangle_mesh(const std::string&, internal::Compiled_mesh&, Read_log&);
template void write_mesh_atomically(const std::string&, const internal::Compiled_mesh&,
                                    const std::function<bool(const std::string&)>&);
} // namespace Nonobtuse_remeshing
} // namespace CGAL
