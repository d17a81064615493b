/*!
\ingroup PkgNonobtuseRemeshingConcepts
\cgalConcept

The visitor of `CGAL::Nonobtuse_remeshing::nonobtuse_remesh()`, given as its named parameter
`remeshing_visitor`: the pipeline tells it when each stage starts and ends and how the fit
progresses, and it may cancel the pipeline.

A visitor given by value is copied and the copy is called, so its type must be copy
constructible; given as `std::ref(visitor)`, the visitor itself is called and keeps its state.

The stages are those of `CGAL::Nonobtuse_remeshing::Remeshing_stage`, in their order; a stage
that is not run (the valence stage with `valence_cleanup` false, the stages after `stop_after`,
the decimation when the fitted mesh is not over a `target_vertices` count by more than 10%)
causes no call.

\cgalHasModel{`CGAL::Nonobtuse_remeshing::Default_visitor`}

The model `Default_visitor` does nothing and never cancels.

\sa `DeformToFitVisitor`
*/
class RemeshingVisitor
{
public:
  /// \name Operations
  /// @{

  /*!
  Called when `stage` starts, after `keep_going()` has let it start.
  */
  void stage_started(CGAL::Nonobtuse_remeshing::Remeshing_stage stage);

  /*!
  Called when `stage` has returned, also when the visitor cancelled the fit, with the time the
  stage took in seconds. It is not called for a stage that throws.
  */
  void stage_finished(CGAL::Nonobtuse_remeshing::Remeshing_stage stage, double seconds);

  /*!
  Called before each stage starts, and before each refinement of the initial mesh for its topology,
  with `progress.stage` that stage, `progress.fraction` 0 and
  `progress.fit` and `progress.decimation` null; during the fit, as a `DeformToFitVisitor` is,
  before each round of vertex moves, with `progress.stage` `Remeshing_stage::fit`,
  `progress.fraction` -1 and `progress.fit` pointing to the fit's statistics so far; and during
  the decimation (which runs only when the fitted mesh is over a `target_vertices` count), as a
  `DecimationVisitor` is, with `progress.stage` `Remeshing_stage::decimation`, `progress.fraction`
  -1 and `progress.decimation` pointing to the decimation's statistics so far.

  Returning `false` stops the pipeline there: the stages not yet started do not run, the returned
  statistics have `cancelled` set, and the output is certified, or empty if the initial mesh was
  not built yet.
  */
  bool keep_going(const CGAL::Nonobtuse_remeshing::Remeshing_progress& progress);

  /// @}
};
