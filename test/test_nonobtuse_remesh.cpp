// SPDX-License-Identifier: GPL-3.0-or-later
//
// The whole pipeline, nonobtuse_remesh(): the same mesh as its stages run by
// hand, a resolution chosen for a vertex count, the visitor's stages and
// cancellation (certified on the written file either way), and refusals that
// leave the output empty.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace NR = CGAL::Nonobtuse_remeshing;
using nonobtuse_test::Mesh;

namespace {

bool certified_on_file(const Mesh& mesh, const std::string& name)
{
  const Mesh reread = nonobtuse_test::written_and_reread(mesh, name);
  return num_faces(reread) == num_faces(mesh) && NR::certify_angle_bounds(reread).is_certified();
}

// Records the calls; cancels at call number `cancel_at` (0: never).
struct Recording_visitor
{
  std::vector<std::string> events;
  std::size_t calls = 0, cancel_at = 0, fit_calls = 0, decimation_calls = 0;
  void stage_started(NR::Remeshing_stage s) { events.push_back("start " + std::to_string(int(s))); }
  void stage_finished(NR::Remeshing_stage s, double seconds)
  {
    EXPECT_GE(seconds, 0.);
    events.push_back("end " + std::to_string(int(s)));
  }
  bool keep_going(const NR::Remeshing_progress& p)
  {
    if(p.fit) {
      EXPECT_EQ(p.stage, NR::Remeshing_stage::fit);
      EXPECT_EQ(p.fraction, -1.);
      ++fit_calls;
    } else if(p.decimation) {
      EXPECT_EQ(p.stage, NR::Remeshing_stage::decimation);
      ++decimation_calls;
    } else {
      EXPECT_TRUE(p.fraction == 0. || p.fraction == 1.);
    }
    return cancel_at == 0 || ++calls < cancel_at;
  }
};

} // namespace

// The pipeline is its three stages: the same vertices, bit for bit, as
// running them by hand on an open input; the statistics are theirs.
TEST(NonobtuseRemesh, IsItsStages)
{
  const Mesh input = nonobtuse_test::load("mesh_with_border.off");
  Mesh by_hand;
  NR::nonobtuse_marching_cubes(input, by_hand, NR::parameters::resolution(30));
  const auto valence = NR::remove_bad_valence_vertices(by_hand);
  by_hand.collect_garbage();
  const auto fit = NR::deform_to_fit(by_hand, input);

  Mesh output;
  Recording_visitor visitor;
  const NR::Nonobtuse_remeshing_statistics s =
      NR::nonobtuse_remesh(input, output, NR::parameters::combine(NR::parameters::resolution(30),
                                                                  NR::parameters::remeshing_visitor(std::ref(visitor))));
  EXPECT_EQ(s.resolution, 30);
  EXPECT_FALSE(s.cancelled);
  EXPECT_TRUE(s.valence_run && s.fit_run);
  EXPECT_EQ(s.valence.vertices_after, valence.vertices_after);
  EXPECT_EQ(s.fit.moves, fit.moves);
  EXPECT_TRUE(s.initial_mesh.face_patch.empty());
  ASSERT_EQ(vertices(output).size(), vertices(by_hand).size());
  EXPECT_FALSE(output.has_garbage());
  auto a = vertices(output).begin();
  for(auto v : vertices(by_hand)) EXPECT_EQ(output.point(*a++), by_hand.point(v));
  EXPECT_TRUE(certified_on_file(output, "pipeline.off"));
  EXPECT_EQ(NR::quality_report(output).border_cycles, NR::quality_report(input).border_cycles);
  EXPECT_EQ(visitor.events, (std::vector<std::string>{"start 0", "end 0", "start 1", "end 1", "start 2", "end 2"}));
  EXPECT_GT(visitor.fit_calls, 0u);
}

