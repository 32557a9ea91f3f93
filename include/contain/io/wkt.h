#pragma once
/// \file
/// Well-known text (OGC Simple Features, ISO 19125-1 §7) for 2D regions: POLYGON and
/// MULTIPOLYGON, read and written.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "contain/core/result.h"
#include "contain/shapes/polygon.h"

namespace contain::io {

/// What a WKT reader accepted that OGC WKT does not allow, as data (the CLI words it).
struct WktNotes {
  /// The 1-based line of each ring that ends without repeating its first point: it is read as
  /// closed (a ring always joins its last point to its first).
  std::vector<std::int64_t> unclosed_rings;
};

/// A region read from WKT with what its text held that OGC WKT does not allow.
struct WktRegion {
  MultiPolygon region;
  WktNotes notes;
};

/// Parses one POLYGON or MULTIPOLYGON, or a GEOMETRYCOLLECTION of them (nested up to 64 deep;
/// its region is all its members' polygons, as for GeoJSON's GeometryCollection and WKB; a member
/// of another type is ErrorKind::unsupported).
///
/// Accepted: keywords in any case; `POLYGON EMPTY`, `MULTIPOLYGON EMPTY` and EMPTY members of a
/// MULTIPOLYGON and EMPTY rings (all give nothing); the dimension tags Z, M and ZM, and untagged
/// coordinates of 3 or 4 ordinates — every extra ordinate (z, m) is dropped, as the region is 2D;
/// any white space and newlines between tokens; an EWKT `SRID=n;` prefix (ignored). A POLYGON gives
/// a MultiPolygon of one polygon. Rings go through `Polygon::from_rings`: the closing point is
/// dropped (an unclosed ring is accepted as closed; `parse_wkt_with_notes` names its line).
///
/// Errors, each naming `source` and the 1-based line: ErrorKind::parse (unknown keyword, missing
/// parenthesis or comma, text that is not a number, trailing text, empty input, coordinates of
/// differing dimension); ErrorKind::unsupported (another WKT type, named: POINT, LINESTRING, ...);
/// ErrorKind::invalid_value (NaN, Inf, a number that overflows such as 1e400);
/// ErrorKind::degenerate (a ring of fewer than 3 distinct points). Numbers are read with
/// std::from_chars, so the shortest round-trip decimal of a double reads back as exactly that
/// double. Linear time.
[[nodiscard]] Result<MultiPolygon> parse_wkt(std::string_view text, const std::string& source);

/// `parse_wkt` with the notes of what the text held that OGC WKT does not allow (the lines of
/// unclosed rings); the same region and the same errors.
[[nodiscard]] Result<WktRegion> parse_wkt_with_notes(std::string_view text,
                                                     const std::string& source);

/// Reads a WKT file (see `parse_wkt`); a missing or unreadable file is ErrorKind::io.
[[nodiscard]] Result<MultiPolygon> read_wkt(const std::filesystem::path& path);

/// `MULTIPOLYGON (((x y, ...)), ...)`, or `MULTIPOLYGON EMPTY` when there is no polygon, with
/// every ring closed (its first point repeated) and every coordinate written as the shortest
/// decimal that reads back as the same double, so `parse_wkt(format_wkt(m)) == m` bit for bit for
/// rings of at least 3 points whose last point differs from the first. Polygons without rings
/// are left out. One line, no newline at the end.
[[nodiscard]] std::string format_wkt(const MultiPolygon& region);

/// `format_wkt(region)` appended to `out` (no temporary string: writers of many regions).
void format_wkt(const MultiPolygon& region, std::string& out);

/// `POLYGON ((x y, ...), ...)`, or `POLYGON EMPTY` for a polygon without rings (as above).
[[nodiscard]] std::string format_wkt(const Polygon& polygon);

}  // namespace contain::io
