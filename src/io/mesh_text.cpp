// OBJ and OFF: line-based text formats, read in one pass over the whole file in memory.
#include <algorithm>
#include <array>
#include <cassert>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

#include "io/mesh_formats.h"
#include "io/point_lines.h"
#include "io/text_scan.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace contain::io::detail {
namespace {

constexpr std::int64_t kMaxIndex = std::numeric_limits<std::int32_t>::max();

// Walks a text line by line; `line` is 1-based, [p, eol) the current line without its '\n'.
struct Lines {
  const char* next;
  const char* end;
  const char* p = nullptr;
  const char* eol = nullptr;
  std::int64_t line = 0;

  explicit Lines(std::string_view text) : next(text.data()), end(text.data() + text.size()) {}

  bool advance() {
    if (next == end) return false;
    ++line;
    p = next;
    eol = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (eol == nullptr) eol = end;
    next = (eol == end) ? end : eol + 1;
    return true;
  }
  // Advances to the next line holding something other than blanks and a `#` comment; p is left at
  // its first non-blank character.
  bool advance_to_content() {
    while (advance()) {
      skip_blanks(p, eol);
      if (p != eol && *p != '#') return true;
    }
    return false;
  }
  [[nodiscard]] bool at_line_end() {
    skip_blanks(p, eol);
    return p == eol || *p == '#';
  }
};

// Reads a finite number at lines.p that must end at a blank, the line end or `#`.
Status read_number(Lines& in, double& out, const std::string& source, const char* what) {
  skip_blanks(in.p, in.eol);
  const char* at = in.p;
  switch (parse_double(in.p, in.eol, out)) {
    case NumberStatus::ok:
      break;
    case NumberStatus::not_a_number:
      return make_error(ErrorKind::parse,
                        std::string("expected ") + what + ", found " + quote_token(at, in.eol),
                        source, in.line);
    case NumberStatus::not_finite:
      return make_error(ErrorKind::invalid_value,
                        std::string(what) + " " + std::string(at, in.p) +
                            " is not finite (NaN, infinite or too large for a double)",
                        source, in.line);
  }
  if (in.p != in.eol && !is_blank(*in.p) && *in.p != '#') {
    return make_error(ErrorKind::parse,
                      "unexpected text " + quote_token(in.p, in.eol) + " after the number " +
                          std::string(at, in.p),
                      source, in.line);
  }
  return Ok{};
}

// Reads an integer at lines.p that must end at a blank, the line end or `#`.
Status read_integer(Lines& in, std::int64_t& out, const std::string& source, const char* what) {
  skip_blanks(in.p, in.eol);
  const char* at = in.p;
  if (!parse_int64(in.p, in.eol, out) || (in.p != in.eol && !is_blank(*in.p) && *in.p != '#')) {
    in.p = at;
    return make_error(ErrorKind::parse,
                      std::string("expected ") + what + ", found " + quote_token(at, in.eol),
                      source, in.line);
  }
  return Ok{};
}

// The rest of a line may only hold numbers (colours, normals, texture coordinates).
Status skip_extra_numbers(Lines& in, const std::string& source) {
  while (!in.at_line_end()) {
    const char* at = in.p;
    double ignored = 0.0;
    if (parse_double(in.p, in.eol, ignored) == NumberStatus::not_a_number ||
        (in.p != in.eol && !is_blank(*in.p) && *in.p != '#')) {
      return make_error(ErrorKind::parse, "unexpected text " + quote_token(at, in.eol), source,
                        in.line);
    }
  }
  return Ok{};
}

// The one-pass OFF scanners: the fast way of the vertex and face blocks, in the manner of
// point_lines.h. They split the lines and scan the values in one walk (no line-end search before
// each line), writing straight into the destination arrays, and take only lines the general
// reading below accepts with the same values. At the first line they cannot take (a bad or
// non-finite number, a comment glued to a value, a signed index, an index out of range...) they
// stop at its start, and the general reading takes that one line, wording any error with its line.

// After the values of a line: blanks, then the line end, a `#` comment or the end of the text;
// or more finite numbers (colours, normals), which both readers skip. False: decline the line.
bool off_scan_line_rest(const char*& p, const char* end) {
  for (;;) {
    const char* after = p;
    skip_blanks(p, end);
    if (p == end) return true;
    if (*p == '\n') {
      ++p;
      return true;
    }
    if (*p == '#') {
      skip_past_line(p, end);
      return true;
    }
    double ignored = 0.0;
    if (p == after || !scan_finite_number(p, end, ignored)) return false;
  }
}

// Plain decimal digits (no sign, at most 9: below 2^31) at p, followed by a blank, a newline or
// the end; false otherwise.
bool off_scan_index(const char*& p, const char* end, std::int64_t& out) {
  const char* q = p;
  const char* const limit = p + std::min<std::ptrdiff_t>(10, end - p);  // one test a digit
  std::int64_t v = 0;
  while (q != limit && static_cast<unsigned char>(*q - '0') <= 9)
    v = 10 * v + (*q++ - '0');
  if (q == p || q - p > 9 || (q != end && !is_space(*q))) return false;
  p = q;
  out = v;
  return true;
}

// Skips blank and comment lines from in.next; false at the end of the text. `line_start` is left
// at the content line's start (for a decline), `p` at its first non-blank character.
bool off_scan_to_content(Lines& in, const char*& line_start, const char*& p) {
  p = in.next;
  while (p != in.end) {
    line_start = p;
    ++in.line;
    skip_blanks(p, in.end);
    if (p == in.end) return false;
    if (*p == '\n') {
      ++p;
      continue;
    }
    if (*p == '#') {
      skip_past_line(p, in.end);
      continue;
    }
    return true;
  }
  return false;
}

// Takes OFF vertex lines from in.next while it can, up to `wanted` vertices; leaves `in` before
// the first line it did not take (or at the end of the text).
void scan_off_vertex_lines(Lines& in, std::int64_t wanted, std::vector<Vec3>& vertices) {
  const char* p = nullptr;
  const char* line_start = nullptr;
  for (std::int64_t i = 0; i < wanted; ++i) {
    if (!off_scan_to_content(in, line_start, p)) {
      in.next = in.end;  // only blank lines remain: the general reading reports the short file
      return;
    }
    double xyz[3];
    bool taken = scan_finite_number(p, in.end, xyz[0]);
    for (int k = 1; taken && k < 3; ++k) {
      const char* after = p;
      skip_blanks(p, in.end);
      taken = p != after && scan_finite_number(p, in.end, xyz[k]);
    }
    if (!taken || !off_scan_line_rest(p, in.end)) {
      in.next = line_start;
      in.line -= 1;  // the general reading counts this line again
      return;
    }
    vertices.push_back({xyz[0], xyz[1], xyz[2]});
    in.next = p;
  }
}

// Takes OFF face lines ("n i0 .. in-1", n >= 3, indices in [0, nv), an optional colour) from
// in.next while it can, up to `wanted` faces, appending their fans; leaves `in` before the first
// line it did not take (or at the end of the text).
void scan_off_face_lines(Lines& in, std::int64_t wanted, std::int64_t nv,
                         std::vector<TriangleIndices>& triangles, std::int64_t& faces) {
  const char* p = nullptr;
  const char* line_start = nullptr;
  for (std::int64_t f = 0; f < wanted; ++f) {
    if (!off_scan_to_content(in, line_start, p)) {
      in.next = in.end;
      return;
    }
    const std::size_t triangles_before = triangles.size();
    std::int64_t n = 0;
    std::int64_t first = 0;
    std::int64_t previous = 0;
    bool taken = off_scan_index(p, in.end, n) && n >= 3;
    for (std::int64_t k = 0; taken && k < n; ++k) {
      skip_blanks(p, in.end);
      std::int64_t index = 0;
      taken = off_scan_index(p, in.end, index) && index < nv;
      if (!taken) break;
      if (k == 0) {
        first = index;
      } else if (k >= 2) {
        triangles.push_back({static_cast<std::int32_t>(first), static_cast<std::int32_t>(previous),
                             static_cast<std::int32_t>(index)});
      }
      previous = index;
    }
    if (!taken || !off_scan_line_rest(p, in.end)) {
      triangles.resize(triangles_before);
      in.next = line_start;
      in.line -= 1;  // the general reading counts this line again
      return;
    }
    ++faces;
    in.next = p;
  }
}

// OFF's vertex section: nv lines of three coordinates (and optional colours or normals).
Status read_off_vertices(Lines& in, std::int64_t nv, std::vector<Vec3>& vertices,
                         const std::string& source) {
  for (auto i = static_cast<std::int64_t>(vertices.size()); i < nv;
       i = static_cast<std::int64_t>(vertices.size())) {
    scan_off_vertex_lines(in, nv - i, vertices);
    i = static_cast<std::int64_t>(vertices.size());
    if (i == nv) break;
    // The line the scanner declined (or the end of the file): the general reading words it.
    if (!in.advance_to_content()) {
      return make_error(ErrorKind::parse,
                        "the file ends after " + std::to_string(i) + " of the " +
                            std::to_string(nv) + " vertices the header announces",
                        source, in.line);
    }
    std::array<double, 3> xyz{};
    for (double& c : xyz) {
      if (auto s = read_number(in, c, source, "a vertex coordinate"); !s) return s;
    }
    if (auto s = skip_extra_numbers(in, source); !s) return s;
    vertices.push_back({xyz[0], xyz[1], xyz[2]});
  }
  return Ok{};
}

// Maps in the pages of a vector's reserved capacity with one call (Linux's
// MADV_POPULATE_WRITE) instead of a page fault each as the scanner first writes them: on the
// 2-core VM of docs/benchmarks.md a fault costs about 12 us, the populated page about half of
// that. Only the pages wholly inside the block are asked for; a hint, no effect on the contents.
template <class T>
void populate_capacity(std::vector<T>& values) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr std::uintptr_t kPage = 4096;
  const auto begin = reinterpret_cast<std::uintptr_t>(values.data());
  const std::uintptr_t first = (begin + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t last = (begin + values.capacity() * sizeof(T)) & ~(kPage - 1);
  if (last > first + 16 * kPage) {
    (void)::madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE);
  }
#else
  (void)values;
#endif
}

