#include "libshapeproc/io/detail/mesh_header_check.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "libshapeproc/core/error.hpp"
#include "libshapeproc/core/format.hpp"
#include "libshapeproc/io/text.hpp"

namespace shapeproc::io {

namespace {

// A count a header may declare: 2^31 - 1 elements at most (OpenMesh indexes with int).
constexpr long long kMaxCount = 2147483647;
// A header is a few lines; more is not a header.
constexpr std::size_t kMaxHeaderLines = 1000;

class HeaderCheck {
 public:
  explicit HeaderCheck(const std::filesystem::path& file)
      : name_(file.string()), in_(file, std::ios::binary) {
    std::error_code ec;
    size_ = std::filesystem::file_size(file, ec);
    if (ec || !in_) fail(0, "cannot open the file for reading");
  }

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw core::InputError(name_, line, message);
  }

  // The next line of text, without its end; false at the end of the file. Lines are bounded in
  // length, and hold no control characters (a NUL or vertical tab made OpenMesh's readers take
  // counts from elsewhere, or loop).
  bool next_line(std::string& line) {
    line.clear();
    char c = 0;
    bool any = false;
    while (in_.get(c)) {
      any = true;
      if (c == '\n') break;
      if (line.size() >= kMaxLine) fail(line_ + 1, "a line longer than 1 MiB");
      const auto byte = static_cast<unsigned char>(c);
      if ((byte < 0x20 && c != '\t' && c != '\r') || byte == 0x7f)
        fail(line_ + 1, "a control character (byte " + std::to_string(byte) + ") in a text line");
      line.push_back(c);
    }
    if (!any) return false;
    ++line_;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  }

  long long count(const std::string& token, const char* what) const {
    long long value = -1;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size() || value < 0 || value > kMaxCount) {
      fail(line_, std::string(what) + " must be a whole number from 0 to 2147483647, got '" +
                      core::printable(token, 40) + "'");
    }
    return value;
  }

  // Refuses a header whose elements need more bytes than the file has after the header.
  void fits(long double needed, const std::string& what) {
    const std::streamoff at = in_.tellg();
    const auto header = static_cast<long double>(at < 0 ? 0 : at);
    if (needed > static_cast<long double>(size_) - header) {
      fail(line_, "the header declares " + what + ", more than the file's " +
                      std::to_string(size_) + " bytes can hold");
    }
  }

  int line() const { return line_; }
  std::uintmax_t size() const { return size_; }
  std::ifstream& stream() { return in_; }

