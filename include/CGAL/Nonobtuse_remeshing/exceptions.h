// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exceptions of the Nonobtuse_remeshing package: one type for a bad
// parameter, one for a mesh or file the function cannot work on, one for an
// output that cannot be written. Internal invariants are CGAL's assertions
// and errors (CGAL::Failure_exception).

#ifndef CGAL_NONOBTUSE_REMESHING_EXCEPTIONS_H
#define CGAL_NONOBTUSE_REMESHING_EXCEPTIONS_H

#include <stdexcept>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// Thrown for a named parameter, or another argument that is not a mesh,
/// outside its range (a usage error), before any work is done. The message
/// is one line naming the parameter and its range.
struct Bad_parameter : std::invalid_argument
{
  using std::invalid_argument::invalid_argument;
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Thrown when a mesh or a file does not meet what the function needs: a
/// file that cannot be read as a triangle mesh, a mesh that is not a triangle
/// mesh, has no face or no size, is not certified where a certified mesh is
/// needed, or is too small, too thin or too far from the origin for the
/// resolution. The message is one line naming the problem; the mesh being
/// changed is left as it was (see each function).
struct Bad_input : std::invalid_argument
{
  using std::invalid_argument::invalid_argument;
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Thrown by `nonobtuse_marching_cubes()` (and so by `nonobtuse_remesh()`)
/// before the initial mesh is built when it would need more memory than the
/// `memory_budget` named parameter allows. The message gives the estimate.
struct Memory_budget_exceeded : Bad_input
{
  using Bad_input::Bad_input;
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Thrown when an output file cannot be written.
struct Output_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_EXCEPTIONS_H