bool keyword_is(std::string_view word, std::initializer_list<std::string_view> list) {
  return std::find(list.begin(), list.end(), word) != list.end();
}

}  // namespace

// OBJ (Wavefront, "Object Files" appendix B1 of the Advanced Visualizer manual): statements
// one a line; only `v` and `f` carry the mesh. Vertex references are 1-based, negative ones count
// back from the latest vertex; a positive one may point past the vertices read so far (some
// writers put faces first), so those are checked at the end, against the line of the largest.
Result<MeshFile> parse_obj(std::string_view text, const std::string& source) {
  text = skip_bom(text);
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    return make_error(ErrorKind::parse, "the file is empty", source, 1);
  }
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  vertices.reserve(text.size() / 64);
  triangles.reserve(text.size() / 32);
  MeshInfo info{.format = MeshFormat::obj};
  std::vector<std::int32_t> corners;
  std::int64_t max_index = -1;
  std::int64_t max_index_line = 0;
  Lines in(text);
  while (in.advance_to_content()) {
    const char* word_begin = in.p;
    while (in.p != in.eol && !is_blank(*in.p) && *in.p != '#')
      ++in.p;
    const std::string_view word(word_begin, static_cast<std::size_t>(in.p - word_begin));
    if (word == "v") {
      std::array<double, 3> xyz{};
      for (double& c : xyz) {
        if (auto s = read_number(in, c, source, "a vertex coordinate"); !s) return s.error();
      }
      // Optional w (a weight for rational curves, meaningless for a mesh) or vertex colours.
      if (auto s = skip_extra_numbers(in, source); !s) return s.error();
      vertices.push_back({xyz[0], xyz[1], xyz[2]});
    } else if (word == "f") {
      corners.clear();
      const auto count = static_cast<std::int64_t>(vertices.size());
      while (!in.at_line_end()) {
        const char* at = in.p;
        std::int64_t index = 0;
        if (!parse_int64(in.p, in.eol, index)) {
          return make_error(ErrorKind::parse,
                            "expected a vertex index, found " + quote_token(at, in.eol), source,
                            in.line);
        }
        // a/b, a//c, a/b/c: the texture and normal references must be integers, and are unused.
        for (int slash = 0; slash < 2 && in.p != in.eol && *in.p == '/'; ++slash) {
          ++in.p;
          std::int64_t ignored = 0;
          if (in.p != in.eol && *in.p != '/' && !is_blank(*in.p) &&
              !parse_int64(in.p, in.eol, ignored)) {
            return make_error(ErrorKind::parse,
                              "malformed vertex reference " + quote_token(at, in.eol), source,
                              in.line);
          }
        }
        if (in.p != in.eol && !is_blank(*in.p) && *in.p != '#') {
          return make_error(ErrorKind::parse,
                            "malformed vertex reference " + quote_token(at, in.eol), source,
                            in.line);
        }
        if (index == 0) {
          return make_error(ErrorKind::invalid_value,
                            "vertex index 0: OBJ indices start at 1 (negative ones count back)",
                            source, in.line);
        }
        if (index < 0) {
          if (index < -count) {
            return make_error(ErrorKind::invalid_value,
                              "relative vertex index " + std::to_string(index) +
                                  " reaches before the first vertex (" + std::to_string(count) +
                                  " read so far)",
                              source, in.line);
          }
          index += count;
        } else {
          if (index > kMaxIndex) {
            return make_error(ErrorKind::invalid_value,
                              "vertex index " + std::to_string(index) + " is out of range", source,
                              in.line);
          }
          index -= 1;
          if (index > max_index) {
            max_index = index;
            max_index_line = in.line;
          }
        }
        corners.push_back(static_cast<std::int32_t>(index));
      }
      if (corners.size() < 3) {
        return make_error(
            ErrorKind::degenerate,
            "a face needs at least 3 vertices, this one has " + std::to_string(corners.size()),
            source, in.line);
      }
      append_fan(triangles, corners);
      ++info.faces;
    } else if (keyword_is(
                   word,
                   {"vt",       "vn",     "vp",     "g",          "o",         "s",     "usemtl",
                    "mtllib",   "l",      "p",      "mg",         "lod",       "bevel", "c_interp",
                    "d_interp", "usemap", "maplib", "shadow_obj", "trace_obj", "ctech", "stech"})) {
      continue;  // texture, normals, grouping, materials, lines and display: not the solid
    } else if (keyword_is(word, {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm",
                                 "trim", "hole", "scrv", "sp", "end", "con"})) {
      return make_error(ErrorKind::unsupported,
                        "OBJ free-form geometry ('" + std::string(word) +
                            "') is not supported: only polygonal faces",
                        source, in.line);
    } else {
      return make_error(ErrorKind::parse,
                        "unknown OBJ statement " + quote_token(word_begin, in.eol), source,
                        in.line);
    }
  }
  if (max_index >= static_cast<std::int64_t>(vertices.size())) {
    return make_error(ErrorKind::invalid_value,
                      "vertex index " + std::to_string(max_index + 1) +
                          " is out of range: the file has " + std::to_string(vertices.size()) +
                          " vertices",
                      source, max_index_line);
  }
  return finish_mesh(std::move(vertices), std::move(triangles), info, source);
}