 private:
  static constexpr std::size_t kMaxLine = std::size_t{1} << 20;
  std::string name_;
  std::ifstream in_;
  std::uintmax_t size_ = 0;
  int line_ = 0;
};

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// OFF (text): OFF alone on the first line, then the line "vertices faces edges"
// (OpenMesh's reader takes the counts from the line after the keyword, and reads no comment
// before them).
void check_off(HeaderCheck& check) {
  std::string line;
  if (!check.next_line(line)) check.fail(0, "no OFF header");
  std::vector<std::string> tokens = words(line);
  if (tokens.empty()) check.fail(1, "the first line is not OFF");
  const std::string keyword = tokens[0];
  const std::size_t off = keyword.rfind("OFF");
  if (off == std::string::npos || off + 3 != keyword.size())
    check.fail(check.line(), "the first word is not OFF");
  if (keyword != "OFF")
    check.fail(check.line(), "only plain OFF is read (positions and faces), not " +
                                 core::printable(keyword, 40) + ": save it as PLY or OBJ");
  if (tokens.size() == 2 && tokens[1] == "BINARY")
    check.fail(check.line(), "binary OFF is not read: save the mesh as text OFF, PLY or OBJ");
  if (tokens.size() > 1)
    check.fail(check.line(), "the counts must be on the line after " + keyword);
  if (!check.next_line(line)) check.fail(check.line(), "no vertex, face and edge counts");
  tokens = words(line);
  if (tokens.size() != 3 || line.find('#') != std::string::npos)
    check.fail(check.line(), "expected the line 'vertices faces edges' after " + keyword +
                                 ", got '" + core::printable(line, 60) + "'");
  const long long vertices = check.count(tokens[0], "the vertex count");
  const long long faces = check.count(tokens[1], "the face count");
  // At least "0 0 0 " per vertex and "3 0 1 2 " per face.
  check.fits(6.0L * vertices + 8.0L * faces - 1.0L,
             std::to_string(vertices) + " vertices and " + std::to_string(faces) + " faces");
  // The vertices as text: OpenMesh's reader stops at a number it cannot read (1e999, nan) and
  // reports the faces after it instead.
  long long v = 0;
  for (; v < vertices && check.next_line(line);) {
    const std::vector<std::string> w = words(line.substr(0, line.find('#')));
    if (w.empty()) continue;
    // Exactly three numbers a line: OpenMesh reads the file as a stream of words, so a line of
    // four would shift every later vertex and face.
    for (std::size_t k = 0; k < 3; ++k) {
      char* end = nullptr;
      const double value = k < w.size() ? std::strtod(w[k].c_str(), &end) : 0.0;
      if (w.size() != 3 || end != w[k].c_str() + w[k].size() || !std::isfinite(value))
        check.fail(check.line(), "vertex " + std::to_string(v) + " is not three finite numbers: '" +
                                     core::printable(line, 80) + "'");
    }
    ++v;
  }
  if (v < vertices)
    check.fail(check.line(), "the file ends after " + std::to_string(v) + " vertices");
  if (faces == 0) return;
  // The faces: 3 to 1024 corners naming existing vertices (OpenMesh took a corner count of -3
  // as a size of 2^64 - 3).
  for (long long f = 0; f < faces && check.next_line(line);) {
    const std::vector<std::string> w = words(line.substr(0, line.find('#')));
    if (w.empty()) continue;
    long long corners = -1;
    const auto [end, ec] = std::from_chars(w[0].data(), w[0].data() + w[0].size(), corners);
    const bool count_ok = ec == std::errc() && end == w[0].data() + w[0].size() && corners >= 3 &&
                          corners <= 1024 && static_cast<long long>(w.size()) == corners + 1;
    if (!count_ok)
      check.fail(check.line(), "face " + std::to_string(f) +
                                   " needs 3 to 1024 corners and their vertices alone: '" +
                                   core::printable(line, 80) + "'");
    for (long long k = 1; k <= corners; ++k) {
      const std::string& token = w[static_cast<std::size_t>(k)];
      long long index = -1;
      const auto [at, error] = std::from_chars(token.data(), token.data() + token.size(), index);
      if (error != std::errc() || at != token.data() + token.size() || index < 0 ||
          index >= vertices)
        check.fail(check.line(), "face " + std::to_string(f) + ": corner '" +
                                     core::printable(token, 40) + "' names no vertex");
    }
    ++f;
    if (f == faces) return;
  }
  check.fail(check.line(), "the file ends before its " + std::to_string(vertices) +
                               " vertices and " + std::to_string(faces) + " faces");
}

