#pragma once
/// \file
/// The choice of algorithm for bounding spheres and circles.

#include <cstdint>

namespace contain::bound {

/// How `bounding_sphere` and `bounding_circle` compute their ball. Both answers contain every
/// input point exactly (checked with the exact predicates and enlarged by the smallest amount).
enum class SphereMethod : std::uint8_t {
  /// The minimal enclosing ball: Welzl's algorithm with move-to-front and Gärtner's numerics,
  /// radius within about 1e-14 relative of the true minimum (see `bounding_sphere`).
  exact,
  /// Ritter's approximate ball (Graphics Gems, 1990): three linear passes, typically 5-20% larger
  /// than the minimum.
  ritter,
};

}  // namespace contain::bound