// OFF (Geomview's "OFF files" page): [ST][C][N][4][n]OFF, then vertex, face and edge counts (on
// the header line or the next), then one vertex a line and one face a line (`n i0 .. in-1`
// followed by an optional colour). `#` starts a comment anywhere.
Result<MeshFile> parse_off(std::string_view text, const std::string& source) {
  text = skip_bom(text);
  Lines in(text);
  if (!in.advance_to_content()) return make_error(ErrorKind::parse, "the file is empty", source, 1);
  const char* word_begin = in.p;
  while (in.p != in.eol && !is_blank(*in.p) && *in.p != '#')
    ++in.p;
  const std::string_view header(word_begin, static_cast<std::size_t>(in.p - word_begin));
  if (header.size() < 3 || header.substr(header.size() - 3) != "OFF" ||
      header.substr(0, header.size() - 3).find_first_not_of("STCN4n") != std::string_view::npos) {
    return make_error(ErrorKind::parse,
                      "expected the OFF header, found " + quote_token(word_begin, in.eol), source,
                      in.line);
  }
  const std::string_view prefix = header.substr(0, header.size() - 3);
  if (prefix.find_first_of("4n") != std::string_view::npos) {
    return make_error(ErrorKind::unsupported,
                      "'" + std::string(header) + "' files (4D or n-D vertices) are not supported",
                      source, in.line);
  }
  if (!in.at_line_end()) {
    const char* at = in.p;
    while (in.p != in.eol && !is_blank(*in.p))
      ++in.p;
    if (std::string_view(at, static_cast<std::size_t>(in.p - at)) == "BINARY") {
      return make_error(ErrorKind::unsupported, "binary OFF is not supported", source, in.line);
    }
    in.p = at;
  } else if (!in.advance_to_content()) {
    return make_error(ErrorKind::parse, "the file ends before the vertex and face counts", source,
                      in.line);
  }
  std::int64_t nv = 0;
  std::int64_t nf = 0;
  std::int64_t ne = 0;
  if (auto s = read_integer(in, nv, source, "the vertex count"); !s) return s.error();
  if (auto s = read_integer(in, nf, source, "the face count"); !s) return s.error();
  if (!in.at_line_end()) {
    if (auto s = read_integer(in, ne, source, "the edge count"); !s) return s.error();
  }
  if (!in.at_line_end()) {
    return make_error(ErrorKind::parse,
                      "unexpected text " + quote_token(in.p, in.eol) + " after the counts", source,
                      in.line);
  }
  if (nv < 0 || nf < 0) {
    return make_error(ErrorKind::invalid_value, "negative vertex or face count", source, in.line);
  }
  if (nv > kMaxIndex) {
    return make_error(ErrorKind::unsupported,
                      "more than 2^31 - 1 vertices (" + std::to_string(nv) + ")", source, in.line);
  }
  const auto cap = static_cast<std::int64_t>(text.size() / 4);  // no header lies us out of memory
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  vertices.reserve(static_cast<std::size_t>(std::min(nv, cap)));
  triangles.reserve(static_cast<std::size_t>(std::min(nf, cap)));
  // Reserving is address space only; populating commits memory: only for a header the text can
  // hold (a vertex line is 6 bytes at least, a face line 8), so that counts that lie cost no
  // more than the file before the lines prove them wrong.
  if (nv * 6 + nf * 8 <= static_cast<std::int64_t>(text.size())) {
    populate_capacity(vertices);
    populate_capacity(triangles);
  }
  if (auto s = read_off_vertices(in, nv, vertices, source); !s) return s.error();
  MeshInfo info{.format = MeshFormat::off};
  std::vector<std::int32_t> corners;
  for (std::int64_t f = 0; f < nf; f = info.faces) {
    scan_off_face_lines(in, nf - f, nv, triangles, info.faces);
    f = info.faces;
    if (f == nf) break;
    // The line the scanner declined (or the end of the file): the general reading words it.
    if (!in.advance_to_content()) {
      return make_error(ErrorKind::parse,
                        "the file ends after " + std::to_string(f) + " of the " +
                            std::to_string(nf) + " faces the header announces",
                        source, in.line);
    }
    std::int64_t n = 0;
    if (auto s = read_integer(in, n, source, "the vertex count of a face"); !s) return s.error();
    if (n < 3) {
      return make_error(ErrorKind::degenerate,
                        "a face needs at least 3 vertices, this one has " + std::to_string(n),
                        source, in.line);
    }
    corners.clear();
    for (std::int64_t k = 0; k < n; ++k) {
      std::int64_t index = 0;
      if (in.at_line_end()) {
        return make_error(
            ErrorKind::parse,
            "the face announces " + std::to_string(n) + " vertices but lists " + std::to_string(k),
            source, in.line);
      }
      if (auto s = read_integer(in, index, source, "a vertex index"); !s) return s.error();
      if (index < 0 || index >= nv) {
        return make_error(ErrorKind::invalid_value,
                          "vertex index " + std::to_string(index) + " is out of range: there are " +
                              std::to_string(nv) + " vertices (indices start at 0)",
                          source, in.line);
      }
      corners.push_back(static_cast<std::int32_t>(index));
    }
    if (auto s = skip_extra_numbers(in, source); !s) return s.error();  // the face colour
    append_fan(triangles, corners);
    ++info.faces;
  }
  if (in.advance_to_content()) {
    return make_error(ErrorKind::parse,
                      "unexpected data after the " + std::to_string(nf) +
                          " faces the header announces: " + quote_token(in.p, in.eol),
                      source, in.line);
  }
  return finish_mesh(std::move(vertices), std::move(triangles), info, source);
}

