// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bounded polygon-soup readers for OFF, OBJ and PLY, and a size check made
// before CGAL's STL reader runs (beyond the thesis: input hygiene).
//
// Nothing is allocated from a count a file announces before the rest of the
// file is known to hold it, so that a few lying bytes cannot exhaust memory.
// These readers are the package's own because CGAL 5.5's size their arrays
// from announced counts (OFF header and faces, PLY lists) and refuse files
// that standard readers accept (OBJ with tabs or a byte order mark, index 0
// taken silently; PLY face lists of char or ushort indices).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_SOUP_READERS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_SOUP_READERS_H

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
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
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  std::string contents(size > 0 ? std::size_t(size) : 0, '\0');
  in.read(&contents[0], std::streamsize(contents.size()));
  return contents;
}

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Tokens of a text, read in place: whitespace-separated, '#' starts a
// comment to the end of the line.
class Text_tokens
{
public:
  Text_tokens(const std::string& text, std::size_t position) : text_(text), position_(position) {}

  // the next token on the current line; false at the end of the line
  bool next_on_line(std::string_view& token)
  {
    while(position_ < text_.size() && is_blank(text_[position_])) ++position_;
    if(position_ >= text_.size() || text_[position_] == '\n' || text_[position_] == '#') return false;
    const std::size_t start = position_;
    while(position_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[position_])) &&
          text_[position_] != '#')
      ++position_;
    token = std::string_view(text_).substr(start, position_ - start);
    return true;
  }

  // the next token, on this line or a later one
  bool next(std::string_view& token)
  {
    for(;;) {
      if(next_on_line(token)) return true;
      if(!skip_line()) return false;
    }
  }

  // to the start of the next line; false at the end of the text
  bool skip_line()
  {
    const std::size_t end = text_.find('\n', position_);
    position_ = end == std::string::npos ? text_.size() : end + 1;
    return end != std::string::npos;
  }

  std::size_t position() const { return position_; }
  std::size_t remaining() const { return text_.size() - position_; }

private:
  const std::string& text_;
  std::size_t position_;
};

inline bool parse_double(std::string_view token, double& value)
{
  char buffer[128];
  if(token.empty() || token.size() >= sizeof(buffer)) return false;
  std::memcpy(buffer, token.data(), token.size());
  buffer[token.size()] = '\0';
  char* end = nullptr;
  value = std::strtod(buffer, &end);
  return end == buffer + token.size();
}

// An integer token in [lo, hi]; false otherwise (no conversion of a double
// that does not fit).
inline bool parse_integer(std::string_view token, long long lo, long long hi, long long& value)
{
  char buffer[32];
  if(token.empty() || token.size() >= sizeof(buffer)) return false;
  std::memcpy(buffer, token.data(), token.size());
  buffer[token.size()] = '\0';
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(buffer, &end, 10);
  return end == buffer + token.size() && errno == 0 && value >= lo && value <= hi;
}

