#include "contain/io/wkt.h"

#include <cctype>
#include <utility>
#include <vector>

#include "io/ring_text.h"
#include "io/text_scan.h"

namespace contain::io {
namespace {

using detail::make_error;
using detail::NumberStatus;

// A recursive-descent reader of the grammar of ISO 19125-1 §7.2 restricted to polygons:
//   geometry  := ('POLYGON' tag polygon | 'MULTIPOLYGON' tag multi
//                | 'GEOMETRYCOLLECTION' tag collection)
//   collection := 'EMPTY' | '(' geometry { ',' geometry } ')'   (members: polygons only)
//   tag       := [ 'Z' | 'M' | 'ZM' ]
//   multi     := 'EMPTY' | '(' polygon { ',' polygon } ')'
//   polygon   := 'EMPTY' | '(' ring { ',' ring } ')'
//   ring      := 'EMPTY' | '(' coord { ',' coord } ')'
//   coord     := number number [ number [ number ] ]
// The line is counted while skipping white space (tokens never hold a newline).
class WktReader {
 public:
  WktReader(std::string_view text, const std::string& source, WktNotes* notes)
      : p_(text.data()), end_(text.data() + text.size()), source_(source), notes_(notes) {}

  Result<MultiPolygon> read() {
    skip_space();
    if (p_ == end_)
      return fail(ErrorKind::parse, "the input is empty: expected POLYGON or MULTIPOLYGON");
    std::string word = keyword();
    if (word == "SRID") {
      // EWKT: SRID=n; before the geometry.
      skip_space();
      if (!eat('=')) return fail(ErrorKind::parse, "expected '=' after SRID");
      skip_space();
      std::int64_t srid = 0;
      if (!detail::parse_int64(p_, end_, srid))
        return fail(ErrorKind::parse, "expected the SRID number");
      skip_space();
      if (!eat(';')) return fail(ErrorKind::parse, "expected ';' after the SRID");
      skip_space();
      word = keyword();
    }
    MultiPolygon out;
    if (Status status = read_geometry(word, out, 0); !status) return status.error();
    skip_space();
    if (p_ != end_) {
      return fail(ErrorKind::parse,
                  "unexpected text " + detail::quote_token(p_, end_) + " after the geometry");
    }
    return out;
  }

 private:
  // One geometry after its keyword `word`: a POLYGON, a MULTIPOLYGON or a GEOMETRYCOLLECTION of
  // them (as GeoJSON's GeometryCollection is read: the union of its members' polygons).
  Status read_geometry(const std::string& word, MultiPolygon& out, int depth) {
    if (word.empty()) {
      return fail(ErrorKind::parse,
                  "expected POLYGON or MULTIPOLYGON, found " + detail::quote_token(p_, end_));
    }
    if (word == "GEOMETRYCOLLECTION") return read_collection(out, depth);
    const bool multi = word == "MULTIPOLYGON";
    if (!multi && word != "POLYGON") {
      static constexpr const char* kOther[] = {
          "POINT",         "LINESTRING",        "MULTIPOINT",     "MULTILINESTRING", "TRIANGLE",
          "TIN",           "POLYHEDRALSURFACE", "CIRCULARSTRING", "CURVEPOLYGON",    "MULTISURFACE",
          "COMPOUNDCURVE", "MULTICURVE",        "LINEARRING"};
      for (const char* other : kOther) {
        if (word == other) {
          return fail(ErrorKind::unsupported,
                      "WKT type " + word +
                          " is not supported: a region must be a POLYGON or a MULTIPOLYGON");
        }
      }
      return fail(ErrorKind::parse,
                  "unknown WKT keyword '" + word + "': expected POLYGON or MULTIPOLYGON");
    }
    if (auto tag = read_tag(); !tag.ok()) return tag.error();
    return multi ? read_multi(out) : read_polygon(out);
  }

  Status read_collection(MultiPolygon& out, int depth) {
    if (depth >= 64) return fail(ErrorKind::unsupported, "collections nested too deeply");
    if (auto tag = read_tag(); !tag.ok()) return tag.error();
    if (empty_token()) return Ok{};
    if (auto s = expect('(', "to open the GEOMETRYCOLLECTION"); !s) return s;
    while (true) {
      skip_space();
      if (auto s = read_geometry(keyword(), out, depth + 1); !s) return s;
      skip_space();
      if (eat(',')) continue;
      if (eat(')')) return Ok{};
      return fail(ErrorKind::parse, "expected ',' or ')' after a member of the collection, found " +
                                        detail::quote_token(p_, end_));
    }
  }

