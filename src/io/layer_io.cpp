#include "contain/io/layer_io.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "contain/inside/point_in_polygon.h"
#include "contain/io/region_io.h"
#include "contain/io/wkt.h"
#include "io/text_scan.h"

namespace contain::io {
namespace {

bool starts_with_ci(std::string_view text, std::string_view prefix) {
  if (text.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(text[i])) !=
        std::tolower(static_cast<unsigned char>(prefix[i]))) {
      return false;
    }
  }
  return true;
}

// A vertex of `ring` that is not on the boundary of `region`, and where it lies; boundary when
// every vertex is on it (the ring says nothing then).
Location first_clear_location(const Ring& ring, std::span<const Ring> region) {
  for (const Vec2 p : ring) {
    const Location l = inside::point_in_polygon(region, p);
    if (l != Location::boundary) return l;
  }
  return Location::boundary;
}

bool boxes_meet(const Box2& a, const Box2& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

// The validity warnings of one region (see Layer::warnings): exact point locations of one vertex
// a ring, so a cheap check rather than a full OGC validation (crossing edges with no vertex
// inside go unseen); parts are compared only where their boxes meet.
void check_region(const MultiPolygon& region, const std::string& what,
                  std::vector<std::string>& warnings) {
  std::vector<Box2> boxes;
  for (const Polygon& polygon : region.polygons) {
    const std::span<const Ring> shell(polygon.rings.data(), polygon.rings.empty() ? 0 : 1);
    boxes.push_back(bounding_box(shell));
    for (std::size_t h = 1; h < polygon.rings.size(); ++h) {
      if (first_clear_location(polygon.rings[h], shell) == Location::outside) {
        warnings.push_back(what + ", polygon " + std::to_string(boxes.size()) + ": hole " +
                           std::to_string(h) + " has a vertex outside its shell (not OGC-valid)");
        return;
      }
    }
  }
  for (std::size_t a = 0; a < region.polygons.size(); ++a) {
    for (std::size_t b = 0; b < region.polygons.size(); ++b) {
      if (a == b || region.polygons[a].rings.empty() || !boxes_meet(boxes[a], boxes[b])) continue;
      if (first_clear_location(region.polygons[a].rings.front(), region.polygons[b].rings) ==
          Location::inside) {
        warnings.push_back(what + ": polygons " + std::to_string(std::min(a, b) + 1) + " and " +
                           std::to_string(std::max(a, b) + 1) +
                           " overlap (a vertex of one inside the other; not OGC-valid)");
        return;
      }
    }
  }
}

}  // namespace

void check_layer(Layer& layer, const std::string& source) {
  for (std::size_t k = 0; k < layer.regions.size(); ++k)
    check_region(layer.regions[k], source + ": shape " + std::to_string(k), layer.warnings);
}

Result<Layer> parse_wkt_layer(std::string_view text, const std::string& source,
                              const LayerOptions& options) {
  if (!options.id.empty()) {
    return detail::make_error(ErrorKind::usage,
                              "--id " + options.id +
                                  ": a WKT layer has no attributes (its ids are the line "
                                  "positions); use GeoJSON or a GDAL format for named ids",
                              source);
  }
  text = detail::skip_bom(text);
  Layer layer;
  std::int64_t line = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t stop = text.find('\n', start);
    if (stop == std::string_view::npos) stop = text.size();
    const std::string_view row = text.substr(start, stop - start);
    start = stop + 1;
    ++line;
    std::size_t first = 0;
    while (first < row.size() && detail::is_space(row[first]))
      ++first;
    if (first == row.size() || row[first] == '#') continue;
    auto region = parse_wkt_with_notes(row, source);
    if (!region) {
      Error error = region.error();
      error.line = line;  // parse_wkt counted lines of this row alone
      return error;
    }
    if (!region->notes.unclosed_rings.empty()) {
      layer.warnings.push_back(source + ":" + std::to_string(line) +
                               ": ring not closed (WKT repeats the first point at the end); read "
                               "as closed");
    }
    layer.ids.push_back(std::to_string(layer.regions.size()));
    layer.regions.push_back(std::move(region->region));
  }
  return layer;
}

std::string layer_source_name(const std::string& source) {
  return detail::connection_name(source);
}

Result<Layer> read_layer(const std::string& source, const LayerOptions& options) {
  const bool database = starts_with_ci(source, "PG:");
  const std::optional<RegionFormat> format =
      database ? std::nullopt : region_format(std::filesystem::path(source));
  if (format) {
    const std::string ext = detail::lower_extension(source);
    auto text = detail::read_file(source);
    if (!text) return text.error();
    const std::string name = detail::source_name(source);
    if (!options.layer_name.empty()) {
      return detail::make_error(
          ErrorKind::usage,
          "--layer-name " + options.layer_name + ": a " + ext + " file holds one layer", name);
    }
    auto layer = format == RegionFormat::wkt ? parse_wkt_layer(*text, name, options)
                                             : parse_geojson_layer(*text, name, options);
    if (layer) check_layer(*layer, name);
    return layer;
  }
  auto layer = read_gdal_layer(source, options);
  if (layer) check_layer(*layer, detail::connection_name(source));
  return layer;
}

}  // namespace contain::io
