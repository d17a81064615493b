// Bounded polygon-soup readers for OBJ and PLY, and size checks made before
// CGAL's OFF and STL readers run (beyond the thesis: input hygiene).
//
// Every count a file announces is checked against what the rest of the file
// can hold before anything is allocated from it, so that a few lying bytes
// cannot exhaust memory. The OBJ and PLY readers are the package's own because
// CGAL 5.5's refuse files that standard readers accept (OBJ with tabs, a byte
// order mark, index 0 taken silently; PLY face lists of char or ushort indices)
// and size a PLY list from its count before reading it.

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_SOUP_READERS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_SOUP_READERS_H

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

/// Thrown by the readers below with a message that does not yet name the
/// file; the caller adds it.
struct Format_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

inline std::string slurp_file(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream contents;
  contents << in.rdbuf();
  return contents.str();
}

// Splits a line at spaces and tabs (and a carriage return).
inline std::vector<std::string> whitespace_tokens(const std::string& line)
{
  std::vector<std::string> tokens;
  std::size_t i = 0;
  while(i < line.size()) {
    while(i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while(i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if(i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

inline bool parse_double(const std::string& token, double& value)
{
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end != token.c_str() && *end == '\0';
}

// ---------------------------------------------------------------------------
// OBJ: `v` and `f` lines; faces by whitespace (tabs too), a vertex reference
// "i", "i/t", "i//n" or "i/t/n", negative ones relative to the vertices read
// so far, 0 refused (OBJ counts from 1). `l` and `p` elements are counted and
// ignored; other statements (vt, vn, g, o, s, usemtl, ...) are ignored.

template <typename Point>
void read_OBJ_soup(const std::string& contents, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t> >& polygons, std::size_t& ignored_elements)
{
  std::size_t begin = 0, line_number = 0;
  if(contents.compare(0, 3, "\xEF\xBB\xBF") == 0) begin = 3;  // UTF-8 byte order mark
  while(begin < contents.size()) {
    std::size_t end = contents.find('\n', begin);
    if(end == std::string::npos) end = contents.size();
    ++line_number;
    std::string line = contents.substr(begin, end - begin);
    begin = end + 1;
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line.resize(hash);
    const std::vector<std::string> tokens = whitespace_tokens(line);
    if(tokens.empty()) continue;
    const std::string where = "line " + std::to_string(line_number);
    if(tokens[0] == "v") {
      double xyz[3];
      if(tokens.size() < 4 || !parse_double(tokens[1], xyz[0]) || !parse_double(tokens[2], xyz[1]) ||
         !parse_double(tokens[3], xyz[2]))
        throw Format_error(where + ": a vertex needs three numbers");
      points.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else if(tokens[0] == "f") {
      std::vector<std::size_t> polygon;
      for(std::size_t i = 1; i < tokens.size(); ++i) {
        const std::string reference = tokens[i].substr(0, tokens[i].find('/'));
        char* stop = nullptr;
        const long long index = std::strtoll(reference.c_str(), &stop, 10);
        if(reference.empty() || *stop != '\0')
          throw Format_error(where + ": '" + tokens[i] + "' is not a vertex reference");
        if(index == 0) throw Format_error(where + ": vertex index 0 (OBJ indices start at 1)");
        const long long resolved = index > 0 ? index - 1 : (long long)(points.size()) + index;
        if(resolved < 0)
          throw Format_error(where + ": relative vertex index " + reference + " before the first vertex");
        polygon.push_back(std::size_t(resolved));
      }
      polygons.push_back(polygon);
    } else if(tokens[0] == "l" || tokens[0] == "p") {
      ++ignored_elements;
    }
  }
}

// ---------------------------------------------------------------------------
// PLY: ascii, binary_little_endian or binary_big_endian; the `vertex`
// element's x, y, z (any numeric type) and the `face` element's
// `vertex_indices` (or `vertex_index`) list (any integer types); every other
// element and property is read and skipped.

struct Ply_property
{
  std::string name;
  int type = 0;        // bytes of a scalar, or of a list's items
  bool is_signed = false, is_float = false;
  bool is_list = false;
  int count_type = 0;  // bytes of a list's count
};

struct Ply_element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;
};

inline bool ply_type(const std::string& name, int& bytes, bool& is_signed, bool& is_float)
{
  static const struct { const char* a; const char* b; int bytes; bool is_signed, is_float; } types[] = {
      {"char", "int8", 1, true, false},     {"uchar", "uint8", 1, false, false},
      {"short", "int16", 2, true, false},   {"ushort", "uint16", 2, false, false},
      {"int", "int32", 4, true, false},     {"uint", "uint32", 4, false, false},
      {"float", "float32", 4, true, true},  {"double", "float64", 8, true, true}};
  for(const auto& t : types)
    if(name == t.a || name == t.b) {
      bytes = t.bytes;
      is_signed = t.is_signed;
      is_float = t.is_float;
      return true;
    }
  return false;
}

class Ply_data
{
public:
  Ply_data(const std::string& contents, std::size_t offset, int format)
    : contents_(contents), position_(offset), format_(format)
  {}

  std::size_t remaining() const { return contents_.size() - position_; }

  // one scalar of the given type, as a double
  double read(int bytes, bool is_signed, bool is_float)
  {
    if(format_ == 0) {
      while(position_ < contents_.size() && std::isspace(static_cast<unsigned char>(contents_[position_])))
        ++position_;
      const std::size_t start = position_;
      while(position_ < contents_.size() && !std::isspace(static_cast<unsigned char>(contents_[position_])))
        ++position_;
      double value = 0.;
      if(start == position_ || !parse_double(contents_.substr(start, position_ - start), value))
        throw Format_error("the data ends early or holds a token that is not a number");
      return value;
    }
    if(remaining() < std::size_t(bytes)) throw Format_error("the data ends early");
    unsigned char raw[8];
    std::memcpy(raw, contents_.data() + position_, std::size_t(bytes));
    position_ += std::size_t(bytes);
    const bool little = format_ == 1;
    std::uint64_t u = 0;
    for(int i = 0; i < bytes; ++i) u |= std::uint64_t(raw[little ? i : bytes - 1 - i]) << (8 * i);
    if(is_float) {
      if(bytes == 4) {
        std::uint32_t u32 = std::uint32_t(u);
        float f;
        std::memcpy(&f, &u32, 4);
        return double(f);
      }
      double d;
      std::memcpy(&d, &u, 8);
      return d;
    }
    if(is_signed && (u >> (8 * bytes - 1)) != 0) return double(std::int64_t(u) - (std::int64_t(1) << (8 * bytes)));
    return double(u);
  }

  double read(const Ply_property& p) { return read(p.type, p.is_signed, p.is_float); }

  // a list's count, bounded by what the rest of the file can hold
  std::size_t read_count(const Ply_property& p)
  {
    const double count = read(p.count_type, false, false);
    const std::size_t least = format_ == 0 ? 2 : std::size_t(p.type);
    if(!(count >= 0.) || count > double(remaining() / least))
      throw Format_error("a list announces " + std::to_string((long long)(count)) +
                         " items, more than the rest of the file can hold");
    return std::size_t(count);
  }

private:
  const std::string& contents_;
  std::size_t position_;
  int format_;  // 0 ascii, 1 little endian, 2 big endian
};

template <typename Point>
void read_PLY_soup(const std::string& contents, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t> >& polygons)
{
  // header
  std::size_t position = 0;
  auto next_line = [&](std::string& line) {
    if(position >= contents.size()) return false;
    std::size_t end = contents.find('\n', position);
    if(end == std::string::npos) end = contents.size();
    line = contents.substr(position, end - position);
    position = end + 1;
    return true;
  };
  std::string line;
  if(!next_line(line) || whitespace_tokens(line) != std::vector<std::string>{"ply"})
    throw Format_error("it does not start with 'ply'");
  int format = -1;
  std::vector<Ply_element> elements;
  for(;;) {
    if(!next_line(line)) throw Format_error("the header has no end_header");
    const std::vector<std::string> t = whitespace_tokens(line);
    if(t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if(t[0] == "end_header") break;
    if(t[0] == "format" && t.size() >= 2) {
      format = t[1] == "ascii" ? 0 : t[1] == "binary_little_endian" ? 1 : t[1] == "binary_big_endian" ? 2 : -1;
      if(format < 0) throw Format_error("unknown format '" + t[1] + "'");
    } else if(t[0] == "element" && t.size() == 3) {
      char* stop = nullptr;
      const unsigned long long count = std::strtoull(t[2].c_str(), &stop, 10);
      if(*stop != '\0' || t[2][0] == '-') throw Format_error("element '" + t[1] + "' has a bad count");
      elements.push_back({t[1], count, {}});
    } else if(t[0] == "property" && !elements.empty()) {
      Ply_property p;
      bool ok = false;
      if(t.size() == 5 && t[1] == "list") {
        int bytes = 0;
        bool s = false, f = false;
        ok = ply_type(t[2], bytes, s, f) && !f && ply_type(t[3], p.type, p.is_signed, p.is_float) && !p.is_float;
        p.count_type = bytes;
        p.is_list = true;
        p.name = t[4];
      } else if(t.size() == 3) {
        ok = ply_type(t[1], p.type, p.is_signed, p.is_float);
        p.name = t[2];
      }
      if(!ok) throw Format_error("unsupported property line '" + line + "'");
      elements.back().properties.push_back(p);
    } else {
      throw Format_error("unexpected header line '" + line + "'");
    }
  }
  if(format < 0) throw Format_error("the header has no format line");

  Ply_data data(contents, position, format);
  for(const Ply_element& element : elements) {
    // the element's smallest size in the file bounds its count
    std::size_t least = 0;
    for(const Ply_property& p : element.properties)
      least += format == 0 ? 2 : std::size_t(p.is_list ? p.count_type : p.type);
    if(least > 0 && element.count > data.remaining() / least)
      throw Format_error("element '" + element.name + "' announces " + std::to_string(element.count) +
                         " entries, more than the rest of the file can hold");
    const bool is_vertex = element.name == "vertex", is_face = element.name == "face";
    int xyz[3] = {-1, -1, -1}, indices = -1;
    for(std::size_t i = 0; i < element.properties.size(); ++i) {
      const Ply_property& p = element.properties[i];
      if(is_vertex && !p.is_list && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z')
        xyz[p.name[0] - 'x'] = int(i);
      if(is_face && p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index") && indices < 0)
        indices = int(i);
    }
    if(is_vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0))
      throw Format_error("the vertex element lacks x, y or z");
    if(is_face && indices < 0) throw Format_error("the face element has no vertex_indices list");
    if(is_vertex) points.reserve(std::size_t(element.count));
    if(is_face) polygons.reserve(std::size_t(element.count));
    for(std::uint64_t e = 0; e < element.count; ++e) {
      double coordinates[3] = {0., 0., 0.};
      for(std::size_t i = 0; i < element.properties.size(); ++i) {
        const Ply_property& p = element.properties[i];
        if(p.is_list) {
          const std::size_t n = data.read_count(p);
          std::vector<std::size_t> polygon;
          if(int(i) == indices) polygon.reserve(n);
          for(std::size_t k = 0; k < n; ++k) {
            const double index = data.read(p);
            if(int(i) != indices) continue;
            if(!(index >= 0.) || index != std::floor(index)) throw Format_error("a face has a negative vertex index");
            polygon.push_back(std::size_t(index));
          }
          if(int(i) == indices) polygons.push_back(std::move(polygon));
        } else {
          const double value = data.read(p);
          for(int a = 0; a < 3; ++a)
            if(int(i) == xyz[a]) coordinates[a] = value;
        }
      }
      if(is_vertex) points.emplace_back(coordinates[0], coordinates[1], coordinates[2]);
    }
  }
}

// ---------------------------------------------------------------------------
// OFF (read by CGAL): the header's counts and every face's vertex count are
// bounded by the file's size first (an ASCII vertex takes at least 6 bytes, a
// face at least 8, a vertex index at least 2), because CGAL's reader sizes
// its arrays from them.

inline void check_OFF_counts(const std::string& contents)
{
  std::istringstream in(contents);
  auto next_token = [&](std::string& token) {
    while(in >> token) {
      if(token[0] != '#') return true;
      std::getline(in, token);
    }
    return false;
  };
  std::string token;
  if(!next_token(token) || token.find("OFF") == std::string::npos) return;  // CGAL says what is wrong
  if(next_token(token) && token == "BINARY") return;                         // fixed-size records
  double counts[2];
  for(double& count : counts) {
    if(!parse_double(token, count)) return;
    if(!next_token(token)) return;
  }
  const double size = double(contents.size());
  if(counts[0] > size / 6. || counts[1] > size / 8.)
    throw Format_error("it announces " + std::to_string((long long)(counts[0])) + " vertices and " +
                       std::to_string((long long)(counts[1])) + " faces, more than its " +
                       std::to_string(contents.size()) + " bytes can hold");
  // `token` is the edge count; skip the vertex lines, then bound each face's count
  std::getline(in, token);
  for(std::size_t v = 0; v < std::size_t(counts[0]) && std::getline(in, token);)
    if(!whitespace_tokens(token).empty() && whitespace_tokens(token)[0][0] != '#') ++v;
  for(std::size_t f = 0; f < std::size_t(counts[1]) && std::getline(in, token);) {
    const std::vector<std::string> t = whitespace_tokens(token);
    if(t.empty() || t[0][0] == '#') continue;
    ++f;
    double n = 0.;
    if(parse_double(t[0], n) && n > size / 2.)
      throw Format_error("face " + std::to_string(f - 1) + " announces " + t[0] +
                         " vertices, more than the file's " + std::to_string(contents.size()) + " bytes can hold");
  }
}

// ---------------------------------------------------------------------------
// STL (read by CGAL): a binary file must hold exactly the 50-byte triangles
// its header announces (CGAL reads the announced number and ignores the rest).

inline void check_STL_size(const std::string& contents)
{
  const bool ascii = contents.compare(0, 5, "solid") == 0 && contents.size() > 5 &&
                     std::isspace(static_cast<unsigned char>(contents[5]));
  if(contents.size() < 84) {
    if(ascii) return;
    throw Format_error("a binary STL needs at least 84 bytes, it has " + std::to_string(contents.size()));
  }
  std::uint32_t announced = 0;
  for(int i = 0; i < 4; ++i) announced |= std::uint32_t(static_cast<unsigned char>(contents[80 + i])) << (8 * i);
  const std::uint64_t expected = 84 + 50 * std::uint64_t(announced);
  if(ascii && contents.size() != expected) return;  // ASCII (a binary header may start with "solid" too)
  if(contents.size() != expected)
    throw Format_error("its header announces " + std::to_string(announced) + " triangles (" +
                       std::to_string(expected) + " bytes) but the file has " + std::to_string(contents.size()) +
                       " bytes" +
                       ((contents.size() - 84) % 50 == 0
                            ? " (" + std::to_string((contents.size() - 84) / 50) + " triangles)"
                            : std::string()));
}

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_SOUP_READERS_H