  Error fail(ErrorKind kind, std::string message) const {
    return make_error(kind, std::move(message), source_, line_);
  }

  void skip_space() {
    while (p_ != end_ && detail::is_space(*p_)) {
      if (*p_ == '\n') ++line_;
      ++p_;
    }
  }

  bool eat(char c) {
    if (p_ != end_ && *p_ == c) {
      ++p_;
      return true;
    }
    return false;
  }

  // An upper-cased word of letters, or "" (nothing consumed) when none starts here.
  std::string keyword() {
    std::string word;
    while (p_ != end_ && std::isalpha(static_cast<unsigned char>(*p_))) {
      word += static_cast<char>(std::toupper(static_cast<unsigned char>(*p_)));
      ++p_;
    }
    return word;
  }

  // Optional Z, M or ZM; sets the count of ordinates per coordinate when given.
  Status read_tag() {
    skip_space();
    const char* before = p_;
    const std::int64_t line_before = line_;
    std::string tag = keyword();
    if (tag == "Z" || tag == "M") {
      ordinates_ = 3;
    } else if (tag == "ZM") {
      ordinates_ = 4;
    } else if (!tag.empty() && tag != "EMPTY") {
      return fail(ErrorKind::parse, "unexpected word '" + tag + "' after the geometry type");
    } else {
      p_ = before;  // EMPTY is read by the caller
      line_ = line_before;
    }
    return Ok{};
  }

  // True (and consumed) when the next token is EMPTY.
  bool empty_token() {
    skip_space();
    const char* before = p_;
    if (keyword() == "EMPTY") return true;
    p_ = before;
    return false;
  }

  Status expect(char c, const char* what) {
    skip_space();
    if (!eat(c)) {
      return fail(ErrorKind::parse, std::string("expected '") + c + "' " + what + ", found " +
                                        detail::quote_token(p_, end_));
    }
    return Ok{};
  }

  Status read_multi(MultiPolygon& out) {
    if (empty_token()) return Ok{};
    if (auto s = expect('(', "to open the MULTIPOLYGON"); !s) return s;
    while (true) {
      if (auto s = read_polygon(out); !s) return s;
      skip_space();
      if (eat(',')) continue;
      if (eat(')')) return Ok{};
      return fail(ErrorKind::parse,
                  "expected ',' or ')' after a polygon, found " + detail::quote_token(p_, end_));
    }
  }

  // Appends the polygon (nothing for EMPTY).
  Status read_polygon(MultiPolygon& out) {
    if (empty_token()) return Ok{};
    if (auto s = expect('(', "to open a polygon"); !s) return s;
    const std::int64_t polygon_line = line_;
    std::vector<Ring> rings;
    while (true) {
      if (empty_token()) {  // an empty ring (GEOS writes them) adds nothing
        skip_space();
        if (eat(',')) continue;
        if (eat(')')) break;
        return fail(ErrorKind::parse,
                    "expected ',' or ')' after a ring, found " + detail::quote_token(p_, end_));
      }
      if (auto s = expect('(', "to open a ring"); !s) return s;
      Ring ring;
      while (true) {
        if (auto s = read_coordinate(ring); !s) return s;
        skip_space();
        if (eat(',')) continue;
        if (eat(')')) break;
        return fail(ErrorKind::parse, "expected ',' or ')' after a coordinate, found " +
                                          detail::quote_token(p_, end_));
      }
      if (notes_ != nullptr && ring.front() != ring.back()) notes_->unclosed_rings.push_back(line_);
      rings.push_back(std::move(ring));
      skip_space();
      if (eat(',')) continue;
      if (eat(')')) break;
      return fail(ErrorKind::parse,
                  "expected ',' or ')' after a ring, found " + detail::quote_token(p_, end_));
    }
    if (rings.empty()) return Ok{};
    auto polygon = Polygon::from_rings(std::move(rings));
    if (!polygon) {
      return make_error(
          polygon.error().kind,
          "polygon " + std::to_string(out.polygons.size() + 1) + ": " + polygon.error().message,
          source_, polygon_line);
    }
    out.polygons.push_back(std::move(*polygon));
    return Ok{};
  }