inline std::string shown_token(std::string_view token)
{
  return "'" + std::string(token.substr(0, 40)) + (token.size() > 40 ? "...'" : "'");
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
  const std::size_t begin = contents.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // UTF-8 byte order mark
  Text_tokens tokens(contents, begin);
  std::size_t line_number = 0;
  do {
    ++line_number;
    std::string_view keyword, token;
    if(!tokens.next_on_line(keyword)) continue;
    const auto where = [line_number]() { return "line " + std::to_string(line_number); };  // for errors only
    if(keyword == "v") {
      double xyz[3];
      for(double& c : xyz)
        if(!tokens.next_on_line(token) || !parse_double(token, c))
          throw Format_error(where() + ": a vertex needs three numbers");
      points.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else if(keyword == "f") {
      std::vector<std::size_t> polygon;
      while(tokens.next_on_line(token)) {
        const std::string_view reference = token.substr(0, token.find('/'));
        long long index = 0;
        if(!parse_integer(reference, -(1LL << 53), 1LL << 53, index))
          throw Format_error(where() + ": " + shown_token(token) + " is not a vertex reference");
        if(index == 0) throw Format_error(where() + ": vertex index 0 (OBJ indices start at 1)");
        const long long resolved = index > 0 ? index - 1 : (long long)(points.size()) + index;
        if(resolved < 0)
          throw Format_error(where() + ": relative vertex index " + shown_token(reference) + " before the first vertex");
        polygon.push_back(std::size_t(resolved));
      }
      polygons.push_back(std::move(polygon));
    } else if(keyword == "l" || keyword == "p") {
      ++ignored_elements;
    }
  } while(tokens.skip_line());
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
      if(start == position_ || !parse_double(std::string_view(contents_).substr(start, position_ - start), value))
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
    if(!(count >= 0. && count <= double(remaining() / least)))
      throw Format_error("a list announces " + (count == count ? std::to_string(count) : std::string("nan")) +
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
  // header: its lines, within its first MiB
  const std::size_t header_end = contents.find("end_header");
  if(header_end == std::string::npos || header_end > (std::size_t(1) << 20))
    throw Format_error("no end_header within the first MiB");
  Text_tokens header(contents, 0);
  std::string_view token;
  if(!header.next_on_line(token) || token != "ply" || header.next_on_line(token))
    throw Format_error("it does not start with 'ply'");
  int format = -1;
  std::vector<Ply_element> elements;
  for(;;) {
    if(!header.skip_line()) throw Format_error("the header has no end_header");
    std::vector<std::string> t;
    while(header.next_on_line(token) && t.size() < 6) t.emplace_back(token);
    if(t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if(t[0] == "end_header") {
      header.skip_line();
      break;
    }
    if(t[0] == "format" && t.size() >= 2) {
      format = t[1] == "ascii" ? 0 : t[1] == "binary_little_endian" ? 1 : t[1] == "binary_big_endian" ? 2 : -1;
      if(format < 0) throw Format_error("unknown format " + shown_token(t[1]));
    } else if(t[0] == "element" && t.size() == 3) {
      long long count = 0;
      if(!parse_integer(t[2], 0, std::numeric_limits<long long>::max(), count))
        throw Format_error("element " + shown_token(t[1]) + " has a bad count");
      elements.push_back({t[1], std::uint64_t(count), {}});
    } else if(t[0] == "property" && !elements.empty()) {
      Ply_property p;
      bool ok = false;
      if(t.size() == 5 && t[1] == "list") {
        int bytes = 0;
        bool s = false, f = false;
        ok = ply_type(t[2], bytes, s, f) && !f && ply_type(t[3], p.type, p.is_signed, p.is_float);
        p.count_type = bytes;
        p.is_list = true;
        p.name = t[4];
      } else if(t.size() == 3) {
        ok = ply_type(t[1], p.type, p.is_signed, p.is_float);
        p.name = t[2];
      }
      if(!ok) throw Format_error("unsupported property " + shown_token(t.back()));
      elements.back().properties.push_back(p);
    } else {
      throw Format_error("unexpected header line starting with " + shown_token(t[0]));
    }
  }
  const std::size_t position = header.position();
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
    if(element.properties.empty() && !is_vertex && !is_face) continue;  // nothing in the file
    int xyz[3] = {-1, -1, -1}, indices = -1;
    for(std::size_t i = 0; i < element.properties.size(); ++i) {
      const Ply_property& p = element.properties[i];
      if(is_vertex && !p.is_list && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z')
        xyz[p.name[0] - 'x'] = int(i);
      if(is_face && p.is_list && !p.is_float && (p.name == "vertex_indices" || p.name == "vertex_index") &&
         indices < 0)
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
            if(!(index >= 0. && index < 9007199254740992.) || index != std::floor(index))
              throw Format_error("a face has a vertex index that is not a non-negative integer");
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
// OFF: the header [ST][C][N]OFF, optionally followed by BINARY; the counts
// (vertices, faces, edges); a vertex per line (x y z, then anything else on
// the line, normals, colours or texture coordinates, skipped); a face per line (n, then n indices, then
// an optional colour, skipped). Binary OFF: big-endian int32 counts, float32
// coordinates, per face int32 n, n int32 indices, int32 colour components
// and as many float32. 4D and nD OFF and SKEL are refused.

template <typename Point>
void read_OFF_soup(const std::string& contents, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t> >& polygons)
{
  Text_tokens tokens(contents, 0);
  std::string_view header, token;
  if(!tokens.next(header)) throw Format_error("it is blank");
  const std::size_t off = header.rfind("OFF");
  if(off == std::string_view::npos || off + 3 != header.size() ||
     header.substr(0, off).find_first_not_of("STCN") != std::string_view::npos)
    throw Format_error("it does not start with an OFF header (" + shown_token(header) + ")" +
                       (header.find("4") != std::string_view::npos || header.find("n") != std::string_view::npos ||
                                header == "SKEL"
                            ? ": only 3D surface OFF is supported"
                            : ""));
  const bool extras = off > 0;  // normals, colours or texture coordinates follow each vertex
  std::size_t counts[3] = {0, 0, 0};
  bool binary = false;
  if(tokens.next_on_line(token)) {
    if(token != "BINARY") throw Format_error("unexpected " + shown_token(token) + " after the OFF header");
    binary = true;
  }
  if(binary) {
    if(extras) throw Format_error("binary OFF with normals, colours or texture coordinates is not supported");
    tokens.skip_line();
    std::size_t position = tokens.position();
    const auto int32 = [&]() {
      if(contents.size() - position < 4) throw Format_error("the binary data ends early");
      std::uint32_t u = 0;
      for(int i = 0; i < 4; ++i) u = (u << 8) | static_cast<unsigned char>(contents[position + std::size_t(i)]);
      position += 4;
      return std::int32_t(u);
    };
    const auto float32 = [&]() {
      const std::uint32_t u = std::uint32_t(int32());
      float f;
      std::memcpy(&f, &u, 4);
      return double(f);
    };
    for(std::size_t& c : counts) {
      const std::int32_t n = int32();
      if(n < 0) throw Format_error("a negative count");
      c = std::size_t(n);
    }
    if(counts[0] > (contents.size() - position) / 12 || counts[1] > (contents.size() - position) / 8)
      throw Format_error("it announces " + std::to_string(counts[0]) + " vertices and " + std::to_string(counts[1]) +
                         " faces, more than its " + std::to_string(contents.size()) + " bytes can hold");
    points.reserve(counts[0]);
    for(std::size_t v = 0; v < counts[0]; ++v) {
      const double x = float32(), y = float32(), z = float32();
      points.emplace_back(x, y, z);
    }
    polygons.reserve(counts[1]);
    for(std::size_t f = 0; f < counts[1]; ++f) {
      const std::int32_t n = int32();
      if(n < 0 || std::size_t(n) > (contents.size() - position) / 4)
        throw Format_error("face " + std::to_string(f) + " announces more vertices than the file can hold");
      std::vector<std::size_t> polygon;
      for(std::int32_t i = 0; i < n; ++i) {
        const std::int32_t index = int32();
        if(index < 0) throw Format_error("face " + std::to_string(f) + " has a negative vertex index");
        polygon.push_back(std::size_t(index));
      }
      const std::int32_t colours = int32();
      if(colours < 0 || colours > 4) throw Format_error("face " + std::to_string(f) + " has a bad colour count");
      for(std::int32_t i = 0; i < colours; ++i) float32();
      polygons.push_back(std::move(polygon));
    }
    return;
  }
  for(std::size_t& c : counts) {
    long long n = 0;
    if(!tokens.next(token) || !parse_integer(token, 0, std::numeric_limits<long long>::max(), n))
      throw Format_error("the counts after the OFF header are missing or not integers");
    c = std::size_t(n);
  }
  // an ASCII vertex takes at least 6 bytes, a face at least 8
  if(counts[0] > tokens.remaining() / 6 || counts[1] > tokens.remaining() / 8)
    throw Format_error("it announces " + std::to_string(counts[0]) + " vertices and " + std::to_string(counts[1]) +
                       " faces, more than its " + std::to_string(contents.size()) + " bytes can hold");
  tokens.skip_line();
  points.reserve(counts[0]);
  for(std::size_t v = 0; v < counts[0]; ++v) {
    double xyz[3];
    for(double& c : xyz)
      if(!tokens.next(token) || !parse_double(token, c))
        throw Format_error("vertex " + std::to_string(v) + " does not have three numbers");
    points.emplace_back(xyz[0], xyz[1], xyz[2]);
    tokens.skip_line();  // a fourth coordinate, normals, colours, texture coordinates
  }
  polygons.reserve(counts[1]);
  for(std::size_t f = 0; f < counts[1]; ++f) {
    long long n = 0;
    if(!tokens.next(token) || !parse_integer(token, 0, std::numeric_limits<long long>::max(), n))
      throw Format_error("face " + std::to_string(f) + " is missing or does not start with its vertex count");
    if(std::size_t(n) > tokens.remaining() / 2)
      throw Format_error("face " + std::to_string(f) + " announces " + std::to_string(n) +
                         " vertices, more than the rest of the file can hold");
    std::vector<std::size_t> polygon;
    polygon.reserve(std::size_t(n));
    for(long long i = 0; i < n; ++i) {
      long long index = 0;
      if(!tokens.next(token) || !parse_integer(token, 0, std::numeric_limits<long long>::max(), index))
        throw Format_error("face " + std::to_string(f) + " has a missing or bad vertex index");
      polygon.push_back(std::size_t(index));
    }
    tokens.skip_line();  // an optional colour
    polygons.push_back(std::move(polygon));
  }
}

// ---------------------------------------------------------------------------
// STL (read by CGAL): a binary file must hold exactly the 50-byte triangles
// its header announces (CGAL reads the announced number and ignores the rest).

inline void check_STL_size(const std::string& contents)
{
  // ASCII as CGAL sees it ("solid" after blanks), and no NUL byte, which
  // binary STL files hold (a binary header may start with "solid" too)
  const std::size_t first = contents.find_first_not_of(" \t\r\n");
  const bool ascii = first != std::string::npos && contents.compare(first, 5, "solid") == 0 &&
                     contents.size() > first + 5 && std::isspace(static_cast<unsigned char>(contents[first + 5])) &&
                     contents.find('\0') == std::string::npos;
  if(contents.size() < 84) {
    if(ascii) return;
    throw Format_error("a binary STL needs at least 84 bytes, it has " + std::to_string(contents.size()));
  }
  std::uint32_t announced = 0;
  for(int i = 0; i < 4; ++i) announced |= std::uint32_t(static_cast<unsigned char>(contents[80 + i])) << (8 * i);
  const std::uint64_t expected = 84 + 50 * std::uint64_t(announced);
  if(ascii) return;
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
