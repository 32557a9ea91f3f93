#include "contain/io/region_io.h"

#include "contain/io/geojson.h"
#include "contain/io/wkt.h"
#include "io/text_scan.h"

namespace contain::io {

Result<MultiPolygon> read_region(const std::filesystem::path& path, WktNotes* notes) {
  const std::string ext = detail::lower_extension(path);
  if (ext == ".wkt") return read_wkt(path, notes);
  if (ext == ".geojson" || ext == ".json") return read_geojson(path);
  return detail::make_error(
      ErrorKind::unsupported,
      "cannot tell the region format from the extension '" + ext + "': use .wkt or .geojson",
      detail::source_name(path));
}

}  // namespace contain::io
