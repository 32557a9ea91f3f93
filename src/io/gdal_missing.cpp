// read_gdal_layer in a build without GDAL: a clear error instead of a missing format.

#include "contain/io/layer_io.h"
#include "io/text_scan.h"

namespace contain::io {

Result<Layer> read_gdal_layer(const std::string& source, const LayerOptions&) {
  const std::string ext = detail::lower_extension(source);
  return detail::make_error(
      ErrorKind::unsupported,
      std::string("reading ") + (ext.empty() ? "this source" : "'" + ext + "' layers") +
          " needs GDAL, and this contain was built without it (install libgdal-dev, then "
          "configure and build again); without GDAL a layer can be a .wkt file (one POLYGON or "
          "MULTIPOLYGON a line) or a GeoJSON FeatureCollection",
      source);
}

bool has_gdal() {
  return false;
}

}  // namespace contain::io