// target_vertices chooses the resolution: within 15% of the target on a
// curved closed mesh, an open one, and an axis-aligned box whose vertex
// density the area formula overestimates (its initial mesh is redone).
TEST(NonobtuseRemesh, TargetVertices)
{
  for(const std::string name : {"sphere.off", "mesh_with_border.off", "cube-meshed.off"}) {
    const Mesh input = nonobtuse_test::load(name);
    Mesh output;
    const auto s = NR::nonobtuse_remesh(
        input, output,
        NR::parameters::combine(NR::parameters::target_vertices(std::size_t(3000)), NR::parameters::oversampling(1.),
                                NR::parameters::stop_after(NR::Remeshing_stage::valence)));
    const double ratio = double(vertices(output).size()) / 3000.;
    EXPECT_GT(ratio, 0.85) << name;
    EXPECT_LT(ratio, 1.15) << name;
    EXPECT_EQ(s.target_vertices, 3000u);
    if(name == "cube-meshed.off") {  // half the density of curved surfaces: redone finer
      EXPECT_GT(s.trial_resolution, 0);
      EXPECT_LT(s.trial_resolution, s.resolution);
    }
    EXPECT_TRUE(certified_on_file(output, "target_" + name)) << name;
  }
  EXPECT_EQ(NR::resolution_for_target_vertices(nonobtuse_test::load("sphere.off"), 1u), 1);
  EXPECT_EQ(NR::resolution_for_target_vertices(nonobtuse_test::load("sphere.off"), 1000000000u), 1024);
}

// A cancel during the fit ends the pipeline with a certified output; a
// cancel before anything leaves it empty; stop_after ends early.
TEST(NonobtuseRemesh, CancellationAndStopAfter)
{
  const Mesh input = nonobtuse_test::load("pig.off");
  Mesh output;
  Recording_visitor visitor;
  visitor.cancel_at = 200;  // stage-boundary calls come first, then the fit's
  auto s = NR::nonobtuse_remesh(input, output, NR::parameters::combine(NR::parameters::resolution(40),
                                                                      NR::parameters::remeshing_visitor(std::ref(visitor))));
  EXPECT_TRUE(s.cancelled);
  EXPECT_TRUE(s.fit_run && s.fit.cancelled);
  EXPECT_EQ(visitor.calls, 200u) << "no call after the cancel";
  EXPECT_GT(num_faces(output), 0u);
  EXPECT_TRUE(certified_on_file(output, "cancelled.off"));

  Recording_visitor at_once;
  at_once.cancel_at = 1;
  s = NR::nonobtuse_remesh(input, output, NR::parameters::remeshing_visitor(std::ref(at_once)));
  EXPECT_TRUE(s.cancelled);
  EXPECT_EQ(num_faces(output), 0u);
  EXPECT_TRUE(at_once.events.empty());

  s = NR::nonobtuse_remesh(input, output, NR::parameters::combine(NR::parameters::resolution(40),
                                                                 NR::parameters::stop_after(NR::Remeshing_stage::initial_mesh)));
  EXPECT_FALSE(s.valence_run || s.fit_run || s.cancelled);
  EXPECT_EQ(vertices(output).size(), s.initial_mesh.vertices_out);
  const Mesh reread = nonobtuse_test::written_and_reread(output, "initial.off");
  EXPECT_EQ(num_faces(reread), num_faces(output));
  EXPECT_TRUE(NR::certify_angle_bounds(reread, NR::parameters::min_angle(35.26)).is_certified());
}