namespace {

// The vertex and index lines of OBJ, OFF and ASCII PLY written in place into a buffer sized for the
// longest lines, then trimmed: no std::string append per number nor std::to_string per index
// (writing was twice the time of reading the same mesh). The same bytes as appending.
constexpr std::size_t kPrefixRoom = 2;  // "v ", "f ", "3 " or nothing
constexpr std::size_t kVertexLineRoom = kPrefixRoom + 3 * kMaxDoubleChars + 3;
constexpr std::size_t kIndexRoom = 20;  // an int64 in decimal, sign included
constexpr std::size_t kIndexLineRoom = kPrefixRoom + 3 * kIndexRoom + 3;

char* put_prefix(char* at, std::string_view prefix) {
  for (const char c : prefix)
    *at++ = c;
  return at;
}

char* put_vertex_line(char* at, std::string_view prefix, Vec3 v) {
  at = put_prefix(at, prefix);
  at = write_double(at, v.x);
  *at++ = ' ';
  at = write_double(at, v.y);
  *at++ = ' ';
  at = write_double(at, v.z);
  *at++ = '\n';
  return at;
}

char* put_index_line(char* at, std::string_view prefix, const TriangleIndices& t, int base) {
  at = put_prefix(at, prefix);
  for (std::size_t k = 0; k < 3; ++k) {
    if (k > 0) *at++ = ' ';
    at = std::to_chars(at, at + kIndexRoom, std::int64_t{t[k]} + base).ptr;
  }
  *at++ = '\n';
  return at;
}

}  // namespace

