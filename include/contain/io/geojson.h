#pragma once
/// \file
/// GeoJSON (RFC 7946) for 2D regions: polygons read from any of the usual containers, and
/// written back.

#include <filesystem>
#include <string>
#include <string_view>

#include "contain/core/result.h"
#include "contain/shapes/polygon.h"

namespace contain::io {

/// Parses a GeoJSON text into one region: the polygons of a Polygon, a MultiPolygon, a Feature
/// (a null geometry gives none), a FeatureCollection or a GeometryCollection (nested
/// collections too), all gathered in document order. Positions may hold more than two numbers
/// (altitude and the rest are dropped: the region is 2D). Rings go through
/// `Polygon::from_rings` (the closing position is dropped). Members other than "type",
/// "coordinates", "geometry", "geometries" and "features" (properties, bbox, crs, id) are ignored.
///
/// Errors, each naming `source` and the 1-based line of the offending value: ErrorKind::parse
/// for malformed JSON (with nlohmann-json's description) and for a missing or mistyped member;
/// ErrorKind::unsupported for another geometry type, named ("Point", "LineString", ...);
/// ErrorKind::invalid_value for a number that overflows a double (1e400); ErrorKind::degenerate
/// for a ring of fewer than 3 distinct points. Numbers are correctly rounded (std::from_chars).
/// Linear time.
[[nodiscard]] Result<MultiPolygon> parse_geojson(std::string_view text, const std::string& source);

/// Reads a GeoJSON file (see `parse_geojson`); a missing or unreadable file is ErrorKind::io.
[[nodiscard]] Result<MultiPolygon> read_geojson(const std::filesystem::path& path);

/// `{"type":"MultiPolygon","coordinates":[...]}` with closed rings and shortest round-trip
/// numbers, so `parse_geojson(format_geojson(m)) == m` bit for bit for rings of at least 3 points
/// whose last point differs from the first. Ring directions are written as given (RFC 7946 asks
/// for counter-clockwise shells; the writer does not reorder). One line, no newline at the end.
[[nodiscard]] std::string format_geojson(const MultiPolygon& region);

/// `format_geojson(region)` appended to `out` (no temporary string: writers of many regions).
void format_geojson(const MultiPolygon& region, std::string& out);

/// `{"type":"Polygon","coordinates":[...]}`, as above.
[[nodiscard]] std::string format_geojson(const Polygon& polygon);

}  // namespace contain::io