// The initial mesh's topology against the input's, per input component:
// two disjoint spheres are two components that match; two overlapping ones
// are one crossing group whose union matches; the hand at resolution 47
// (a fingertip cut off, found by hand) differs, and is refined when asked.
TEST(NonobtuseRemesh, TopologyIsComparedPerInputComponent)
{
  const Mesh sphere = nonobtuse_test::load("sphere.off");
  const auto two_spheres = [&](double offset) {
    Mesh mesh = sphere;
    Mesh moved = sphere;
    for(auto v : vertices(moved)) moved.point(v) = moved.point(v) + nonobtuse_test::Kernel::Vector_3(offset, 0.1, 0.05);
    mesh.join(moved);
    return mesh;
  };
  const auto init = NR::parameters::stop_after(NR::Remeshing_stage::initial_mesh);
  Mesh output;
  auto s = NR::nonobtuse_remesh(two_spheres(3.), output, NR::parameters::combine(NR::parameters::resolution(30), init));
  EXPECT_TRUE(s.topology.compared && s.topology.matches) << s.topology.difference;
  EXPECT_EQ(s.topology.input_components, 2u);
  EXPECT_EQ(s.topology.input_groups, 2u);
  EXPECT_EQ(s.topology.crossing_groups, 0u);
  EXPECT_EQ(s.topology.output_euler_characteristic, 4);
  EXPECT_TRUE(s.keep_topology);  // the default, with a resolution too
  EXPECT_EQ(s.refinements, 0);   // nothing to refine
  EXPECT_EQ(s.decimation_target, 0u);

  s = NR::nonobtuse_remesh(two_spheres(0.7), output, NR::parameters::combine(NR::parameters::resolution(30), init));
  EXPECT_TRUE(s.topology.matches) << s.topology.difference;
  EXPECT_EQ(s.topology.input_components, 2u);
  EXPECT_EQ(s.topology.input_groups, 1u);
  EXPECT_EQ(s.topology.crossing_groups, 1u);
  EXPECT_EQ(s.topology.output_components, 1u);

  const Mesh hand = nonobtuse_test::load("hand.off");
  s = NR::nonobtuse_remesh(hand, output,
                           NR::parameters::combine(NR::parameters::resolution(47), NR::parameters::keep_topology(false), init));
  EXPECT_FALSE(s.topology.matches);
  EXPECT_EQ(s.topology.groups_differing, 1u);
  EXPECT_EQ(s.topology.output_components, NR::quality_report(output).connected_components);
  EXPECT_GT(s.topology.output_components, 1u);
  EXPECT_GE(s.topology.mismatch, 2u);  // a piece cut off: a component and its Euler characteristic
  EXPECT_NE(s.topology.difference.find("became " + std::to_string(s.topology.output_components) + " components"),
            std::string::npos)
      << s.topology.difference;
  EXPECT_EQ(s.refinements, 0);

  // refined (the default): 47 -> 59 keeps it; a cap at 47 does not let it
  const std::size_t vertices_at_47 = vertices(output).size();
  s = NR::nonobtuse_remesh(hand, output, NR::parameters::combine(NR::parameters::resolution(47), init));
  EXPECT_TRUE(s.topology.matches) << s.topology.difference;
  EXPECT_EQ(s.decimation_target, vertices_at_47);  // the size the resolution gives, after the fit
  EXPECT_GE(s.refinements, 1);
  EXPECT_EQ(s.budget_resolution, 47);
  EXPECT_GT(s.resolution, 47);
  EXPECT_EQ(s.max_resolution, 94);
  const Mesh reread = nonobtuse_test::written_and_reread(output, "refined_hand.off");
  const NR::Quality_report q = NR::quality_report(reread), in = NR::quality_report(hand);
  EXPECT_EQ(q.connected_components, in.connected_components);
  EXPECT_EQ(q.border_cycles, in.border_cycles);
  EXPECT_EQ(q.euler_characteristic, in.euler_characteristic);
  EXPECT_TRUE(NR::certify_angle_bounds(reread, NR::parameters::min_angle(35.26)).is_certified());
  s = NR::nonobtuse_remesh(hand, output,
                           NR::parameters::combine(NR::parameters::resolution(47), NR::parameters::keep_topology(true),
                                                   NR::parameters::max_resolution(47), init));
  EXPECT_FALSE(s.topology.matches);
  EXPECT_EQ(s.refinements, 0);
  // a cap below the resolution: no refinement either
  s = NR::nonobtuse_remesh(hand, output,
                           NR::parameters::combine(NR::parameters::resolution(47), NR::parameters::keep_topology(true),
                                                   NR::parameters::max_resolution(20), init));
  EXPECT_EQ(s.refinements, 0);
  EXPECT_EQ(s.resolution, 47);
  EXPECT_EQ(s.max_resolution, 47);
  EXPECT_THROW(NR::nonobtuse_remesh(hand, output, NR::parameters::max_resolution(2000)), NR::Bad_parameter);
}