// Bytes of a PLY scalar type in binary; 0 for an unknown type.
int ply_type_size(const std::string& type) {
  static const std::map<std::string, int> sizes = {
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto at = sizes.find(type);
  return at == sizes.end() ? 0 : at->second;
}

bool ply_integer_type(const std::string& type) {
  return type != "float" && type != "float32" && type != "double" && type != "float64" &&
         ply_type_size(type) > 0;
}

struct PlyProperty {
  bool list;
  std::string count_type, type, name;
};

struct PlyElement {
  std::string name;
  long long count;
  long double min_bytes = 0;  // per item
  std::vector<PlyProperty> properties;
};

// Reads PLY values one at a time, as text tokens or binary scalars of either byte order.
class PlyValues {
 public:
  PlyValues(HeaderCheck& check, bool binary, bool big_endian)
      : check_(check), binary_(binary), big_endian_(big_endian) {}

  double next(const std::string& type, const std::string& what) {
    if (!binary_) {
      std::string token;
      if (!(check_.stream() >> token)) check_.fail(0, "the data end before " + what);
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if (end != token.c_str() + token.size() || !std::isfinite(value) ||
          (ply_integer_type(type) && value != std::floor(value)))
        check_.fail(0, what + ": '" + core::printable(token, 40) + "' is not a " + type);
      return value;
    }
    const int size = ply_type_size(type);
    std::array<unsigned char, 8> bytes{};
    if (!check_.stream().read(reinterpret_cast<char*>(bytes.data()), size))
      check_.fail(0, "the data end before " + what);
    if (big_endian_) std::reverse(bytes.begin(), bytes.begin() + size);
    return decode(type, bytes);
  }

 private:
  static double decode(const std::string& type, const std::array<unsigned char, 8>& b) {
    std::uint64_t bits = 0;
    for (int k = 7; k >= 0; --k) bits = (bits << 8) | b[static_cast<std::size_t>(k)];
    if (type == "float" || type == "float32") {
      float f = 0;
      const auto low = static_cast<std::uint32_t>(bits);
      std::memcpy(&f, &low, 4);
      return f;
    }
    if (type == "double" || type == "float64") {
      double d = 0;
      std::memcpy(&d, &bits, 8);
      return d;
    }
    const int size = ply_type_size(type);
    const bool is_signed = type == "char" || type == "int8" || type == "short" || type == "int16" ||
                           type == "int" || type == "int32";
    const std::uint64_t mask = size == 8 ? ~0ull : (1ull << (8 * size)) - 1;
    const std::uint64_t raw = bits & mask;
    if (is_signed && (raw >> (8 * size - 1)) != 0)
      return static_cast<double>(static_cast<std::int64_t>(raw | ~mask));
    return static_cast<double>(raw);
  }

  HeaderCheck& check_;
  bool binary_, big_endian_;
};

// The data after the header: every value readable and finite, vertex positions finite, face
// lists of 3 to 1024 corners naming existing vertices, other lists of 0 to 1024 items (OpenMesh
// took a negative corner count as a size of 2^64 - 3).
void check_ply_body(HeaderCheck& check, const std::vector<PlyElement>& elements, bool binary,
                    bool big_endian) {
  long long vertices = 0;
  for (const PlyElement& e : elements)
    if (e.name == "vertex") vertices = e.count;
  PlyValues values(check, binary, big_endian);
  for (const PlyElement& e : elements) {
    for (long long item = 0; item < e.count; ++item) {
      const std::string where = e.name + " " + std::to_string(item);
      for (const PlyProperty& p : e.properties) {
        if (!p.list) {
          values.next(p.type, where);
          continue;
        }
        const bool corners =
            e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
        const double count = values.next(p.count_type, where);
        if (count < (corners ? 3 : 0) || count > 1024)
          check.fail(0, where + ": a list of " + core::format_general(count, 6) + " items" +
                            (corners ? " (a face needs 3 to 1024 corners)" : " (at most 1024)"));
        for (int k = 0; k < static_cast<int>(count); ++k) {
          const double index = values.next(p.type, where);
          if (corners && (index < 0 || index >= static_cast<double>(vertices)))
            check.fail(0,
                       where + ": corner " + core::format_general(index, 12) + " names no vertex");
        }
      }
    }
  }
}

// PLY: "ply", a format line, elements with their properties, "end_header".
void check_ply(HeaderCheck& check) {
  std::string line;
  if (!check.next_line(line) || words(line) != std::vector<std::string>{"ply"})
    check.fail(1, "the first line is not 'ply'");
  bool binary = false, big_endian = false, format_seen = false, vertex_xyz = false,
       face_list = false;
  std::vector<PlyElement> elements;
  std::vector<std::string> vertex_properties;
  bool ended = false;
  while (!ended && check.next_line(line)) {
    if (static_cast<std::size_t>(check.line()) > kMaxHeaderLines)
      check.fail(check.line(), "no end_header within 1000 lines");
    const std::vector<std::string> w = words(line);
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") {
      ended = true;
    } else if (w[0] == "format") {
      if (w.size() != 3 || w[2] != "1.0" ||
          (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
        check.fail(check.line(), "unknown format line '" + core::printable(line, 80) + "'");
      binary = w[1] != "ascii";
      big_endian = w[1] == "binary_big_endian";
      format_seen = true;
    } else if (w[0] == "element") {
      if (w.size() != 3) check.fail(check.line(), "an element line needs a name and a count");
      elements.push_back({w[1], check.count(w[2], "an element count"), 0, {}});
    } else if (w[0] == "property") {
      if (elements.empty()) check.fail(check.line(), "a property before any element");
      PlyElement& e = elements.back();
      if (w.size() == 5 && w[1] == "list") {
        e.properties.push_back({true, w[2], w[3], w[4]});
        if (!ply_integer_type(w[2]) || ply_type_size(w[3]) == 0)
          check.fail(check.line(), "bad list types in '" + core::printable(line, 80) + "'");
        if (e.name == "vertex") check.fail(check.line(), "a list property of vertices");
        if (e.name == "face" && (w[4] == "vertex_indices" || w[4] == "vertex_index")) {
          if (!ply_integer_type(w[3]))
            check.fail(check.line(), "vertex indices must have an integer type");
          face_list = true;
        }
        e.min_bytes += binary ? ply_type_size(w[2]) : 2;
      } else if (w.size() == 3 && ply_type_size(w[1]) > 0) {
        e.properties.push_back({false, "", w[1], w[2]});
        if (e.name == "vertex") vertex_properties.push_back(w[2]);
        e.min_bytes += binary ? ply_type_size(w[1]) : 2;
      } else {
        check.fail(check.line(), "bad property line '" + core::printable(line, 80) + "'");
      }
    } else {
      check.fail(check.line(), "unknown header line '" + core::printable(line, 80) + "'");
    }
  }
  if (!ended) check.fail(check.line(), "no end_header");
  if (!format_seen) check.fail(check.line(), "no format line");
  for (const char* axis : {"x", "y", "z"}) {
    vertex_xyz = std::find(vertex_properties.begin(), vertex_properties.end(), axis) !=
                 vertex_properties.end();
    if (!vertex_xyz) check.fail(check.line(), std::string("the vertices have no ") + axis);
  }
  if (!face_list) check.fail(check.line(), "no face element with a vertex_indices list");
  long double needed = 0;
  std::string declared;
  for (const PlyElement& e : elements) {
    needed += e.min_bytes * static_cast<long double>(e.count);
    declared += (declared.empty() ? "" : ", ") + std::to_string(e.count) + " " + e.name;
  }
  check.fits(needed - (binary ? 0 : 1), declared + " elements");
  check_ply_body(check, elements, binary, big_endian);
}

// OBJ: faces must name existing vertices (1-based, or negative from the last one read) and have
// at least three corners; a material library must be a readable file of bounded size.
void check_obj(HeaderCheck& check, const std::filesystem::path& file) {
  std::string line;
  std::array<long long, 3> counts{};  // v, vt, vn read so far
  while (check.next_line(line)) {
    const std::size_t hash = line.find('#');
    const std::vector<std::string> w =
        words(hash == std::string::npos ? line : line.substr(0, hash));
    if (w.empty()) continue;
    if (w[0] == "v") {
      ++counts[0];
    } else if (w[0] == "vt") {
      ++counts[1];
    } else if (w[0] == "vn") {
      ++counts[2];
    } else if (w[0] == "mtllib") {
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::filesystem::path library = file.parent_path() / w[k];
        std::error_code ec;
        if (std::filesystem::exists(library, ec) &&
            (!std::filesystem::is_regular_file(library, ec) ||
             std::filesystem::file_size(library, ec) > kMaxInputBytes))
          check.fail(check.line(), "mtllib '" + core::printable(w[k], 80) +
                                       "' is not a regular file of at most 512 MiB");
      }
    } else if (w[0] == "f") {
      if (w.size() < 4) check.fail(check.line(), "a face with fewer than three corners");
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::vector<std::string> parts = split(w[k], '/');
        if (parts.size() > 3) check.fail(check.line(), "bad face corner '" + w[k] + "'");
        for (std::size_t p = 0; p < parts.size(); ++p) {
          if (parts[p].empty() && p > 0) continue;
          long long index = 0;
          const auto [end, ec] =
              std::from_chars(parts[p].data(), parts[p].data() + parts[p].size(), index);
          const long long available = counts[p];
          if (ec != std::errc() || end != parts[p].data() + parts[p].size() || index == 0 ||
              index > available || -index > available) {
            check.fail(check.line(), "face corner '" + core::printable(w[k], 40) + "' names no " +
                                         (p == 0   ? "vertex"
                                          : p == 1 ? "texture coordinate"
                                                   : "normal") +
                                         " read before it");
          }
        }
      }
    }
  }
}

// STL: binary with a triangle count that matches its size, or text beginning with "solid".
void check_stl(HeaderCheck& check) {
  std::array<char, 84> head{};
  check.stream().read(head.data(), head.size());
  const auto got = static_cast<std::uintmax_t>(check.stream().gcount());
  if (got == head.size()) {
    std::uint32_t triangles = 0;
    for (int k = 3; k >= 0; --k)
      triangles = (triangles << 8) | static_cast<unsigned char>(head[80 + k]);
    if (84 + 50 * static_cast<std::uintmax_t>(triangles) == check.size()) return;
  }
  if (std::string(head.data(), std::min<std::uintmax_t>(got, 5)) != "solid") {
    check.fail(0,
               "neither text STL (beginning with 'solid') nor binary STL whose triangle count "
               "matches its size");
  }
}

}  // namespace

void check_mesh_header(const std::filesystem::path& file) {
  HeaderCheck check(file);
  const std::string ext = extension_of(file);
  if (ext == "off") check_off(check);
  if (ext == "ply") check_ply(check);
  if (ext == "obj") check_obj(check, file);
  if (ext == "stl") check_stl(check);
}

}  // namespace shapeproc::io
