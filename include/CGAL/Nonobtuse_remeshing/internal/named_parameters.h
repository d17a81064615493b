// SPDX-License-Identifier: GPL-3.0-or-later
//
// The machinery of parameters.h: chaining named-parameter lists (combine()),
// and visitors passed by value or by std::ref.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_NAMED_PARAMETERS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <functional>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace parameters {
namespace internal {

// Rebuilds the chain `np` on top of `base`: the result holds every parameter of
// both, those of `np` looked up first.
template <typename Base, typename T, typename Tag>
Named_function_parameters<T, Tag, Base>
append(const Base& base, const Named_function_parameters<T, Tag>& np)
{
  return Named_function_parameters<T, Tag, Base>(np.v, base);
}

template <typename Base, typename T, typename Tag, typename NpBase>
auto append(const Base& base, const Named_function_parameters<T, Tag, NpBase>& np)
{
  const NpBase& rest = np;
  auto chained = internal::append(base, rest);
  return Named_function_parameters<T, Tag, decltype(chained)>(np.v, chained);
}

} // namespace internal
} // namespace parameters

namespace internal {

// A visitor given by value is copied, one given with std::ref is used in place.
template <typename Visitor>
Visitor& visitor_reference(Visitor& v) { return v; }
template <typename Visitor>
Visitor& visitor_reference(std::reference_wrapper<Visitor>& v) { return v.get(); }

// A visitor whose keep_going() asks `ask(statistics)`: how a stage run inside
// another (the fit in the pipeline, the relaxation in the decimation) passes
// its progress on to the outer stage's visitor.
template <typename Ask>
struct Keep_going_relay
{
  Ask ask;
  template <typename Statistics>
  bool keep_going(const Statistics& statistics)
  {
    return ask(statistics);
  }
};

template <typename Ask>
Keep_going_relay<Ask> keep_going_relay(Ask ask)
{
  return Keep_going_relay<Ask>{ask};
}

// A visitor's keep_going() behind a fixed type: the stages' cores take this,
// so that they are instantiated once per mesh type whatever the visitor
// (compiled_surface_mesh.h).
template <typename Statistics>
using Keep_going_function = std::function<bool(const Statistics&)>;

template <typename Statistics, typename Visitor>
Keep_going_function<Statistics> keep_going_function(Visitor& visitor)
{
  return [&visitor](const Statistics& s) { return bool(visitor.keep_going(s)); };
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_NAMED_PARAMETERS_H
