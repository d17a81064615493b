// SPDX-License-Identifier: GPL-3.0-or-later
//
// The initial mesh: nonobtuse Marching Cubes, patch-based so that open and
// self-intersecting inputs work (thesis, chapter 4).

#ifndef CGAL_NONOBTUSE_REMESHING_NONOBTUSE_MARCHING_CUBES_H
#define CGAL_NONOBTUSE_REMESHING_NONOBTUSE_MARCHING_CUBES_H

#include <CGAL/Nonobtuse_remeshing/certify_angle_bounds.h>
#include <CGAL/Nonobtuse_remeshing/exceptions.h>
#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>
#include <CGAL/Nonobtuse_remeshing/internal/grid.h>
#include <CGAL/Nonobtuse_remeshing/internal/input_triangles.h>
#include <CGAL/Nonobtuse_remeshing/internal/inside_test.h>
#include <CGAL/Nonobtuse_remeshing/internal/marching_cubes_table.h>
#include <CGAL/Nonobtuse_remeshing/internal/mesh_helpers.h>
#include <CGAL/Nonobtuse_remeshing/internal/mesh_cube_intersection.h>
#include <CGAL/Nonobtuse_remeshing/internal/patches_and_signs.h>
#include <CGAL/Nonobtuse_remeshing/internal/stitching.h>
#include <CGAL/Nonobtuse_remeshing/internal/winding_number_signs.h>
#include <CGAL/Nonobtuse_remeshing/parameters.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {

/// \ingroup PkgNonobtuseRemeshingRef
/// Where the corner signs of the Marching Cubes come from.
enum class Sign_source
{
  /// `patches`, except in the cubes where the input overlaps itself or has a
  /// gap (a border cycle smaller than a cube), which are signed by the
  /// generalized winding number: the surface of what the input encloses (the
  /// union of overlapping parts) stays closed there; on inputs without
  /// self-intersections and gaps, exactly `patches`
  automatic,
  /// per cube and per patch of input triangles, from the orientation of the
  /// patch (thesis, section 4.2.2); works for open inputs
  patches,
  /// one sign per grid corner from the generalized winding number (inside
  /// where it is 1 or more: the union of overlapping parts): closed or nearly
  /// closed inputs, self-intersecting ones included; gaps smaller than about a
  /// cube are closed, larger holes stay open (no cube there holds a triangle)
  winding_number,
  /// one sign per grid corner from an exact inside/outside test (ray parity:
  /// where parts overlap, the overlap is outside); closed inputs only
  inside_test
};

/// \ingroup PkgNonobtuseRemeshingRef
/// Default of the `memory_budget` named parameter: 4 GiB.
constexpr double default_memory_budget = 4. * 1024. * 1024. * 1024.;

/// \ingroup PkgNonobtuseRemeshingRef
/// Result of `nonobtuse_marching_cubes()`: the statistics of the thesis's
/// Table 4.1, and the correspondence between output faces and input patches.
struct Marching_cubes_result
{
  int resolution = 0;
  double cube_size = 0.;
  std::size_t input_triangles = 0;
  std::size_t degenerate_input_triangles = 0;  ///< ignored: they have no orientation
  std::size_t cubes_intersected = 0;
  std::size_t cubes_with_several_patches = 0;
  std::size_t patches = 0;
  std::size_t patches_ignored = 0;             ///< sign conflicts
  bool self_intersecting_input = false;        ///< decided when the sign source is `automatic`
  std::size_t cubes_signed_by_patches = 0;     ///< cubes whose corner signs came from patches (section 4.2.2)
  std::size_t cubes_signed_by_winding_number = 0;  ///< ... from the winding number
  std::size_t cubes_signed_by_inside_test = 0;     ///< ... from the inside test
  double winding_number_seconds = 0.;          ///< self-intersection test, gap search and winding numbers
  std::size_t faces_stitched = 0;              ///< grid faces where stitching acted
  std::size_t welds_refused = 0;               ///< midpoint copies kept apart
  std::size_t non_manifold_faces_removed = 0;  ///< defects removed, never left
  std::size_t islands_removed = 0;             ///< pieces cut off their input component
  std::size_t vertices_out = 0, triangles_out = 0, borders_out = 0, components_out = 0;
  std::size_t min_valence = 0, max_valence = 0;
  double min_angle = 0., max_angle = 0.;
  double seconds = 0.;
  /// input face indices (in the order of `faces(input)`) of each patch
  std::vector<std::vector<std::size_t> > patch_faces;
  /// for each output face (in the order of `faces(output)`), its patch
  std::vector<std::size_t> face_patch;
};

