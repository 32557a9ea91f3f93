// STL: a list of independent triangles (3D Systems' StereoLithography Interface Specification,
// 1989), ASCII or binary. The corners are welded into shared vertices so that the mesh is
// indexed and its topology (closedness, neighbours) can be seen.
#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

#include "io/mesh_formats.h"
#include "io/text_scan.h"

namespace contain::io::detail {
namespace {

// Welds corners whose coordinates compare equal (+0 and -0 alike: the key is taken after adding
// 0.0, which turns -0 into +0; NaN never reaches here). The first corner seen gives the vertex.
// An open-addressing table of vertex indices (linear probing, load <= 1/2) rather than a
// node-based map: a 100 MB STL has 6 million corners, and one cache miss per corner is the cost.
class Welder {
 public:
  explicit Welder(std::size_t expected_corners) {
    keys_.reserve(expected_corners / 4 + 16);
    vertices_.reserve(expected_corners / 4 + 16);
    rehash(std::bit_ceil(std::max<std::size_t>(64, expected_corners / 2)));
  }

  std::int32_t add(Vec3 v) {
    const Key key{std::bit_cast<std::uint64_t>(v.x + 0.0), std::bit_cast<std::uint64_t>(v.y + 0.0),
                  std::bit_cast<std::uint64_t>(v.z + 0.0)};
    std::size_t slot = hash(key) & mask_;
    while (true) {
      const std::int32_t at = slots_[slot];
      if (at < 0) break;
      const Key& seen = keys_[static_cast<std::size_t>(at)];
      if (seen[0] == key[0] && seen[1] == key[1] && seen[2] == key[2]) {  // no memcmp call
        ++welded_;
        return at;
      }
      slot = (slot + 1) & mask_;
    }
    const auto index = static_cast<std::int32_t>(vertices_.size());
    slots_[slot] = index;
    keys_.push_back(key);
    vertices_.push_back(v);
    if (2 * keys_.size() > slots_.size()) rehash(2 * slots_.size());
    return index;
  }

  std::vector<Vec3> take_vertices() { return std::move(vertices_); }
  [[nodiscard]] std::int64_t welded() const { return welded_; }
  [[nodiscard]] std::size_t size() const { return vertices_.size(); }

 private:
  using Key = std::array<std::uint64_t, 3>;

  // The low bits index the table, and the low mantissa bits of typical coordinates (integers,
  // short decimals) are all zero: every key bit must reach them (murmur3's 64-bit finaliser).
  static std::uint64_t mix(std::uint64_t h) {
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDull;
    h ^= h >> 33;
    h *= 0xC4CEB9FE1A85EC53ull;
    return h ^ (h >> 33);
  }
  static std::size_t hash(const Key& k) {
    return static_cast<std::size_t>(mix(k[0] ^ mix(k[1] ^ mix(k[2]))));
  }

  void rehash(std::size_t capacity) {
    slots_.assign(capacity, -1);
    mask_ = capacity - 1;
    for (std::size_t i = 0; i < keys_.size(); ++i) {
      std::size_t slot = hash(keys_[i]) & mask_;
      while (slots_[slot] >= 0)
        slot = (slot + 1) & mask_;
      slots_[slot] = static_cast<std::int32_t>(i);
    }
  }

