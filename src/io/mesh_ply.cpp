// PLY (Greg Turk's "The PLY Polygon File Format", 1994): a text header describing elements and
// their typed properties, then the data in ASCII or binary (either byte order). Only the vertex
// positions and the face index lists are kept; every other element and property is read past.
#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <limits>

#include "io/mesh_formats.h"
#include "io/text_scan.h"

namespace contain::io::detail {
namespace {

enum class Type : std::uint8_t { i8, u8, i16, u16, i32, u32, f32, f64 };

int size_of(Type t) {
  switch (t) {
    case Type::i8:
    case Type::u8:
      return 1;
    case Type::i16:
    case Type::u16:
      return 2;
    case Type::i32:
    case Type::u32:
    case Type::f32:
      return 4;
    case Type::f64:
      return 8;
  }
  return 1;
}

bool is_integer(Type t) {
  return t != Type::f32 && t != Type::f64;
}

bool type_from_name(std::string_view name, Type& out) {
  static constexpr std::array<std::pair<std::string_view, Type>, 16> kNames{{
      {"char", Type::i8},
      {"int8", Type::i8},
      {"uchar", Type::u8},
      {"uint8", Type::u8},
      {"short", Type::i16},
      {"int16", Type::i16},
      {"ushort", Type::u16},
      {"uint16", Type::u16},
      {"int", Type::i32},
      {"int32", Type::i32},
      {"uint", Type::u32},
      {"uint32", Type::u32},
      {"float", Type::f32},
      {"float32", Type::f32},
      {"double", Type::f64},
      {"float64", Type::f64},
  }};
  for (const auto& [n, t] : kNames) {
    if (n == name) {
      out = t;
      return true;
    }
  }
  return false;
}

struct Property {
  std::string name;
  Type type = Type::f32;
  bool is_list = false;
  Type count_type = Type::u8;
};

struct Element {
  std::string name;
  std::int64_t count = 0;
  std::vector<Property> properties;
};

enum class Encoding : std::uint8_t { ascii, little, big };

// Reads data values one at a time from either encoding. Binary values are read with bounds
// checks (truncation is reported with the byte offset); ASCII values are white-space separated
// tokens (the line is counted for messages).
class DataReader {
 public:
  DataReader(std::string_view bytes, std::size_t start, Encoding encoding, std::int64_t line,
             const std::string& source)
      : bytes_(bytes), pos_(start), encoding_(encoding), line_(line), source_(source) {}

  // Reads a value of type `t` as an integer (integer types) — or fails.
  Status integer(Type t, std::int64_t& out, const char* what) {
    if (!is_integer(t)) {
      return fail(ErrorKind::unsupported, std::string(what) + " has a floating-point type");
    }
    if (encoding_ == Encoding::ascii) {
      if (auto s = token(what); !s) return s;
      const char* p = token_begin_;
      if (!parse_int64(p, token_end_, out) || p != token_end_) {
        return fail(ErrorKind::parse, std::string("expected ") + what + " (an integer), found " +
                                          quote_token(token_begin_, token_end_));
      }
      return Ok{};
    }
    std::uint64_t raw = 0;
    if (auto s = raw_bytes(t, raw, what); !s) return s;
    switch (t) {
      case Type::i8:
        out = static_cast<std::int8_t>(raw);
        break;
      case Type::i16:
        out = static_cast<std::int16_t>(raw);
        break;
      case Type::i32:
        out = static_cast<std::int32_t>(raw);
        break;
      default:
        out = static_cast<std::int64_t>(raw);
        break;
    }
    return Ok{};
  }

  // Reads a value of any type as a double; rejects NaN and infinities.
  Status real(Type t, double& out, const char* what) {
    if (is_integer(t)) {
      std::int64_t v = 0;
      if (auto s = integer(t, v, what); !s) return s;
      out = static_cast<double>(v);
      return Ok{};
    }
    const std::size_t at = pos_;
    if (encoding_ == Encoding::ascii) {
      if (auto s = token(what); !s) return s;
      const char* p = token_begin_;
      const NumberStatus status = parse_double(p, token_end_, out);
      if (status == NumberStatus::not_a_number || p != token_end_) {
        return fail(ErrorKind::parse, std::string("expected ") + what + ", found " +
                                          quote_token(token_begin_, token_end_));
      }
      if (status == NumberStatus::not_finite) {
        return fail(ErrorKind::invalid_value, std::string(what) + " " +
                                                  std::string(token_begin_, token_end_) +
                                                  " is not finite (NaN, infinite or too large)");
      }
      return Ok{};
    }
    std::uint64_t raw = 0;
    if (auto s = raw_bytes(t, raw, what); !s) return s;
    out = t == Type::f32
              ? static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(raw)))
              : std::bit_cast<double>(raw);
    if (!std::isfinite(out)) {
      return fail_at(ErrorKind::invalid_value, std::string(what) + " is NaN or infinite", at);
    }
    return Ok{};
  }

