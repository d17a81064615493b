// SPDX-License-Identifier: GPL-3.0-or-later
//
// NonobtuseRemeshing::Compiled: the quality report's core for Surface_mesh<Epick::Point_3>.

#define CGAL_NONOBTUSE_REMESHING_INSTANTIATE_QUALITY_REPORT
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
#include <CGAL/Nonobtuse_remeshing/quality_report.h>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
template Quality_report quality_report_with(const Compiled_mesh&, const Compiled_mesh*, std::size_t, double,
                                            const Angle_certificate<Compiled_mesh::Face_index>&);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
