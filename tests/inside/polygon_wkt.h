#pragma once
/// \file
/// Test-only reader of POLYGON / MULTIPOLYGON WKT (2D, EMPTY allowed), for the corpus tests of
/// point in polygon (the library's reader belongs to io/, which inside/ must not use).

#include <optional>
#include <string_view>

#include "contain/shapes/polygon.h"

namespace contain::test {

/// The polygons of a POLYGON or MULTIPOLYGON WKT string, rings as written (closing point
/// dropped); nothing if the text is not such WKT.
[[nodiscard]] std::optional<MultiPolygon> parse_polygon_wkt(std::string_view text);

}  // namespace contain::test
