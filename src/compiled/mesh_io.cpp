// SPDX-License-Identifier: GPL-3.0-or-later
//
// NonobtuseRemeshing::Compiled: reading and writing, for Surface_mesh<Epick::Point_3>.
// With this macro, the declarations at the end of the header are the
// explicit instantiations themselves.

#define CGAL_NONOBTUSE_REMESHING_INSTANTIATE_MESH_IO
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>