/// \ingroup PkgNonobtuseRemeshingRef
/// The fields of `r` (Table 4.1), as `for_each_field()` of statistics.h;
/// the face maps are not fields.
template <typename F>
void for_each_field(const Marching_cubes_result& r, F&& f)
{
  f("resolution", r.resolution);
  f("cube_size", r.cube_size);
  f("input_triangles", r.input_triangles);
  f("degenerate_input_triangles", r.degenerate_input_triangles);
  f("cubes_intersected", r.cubes_intersected);
  f("cubes_with_several_patches", r.cubes_with_several_patches);
  f("patches", r.patches);
  f("patches_ignored", r.patches_ignored);
  f("self_intersecting_input", r.self_intersecting_input);
  f("cubes_signed_by_patches", r.cubes_signed_by_patches);
  f("cubes_signed_by_winding_number", r.cubes_signed_by_winding_number);
  f("cubes_signed_by_inside_test", r.cubes_signed_by_inside_test);
  f("winding_number_seconds", r.winding_number_seconds);
  f("cube_faces_stitched", r.faces_stitched);
  f("welds_refused", r.welds_refused);
  f("non_manifold_faces_removed", r.non_manifold_faces_removed);
  f("islands_removed", r.islands_removed);
  f("vertices_out", r.vertices_out);
  f("triangles_out", r.triangles_out);
  f("borders_out", r.borders_out);
  f("components_out", r.components_out);
  f("valence_range", std::array<std::size_t, 2>{r.min_valence, r.max_valence});
  f("angle_range", std::array<double, 2>{r.min_angle, r.max_angle});
  f("seconds", r.seconds);
}

