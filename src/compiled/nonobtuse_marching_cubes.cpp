// SPDX-License-Identifier: GPL-3.0-or-later
//
// NonobtuseRemeshing::Compiled: the initial mesh's core, for Surface_mesh<Epick::Point_3>.
// With this macro, the declarations at the end of the header are the
// explicit instantiations themselves.

#define CGAL_NONOBTUSE_REMESHING_INSTANTIATE_MARCHING_CUBES
#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>