  std::vector<std::int32_t> slots_;  // vertex index, or -1 for an empty slot
  std::size_t mask_ = 0;
  std::vector<Key> keys_;  // keys_[i] is the key of vertices_[i]
  std::vector<Vec3> vertices_;
  std::int64_t welded_ = 0;
};

std::uint32_t load_u32_le(const char* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i)
    v = (v << 8) | static_cast<unsigned char>(p[i]);
  return v;
}

float load_f32_le(const char* p) {
  return std::bit_cast<float>(load_u32_le(p));
}

Result<MeshFile> parse_binary_stl(std::string_view bytes, const std::string& source) {
  const std::uint64_t n = load_u32_le(bytes.data() + 80);
  const std::uint64_t needed = 84 + 50 * n;
  if (bytes.size() != needed) {
    return make_error(ErrorKind::parse,
                      "binary STL: the header at byte offset 80 announces " + std::to_string(n) +
                          " triangles, which take " + std::to_string(needed) +
                          " bytes, but the file has " + std::to_string(bytes.size()) +
                          (bytes.size() < needed ? " (truncated)" : " (trailing bytes)"),
                      source);
  }
  if (n > static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max()) / 3) {
    return make_error(ErrorKind::unsupported, "binary STL: too many triangles", source);
  }
  Welder welder(3 * n);
  std::vector<TriangleIndices> triangles;
  triangles.reserve(n);
  for (std::uint64_t t = 0; t < n; ++t) {
    const char* record = bytes.data() + 84 + 50 * t;
    TriangleIndices tri{};
    for (int k = 0; k < 3; ++k) {
      const char* at = record + 12 + 12 * k;  // after the normal
      const Vec3 v{load_f32_le(at), load_f32_le(at + 4), load_f32_le(at + 8)};
      if (!is_finite(v)) {
        return make_error(ErrorKind::invalid_value,
                          "binary STL: triangle " + std::to_string(t) +
                              " has a NaN or infinite coordinate at byte offset " +
                              std::to_string(at - bytes.data()),
                          source);
      }
      tri[static_cast<std::size_t>(k)] = welder.add(v);
    }
    triangles.push_back(tri);
  }
  MeshInfo info{.format = MeshFormat::stl_binary,
                .faces = static_cast<std::int64_t>(n),
                .welded_vertices = welder.welded()};
  return finish_mesh(welder.take_vertices(), std::move(triangles), info, source);
}

// ASCII STL, token by token (line breaks are not significant, but counted for messages).
class AsciiStl {
 public:
  AsciiStl(std::string_view text, const std::string& source)
      : p_(text.data()),
        end_(text.data() + text.size()),
        source_(source),
        welder_(text.size() / 40) {}

  Result<MeshFile> read() {
    MeshInfo info{.format = MeshFormat::stl_ascii};
    std::vector<TriangleIndices> triangles;
    std::vector<std::int32_t> corners;
    if (word() != "solid") return fail(ErrorKind::parse, "expected 'solid' to begin an ASCII STL");
    while (true) {
      skip_rest_of_line();  // the solid's name
      while (true) {
        std::string_view w = word();
        if (w == "endsolid") break;
        if (w != "facet") {
          return fail(ErrorKind::parse,
                      w.empty() ? "the file ends inside a solid (no 'endsolid')"
                                : "expected 'facet' or 'endsolid', found '" + std::string(w) + "'");
        }
        if (word() != "normal") return fail(ErrorKind::parse, "expected 'normal' after 'facet'");
        for (int k = 0; k < 3; ++k) {  // the normal: recomputed by users, but must be a number
          double ignored = 0.0;
          skip_space();
          if (parse_double(p_, end_, ignored) == NumberStatus::not_a_number || !at_separator()) {
            return fail(ErrorKind::parse,
                        "expected a normal component, found " + quote_token(p_, end_));
          }
        }
        if (word() != "outer" || word() != "loop") {
          return fail(ErrorKind::parse, "expected 'outer loop'");
        }
        corners.clear();
        while (true) {
          std::string_view v = word();
          if (v == "endloop") break;
          if (v != "vertex") return fail(ErrorKind::parse, "expected 'vertex' or 'endloop'");
          std::array<double, 3> xyz{};
          for (double& c : xyz) {
            if (auto s = number(c); !s) return s.error();
          }
          corners.push_back(welder_.add({xyz[0], xyz[1], xyz[2]}));
        }
        if (corners.size() < 3) {
          return fail(ErrorKind::degenerate,
                      "a facet needs 3 vertices, this one has " + std::to_string(corners.size()));
        }
        if (word() != "endfacet") return fail(ErrorKind::parse, "expected 'endfacet'");
        append_fan(triangles, corners);
        ++info.faces;
      }
      skip_rest_of_line();  // the name after endsolid
      const std::string_view next = word();
      if (next.empty()) break;
      if (next != "solid") {
        return fail(ErrorKind::parse,
                    "unexpected text '" + std::string(next) + "' after 'endsolid'");
      }
    }
    info.welded_vertices = welder_.welded();
    return finish_mesh(welder_.take_vertices(), std::move(triangles), info, source_);
  }

