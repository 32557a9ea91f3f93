#include "contain/io/geojson.h"

#include <cstddef>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <utility>
#include <vector>

#include "io/text_scan.h"

namespace contain::io {
namespace {

using detail::make_error;

// nlohmann-json's DOM keeps no positions, so the text goes through its SAX parser into this small
// tree, each value remembering the byte offset where the parser stood when it was read (the end
// of its first token): enough to name the line of every semantic error.
struct JsonMember;

struct JsonValue {
  enum class Kind : std::uint8_t { null, boolean, number, string, array, object };
  Kind kind = Kind::null;
  double number = 0.0;
  std::string text;
  std::vector<JsonValue> items;
  std::vector<JsonMember> members;
  std::size_t offset = 0;

  [[nodiscard]] const JsonValue* member(std::string_view name) const;
};

// A named struct rather than std::pair<std::string, JsonValue>, and member() out of the
// class: clang with libstdc++ rejects the pair of a still incomplete JsonValue.
struct JsonMember {
  std::string key;
  JsonValue value;
};

const JsonValue* JsonValue::member(std::string_view name) const {
  for (const auto& [key, value] : members) {
    if (key == name) return &value;
  }
  return nullptr;
}

// A char iterator that publishes how far nlohmann's lexer has read.
class TrackingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  TrackingIterator() = default;
  TrackingIterator(const char* p, const char** cursor) : p_(p), cursor_(cursor) {}
  reference operator*() const { return *p_; }
  TrackingIterator& operator++() {
    ++p_;
    if (cursor_ != nullptr) *cursor_ = p_;
    return *this;
  }
  TrackingIterator operator++(int) {
    TrackingIterator old = *this;
    ++*this;
    return old;
  }
  friend bool operator==(const TrackingIterator& a, const TrackingIterator& b) {
    return a.p_ == b.p_;
  }

 private:
  const char* p_ = nullptr;
  const char** cursor_ = nullptr;
};

class TreeBuilder : public nlohmann::json_sax<nlohmann::json> {
 public:
  TreeBuilder(const char* begin, const char** cursor) : begin_(begin), cursor_(cursor) {}

  bool null() override { return add(JsonValue{}); }
  bool boolean(bool) override { return add(make(JsonValue::Kind::boolean)); }
  bool number_integer(number_integer_t v) override { return add_number(static_cast<double>(v)); }
  bool number_unsigned(number_unsigned_t v) override { return add_number(static_cast<double>(v)); }
  bool number_float(number_float_t, const string_t& text) override {
    // Re-read with from_chars: correctly rounded, and overflow is reported instead of infinity.
    const char* p = text.data();
    double v = 0.0;
    if (detail::parse_double(p, text.data() + text.size(), v) != detail::NumberStatus::ok) {
      error_offset_ = offset();
      error_ = "the number " + text + " is not finite (too large for a double)";
      overflow_ = true;
      return false;
    }
    return add_number(v);
  }
  bool string(string_t& s) override {
    JsonValue v = make(JsonValue::Kind::string);
    v.text = std::move(s);
    return add(std::move(v));
  }
  bool binary(binary_t&) override { return add(JsonValue{}); }
  bool start_object(std::size_t) override {
    if (!can_open()) return false;
    stack_.push_back({make(JsonValue::Kind::object), {}});
    return true;
  }
  bool key(string_t& k) override {
    stack_.back().key = std::move(k);
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override {
    if (!can_open()) return false;
    stack_.push_back({make(JsonValue::Kind::array), {}});
    return true;
  }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string&,
                   const nlohmann::detail::exception& ex) override {
    // Keep nlohmann's description, without its "[json.exception...] parse error at line L, column
    // C: " prefix (the line is ours to report).
    std::string message = ex.what();
    const std::size_t column = message.find("column");
    if (column != std::string::npos) {
      const std::size_t colon = message.find(": ", column);
      if (colon != std::string::npos) message = message.substr(colon + 2);
    } else if (const std::size_t bracket = message.find("] "); bracket != std::string::npos) {
      message = message.substr(bracket + 2);
    }
    // 406: a number too large for a double (nlohmann-json's out_of_range.406).
    overflow_ = ex.id == 406;
    error_ = (overflow_ ? "a number is too large for a double: " : "malformed JSON: ") + message;
    error_offset_ = position == 0 ? 0 : position - 1;
    return false;
  }

  std::optional<JsonValue> root;
  std::string error_;
  std::size_t error_offset_ = 0;
  bool overflow_ = false;

 private:
  struct Open {
    JsonValue value;
    std::string key;
  };

  // The tree is freed recursively: bound its depth (GeoJSON needs 4 levels and a few wrappers).
  bool can_open() {
    if (stack_.size() < 256) return true;
    error_offset_ = offset();
    error_ = "the JSON is nested more than 256 levels deep";
    return false;
  }

