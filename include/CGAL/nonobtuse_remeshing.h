// SPDX-License-Identifier: GPL-3.0-or-later
//
// Umbrella header of the Nonobtuse_remeshing package: remeshing of triangulated
// surfaces into meshes whose angles all lie in [30, 90] degrees, certified
// exactly (after Li, "Nonobtuse meshes with guaranteed angle bounds").
//
// The package lives in namespace CGAL::Nonobtuse_remeshing. Stages available:
//   nonobtuse_remesh()      the whole pipeline: the stages below, the decimation
//                           only down to a target vertex count
//   nonobtuse_marching_cubes()  the initial mesh (thesis, chapter 4)
//   remove_bad_valence_vertices()  bad valences out, by removal and split (5.7)
//   deform_to_fit()         the fit with constrained smoothing (chapter 5)
//   angle_bounded_decimation(), angle_bounded_decimation_hierarchy()  (chapter 6)
//   levels_of_detail()      each level the closer of its decimation and a rebuild
//   certify_angle_bounds()  exact certification of the angle bounds
//   quality_report()        angles, valences, topology, defects, distances
//   read_triangle_mesh(), write_mesh_atomically()  checked, exact file IO
//   write_angle_histogram_svg(), write_mesh_colored_by_angle_atomically()  pictures

#ifndef CGAL_NONOBTUSE_REMESHING_H
#define CGAL_NONOBTUSE_REMESHING_H

/// \defgroup PkgNonobtuseRemeshingRef Reference of the Nonobtuse_remeshing package
/// Functions, results, visitors and parameters of namespace
/// `CGAL::Nonobtuse_remeshing`: the pipeline `nonobtuse_remesh()`, its
/// stages, the exact certification, the quality report, checked file IO and
/// the pictures. The user manual is the main page.

#include <CGAL/Nonobtuse_remeshing/parameters.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/statistics.h>
#include <CGAL/Nonobtuse_remeshing/visitors.h>
#include <CGAL/Nonobtuse_remeshing/angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/read_log.h>
#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/quality_report.h>
#include <CGAL/Nonobtuse_remeshing/mesh_io.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>
#include <CGAL/Nonobtuse_remeshing/remove_bad_valence_vertices.h>
#include <CGAL/Nonobtuse_remeshing/deform_to_fit.h>
#include <CGAL/Nonobtuse_remeshing/angle_bounded_decimation.h>
#include <CGAL/Nonobtuse_remeshing/remeshing_stages.h>
#include <CGAL/Nonobtuse_remeshing/resolution_for_target_vertices.h>
#include <CGAL/Nonobtuse_remeshing/nonobtuse_remesh.h>
#include <CGAL/Nonobtuse_remeshing/levels_of_detail.h>
#include <CGAL/Nonobtuse_remeshing/angle_pictures.h>

#endif // CGAL_NONOBTUSE_REMESHING_H