 private:
  Error fail(ErrorKind kind, std::string message) const {
    return make_error(kind, "ASCII STL: " + std::move(message), source_, line_);
  }
  void skip_space() {
    while (p_ != end_ && is_space(*p_)) {
      if (*p_ == '\n') ++line_;
      ++p_;
    }
  }
  bool at_separator() const { return p_ == end_ || is_space(*p_); }
  std::string_view word() {
    skip_space();
    const char* begin = p_;
    while (p_ != end_ && !is_space(*p_))
      ++p_;
    return {begin, static_cast<std::size_t>(p_ - begin)};
  }
  void skip_rest_of_line() {
    while (p_ != end_ && *p_ != '\n')
      ++p_;
  }
  Status number(double& out) {
    skip_space();
    const char* at = p_;
    switch (parse_double(p_, end_, out)) {
      case NumberStatus::ok:
        break;
      case NumberStatus::not_a_number:
        return fail(ErrorKind::parse,
                    "expected a vertex coordinate, found " + quote_token(at, end_));
      case NumberStatus::not_finite:
        return fail(ErrorKind::invalid_value, "the coordinate " + std::string(at, p_) +
                                                  " is not finite (NaN, infinite or too large)");
    }
    if (!at_separator()) {
      return fail(ErrorKind::parse, "unexpected text " + quote_token(p_, end_) + " after a number");
    }
    return Ok{};
  }

  const char* p_;
  const char* end_;
  const std::string& source_;
  std::int64_t line_ = 1;
  Welder welder_;
};

bool starts_with_solid(std::string_view bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && is_space(bytes[i]))
    ++i;
  return bytes.substr(i, 5) == "solid" && (i + 5 == bytes.size() || is_space(bytes[i + 5]));
}

void append_f32_le(std::string& out, float f) {
  const auto v = std::bit_cast<std::uint32_t>(f);
  for (int i = 0; i < 4; ++i)
    out += static_cast<char>((v >> (8 * i)) & 0xFF);
}

}  // namespace

Result<MeshFile> parse_stl(std::string_view bytes, const std::string& source) {
  if (bytes.empty()) return make_error(ErrorKind::parse, "the file is empty", source);
  // Binary files may begin with "solid" too (many exporters do); the exact size decides.
  if (bytes.size() >= 84 &&
      bytes.size() == 84 + 50 * std::uint64_t{load_u32_le(bytes.data() + 80)}) {
    return parse_binary_stl(bytes, source);
  }
  // A truncated binary file whose header says "solid" shows itself by its non-text bytes.
  const std::string_view head = bytes.substr(0, 1024);
  const bool text = std::none_of(head.begin(), head.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x80 || (u < 0x20 && !is_space(c));
  });
  if (text && starts_with_solid(bytes)) return AsciiStl(bytes, source).read();
  if (bytes.size() < 84) {
    return make_error(ErrorKind::parse,
                      "binary STL: truncated: " + std::to_string(bytes.size()) +
                          " bytes, the header alone takes 84",
                      source);
  }
  return parse_binary_stl(bytes, source);
}

std::string format_stl(const Mesh& mesh, MeshFormat format) {
  std::string out;
  if (format == MeshFormat::stl_ascii) {
    // Doubles in full (ASCII STL is text), so this form is lossless.
    out.reserve(mesh.triangles.size() * 200);
    out += "solid contain\n";
    for (const TriangleIndices& t : mesh.triangles) {
      out += "facet normal 0 0 0\nouter loop\n";
      for (std::int32_t i : t)
        append_vertex_line(out, "vertex ", mesh.vertex(i));
      out += "endloop\nendfacet\n";
    }
    out += "endsolid contain\n";
    return out;
  }
  out.reserve(84 + 50 * mesh.triangles.size());
  std::string header = "binary STL written by contain";  // must not begin with "solid"
  header.resize(80, ' ');
  out += header;
  const auto n = static_cast<std::uint32_t>(mesh.triangles.size());
  for (int i = 0; i < 4; ++i)
    out += static_cast<char>((n >> (8 * i)) & 0xFF);
  for (const TriangleIndices& t : mesh.triangles) {
    const Vec3 a = mesh.vertex(t[0]);
    const Vec3 b = mesh.vertex(t[1]);
    const Vec3 c = mesh.vertex(t[2]);
    Vec3 normal = cross(b - a, c - a);
    const double len = length(normal);
    normal = (len > 0.0 && std::isfinite(len)) ? (1.0 / len) * normal : Vec3{};
    for (const Vec3& v : {normal, a, b, c}) {
      append_f32_le(out, static_cast<float>(v.x));
      append_f32_le(out, static_cast<float>(v.y));
      append_f32_le(out, static_cast<float>(v.z));
    }
    out += '\0';
    out += '\0';
  }
  return out;
}

}  // namespace contain::io::detail
