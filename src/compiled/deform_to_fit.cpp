// SPDX-License-Identifier: GPL-3.0-or-later
//
// NonobtuseRemeshing::Compiled: the fit's core for Surface_mesh<Epick::Point_3>.

#define CGAL_NONOBTUSE_REMESHING_INSTANTIATE_FIT
#include <CGAL/Nonobtuse_remeshing/deform_to_fit.h>
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
template Deform_to_fit_statistics deform_to_fit_with(Compiled_mesh&, Compiled_point_map, const Compiled_mesh&,
                                                     Compiled_point_map, const Deform_to_fit_options&, int,
                                                     const Keep_going_function<Deform_to_fit_statistics>&);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