  Status read_coordinate(Ring& ring) {
    double values[4] = {0, 0, 0, 0};
    int count = 0;
    while (true) {
      skip_space();
      if (p_ == end_ || *p_ == ',' || *p_ == ')') break;
      const char* at = p_;
      double v = 0.0;
      switch (detail::parse_double(p_, end_, v)) {
        case NumberStatus::ok:
          break;
        case NumberStatus::not_a_number:
          return fail(ErrorKind::parse,
                      "expected a number, found " + detail::quote_token(at, end_));
        case NumberStatus::not_finite:
          return fail(ErrorKind::invalid_value,
                      "the number " + std::string(at, p_) +
                          " is not finite (NaN, infinite or too large for a double)");
      }
      if (p_ != end_ && !detail::is_space(*p_) && *p_ != ',' && *p_ != ')') {
        return fail(ErrorKind::parse, "unexpected text " + detail::quote_token(p_, end_) +
                                          " after the number " + std::string(at, p_));
      }
      if (count == 4) {
        return fail(ErrorKind::parse, "a coordinate has more than 4 ordinates");
      }
      values[count++] = v;
    }
    if (count < 2) {
      return fail(ErrorKind::parse,
                  count == 0 ? "expected a coordinate (x y), found " + detail::quote_token(p_, end_)
                             : std::string("a coordinate needs at least x and y"));
    }
    if (ordinates_ == 0) ordinates_ = count;
    if (count != ordinates_) {
      return fail(ErrorKind::parse, "a coordinate has " + std::to_string(count) +
                                        " ordinates where the geometry has " +
                                        std::to_string(ordinates_));
    }
    ring.push_back({values[0], values[1]});
    return Ok{};
  }

  const char* p_;
  const char* end_;
  const std::string& source_;
  WktNotes* notes_;
  std::int64_t line_ = 1;
  int ordinates_ = 0;  // per coordinate, fixed by the tag or by the first coordinate
};

void append_ring(std::string& out, const Ring& ring) {
  detail::append_ring_text(out, ring, detail::RingSyntax::wkt);
}

void append_polygon(std::string& out, const Polygon& polygon) {
  out += '(';
  bool first = true;
  for (const Ring& ring : polygon.rings) {
    if (ring.empty()) continue;
    if (!first) out += ", ";
    first = false;
    append_ring(out, ring);
  }
  out += ')';
}

bool has_points(const Polygon& polygon) {
  for (const Ring& ring : polygon.rings) {
    if (!ring.empty()) return true;
  }
  return false;
}

}  // namespace

Result<MultiPolygon> parse_wkt(std::string_view text, const std::string& source) {
  return WktReader(detail::skip_bom(text), source, nullptr).read();
}

Result<WktRegion> parse_wkt_with_notes(std::string_view text, const std::string& source) {
  WktRegion read;
  auto region = WktReader(detail::skip_bom(text), source, &read.notes).read();
  if (!region) return region.error();
  read.region = std::move(*region);
  return read;
}

Result<MultiPolygon> read_wkt(const std::filesystem::path& path) {
  auto text = detail::read_file(path);
  if (!text) return text.error();
  return parse_wkt(*text, detail::source_name(path));
}

std::string format_wkt(const MultiPolygon& region) {
  std::string out;
  format_wkt(region, out);
  return out;
}

void format_wkt(const MultiPolygon& region, std::string& out) {
  out += "MULTIPOLYGON ";
  bool first = true;
  for (const Polygon& polygon : region.polygons) {
    if (!has_points(polygon)) continue;
    out += first ? "(" : ", ";
    first = false;
    append_polygon(out, polygon);
  }
  out += first ? "EMPTY" : ")";
}

std::string format_wkt(const Polygon& polygon) {
  std::string out = "POLYGON ";
  if (!has_points(polygon)) return out + "EMPTY";
  append_polygon(out, polygon);
  return out;
}

}  // namespace contain::io
