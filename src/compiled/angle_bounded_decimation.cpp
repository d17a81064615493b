// SPDX-License-Identifier: GPL-3.0-or-later
//
// NonobtuseRemeshing::Compiled: the decimation's core for Surface_mesh<Epick::Point_3>.

#define CGAL_NONOBTUSE_REMESHING_INSTANTIATE_DECIMATION
#include <CGAL/Nonobtuse_remeshing/angle_bounded_decimation.h>
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
template Angle_bounded_decimation_statistics angle_bounded_decimation_with(
    Compiled_mesh&, Compiled_point_map, const Angle_bounded_decimation_options&, double,
    const std::vector<std::size_t>&, const Compiled_mesh&, Compiled_point_map,
    const Keep_going_function<Angle_bounded_decimation_statistics>&,
    const std::function<void(std::size_t, bool, const Angle_bounded_decimation_statistics&)>&);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
