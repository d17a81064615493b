/*!
\ingroup PkgNonobtuseRemeshingConcepts
\cgalConcept

The visitor of `CGAL::Nonobtuse_remeshing::deform_to_fit()`, given as its named parameter
`fit_visitor`: the fit tells it its statistics while it runs, and it may cancel the fit.

A visitor given by value is copied and the copy is called, so its type must be copy
constructible; given as `std::ref(visitor)`, the visitor itself is called and keeps its state.

`CGAL::Nonobtuse_remeshing::nonobtuse_remesh()` gives the fit a visitor of its own, which passes
the fit's progress on to its `RemeshingVisitor`; a `fit_visitor` among its named parameters is not
used.

\cgalHasModel{`CGAL::Nonobtuse_remeshing::Default_visitor`}

The model `Default_visitor` never cancels.

\sa `RemeshingVisitor`
*/
class DeformToFitVisitor
{
public:
  /// \name Operations
  /// @{

  /*!
  Called by `deform_to_fit()` before each round of moves (at most 32 vertices that share no edge,
  moved at the same time; a colour class, or a part of one, in the smoothing passes) and before
  each move of the untangling at the end, unless the budget of `max_moves` or `max_seconds` is
  exhausted. `statistics` are those of the fit so far;
  `statistics.stage` says whether it is optimizing or smoothing.

  Returning `false` stops the fit: the moves made so far stay, the mesh is certified, no
  untangling follows, the returned statistics have `cancelled` set, and the visitor is not
  called again.
  */
  bool keep_going(const CGAL::Nonobtuse_remeshing::Deform_to_fit_statistics& statistics);

  /// @}
};