  // Reads past one value (its content unchecked beyond being a number in ASCII).
  Status skip(Type t, const char* what) {
    if (encoding_ != Encoding::ascii) {
      const std::size_t n = static_cast<std::size_t>(size_of(t));
      if (bytes_.size() - pos_ < n) return truncated(what);
      pos_ += n;
      return Ok{};
    }
    if (auto s = token(what); !s) return s;
    const char* p = token_begin_;
    double ignored = 0.0;
    if (parse_double(p, token_end_, ignored) == NumberStatus::not_a_number || p != token_end_) {
      return fail(ErrorKind::parse, std::string("expected ") + what + ", found " +
                                        quote_token(token_begin_, token_end_));
    }
    return Ok{};
  }

  // After the last element: nothing but white space (ASCII) or nothing at all (binary).
  Status at_end() {
    if (encoding_ == Encoding::ascii) {
      skip_space();
      if (pos_ != bytes_.size()) {
        return fail(ErrorKind::parse,
                    "unexpected data after the last element: " +
                        quote_token(bytes_.data() + pos_, bytes_.data() + bytes_.size()));
      }
      return Ok{};
    }
    if (pos_ != bytes_.size()) {
      return fail_at(ErrorKind::parse,
                     std::to_string(bytes_.size() - pos_) +
                         " unexpected bytes after the last element (wrong counts in the header?)",
                     pos_);
    }
    return Ok{};
  }

  [[nodiscard]] std::size_t position() const { return pos_; }
  [[nodiscard]] std::int64_t line() const { return line_; }

  Error fail(ErrorKind kind, std::string message) const {
    if (encoding_ == Encoding::ascii) return make_error(kind, "PLY: " + message, source_, line_);
    return fail_at(kind, std::move(message), pos_);
  }
  Error fail_at(ErrorKind kind, std::string message, std::size_t offset) const {
    return make_error(kind, "PLY: " + message + " (at byte offset " + std::to_string(offset) + ")",
                      source_);
  }

 private:
  Error truncated(const char* what) const {
    return fail_at(ErrorKind::parse,
                   std::string("the file is truncated: it ends while reading ") + what, pos_);
  }

