// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default visitor of every stage: one class for the three visitor
// concepts (DeformToFitVisitor, DecimationVisitor, RemeshingVisitor), which
// share their one operation, keep_going() with the stage's statistics.

#ifndef CGAL_NONOBTUSE_REMESHING_VISITORS_H
#define CGAL_NONOBTUSE_REMESHING_VISITORS_H

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// The default visitor of `deform_to_fit()`, `angle_bounded_decimation()`,
/// `angle_bounded_decimation_hierarchy()` and `nonobtuse_remesh()`: never
/// cancels, and ignores the stages starting and finishing. A model of
/// `DeformToFitVisitor`, `DecimationVisitor` and `RemeshingVisitor`. A
/// visitor of one's own needs only the members its function calls.
struct Default_visitor
{
  /// called with the statistics so far (or the pipeline's `Remeshing_progress`); true: go on
  template <typename Statistics>
  bool keep_going(const Statistics&)
  {
    return true;
  }
  /// `nonobtuse_remesh()` only: a stage starts
  template <typename Stage>
  void stage_started(Stage)
  {
  }
  /// `nonobtuse_remesh()` only: a stage finished after `seconds`
  template <typename Stage>
  void stage_finished(Stage, double /* seconds */)
  {
  }
};

/// \ingroup PkgNonobtuseRemeshingRef
/// The default `fit_visitor` of `deform_to_fit()`.
using Default_deform_to_fit_visitor = Default_visitor;
/// \ingroup PkgNonobtuseRemeshingRef
/// The default `decimation_visitor` of `angle_bounded_decimation()`.
using Default_decimation_visitor = Default_visitor;
/// \ingroup PkgNonobtuseRemeshingRef
/// The default `remeshing_visitor` of `nonobtuse_remesh()`.
using Default_remeshing_visitor = Default_visitor;

} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_VISITORS_H
