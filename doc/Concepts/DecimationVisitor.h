/*!
\ingroup PkgNonobtuseRemeshingConcepts
\cgalConcept

The visitor of `CGAL::Nonobtuse_remeshing::angle_bounded_decimation()` and
`CGAL::Nonobtuse_remeshing::angle_bounded_decimation_hierarchy()`, given as their named parameter
`decimation_visitor`: the decimation tells it its statistics while it runs, and it may cancel the
decimation.

A visitor given by value is copied and the copy is called, so its type must be copy
constructible; given as `std::ref(visitor)`, the visitor itself is called and keeps its state.

\cgalHasModel{`CGAL::Nonobtuse_remeshing::Default_visitor`}

The model `Default_visitor` never cancels.
*/
class DecimationVisitor
{
public:
  /// \name Operations
  /// @{

  /*!
  Called before each edge collapse, while a target vertex count is left and the cheapest
  collapse is within the cost ceiling of the round, and, with the named parameter `relaxation`
  (the default), before each round of vertex moves of the deform-to-fit runs between rounds.
  `statistics` are those of the decimation, also during these fits.

  Returning `false` stops the decimation with `stop_reason` equal to
  `Decimation_stop_reason::cancelled`; the mesh is certified. In a hierarchy, the level being
  decimated then holds the mesh where it stopped, with `reached` false, and the levels after it
  are left out.
  */
  bool keep_going(const CGAL::Nonobtuse_remeshing::Angle_bounded_decimation_statistics& statistics);

  /// @}
};