  Status raw_bytes(Type t, std::uint64_t& raw, const char* what) {
    const auto n = static_cast<std::size_t>(size_of(t));
    if (bytes_.size() - pos_ < n) return truncated(what);
    const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data() + pos_);
    raw = 0;
    if (encoding_ == Encoding::little) {
      for (std::size_t i = n; i-- > 0;)
        raw = (raw << 8) | p[i];
    } else {
      for (std::size_t i = 0; i < n; ++i)
        raw = (raw << 8) | p[i];
    }
    pos_ += n;
    return Ok{};
  }

  void skip_space() {
    while (pos_ < bytes_.size() && is_space(bytes_[pos_])) {
      if (bytes_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  Status token(const char* what) {
    skip_space();
    if (pos_ == bytes_.size()) {
      // Name the last line that has data, not the empty one after its newline.
      const std::int64_t last = line_ - (!bytes_.empty() && bytes_.back() == '\n' ? 1 : 0);
      return make_error(ErrorKind::parse, std::string("PLY: the file ends while reading ") + what,
                        source_, last);
    }
    token_begin_ = bytes_.data() + pos_;
    while (pos_ < bytes_.size() && !is_space(bytes_[pos_]))
      ++pos_;
    token_end_ = bytes_.data() + pos_;
    return Ok{};
  }

  std::string_view bytes_;
  std::size_t pos_;
  Encoding encoding_;
  std::int64_t line_;
  const std::string& source_;
  const char* token_begin_ = nullptr;
  const char* token_end_ = nullptr;
};

struct Header {
  Encoding encoding = Encoding::ascii;
  std::vector<Element> elements;
  std::size_t data_start = 0;
  std::int64_t data_line = 1;  // the line where ASCII data starts
};

Result<Header> parse_header(std::string_view bytes, const std::string& source) {
  Header header;
  std::size_t pos = 0;
  std::int64_t line = 0;
  bool have_format = false;
  while (true) {
    if (pos >= bytes.size()) {
      return make_error(ErrorKind::parse, "PLY: the header has no 'end_header' line", source, line);
    }
    ++line;
    std::size_t eol = bytes.find('\n', pos);
    const std::size_t next = eol == std::string_view::npos ? bytes.size() : eol + 1;
    std::string_view text =
        bytes.substr(pos, (eol == std::string_view::npos ? bytes.size() : eol) - pos);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    pos = next;
    // Split the line into words.
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && is_blank(text[i]))
        ++i;
      const std::size_t b = i;
      while (i < text.size() && !is_blank(text[i]))
        ++i;
      if (i > b) words.push_back(text.substr(b, i - b));
    }
    auto fail = [&](ErrorKind kind, const std::string& message) {
      return make_error(kind, "PLY header: " + message, source, line);
    };
    if (line == 1) {
      if (words.size() != 1 || words[0] != "ply")
        return fail(ErrorKind::parse, "the first line must be 'ply'");
      continue;
    }
    if (words.empty()) continue;
    const std::string_view key = words[0];
    if (key == "comment" || key == "obj_info") continue;
    if (key == "format") {
      if (words.size() != 3) return fail(ErrorKind::parse, "expected 'format <encoding> 1.0'");
      if (words[1] == "ascii") {
        header.encoding = Encoding::ascii;
      } else if (words[1] == "binary_little_endian") {
        header.encoding = Encoding::little;
      } else if (words[1] == "binary_big_endian") {
        header.encoding = Encoding::big;
      } else {
        return fail(ErrorKind::unsupported, "unknown encoding '" + std::string(words[1]) + "'");
      }
      if (words[2] != "1.0") {
        return fail(ErrorKind::unsupported, "version " + std::string(words[2]) + " (only 1.0)");
      }
      have_format = true;
    } else if (key == "element") {
      std::int64_t count = -1;
      const char* p = words.size() == 3 ? words[2].data() : nullptr;
      if (p == nullptr || !parse_int64(p, words[2].data() + words[2].size(), count) ||
          p != words[2].data() + words[2].size() || count < 0) {
        return fail(ErrorKind::parse, "expected 'element <name> <count>'");
      }
      header.elements.push_back({std::string(words[1]), count, {}});
    } else if (key == "property") {
      if (header.elements.empty()) return fail(ErrorKind::parse, "a property before any element");
      Property prop;
      if (words.size() == 5 && words[1] == "list") {
        prop.is_list = true;
        if (!type_from_name(words[2], prop.count_type) || !is_integer(prop.count_type) ||
            !type_from_name(words[3], prop.type)) {
          return fail(ErrorKind::parse, "unknown or non-integer list types");
        }
        prop.name = words[4];
      } else if (words.size() == 3) {
        if (!type_from_name(words[1], prop.type)) {
          return fail(ErrorKind::parse, "unknown type '" + std::string(words[1]) + "'");
        }
        prop.name = words[2];
      } else {
        return fail(ErrorKind::parse,
                    "expected 'property <type> <name>' or 'property list <type> <type> <name>'");
      }
      header.elements.back().properties.push_back(std::move(prop));
    } else if (key == "end_header") {
      if (!have_format) return fail(ErrorKind::parse, "no 'format' line before 'end_header'");
      header.data_start = pos;
      header.data_line = line + 1;
      return header;
    } else {
      return fail(ErrorKind::parse, "unknown header line '" + std::string(key) + "'");
    }
  }
}

}  // namespace

