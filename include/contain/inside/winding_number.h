#pragma once
/// \file
/// The exact winding number of a set of closed paths around a point.

#include <span>

#include "contain/shapes/polygon.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// The winding number of `rings` (closed paths in the direction written; counter-clockwise
/// loops count +1) around `point`, exactly on the given doubles.
///
/// For a point on no edge this is the usual winding number. For a point on an edge or vertex it
/// is, by the **right-up perturbation rule**, the winding number of p + delta*(1, eta) for
/// delta, eta -> 0+ (the sector just counter-clockwise of the +x direction), which is what the
/// **half-open ray rule** counts when the edges through the point are left out (see
/// `point_in_polygon`). Coordinates must be finite.
///
/// Complexity: O(n) for n edges, no allocation.
[[nodiscard]] int winding_number(std::span<const Ring> rings, Vec2 point);

/// The same for the rings of a polygon.
[[nodiscard]] int winding_number(const Polygon& polygon, Vec2 point);

}  // namespace contain::inside