// `header`, then a line per vertex and per triangle, written through a buffer of a few pages
// (a buffer for the whole text, zeroed by resizing, was a pass more over megabytes).
std::string format_lines(const Mesh& mesh, const std::string& header, std::string_view vertex,
                         std::string_view face, int base) {
  assert(vertex.size() <= kPrefixRoom && face.size() <= kPrefixRoom && "lines sized for these");
  std::string out;
  out.reserve(header.size() + mesh.vertices.size() * 48 + mesh.triangles.size() * 24);
  out += header;
  std::array<char, 1U << 15U> chunk{};
  char* at = chunk.data();
  const auto room = [&](std::size_t line) {
    if (static_cast<std::size_t>(chunk.data() + chunk.size() - at) >= line) return;
    out.append(chunk.data(), at);
    at = chunk.data();
  };
  for (const Vec3& v : mesh.vertices) {
    room(kVertexLineRoom);
    at = put_vertex_line(at, vertex, v);
  }
  for (const TriangleIndices& t : mesh.triangles) {
    room(kIndexLineRoom);
    at = put_index_line(at, face, t, base);
  }
  out.append(chunk.data(), at);
  return out;
}

void append_vertex_line(std::string& out, const char* prefix, Vec3 v) {
  out += prefix;  // any length (STL's "vertex "): the line after it put in place
  char line[kVertexLineRoom];
  out.append(line, put_vertex_line(line, "", v));
}

std::string format_obj(const Mesh& mesh) {
  return format_lines(mesh, "# written by contain\n", "v ", "f ", 1);
}

std::string format_off(const Mesh& mesh) {
  return format_lines(mesh,
                      "OFF\n" + std::to_string(mesh.vertices.size()) + ' ' +
                          std::to_string(mesh.triangles.size()) + " 0\n",
                      "", "3 ", 0);
}

}  // namespace contain::io::detail