// A resolution keeps the topology too (the default): the hand's grid at 47
// cuts a fingertip off, so the initial mesh is refined, fitted, and
// decimated back to the vertex count of the grid at 47. The written file
// has the input's topology and that size within 10%, and certifies.
TEST(NonobtuseRemesh, ResolutionKeepsTheTopologyAndTheSize)
{
  const Mesh hand = nonobtuse_test::load("hand.off");
  Mesh first, output;
  NR::nonobtuse_remesh(hand, first,
                       NR::parameters::combine(NR::parameters::resolution(47), NR::parameters::keep_topology(false),
                                               NR::parameters::stop_after(NR::Remeshing_stage::initial_mesh)));
  const auto s = NR::nonobtuse_remesh(hand, output, NR::parameters::resolution(47));
  EXPECT_GE(s.refinements, 1);
  EXPECT_EQ(s.target_vertices, 0u);
  EXPECT_EQ(s.decimation_target, vertices(first).size());
  ASSERT_TRUE(s.decimation_run);
  const Mesh reread = nonobtuse_test::written_and_reread(output, "hand_47.off");
  EXPECT_NEAR(double(vertices(reread).size()), double(s.decimation_target), 0.1 * double(s.decimation_target));
  const NR::Quality_report q = NR::quality_report(reread), in = NR::quality_report(hand);
  EXPECT_EQ(q.connected_components, in.connected_components);
  EXPECT_EQ(q.border_cycles, in.border_cycles);
  EXPECT_EQ(q.euler_characteristic, in.euler_characteristic);
  EXPECT_TRUE(NR::certify_angle_bounds(reread).is_certified());
}

// A target vertex count keeps the topology: the hand's initial mesh for
// 10,000 vertices cuts a fingertip off, so it is refined, fitted and
// decimated back to the target (the fifth stage); the written file has the
// input's topology, the target's vertex count within 10%, and certifies.
TEST(NonobtuseRemesh, TargetVerticesKeepsTheTopology)
{
  const Mesh hand = nonobtuse_test::load("hand.off");
  Mesh output;
  Recording_visitor visitor;
  const auto s = NR::nonobtuse_remesh(
      hand, output,
      NR::parameters::combine(NR::parameters::target_vertices(std::size_t(10000)),
                              NR::parameters::remeshing_visitor(std::ref(visitor))));
  EXPECT_TRUE(s.keep_topology);
  EXPECT_GE(s.refinements, 1);
  EXPECT_TRUE(s.topology.matches) << s.topology.difference;
  ASSERT_TRUE(s.decimation_run);
  EXPECT_EQ(s.decimation.stop_reason, NR::Decimation_stop_reason::target_reached);
  EXPECT_EQ(visitor.events.back(), "end 3");
  EXPECT_GT(visitor.decimation_calls, 0u);
  const Mesh reread = nonobtuse_test::written_and_reread(output, "hand_10000.off");
  EXPECT_NEAR(double(vertices(reread).size()), 10000., 1000.);
  EXPECT_TRUE(NR::certify_angle_bounds(reread).is_certified());
  const NR::Quality_report q = NR::quality_report(reread), in = NR::quality_report(hand);
  EXPECT_EQ(q.connected_components, in.connected_components);
  EXPECT_EQ(q.border_cycles, in.border_cycles);
  EXPECT_EQ(q.euler_characteristic, in.euler_characteristic);

  // oversampled: built for twice the target, fitted, decimated to it
  const Mesh pig = nonobtuse_test::load("pig.off");
  const auto o = NR::nonobtuse_remesh(pig, output,
                                      NR::parameters::combine(NR::parameters::target_vertices(std::size_t(3000)),
                                                              NR::parameters::oversampling(2.)));
  EXPECT_TRUE(o.decimation_run);
  EXPECT_GT(o.fit.vertices, 5000u);
  const Mesh pig_file = nonobtuse_test::written_and_reread(output, "pig_3000.off");
  EXPECT_NEAR(double(vertices(pig_file).size()), 3000., 300.);
  EXPECT_TRUE(NR::certify_angle_bounds(pig_file).is_certified());
  EXPECT_EQ(NR::quality_report(pig_file).border_cycles, 7u);
  EXPECT_EQ(NR::quality_report(pig_file).euler_characteristic, NR::quality_report(pig).euler_characteristic);
  EXPECT_THROW(NR::nonobtuse_remesh(pig, output, NR::parameters::oversampling(0.5)), NR::Bad_parameter);
}

