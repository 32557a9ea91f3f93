#include "contain/io/region_io.h"

#include "contain/io/geojson.h"
#include "contain/io/wkt.h"
#include "io/text_scan.h"

namespace contain::io {

std::optional<RegionFormat> region_format(const std::filesystem::path& path) {
  const std::string ext = detail::lower_extension(path);
  if (ext == ".wkt") return RegionFormat::wkt;
  if (ext == ".geojson" || ext == ".json") return RegionFormat::geojson;
  return std::nullopt;
}

Result<MultiPolygon> read_region(const std::filesystem::path& path) {
  auto read = read_region_with_notes(path);
  if (!read) return read.error();
  return std::move(read->region);
}

Result<WktRegion> read_region_with_notes(const std::filesystem::path& path) {
  const std::optional<RegionFormat> format = region_format(path);
  if (format == RegionFormat::wkt) {
    auto text = detail::read_file(path);
    if (!text) return text.error();
    return parse_wkt_with_notes(*text, detail::source_name(path));
  }
  if (format == RegionFormat::geojson) {
    auto region = read_geojson(path);
    if (!region) return region.error();
    return WktRegion{.region = std::move(*region), .notes = {}};
  }
  const std::string ext = detail::lower_extension(path);
  return detail::make_error(
      ErrorKind::unsupported,
      "cannot tell the region format from the extension '" + ext + "': use .wkt or .geojson",
      detail::source_name(path));
}

}  // namespace contain::io
