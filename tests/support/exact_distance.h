#pragma once
/// \file
/// The exact oracle of the distance tests, in GMP rationals and written independently of the
/// library (projection by solving the normal equations, clamped parameters): exact squared
/// distances and closest points to triangles and segments, and the double nearest to a rational
/// or to the square root of one, by exact comparisons with the rounding boundaries.

#include <gmpxx.h>

#include "contain/values/box.h"
#include "contain/values/segment.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"
#include "support/exact.h"

namespace contain::test {

struct ExactClosest3 {
  mpq_class squared_distance;
  QVec3 point;
};
struct ExactClosest2 {
  mpq_class squared_distance;
  QVec2 point;
};

/// The closed triangle's (degenerate: its segment hull's) point closest to p, exactly.
[[nodiscard]] ExactClosest3 exact_closest(Vec3 p, const Triangle3& t);
/// The closed segment's point closest to p, exactly.
[[nodiscard]] ExactClosest3 exact_closest(Vec3 p, const Segment3& s);
[[nodiscard]] ExactClosest2 exact_closest(Vec2 p, const Segment2& s);

/// Squared distance between two closed segments, exactly (the least of the interior critical
/// point, when the segments are not parallel and it lies in both, and the four endpoint-segment
/// distances).
[[nodiscard]] mpq_class exact_squared_distance(const Segment3& s, const Segment3& t);
[[nodiscard]] mpq_class exact_squared_distance(const Segment2& s, const Segment2& t);

/// Squared distance from p to the closed box, exactly: a lower bound of the distance to anything
/// inside it, with which the brute-force oracles skip what cannot matter.
[[nodiscard]] mpq_class exact_squared_distance(Vec3 p, const Box3& b);

/// The double nearest to x (ties to even; +-infinity beyond DBL_MAX + ulp/2).
[[nodiscard]] double nearest_double(const mpq_class& x);
/// The double nearest to sqrt(x), x >= 0 (ties to even; +infinity beyond DBL_MAX + ulp/2).
[[nodiscard]] double nearest_double_sqrt(const mpq_class& x);

}  // namespace contain::test