namespace internal {

// nonobtuse_marching_cubes() once its parameters are read: one instantiation
// per mesh type and point maps.
template <typename TriangleMesh, typename InputPointMap, typename OutputPointMap>
Marching_cubes_result nonobtuse_marching_cubes_with(const TriangleMesh& input, InputPointMap input_vpm,
                                                    TriangleMesh& output, OutputPointMap output_vpm, int resolution,
                                                    Sign_source source, int threads, double budget)
{
  namespace PMP = Polygon_mesh_processing;
  const auto start = std::chrono::steady_clock::now();

  Marching_cubes_result result;
  result.resolution = resolution;
  if(!is_triangle_mesh(input) || faces(input).size() == 0)
    throw Bad_input("nonobtuse_marching_cubes: the input must be a non-empty triangle mesh");
  if(source == Sign_source::inside_test && !is_closed(input))
    throw Bad_input("the inside test needs a closed input");

  const internal::Input_triangles in = internal::input_triangles(input, input_vpm);
  std::vector<internal::Epick::Point_3> corners;
  for(const auto& t : in.triangles)
    for(int i = 0; i < 3; ++i) corners.push_back(t[i]);
  // the box of the faces: vertices used by no face do not count
  const internal::Grid grid(CGAL::bbox_3(corners.begin(), corners.end()), result.resolution, corners);
  result.cube_size = grid.cube_size();
  result.input_triangles = in.triangles.size();
  std::vector<bool> usable(in.triangles.size());
  for(std::size_t t = 0; t < in.triangles.size(); ++t) {
    usable[t] = !in.triangles[t].is_degenerate();
    result.degenerate_input_triangles += !usable[t];
  }

  // Memory (beyond the thesis): the peak of the construction and of the
  // stages after it, measured with /usr/bin/time on sphere, pig, elephant and
  // rotor at N = 100 to 400, is 1.7 to 1.95 KiB per patch (a patch per
  // intersected cube, more where input sheets share a cube); 16 bytes per
  // (cube, triangle) pair come first. Both are checked before they are spent.
  constexpr double bytes_per_patch = 2048., bytes_per_pair = 32.;
  const auto gib = [](double bytes) {
    std::ostringstream text;
    text << std::setprecision(3) << bytes / (1024. * 1024. * 1024.) << " GiB";
    return text.str();
  };

  // Phase 1: cubes and their triangles.
  internal::Cube_triangles cubes;
  if(!internal::mesh_cube_intersection(grid, in.triangles, usable,
                                       std::size_t((std::min)(budget / bytes_per_pair, 1e18)), cubes))
    throw Memory_budget_exceeded("at resolution " + std::to_string(result.resolution) +
                                 " the input meets more grid cubes than the memory budget of " + gib(budget) +
                                 " allows: lower the resolution or raise the budget");
  result.cubes_intersected = cubes.size();

  // Phase 2: patches and signs.
  std::vector<std::size_t> input_component = internal::input_components(in);
  std::vector<internal::Patch> patches;
  if(source == Sign_source::inside_test) {
    patches = internal::inside_test_patches(input, input_vpm, grid, cubes);
    result.cubes_signed_by_inside_test = cubes.size();
  } else {
    if(source != Sign_source::winding_number) patches = internal::patches_and_signs(grid, cubes, in);
    const auto winding_start = std::chrono::steady_clock::now();
    internal::Thread_pool pool(threads);
    // defects: faces that cross another one or border a gap
    std::vector<bool> defect;
    bool defects = false;
    if(source == Sign_source::automatic) {
      defect = internal::crossing_faces(input, input_vpm, pool);
      result.self_intersecting_input = std::find(defect.begin(), defect.end(), true) != defect.end();
      const std::vector<bool> gap = internal::gap_faces(input, input_vpm, grid.cube_size());
      for(std::size_t t = 0; t < defect.size(); ++t) defect[t] = defect[t] || gap[t];
      defects = std::find(defect.begin(), defect.end(), true) != defect.end();
    }
    if(source == Sign_source::winding_number || defects) {
      const internal::Corner_winding_numbers w(grid, cubes, in, usable, pool);
      if(source == Sign_source::winding_number) {
        patches = internal::winding_number_patches(grid, cubes, w, input_component);
        result.cubes_signed_by_winding_number = cubes.size();
      } else {
        result.cubes_signed_by_winding_number =
            internal::sign_overlaps_and_gaps_by_winding_number(grid, cubes, w, defect, patches, input_component);
      }
    }
    result.winding_number_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - winding_start).count();
    result.cubes_signed_by_patches = cubes.size() - result.cubes_signed_by_winding_number;
  }
  result.patches = patches.size();
  if(bytes_per_patch * double(patches.size()) > budget)
    throw Memory_budget_exceeded("at resolution " + std::to_string(result.resolution) + " the initial mesh would need about " +
                                 gib(bytes_per_patch * double(patches.size())) + " (" + std::to_string(patches.size()) +
                                 " patches in " + std::to_string(cubes.size()) +
                                 " cubes), more than the memory budget of " + gib(budget) +
                                 ": lower the resolution or raise the budget");
  for(std::size_t p = 0; p < patches.size(); ++p) {
    result.patches_ignored += (patches[p].state == internal::Patch::ignored);
    if(p > 0 && patches[p].cube == patches[p - 1].cube && (p < 2 || patches[p - 2].cube != patches[p].cube))
      ++result.cubes_with_several_patches;
  }