  [[nodiscard]] std::size_t offset() const {
    return *cursor_ == nullptr ? 0 : static_cast<std::size_t>(*cursor_ - begin_);
  }
  [[nodiscard]] JsonValue make(JsonValue::Kind kind) const {
    JsonValue v;
    v.kind = kind;
    v.offset = offset() == 0 ? 0 : offset() - 1;
    return v;
  }
  bool add_number(double x) {
    JsonValue v = make(JsonValue::Kind::number);
    v.number = x;
    return add(std::move(v));
  }
  bool add(JsonValue v) {
    if (v.kind == JsonValue::Kind::null) v.offset = offset() == 0 ? 0 : offset() - 1;
    if (stack_.empty()) {
      root = std::move(v);
    } else if (stack_.back().value.kind == JsonValue::Kind::array) {
      stack_.back().value.items.push_back(std::move(v));
    } else {
      stack_.back().value.members.push_back({std::move(stack_.back().key), std::move(v)});
    }
    return true;
  }
  bool close() {
    JsonValue v = std::move(stack_.back().value);
    stack_.pop_back();
    if (stack_.empty()) {
      root = std::move(v);
      return true;
    }
    if (stack_.back().value.kind == JsonValue::Kind::array) {
      stack_.back().value.items.push_back(std::move(v));
    } else {
      stack_.back().value.members.push_back({std::move(stack_.back().key), std::move(v)});
    }
    return true;
  }

