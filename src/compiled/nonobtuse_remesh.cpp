// SPDX-License-Identifier: GPL-3.0-or-later
//
// NonobtuseRemeshing::Compiled: the pipeline's core, for Surface_mesh<Epick::Point_3>
// (its stages' cores are in the other files of src/compiled).
// With this macro, the declarations at the end of the header are the
// explicit instantiations themselves.

#define CGAL_NONOBTUSE_REMESHING_INSTANTIATE_PIPELINE
#include <CGAL/Nonobtuse_remeshing/nonobtuse_remesh.h>