  // Stacked sheets (beyond the thesis): two triangulated patches of one cube
  // with the same configuration give the same triangles with the same
  // orientation, which deform-to-fit cannot pull apart (a blade's two sides
  // have complementary configurations). Many of them mean sheets closer
  // together than a cube (an accordion of folds): the initial mesh would grow
  // with the number of sheets and overlap itself, so it is refused here,
  // before it is built (a 40-layer accordion took 82 s and left 3.7 million
  // intersecting face pairs).
  {
    std::size_t triangulated = 0, stacked = 0, most = 0;
    for(std::size_t begin = 0, end = 0; begin < patches.size(); begin = end) {
      for(end = begin; end < patches.size() && patches[end].cube == patches[begin].cube; ++end) {}
      std::vector<unsigned> configs;
      for(std::size_t p = begin; p < end; ++p)
        if(patches[p].state == internal::Patch::triangulated) configs.push_back(patches[p].config);
      std::sort(configs.begin(), configs.end());
      triangulated += configs.size();
      for(std::size_t i = 0, j = 0; i < configs.size(); i = j) {
        for(j = i; j < configs.size() && configs[j] == configs[i]; ++j) {}
        stacked += j - i - 1;
        most = (std::max)(most, j - i);
      }
    }
    if(stacked > 100 && 4 * stacked > triangulated)
      throw Bad_input("at resolution " + std::to_string(result.resolution) + ", " + std::to_string(stacked) +
                                  " of " + std::to_string(triangulated) +
                                  " patches repeat another one of their cube with the same orientation (up to " +
                                  std::to_string(most) + " sheets in one cube): the input has sheets closer "
                                  "together than a cube, and the mesh would overlap itself; raise the resolution "
                                  "above the sheets' spacing or separate the sheets");
  }

  // Phase 3: welding, stitching, clean-up.
  internal::Stitcher stitcher(grid, cubes.cube_ids, patches, input_component);
  internal::Marching_cubes_soup soup = stitcher.run();
  if(source == Sign_source::inside_test || source == Sign_source::winding_number)
    internal::orient_like_input(in, input_component, patches, soup);
  result.faces_stitched = soup.faces_stitched;
  result.welds_refused = soup.welds_refused;
  result.non_manifold_faces_removed = soup.removed_non_manifold;
  result.islands_removed = soup.islands_removed;

  using Point = typename boost::property_traits<std::remove_const_t<decltype(output_vpm)> >::value_type;
  std::vector<Point> points;
  for(const auto& p : soup.positions)
    points.emplace_back(grid.coordinate(0, p[0]), grid.coordinate(1, p[1]), grid.coordinate(2, p[2]));
  std::vector<std::array<std::size_t, 3> > triangles = soup.triangles;
  if(!PMP::is_polygon_soup_a_polygon_mesh(triangles))
    CGAL_error_msg("nonobtuse_marching_cubes: the stitched soup is not a polygon mesh");
  internal::clear_keeping_maps(output, 0);
  PMP::polygon_soup_to_polygon_mesh(points, triangles, output, CGAL::parameters::default_values(),
                                    CGAL::parameters::vertex_point_map(output_vpm));