// With a distance bound, the fitted mesh is decimated to the coarsest level
// within it, and the bound holds on the written file as measured by CGAL's
// bounded-error Hausdorff distance on its own; a bound the cap keeps out of
// reach is reported as not met, the closest mesh certified all the same.
TEST(NonobtuseRemesh, MaxDistanceHoldsOnTheWrittenFile)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Mesh elephant = nonobtuse_test::load("elephant.off");
  Mesh output;
  const auto s = NR::nonobtuse_remesh(elephant, output, NR::parameters::max_distance(0.02));
  EXPECT_TRUE(s.keep_topology);
  EXPECT_TRUE(s.distance.met);
  EXPECT_DOUBLE_EQ(s.distance.max_distance, 0.02);
  EXPECT_LE(s.distance.distance, 0.02);
  EXPECT_LE(s.distance.fitted_distance, 0.02);
  EXPECT_GE(s.distance.measurements, 2u);
  ASSERT_TRUE(s.decimation_run);
  EXPECT_LT(2 * vertices(output).size(), s.fit.vertices);  // the decimation removed more than half
  const Mesh reread = nonobtuse_test::written_and_reread(output, "elephant_2pct.off");
  EXPECT_TRUE(NR::certify_angle_bounds(reread).is_certified());
  const double diagonal = NR::internal::bbox_diagonal(elephant), error = 1e-4 * diagonal;
  EXPECT_LE(PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(reread, elephant, error),
            0.02 * diagonal + error);
  const NR::Quality_report q = NR::quality_report(reread), in = NR::quality_report(elephant);
  EXPECT_EQ(q.connected_components, in.connected_components);
  EXPECT_EQ(q.border_cycles, in.border_cycles);
  EXPECT_EQ(q.euler_characteristic, in.euler_characteristic);

  // rotor's sharp edges keep its fitted mesh over 5% at the first grid, and
  // the cap forbids a finer one
  const Mesh rotor = nonobtuse_test::load("rotor.off");
  const auto r = NR::nonobtuse_remesh(
      rotor, output, NR::parameters::combine(NR::parameters::max_distance(0.05), NR::parameters::max_resolution(1)));
  EXPECT_FALSE(r.distance.met);
  EXPECT_GT(r.distance.distance, 0.05);
  EXPECT_EQ(r.distance.refinements, 0);
  EXPECT_FALSE(r.decimation_run);
  EXPECT_TRUE(NR::certify_angle_bounds(nonobtuse_test::written_and_reread(output, "rotor_5pct.off")).is_certified());

  EXPECT_THROW(NR::nonobtuse_remesh(rotor, output,
                                    NR::parameters::combine(NR::parameters::max_distance(0.05),
                                                            NR::parameters::target_vertices(std::size_t(1000)))),
               NR::Bad_parameter);
  EXPECT_THROW(NR::nonobtuse_remesh(rotor, output, NR::parameters::max_distance(1.5)), NR::Bad_parameter);
  EXPECT_THROW(NR::nonobtuse_remesh(rotor, output,
                                    NR::parameters::combine(NR::parameters::max_distance(0.05),
                                                            NR::parameters::stop_after(NR::Remeshing_stage::valence))),
               NR::Bad_parameter);
  EXPECT_EQ(num_faces(output), 0u);
}

