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

Result<MultiPolygon> read_region(const std::filesystem::path& path, WktNotes* notes) {
  const std::optional<RegionFormat> format = region_format(path);
  if (format == RegionFormat::wkt) return read_wkt(path, notes);
  if (format == RegionFormat::geojson) return read_geojson(path);
  const std::string ext = detail::lower_extension(path);
  return detail::make_error(
      ErrorKind::unsupported,
      "cannot tell the region format from the extension '" + ext + "': use .wkt or .geojson",
      detail::source_name(path));
}

}  // namespace contain::io