  // Statistics (Table 4.1) and the face-to-patch correspondence.
  for(const auto& patch : patches) result.patch_faces.push_back(patch.triangles);
  result.face_patch = soup.triangle_patch;
  result.vertices_out = num_vertices(output);
  result.triangles_out = num_faces(output);
  std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> borders;
  PMP::extract_boundary_cycles(output, std::back_inserter(borders));
  result.borders_out = borders.size();
  std::unordered_map<typename boost::graph_traits<TriangleMesh>::face_descriptor, std::size_t> component;
  result.components_out = result.triangles_out == 0 ? 0
      : PMP::connected_components(output, boost::make_assoc_property_map(component));
  result.min_valence = std::size_t(-1);
  for(auto v : vertices(output)) {
    result.min_valence = (std::min)(result.min_valence, std::size_t(degree(v, output)));
    result.max_valence = (std::max)(result.max_valence, std::size_t(degree(v, output)));
  }
  if(result.vertices_out == 0) result.min_valence = 0;
  const auto certificate = certify_angle_bounds(
      output, parameters::combine(parameters::min_angle(35.26), CGAL::parameters::vertex_point_map(output_vpm)));
  if(result.triangles_out > 0 && !certificate.is_certified())
    CGAL_error_msg("nonobtuse_marching_cubes: an output angle is outside [35.26, 90]");
  result.min_angle = certificate.min_angle;
  result.max_angle = certificate.max_angle;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace internal

/// \ingroup PkgNonobtuseRemeshingRef
/// Builds the initial nonobtuse mesh of `input` into `output` (cleared first):
/// the nonobtuse Marching Cubes of the thesis's chapter 4 on a grid of
/// `resolution` cubes along the longest side of the input's bounding box.
/// Output vertices lie at cube-edge midpoints and cube centres, exactly, so
/// every angle lies in [35.26, 90] degrees exactly; the output is a manifold
/// triangle mesh oriented like the input (with the inside test, each output
/// component follows the orientation of the input component it comes from).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{resolution} cubes along the longest side (default 100)
///     \cgalParamType{`int`} \cgalParamNEnd
///   \cgalParamNBegin{sign_source} `Sign_source::automatic` (default),
///     `Sign_source::patches`, `Sign_source::winding_number` or
///     `Sign_source::inside_test` (closed inputs only)
///     \cgalParamType{`Sign_source`} \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads} threads of the self-intersection test and of the
///     winding numbers (0, the default: one per core); the result does not depend on it
///     \cgalParamType{`int`} \cgalParamNEnd
///   \cgalParamNBegin{memory_budget} bytes the construction, and the stages
///     after it, may use, as estimated from the patches of input triangles met
///     by the grid (about 2 KiB each, measured peak); a `double`, default
///     `default_memory_budget` (4 GiB). Beyond it `Memory_budget_exceeded` is
///     thrown before the mesh is built.
///     \cgalParamType{`double`} \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `input`; default its internal point map
///     \cgalParamType{a model of `ReadWritePropertyMap` (`ReadablePropertyMap` for a mesh only read) with the vertex descriptors as keys and points with double coordinates as values} \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// `np_out` may hold the `vertex_point_map` of `output`, through which its points are written.
/// The points must have double coordinates (see `deform_to_fit()`).
///
/// Throws `Bad_parameter` for a resolution outside [1, 1024] or a budget that
/// is not positive; `Bad_input` for a flat input, an input too small or too
/// far from the origin for exact grid coordinates, sheets closer together
/// than a cube, or an inside test asked on an open input; and
/// `Memory_budget_exceeded` (a `Bad_input`) as said above.
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters,
          typename OutputNamedParameters = CGAL::parameters::Default_named_parameters>
Marching_cubes_result nonobtuse_marching_cubes(const TriangleMesh& input, TriangleMesh& output,
                                               const NamedParameters& np = CGAL::parameters::default_values(),
                                               const OutputNamedParameters& np_out = CGAL::parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const int resolution = choose_parameter(get_parameter(np, internal_np::resolution), 100);
  const Sign_source source = choose_parameter(get_parameter(np, internal_np::sign_source), Sign_source::automatic);
  const int threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 0);
  if(threads < 0) throw Bad_parameter("the number of threads must not be negative");
  const double budget = choose_parameter(get_parameter(np, internal_np::memory_budget), default_memory_budget);
  if(!(budget > 0.)) throw Bad_parameter("the memory budget must be positive");
  return internal::nonobtuse_marching_cubes_with(
      input, choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, input)),
      output, choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                               get_property_map(CGAL::vertex_point, output)),
      resolution, source, threads, budget);
}

} // namespace Nonobtuse_remeshing
} // namespace CGAL

// With NonobtuseRemeshing::Compiled (compiled_surface_mesh.h): the declarations
// of its instantiations; src/compiled/nonobtuse_marching_cubes.cpp defines
// CGAL_NONOBTUSE_REMESHING_INSTANTIATE_MARCHING_CUBES, and there they are the instantiations.
#ifdef CGAL_NONOBTUSE_REMESHING_COMPILED
#include <CGAL/Nonobtuse_remeshing/internal/compiled_surface_mesh.h>
namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {
#ifndef CGAL_NONOBTUSE_REMESHING_INSTANTIATE_MARCHING_CUBES
extern
#endif
template Marching_cubes_result nonobtuse_marching_cubes_with(const Compiled_mesh&, Compiled_point_map,
                                                             Compiled_mesh&, Compiled_point_map, int,
                                                             Sign_source, int, double);
} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL
#endif

#endif // CGAL_NONOBTUSE_REMESHING_NONOBTUSE_MARCHING_CUBES_H
