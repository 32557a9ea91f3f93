#pragma once
// Private to contain::inside: the neighbourhood analysis of CsgSolid at a point p on the boundary
// of some leaves (the derivation is in include/contain/inside/csg.h and csg_local.cpp).

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "contain/core/location.h"
#include "exact_number.h"

namespace contain::inside::detail {

/// One plane through p that bounds a leaf near p: the leaf's side is normal . (q - p) > 0.
/// `curved`: the tangent plane of a ball whose centre is p + normal (so |normal| = radius), whose
/// surface bends towards the normal at second order. A zero normal is a constraint without
/// geometry whose value is `fixed_value` at every point near p.
struct LocalConstraint {
  ExactVec3 normal;
  bool curved = false;
  bool fixed_value = false;
};

/// Samples every open region of the neighbourhood of p cut by the constraints and calls
/// `solid_contains(positive)` with, for each constraint, whether the region is on its positive
/// side. Returns `inside` if every call returned true, `outside` if every call returned false,
/// else `boundary`; stops as soon as both answers have been seen.
[[nodiscard]] Location classify_neighbourhood(
    std::span<const LocalConstraint> constraints,
    const std::function<bool(std::span<const char> positive)>& solid_contains);

}  // namespace contain::inside::detail