  const char* begin_;
  const char** cursor_;
  std::vector<Open> stack_;
};

const char* kind_name(JsonValue::Kind kind) {
  switch (kind) {
    case JsonValue::Kind::null:
      return "null";
    case JsonValue::Kind::boolean:
      return "a boolean";
    case JsonValue::Kind::number:
      return "a number";
    case JsonValue::Kind::string:
      return "a string";
    case JsonValue::Kind::array:
      return "an array";
    case JsonValue::Kind::object:
      return "an object";
  }
  return "a value";
}

class GeoJsonReader {
 public:
  GeoJsonReader(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  Status read_object(const JsonValue& value, MultiPolygon& out, int depth) {
    if (depth > 64) return fail(value, ErrorKind::unsupported, "collections nested too deeply");
    if (value.kind != JsonValue::Kind::object) {
      return fail(value, ErrorKind::parse,
                  std::string("expected a GeoJSON object, found ") + kind_name(value.kind));
    }
    const JsonValue* type = value.member("type");
    if (type == nullptr) return fail(value, ErrorKind::parse, "the object has no \"type\" member");
    if (type->kind != JsonValue::Kind::string) {
      return fail(*type, ErrorKind::parse, "\"type\" must be a string");
    }
    const std::string& t = type->text;
    if (t == "FeatureCollection") {
      const JsonValue* features = array_member(value, "features");
      if (features == nullptr) return last_;
      for (const JsonValue& f : features->items) {
        if (auto s = read_object(f, out, depth + 1); !s) return s;
      }
      return Ok{};
    }
    if (t == "Feature") {
      const JsonValue* geometry = value.member("geometry");
      if (geometry == nullptr) {
        return fail(value, ErrorKind::parse, "the Feature has no \"geometry\" member");
      }
      if (geometry->kind == JsonValue::Kind::null) return Ok{};
      return read_object(*geometry, out, depth + 1);
    }
    if (t == "GeometryCollection") {
      const JsonValue* geometries = array_member(value, "geometries");
      if (geometries == nullptr) return last_;
      for (const JsonValue& g : geometries->items) {
        if (auto s = read_object(g, out, depth + 1); !s) return s;
      }
      return Ok{};
    }
    if (t == "Polygon" || t == "MultiPolygon") {
      const JsonValue* coordinates = array_member(value, "coordinates");
      if (coordinates == nullptr) return last_;
      if (t == "Polygon") return read_polygon(*coordinates, out);
      for (const JsonValue& p : coordinates->items) {
        if (auto s = expect_array(p, "a polygon (an array of rings)"); !s) return s;
        if (auto s = read_polygon(p, out); !s) return s;
      }
      return Ok{};
    }
    if (t == "Point" || t == "MultiPoint" || t == "LineString" || t == "MultiLineString") {
      return fail(*type, ErrorKind::unsupported,
                  "GeoJSON type \"" + t +
                      "\" is not supported: a region must be a Polygon or a MultiPolygon");
    }
    return fail(*type, ErrorKind::parse, "unknown GeoJSON type \"" + t + "\"");
  }

 private:
  Error fail(const JsonValue& at, ErrorKind kind, std::string message) const {
    return make_error(kind, std::move(message), source_, detail::line_of_offset(text_, at.offset));
  }

  // The array member `name`, or nullptr with last_ set.
  const JsonValue* array_member(const JsonValue& object, const char* name) {
    const JsonValue* m = object.member(name);
    if (m == nullptr) {
      last_ =
          fail(object, ErrorKind::parse, std::string("the object has no \"") + name + "\" member");
      return nullptr;
    }
    if (m->kind != JsonValue::Kind::array) {
      last_ = fail(*m, ErrorKind::parse,
                   std::string("\"") + name + "\" must be an array, found " + kind_name(m->kind));
      return nullptr;
    }
    return m;
  }

  Status expect_array(const JsonValue& v, const char* what) const {
    if (v.kind != JsonValue::Kind::array) {
      return fail(v, ErrorKind::parse,
                  std::string("expected ") + what + ", found " + kind_name(v.kind));
    }
    return Ok{};
  }

  Status read_polygon(const JsonValue& rings_value, MultiPolygon& out) const {
    if (rings_value.items.empty()) return Ok{};  // an empty polygon
    std::vector<Ring> rings;
    for (const JsonValue& ring_value : rings_value.items) {
      if (auto s = expect_array(ring_value, "a ring (an array of positions)"); !s) return s;
      Ring ring;
      ring.reserve(ring_value.items.size());
      for (const JsonValue& position : ring_value.items) {
        if (auto s = expect_array(position, "a position [x, y]"); !s) return s;
        if (position.items.size() < 2) {
          return fail(position, ErrorKind::parse, "a position needs at least two numbers [x, y]");
        }
        for (const JsonValue& n : position.items) {
          if (n.kind != JsonValue::Kind::number) {
            return fail(n, ErrorKind::parse,
                        std::string("a position holds numbers, found ") + kind_name(n.kind));
          }
        }
        ring.push_back({position.items[0].number, position.items[1].number});
      }
      rings.push_back(std::move(ring));
    }
    auto polygon = Polygon::from_rings(std::move(rings));
    if (!polygon) {
      return fail(
          rings_value, polygon.error().kind,
          "polygon " + std::to_string(out.polygons.size() + 1) + ": " + polygon.error().message);
    }
    out.polygons.push_back(std::move(*polygon));
    return Ok{};
  }

  std::string_view text_;
  const std::string& source_;
  Status last_ = Ok{};
};

void append_ring(std::string& out, const Ring& ring) {
  out += '[';
  for (std::size_t i = 0; i <= ring.size(); ++i) {
    const Vec2& q = ring[i % ring.size()];
    if (i > 0) out += ',';
    out += '[';
    detail::append_double(out, q.x);
    out += ',';
    detail::append_double(out, q.y);
    out += ']';
  }
  out += ']';
}

void append_polygon(std::string& out, const Polygon& polygon) {
  out += '[';
  bool first = true;
  for (const Ring& ring : polygon.rings) {
    if (ring.empty()) continue;
    if (!first) out += ',';
    first = false;
    append_ring(out, ring);
  }
  out += ']';
}

}  // namespace

Result<MultiPolygon> parse_geojson(std::string_view text, const std::string& source) {
  text = detail::skip_bom(text);
  const char* cursor = nullptr;
  TreeBuilder builder(text.data(), &cursor);
  const char* begin = text.data();
  const char* end = begin + text.size();
  bool ok = false;
  try {
    ok = nlohmann::json::sax_parse(TrackingIterator(begin, &cursor), TrackingIterator(end, nullptr),
                                   &builder);
  } catch (const std::exception& ex) {  // allocation failure and the like: still an Error
    return make_error(ErrorKind::parse, std::string("cannot read the JSON: ") + ex.what(), source);
  }
  if (!ok || !builder.root) {
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
      return make_error(ErrorKind::parse, "the input is empty: expected a GeoJSON object", source,
                        1);
    }
    const ErrorKind kind = builder.overflow_ ? ErrorKind::invalid_value : ErrorKind::parse;
    return make_error(kind, builder.error_, source,
                      detail::line_of_offset(text, builder.error_offset_));
  }
  MultiPolygon out;
  GeoJsonReader reader(text, source);
  if (auto s = reader.read_object(*builder.root, out, 0); !s) return s.error();
  return out;
}

Result<MultiPolygon> read_geojson(const std::filesystem::path& path) {
  auto text = detail::read_file(path);
  if (!text) return text.error();
  return parse_geojson(*text, detail::source_name(path));
}

std::string write_geojson(const MultiPolygon& region) {
  std::string out = R"({"type":"MultiPolygon","coordinates":[)";
  bool first = true;
  for (const Polygon& polygon : region.polygons) {
    if (polygon.rings.empty()) continue;
    if (!first) out += ',';
    first = false;
    append_polygon(out, polygon);
  }
  out += "]}";
  return out;
}

std::string write_geojson(const Polygon& polygon) {
  std::string out = R"({"type":"Polygon","coordinates":)";
  append_polygon(out, polygon);
  out += '}';
  return out;
}

}  // namespace contain::io