// The distance guard: at N = 50 the fit of rotor rounds off the rims of its
// flat ends and, unguarded, ends farther from the input than the mesh it
// started from. Guarded, its own measure ends no larger than at the start,
// and the Hausdorff distance measured on the written file comes back to
// within 5% of the start's (the guard samples the input about one mesh edge
// apart, so what lies between its samples may still differ a little).
TEST(NonobtuseRemesh, FitEndsNoFartherThanItsStart)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Mesh rotor = nonobtuse_test::load("rotor.off");
  const double diagonal = NR::internal::bbox_diagonal(rotor), error = 2e-4 * diagonal;
  NR::Nonobtuse_remeshing_statistics s;
  const auto hausdorff = [&](NR::Remeshing_stage last, bool guard, const std::string& name) {
    Mesh output;
    s = NR::nonobtuse_remesh(rotor, output,
                             NR::parameters::combine(NR::parameters::resolution(50), NR::parameters::stop_after(last),
                                                     NR::parameters::distance_guard(guard)));
    const Mesh reread = nonobtuse_test::written_and_reread(output, name);
    EXPECT_TRUE(NR::certify_angle_bounds(reread).is_certified());
    return PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(reread, rotor, error);
  };
  const double start = hausdorff(NR::Remeshing_stage::valence, true, "rotor_start.off");
  const double unguarded = hausdorff(NR::Remeshing_stage::fit, false, "rotor_unguarded.off");
  EXPECT_EQ(s.fit.start_distance, 0.);
  EXPECT_EQ(s.fit.guard_moves, 0u);
  EXPECT_GT(unguarded, 1.1 * start);
  const double guarded = hausdorff(NR::Remeshing_stage::fit, true, "rotor_guarded.off");
  EXPECT_GT(s.fit.guard_moves, 0u);
  EXPECT_GT(s.fit.start_distance, 0.);
  EXPECT_LE(s.fit.end_distance, s.fit.start_distance);
  EXPECT_NEAR(s.fit.start_distance, 100. * start / diagonal, 0.05 * 100. * start / diagonal);
  EXPECT_EQ(s.fit.intersecting_pairs, 0u);
  EXPECT_LT(guarded, unguarded);
  EXPECT_LE(guarded, 1.05 * start + error);
}

// Bad parameters and inputs throw before any work and leave the output empty.
TEST(NonobtuseRemesh, Refusals)
{
  const Mesh input = nonobtuse_test::load("sphere.off");
  Mesh output = input;
  EXPECT_THROW(NR::nonobtuse_remesh(input, output, NR::parameters::alpha(2.)), NR::Bad_parameter);
  EXPECT_EQ(num_faces(output), 0u);
  output = input;
  EXPECT_THROW(NR::nonobtuse_remesh(input, output, NR::parameters::resolution(0)), NR::Bad_parameter);
  EXPECT_EQ(num_faces(output), 0u);
  EXPECT_THROW(NR::nonobtuse_remesh(input, output,
                                    NR::parameters::combine(NR::parameters::valence_cleanup(false),
                                                            NR::parameters::stop_after(NR::Remeshing_stage::valence))),
               NR::Bad_parameter);
  EXPECT_THROW(NR::nonobtuse_remesh(Mesh(), output), NR::Bad_input);
  // too coarse a grid for the input: an empty initial mesh is refused
  EXPECT_THROW(NR::nonobtuse_remesh(input, output, NR::parameters::resolution(1)), NR::Bad_input);
  EXPECT_EQ(num_faces(output), 0u);
}

// A Surface_mesh with garbage (a decimation without collect_garbage()):
// the report, the certifying write and the coloured PLY count live elements.
TEST(NonobtuseRemesh, GarbageIsNotCounted)
{
  Mesh mesh;
  NR::nonobtuse_remesh(nonobtuse_test::load("sphere.off"), mesh,
                       NR::parameters::combine(NR::parameters::resolution(20),
                                               NR::parameters::stop_after(NR::Remeshing_stage::initial_mesh)));
  NR::angle_bounded_decimation(mesh, NR::parameters::vertex_ratio(0.8));
  ASSERT_TRUE(mesh.has_garbage());
  const NR::Quality_report r = NR::quality_report(mesh);
  EXPECT_EQ(r.vertices, vertices(mesh).size());
  EXPECT_EQ(r.euler_characteristic, 2);
  const std::string folder = nonobtuse_test::scratch_folder("garbage");
  EXPECT_NO_THROW(NR::write_mesh_atomically(folder + "/m.off", mesh, NR::certifying_check(mesh)));
  EXPECT_NO_THROW(NR::write_mesh_colored_by_angle_atomically(folder + "/m.ply", mesh, NR::Angle_coloring::largest_angle,
                                                             NR::certifying_check(mesh)));
  Mesh reread;
  NR::read_triangle_mesh(folder + "/m.ply", reread);
  EXPECT_EQ(vertices(reread).size(), vertices(mesh).size());
}
