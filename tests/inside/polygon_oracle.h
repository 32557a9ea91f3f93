#pragma once
/// \file
/// Test-only exact oracle for point in polygon, in GMP rationals and independent of the library's
/// method: exact crossing abscissae for the winding number, and for a point on edges the true
/// winding number at a rational point inside every sector around it (closer than any other edge).

#include <span>

#include "contain/core/location.h"
#include "contain/shapes/polygon.h"
#include "contain/values/vec.h"

namespace contain::test {

/// Where `p` lies relative to the region `rings` fill under `fill` (the library's contract:
/// `boundary` only on the boundary of the filled region), computed exactly.
[[nodiscard]] Location oracle_point_in_polygon(std::span<const Ring> rings, Vec2 p, Fill fill);

/// The winding number of `rings` around `p`, which must lie on no edge.
[[nodiscard]] int oracle_winding_number(std::span<const Ring> rings, Vec2 p);

/// True when `p` lies on some edge (closed segment) of `rings`, exactly.
[[nodiscard]] bool oracle_on_edge(std::span<const Ring> rings, Vec2 p);

}  // namespace contain::test