Result<MeshFile> parse_ply(std::string_view bytes, const std::string& source) {
  if (bytes.empty()) return make_error(ErrorKind::parse, "the file is empty", source, 1);
  auto header = parse_header(bytes, source);
  if (!header) return header.error();
  MeshInfo info{.format = header->encoding == Encoding::ascii ? MeshFormat::ply_ascii
                          : header->encoding == Encoding::little
                              ? MeshFormat::ply_binary_little_endian
                              : MeshFormat::ply_binary_big_endian};
  // Counts from the header; the vertex count bounds indices before the vertices are read.
  std::int64_t vertex_count = -1;
  bool has_faces = false;
  for (const Element& e : header->elements) {
    if (e.name == "vertex") {
      vertex_count = e.count;
      int found = 0;
      for (const Property& p : e.properties) {
        if (!p.is_list && (p.name == "x" || p.name == "y" || p.name == "z")) ++found;
      }
      if (found != 3) {
        return make_error(ErrorKind::unsupported, "PLY: the vertex element lacks x, y or z",
                          source);
      }
    }
    if (e.name == "face") {
      has_faces = true;
      const bool has_list =
          std::any_of(e.properties.begin(), e.properties.end(), [](const Property& p) {
            return p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
          });
      if (!has_list) {
        return make_error(ErrorKind::unsupported,
                          "PLY: the face element has no 'vertex_indices' list", source);
      }
    }
  }
  if (vertex_count < 0) return make_error(ErrorKind::parse, "PLY: no vertex element", source);
  if (vertex_count > std::numeric_limits<std::int32_t>::max()) {
    return make_error(ErrorKind::unsupported, "PLY: more than 2^31 - 1 vertices", source);
  }
  if (!has_faces)
    return make_error(ErrorKind::degenerate, "PLY: no face element (a point cloud?)", source);

  DataReader in(bytes, header->data_start, header->encoding, header->data_line, source);
  const auto cap = static_cast<std::int64_t>(bytes.size() / 3);  // counts cannot exhaust memory
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  std::vector<std::int32_t> corners;
  for (const Element& e : header->elements) {
    const bool is_vertex = e.name == "vertex";
    const bool is_face = e.name == "face";
    if (is_vertex) vertices.reserve(static_cast<std::size_t>(std::min(e.count, cap)));
    if (is_face) triangles.reserve(static_cast<std::size_t>(std::min(e.count, cap)));
    // Rows of an element without properties hold no bytes: counting through 10^12 of them
    // would hang the reader (found by the bad-input tests), and there is nothing to read.
    if (e.properties.empty()) continue;
    for (std::int64_t r = 0; r < e.count; ++r) {
      Vec3 v;
      bool face_list_seen = false;  // the first vertex_indices list of the face is the one
      for (const Property& p : e.properties) {
        if (p.is_list) {
          std::int64_t n = 0;
          if (auto s = in.integer(p.count_type, n, "a list length"); !s) return s.error();
          if (n < 0) return in.fail(ErrorKind::invalid_value, "negative list length");
          const bool indices = is_face && !face_list_seen &&
                               (p.name == "vertex_indices" || p.name == "vertex_index");
          if (!indices) {
            for (std::int64_t k = 0; k < n; ++k) {
              if (auto s = in.skip(p.type, "a list item"); !s) return s.error();
            }
            continue;
          }
          face_list_seen = true;
          if (n < 3) {
            return in.fail(ErrorKind::degenerate, "face " + std::to_string(r) + " has " +
                                                      std::to_string(n) +
                                                      " vertices (at least 3 are needed)");
          }
          corners.clear();
          for (std::int64_t k = 0; k < n; ++k) {
            std::int64_t index = 0;
            if (auto s = in.integer(p.type, index, "a vertex index"); !s) return s.error();
            if (index < 0 || index >= vertex_count) {
              return in.fail(ErrorKind::invalid_value,
                             "face " + std::to_string(r) + " refers to vertex " +
                                 std::to_string(index) + ", but there are " +
                                 std::to_string(vertex_count));
            }
            corners.push_back(static_cast<std::int32_t>(index));
          }
          append_fan(triangles, corners);
          ++info.faces;
          continue;
        }
        if (is_vertex && (p.name == "x" || p.name == "y" || p.name == "z")) {
          double c = 0.0;
          if (auto s = in.real(p.type, c, "a vertex coordinate"); !s) return s.error();
          (p.name == "x" ? v.x : p.name == "y" ? v.y : v.z) = c;
        } else if (auto s = in.skip(p.type, "a property"); !s) {
          return s.error();
        }
      }
      if (is_vertex) vertices.push_back(v);
    }
  }
  if (auto s = in.at_end(); !s) return s.error();
  return finish_mesh(std::move(vertices), std::move(triangles), info, source);
}

std::string format_ply(const Mesh& mesh, MeshFormat format) {
  const bool ascii = format == MeshFormat::ply_ascii;
  const bool big = format == MeshFormat::ply_binary_big_endian;
  std::string out = "ply\nformat ";
  out += ascii ? "ascii" : big ? "binary_big_endian" : "binary_little_endian";
  out += " 1.0\ncomment written by contain\nelement vertex " +
         std::to_string(mesh.vertices.size()) +
         "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
         std::to_string(mesh.triangles.size()) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
  if (ascii) return format_lines(mesh, out, "", "3 ", 0);  // OFF's lines under PLY's header
  auto put = [&](std::uint64_t raw, int n) {
    for (int i = 0; i < n; ++i) {
      const int shift = big ? 8 * (n - 1 - i) : 8 * i;
      out += static_cast<char>((raw >> shift) & 0xFF);
    }
  };
  out.reserve(out.size() + mesh.vertices.size() * 24 + mesh.triangles.size() * 13);
  for (const Vec3& v : mesh.vertices) {
    put(std::bit_cast<std::uint64_t>(v.x), 8);
    put(std::bit_cast<std::uint64_t>(v.y), 8);
    put(std::bit_cast<std::uint64_t>(v.z), 8);
  }
  for (const TriangleIndices& t : mesh.triangles) {
    put(3, 1);
    for (std::int32_t i : t)
      put(static_cast<std::uint32_t>(i), 4);
  }
  return out;
}

}  // namespace contain::io::detail
