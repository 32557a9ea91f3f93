#include "contain/io/geojson.h"

#include "contain/io/layer_io.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "io/json_tree.h"
#include "io/ring_text.h"
#include "io/text_scan.h"

namespace contain::io {
namespace {

using detail::JsonValue;
using detail::kind_name;
using detail::make_error;

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

void append_json_ring(std::string& out, const Ring& ring) {
  detail::append_ring_text(out, ring, detail::RingSyntax::geojson);
}

void append_json_polygon(std::string& out, const Polygon& polygon) {
  out += '[';
  bool first = true;
  for (const Ring& ring : polygon.rings) {
    if (ring.empty()) continue;
    if (!first) out += ',';
    first = false;
    append_json_ring(out, ring);
  }
  out += ']';
}

}  // namespace

Result<MultiPolygon> parse_geojson(std::string_view text, const std::string& source) {
  text = detail::skip_bom(text);
  auto root = detail::parse_json_tree(text, source);
  if (!root) return root.error();
  MultiPolygon out;
  GeoJsonReader reader(text, source);
  if (auto s = reader.read_object(*root, out, 0); !s) return s.error();
  return out;
}

namespace {

// The text of an id or a property value, or nullopt where there is none (null, missing).
std::optional<std::string> id_text(const JsonValue* value) {
  if (value == nullptr) return std::nullopt;
  switch (value->kind) {
    case JsonValue::Kind::string:
      return value->text;
    case JsonValue::Kind::number:
      // An integer as written (beyond a double's 2^53 too); 3.0 or 3e0 as GDAL reads them.
      if (value->text.find_first_of(".eE") == std::string::npos) return value->text;
      return detail::number_id(value->number);
    case JsonValue::Kind::boolean:
      return value->number != 0.0 ? "true" : "false";
    default:
      return std::nullopt;
  }
}

const JsonValue* properties_of(const JsonValue& shape) {
  const JsonValue* p = shape.member("properties");
  return p != nullptr && p->kind == JsonValue::Kind::object ? p : nullptr;
}

bool any_feature_has(const std::vector<const JsonValue*>& shapes, const std::string& name) {
  for (const JsonValue* shape : shapes) {
    const JsonValue* p = properties_of(*shape);
    if (p != nullptr && p->member(name) != nullptr) return true;
  }
  return false;
}

// The property names of the features, each once, in order of first appearance.
std::string property_names(const std::vector<const JsonValue*>& shapes) {
  std::vector<std::string_view> names;
  for (const JsonValue* shape : shapes) {
    const JsonValue* p = properties_of(*shape);
    if (p == nullptr) continue;
    for (const detail::JsonMember& m : p->members) {
      if (std::find(names.begin(), names.end(), m.key) == names.end()) names.push_back(m.key);
    }
  }
  std::string out;
  for (const std::string_view n : names)
    out += (out.empty() ? "" : ", ") + std::string(n);
  return out.empty() ? "none" : out;
}

}  // namespace

Result<Layer> parse_geojson_layer(std::string_view text, const std::string& source,
                                  const LayerOptions& options) {
  text = detail::skip_bom(text);
  const std::array<std::string_view, 2> keep{"id", options.id};
  auto root = detail::parse_json_tree(text, source, keep);
  if (!root) return root.error();
  // The shapes of the layer: the features of a collection, or the one object given.
  std::vector<const JsonValue*> shapes;
  const JsonValue* type = root->kind == JsonValue::Kind::object ? root->member("type") : nullptr;
  const std::string_view t = type != nullptr ? std::string_view(type->text) : std::string_view();
  const char* list = t == "FeatureCollection"    ? "features"
                     : t == "GeometryCollection" ? "geometries"
                                                 : nullptr;
  if (list != nullptr) {
    const JsonValue* items = root->member(list);
    if (items == nullptr || items->kind != JsonValue::Kind::array) {
      return make_error(ErrorKind::parse,
                        std::string("the ") + std::string(t) + " has no \"" + list + "\" array",
                        source, detail::line_of_offset(text, root->offset));
    }
    for (const JsonValue& item : items->items)
      shapes.push_back(&item);
  } else {
    shapes.push_back(&*root);
  }
  Layer layer;
  layer.regions.resize(shapes.size());
  GeoJsonReader reader(text, source);
  bool every_id = !shapes.empty();
  std::vector<std::string> feature_ids;
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const JsonValue& shape = *shapes[k];
    if (auto s = reader.read_object(shape, layer.regions[k], 1); !s) return s.error();
    const JsonValue* properties = shape.member("properties");
    if (!options.id.empty()) {
      const JsonValue* value = properties != nullptr && properties->kind == JsonValue::Kind::object
                                   ? properties->member(options.id)
                                   : nullptr;
      std::optional<std::string> id = id_text(value);
      if (!id && !any_feature_has(shapes, options.id)) {
        // The option names what the file does not have: a usage error, as GDAL's readers give
        // for a field that is not in the layer (the same code for GeoJSON and a Shapefile).
        return make_error(ErrorKind::usage,
                          "no property '" + options.id +
                              "' in any feature (properties: " + property_names(shapes) + ")",
                          source);
      }
      if (!id) {
        return make_error(ErrorKind::invalid_value,
                          "feature " + std::to_string(k) + " has no value of the property '" +
                              options.id + "'" + (value != nullptr ? " (null)" : ""),
                          source, detail::line_of_offset(text, shape.offset));
      }
      layer.ids.push_back(std::move(*id));
    } else if (every_id) {
      std::optional<std::string> id = id_text(shape.member("id"));
      if (id) {
        feature_ids.push_back(std::move(*id));
      } else {
        every_id = false;
      }
    }
  }
  if (options.id.empty()) {
    if (every_id && (t == "FeatureCollection" || t == "Feature")) {
      layer.ids = std::move(feature_ids);
    } else {
      for (std::size_t k = 0; k < shapes.size(); ++k)
        layer.ids.push_back(std::to_string(k));
    }
  }
  return layer;
}

Result<MultiPolygon> read_geojson(const std::filesystem::path& path) {
  auto text = detail::read_file(path);
  if (!text) return text.error();
  return parse_geojson(*text, detail::source_name(path));
}

std::string format_geojson(const MultiPolygon& region) {
  std::string out;
  format_geojson(region, out);
  return out;
}

void format_geojson(const MultiPolygon& region, std::string& out) {
  out += R"({"type":"MultiPolygon","coordinates":[)";
  bool first = true;
  for (const Polygon& polygon : region.polygons) {
    if (polygon.rings.empty()) continue;
    if (!first) out += ',';
    first = false;
    append_json_polygon(out, polygon);
  }
  out += "]}";
}

std::string format_geojson(const Polygon& polygon) {
  std::string out = R"({"type":"Polygon","coordinates":)";
  append_json_polygon(out, polygon);
  out += '}';
  return out;
}

}  // namespace contain::io
