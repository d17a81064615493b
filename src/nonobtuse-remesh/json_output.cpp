// SPDX-License-Identifier: GPL-3.0-or-later
//
#include "json_output.h"

#include <CGAL/Nonobtuse_remeshing/mesh_io.h>


namespace nonobtuse_cli {

namespace NR = CGAL::Nonobtuse_remeshing;

namespace {

json valences_json(const std::map<std::size_t, std::size_t>& valences)
{
  json j = json::object();
  for(const auto& entry : valences) j[std::to_string(entry.first)] = entry.second;
  return j;
}

} // namespace

json report_to_json(const std::string& path, const NR::Quality_report& r,
                    const std::vector<std::string>& repairs)
{
  json j;
  j["mesh"] = path;
  j["input_repairs"] = repairs;
  j["vertices"] = r.vertices;
  j["edges"] = r.edges;
  j["faces"] = r.faces;
  j["certification"] = {{"min_bound", r.min_bound},
                        {"max_bound", r.max_bound},
                        {"bounds_exact", r.bounds_exact},
                        {"certified", r.certified},
                        {"too_small_corners", r.too_small_corners},
                        {"too_large_corners", r.too_large_corners},
                        {"degenerate_faces", r.degenerate_faces},
                        {"offending_faces", r.offending_faces},
                        {"min_angle", r.has_angles ? json(r.min_angle) : json(nullptr)},
                        {"max_angle", r.has_angles ? json(r.max_angle) : json(nullptr)}};
  j["angle_histogram"] = {{"bins", "[5i, 5i+5) for i = 0..35, except [85, 90] and (90, 95)"},
                          {"counts", r.angle_histogram}};
  j["valences"] = {{"interior", valences_json(r.interior_valences)},
                   {"boundary", valences_json(r.boundary_valences)}};
  j["topology"] = {{"border_cycles", r.border_cycles},
                   {"connected_components", r.connected_components},
                   {"euler_characteristic", r.euler_characteristic},
                   {"non_manifold_vertices", r.non_manifold_vertices}};
  j["self_intersections"] = {{"face_pairs", r.self_intersections},
                             {"cap", r.self_intersections_cap},
                             {"capped", r.self_intersections_capped}};
  j["bbox_diagonal"] = r.bbox_diagonal;
  if(r.distance) {
    const NR::Distance_report& d = *r.distance;
    j["distance_to_reference"] = {{"unit", "percent of the reference's bounding-box diagonal"},
                                  {"reference_diagonal", d.reference_diagonal},
                                  {"hausdorff_to_reference", d.hausdorff_to_reference},
                                  {"hausdorff_from_reference", d.hausdorff_from_reference},
                                  {"hausdorff_symmetric", d.hausdorff_symmetric},
                                  {"hausdorff_error_bound", d.hausdorff_error_bound},
                                  {"mean_to_reference", d.mean_to_reference},
                                  {"mean_from_reference", d.mean_from_reference}};
  }
  return j;
}

void write_json_atomically(const std::string& path, const json& j)
{
  NR::write_text_atomically(path, j.dump(2) + "\n");
}

} // namespace nonobtuse_cli
