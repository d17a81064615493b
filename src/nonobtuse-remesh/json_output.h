// SPDX-License-Identifier: GPL-3.0-or-later
//
// JSON output of the tool: the quality report as JSON, written atomically.

#ifndef NONOBTUSE_REMESH_JSON_OUTPUT_H
#define NONOBTUSE_REMESH_JSON_OUTPUT_H

#include <CGAL/Nonobtuse_remeshing/quality_report.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace nonobtuse_cli {

using json = nlohmann::ordered_json;

json report_to_json(const std::string& path, const CGAL::Nonobtuse_remeshing::Quality_report& r,
                    const std::vector<std::string>& repairs);

// Writes `j` to `path` through a temporary file and a rename.
void write_json_atomically(const std::string& path, const json& j);

} // namespace nonobtuse_cli

#endif // NONOBTUSE_REMESH_JSON_OUTPUT_H
