#pragma once
// Invariant checks of clipped polygons: OGC validity and areas.

#include <string>

#include "contain/shapes/polygon.h"

namespace contain::test {

/// Empty when `region` is valid by OGC rules (rings of >= 3 distinct points, shells
/// counter-clockwise, holes clockwise, no two edges meeting except consecutive ones at their
/// shared vertex, exact orient2d); otherwise what is wrong.
[[nodiscard]] std::string ogc_problem(const MultiPolygon& region);

/// Shells minus holes, by the shoelace formula (holes clockwise count negative).
[[nodiscard]] double area(const MultiPolygon& region);

}  // namespace contain::test
