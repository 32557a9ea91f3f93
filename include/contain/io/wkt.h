#pragma once
/// \file
/// Well-known text (OGC Simple Features, ISO 19125-1 §7) for 2D regions: POLYGON and
/// MULTIPOLYGON, read and written.

#include <filesystem>
#include <string>
#include <string_view>

#include "contain/core/result.h"
#include "contain/shapes/polygon.h"

namespace contain::io {

/// Parses one POLYGON or MULTIPOLYGON.
///
/// Accepted: keywords in any case; `POLYGON EMPTY`, `MULTIPOLYGON EMPTY` and EMPTY members of a
/// MULTIPOLYGON and EMPTY rings (all give nothing); the dimension tags Z, M and ZM, and untagged
/// coordinates of 3 or 4 ordinates — every extra ordinate (z, m) is dropped, as the region is 2D;
/// any white space and newlines between tokens; an EWKT `SRID=n;` prefix (ignored). A POLYGON gives
/// a MultiPolygon of one polygon. Rings go through `Polygon::from_rings`: the closing point is
/// dropped (an unclosed ring is accepted as closed).
///
/// Errors, each naming `source` and the 1-based line: ErrorKind::parse (unknown keyword, missing
/// parenthesis or comma, text that is not a number, trailing text, empty input, coordinates of
/// differing dimension); ErrorKind::unsupported (another WKT type, named: POINT, LINESTRING, ...);
/// ErrorKind::invalid_value (NaN, Inf, a number that overflows such as 1e400);
/// ErrorKind::degenerate (a ring of fewer than 3 distinct points). Numbers are read with
/// std::from_chars, so the shortest round-trip decimal of a double reads back as exactly that
/// double. Linear time.
[[nodiscard]] Result<MultiPolygon> parse_wkt(std::string_view text, const std::string& source);

/// Reads a WKT file (see `parse_wkt`); a missing or unreadable file is ErrorKind::io.
[[nodiscard]] Result<MultiPolygon> read_wkt(const std::filesystem::path& path);

/// `MULTIPOLYGON (((x y, ...)), ...)`, or `MULTIPOLYGON EMPTY` when there is no polygon, with
/// every ring closed (its first point repeated) and every coordinate written as the shortest
/// decimal that reads back as the same double, so `parse_wkt(write_wkt(m)) == m` bit for bit for
/// rings of at least 3 points whose last point differs from the first. Polygons without rings
/// are left out. One line, no newline at the end.
[[nodiscard]] std::string write_wkt(const MultiPolygon& region);

/// `POLYGON ((x y, ...), ...)`, or `POLYGON EMPTY` for a polygon without rings (as above).
[[nodiscard]] std::string write_wkt(const Polygon& polygon);

}  // namespace contain::io
