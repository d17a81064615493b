// SPDX-License-Identifier: GPL-3.0-or-later
//
// The statistics of the stages as the tool shows them, as JSON and as text,
// both made from the library's for_each_field(): the names and the fields
// are defined once, in the library.

#ifndef NONOBTUSE_REMESH_STATISTICS_OUTPUT_H
#define NONOBTUSE_REMESH_STATISTICS_OUTPUT_H

#include "json_output.h"

#include <CGAL/Nonobtuse_remeshing/nonobtuse_marching_cubes.h>
#include <CGAL/Nonobtuse_remeshing/remeshing_stages.h>
#include <CGAL/Nonobtuse_remeshing/statistics.h>

#include <array>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>

namespace nonobtuse_cli {

template <typename Statistics>
json fields_json(const Statistics& s);
template <typename Statistics>
std::string fields_text(const Statistics& s, std::size_t width = 0, const std::string& indent = "");

// One field's value.
template <typename T>
std::enable_if_t<std::is_arithmetic<T>::value, json> field_json(T value)
{
  return value;
}
inline json field_json(CGAL::Nonobtuse_remeshing::Decimation_stop_reason reason)
{
  return CGAL::Nonobtuse_remeshing::stop_reason_name(reason);
}
template <typename T, std::size_t N>
json field_json(const std::array<T, N>& values)
{
  return values;
}
inline json field_json(const CGAL::Nonobtuse_remeshing::Valence_counts& counts) { return fields_json(counts); }
inline json field_json(const std::string& text) { return text; }

template <typename T>
std::enable_if_t<std::is_arithmetic<T>::value, std::string> field_text(T value)
{
  if constexpr(std::is_same<T, bool>::value) {
    return value ? "yes" : "no";
  } else {
    std::ostringstream text;
    text << std::setprecision(6) << value;
    return text.str();
  }
}
inline std::string field_text(CGAL::Nonobtuse_remeshing::Decimation_stop_reason reason)
{
  return CGAL::Nonobtuse_remeshing::stop_reason_name(reason);
}
template <typename T, std::size_t N>
std::string field_text(const std::array<T, N>& values)
{
  std::string text = "[";
  for(std::size_t i = 0; i < N; ++i) text += (i > 0 ? ", " : "") + field_text(values[i]);
  return text + "]";
}
inline std::string field_text(const std::string& text) { return text; }
inline std::string field_text(const CGAL::Nonobtuse_remeshing::Valence_counts& counts)
{
  return "(" + fields_text(counts) + ")";
}

// The JSON object of `s`: one key per field.
template <typename Statistics>
json fields_json(const Statistics& s)
{
  json j = json::object();
  CGAL::Nonobtuse_remeshing::for_each_field(s, [&](const char* name, const auto& value) { j[name] = field_json(value); });
  return j;
}

// "name value, name value, ..." with the underscores of the names as
// spaces; with a `width`, cut into lines of about that many characters, each
// starting with `indent` and ending with a newline.
template <typename Statistics>
std::string fields_text(const Statistics& s, std::size_t width, const std::string& indent)
{
  std::string text, line;
  CGAL::Nonobtuse_remeshing::for_each_field(s, [&](const char* name, const auto& value) {
    std::string item = name;
    for(char& c : item)
      if(c == '_') c = ' ';
    item += " " + field_text(value);
    if(width > 0 && !line.empty() && indent.size() + line.size() + 2 + item.size() > width) {
      text += indent + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : ", ") + item;
  });
  if(width == 0) return line;
  return line.empty() ? text : text + indent + line + "\n";
}

// The report of a stage: a heading line, then its fields.
template <typename Statistics>
void print_fields(std::ostream& out, const std::string& heading, const Statistics& s)
{
  out << heading << ":\n" << fields_text(s, 100, "  ");
}

} // namespace nonobtuse_cli

#endif // NONOBTUSE_REMESH_STATISTICS_OUTPUT_H
