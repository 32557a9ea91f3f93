#pragma once
/// \file
/// Reading a 2D region from a file whose extension names its format (the CLI's `--polygon`).

#include <filesystem>
#include <optional>

#include "contain/core/result.h"
#include "contain/io/wkt.h"
#include "contain/shapes/polygon.h"

namespace contain::io {

/// The formats of a 2D region file.
enum class RegionFormat { wkt, geojson };

/// The one rule for a region's format from its file name, used by every reader and front end:
/// `.wkt` is WKT, `.geojson` and `.json` are GeoJSON (case-insensitive); anything else is none
/// (a mesh, a GDAL source, an unknown file).
[[nodiscard]] std::optional<RegionFormat> region_format(const std::filesystem::path& path);

/// Reads a region: `.wkt` with `read_wkt`, `.geojson` (and `.json`) with `read_geojson`; the
/// extension is compared case-insensitively. Another extension is ErrorKind::unsupported naming
/// it; every reader error comes back as is (source = the path, line where one applies).
[[nodiscard]] Result<MultiPolygon> read_region(const std::filesystem::path& path);

/// `read_region` with the notes of what a WKT file held that OGC WKT does not allow (none for
/// GeoJSON); the same region and the same errors.
[[nodiscard]] Result<WktRegion> read_region_with_notes(const std::filesystem::path& path);

}  // namespace contain::io
