#pragma once
// Private to contain::distance: turning an exactly chosen pair of flats into an answer.

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "contain/distance/closest.h"
#include "contain/predicates/rounded_distance.h"
#include "contain/predicates/squared_distance.h"

namespace contain::distance::detail {

/// The rounded distance of `pair` (a point flat first) and, when asked, the rounded closest
/// point on the second flat.
[[nodiscard]] inline Closest3 answer(const predicates::FlatPair3& pair, bool closest_point) {
  Closest3 out;
  if (closest_point) {
    const predicates::RoundedPointDistance3 r = predicates::rounded_point_distance(pair);
    out.distance = r.distance;
    out.point = r.point;
  } else {
    out.distance = predicates::rounded_distance(pair);
  }
  return out;
}
[[nodiscard]] inline Closest2 answer(const predicates::FlatPair2& pair, bool closest_point) {
  Closest2 out;
  out.distance = predicates::rounded_distance(pair);
  if (closest_point) out.point = predicates::rounded_closest_points(pair).b;
  return out;
}

/// Applies a location to an unsigned answer: negative inside; on the boundary the distance is 0.
template <class C>
void apply_sign(C& c, Location location) {
  c.location = location;
  if (location == Location::inside) c.distance = -c.distance;
  if (location == Location::boundary) c.distance = 0.0;
}

/// Bounds lo <= d^2 <= hi for the floating-point stage of a `within d` test: d * d rounded,
/// widened by four ulps each way and by two subnormal units (the product may underflow); d * d
/// may overflow, and the exact d^2 is then above DBL_MAX.
struct SquaredBounds {
  double lo;
  double hi;
};
[[nodiscard]] inline SquaredBounds squared_bounds(double d) {
  const double d2 = d * d;
  const double tiny = 2 * std::numeric_limits<double>::denorm_min();
  return {std::isfinite(d2) ? std::max(0.0, d2 * (1 - 0x1p-50) - tiny) : DBL_MAX,
          d2 * (1 + 0x1p-50) + tiny};
}

}  // namespace contain::distance::detail
