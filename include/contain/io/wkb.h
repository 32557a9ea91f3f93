#pragma once
/// \file
/// Well-known binary (OGC Simple Features, ISO 19125-1 §8, and PostGIS's EWKB) for 2D regions:
/// POLYGON and MULTIPOLYGON, read and written. What shapely's `.wkb`, GeoPandas' `to_wkb()`,
/// GDAL and PostGIS (`ST_AsBinary`, `ST_AsEWKB`, hex EWKB of a geometry column) hand over.

#include <string>
#include <string_view>

#include "contain/core/result.h"
#include "contain/shapes/polygon.h"

namespace contain::io {

/// Parses one POLYGON or MULTIPOLYGON, or a GEOMETRYCOLLECTION of them (nested collections too),
/// gathered in order into one region.
///
/// Accepted: either byte order per geometry (the first byte, 0 big endian, 1 little endian);
/// ISO type codes with Z, M and ZM (1003, 2003, 3003, ...) and EWKB's flag bits (Z 0x80000000,
/// M 0x40000000, SRID 0x20000000 followed by the 4-byte SRID, which is ignored) — every extra
/// ordinate is dropped, as the region is 2D; empty polygons and rings (they give nothing). Rings
/// go through `Polygon::from_rings` (the closing point is dropped). `text` may also be the
/// hexadecimal form (upper or lower case, as PostGIS prints a geometry column).
///
/// Errors, naming `source` and the byte offset in the message: ErrorKind::parse (truncated
/// input, a byte order other than 0 or 1, bytes after the geometry, a count larger than the
/// bytes left, an odd-length or non-hex text); ErrorKind::unsupported (another geometry type,
/// named: Point, LineString, ...); ErrorKind::invalid_value (NaN or infinite coordinates);
/// ErrorKind::degenerate (a ring of fewer than 3 distinct points). Linear time; coordinates are
/// the stored doubles bit for bit.
[[nodiscard]] Result<MultiPolygon> parse_wkb(std::string_view bytes, const std::string& source);

/// Little-endian WKB of a MULTIPOLYGON (type 6) with every ring closed (its first point
/// repeated), so that `parse_wkb(format_wkb(m)) == m` bit for bit for rings of at least 3 points
/// whose last point differs from the first. Polygons without rings are left out.
[[nodiscard]] std::string format_wkb(const MultiPolygon& region);

/// Little-endian WKB of a POLYGON (type 3), as above.
[[nodiscard]] std::string format_wkb(const Polygon& polygon);

}  // namespace contain::io
