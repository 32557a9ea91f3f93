#include "contain/io/layer_io.h"

#include <filesystem>
#include <optional>

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

}  // namespace

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
    auto region = parse_wkt(row, source);
    if (!region) {
      Error error = region.error();
      error.line = line;  // parse_wkt counted lines of this row alone
      return error;
    }
    layer.ids.push_back(std::to_string(layer.regions.size()));
    layer.regions.push_back(std::move(*region));
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
    return format == RegionFormat::wkt ? parse_wkt_layer(*text, name, options)
                                       : parse_geojson_layer(*text, name, options);
  }
  return read_gdal_layer(source, options);
}

}  // namespace contain::io
