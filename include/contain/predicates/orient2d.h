#pragma once
/// \file
/// Exact 2D orientation.

#include <cfloat>
#include <cmath>

#include "contain/predicates/sign.h"
#include "contain/predicates/unit_roundoff.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// Sign of det[b - a, c - a] = (b.x - a.x)(c.y - a.y) - (b.y - a.y)(c.x - a.x), computed exactly on
/// the given doubles: positive when a, b, c turn counter-clockwise (c left of the line a->b),
/// zero when they are collinear (including coincident points).
/// A floating-point filter with a proven error bound answers most calls; the rest fall back to
/// exact expansion arithmetic (Shewchuk 1997); inputs beyond 2^-480..2^500 in magnitude are first
/// rescaled by a power of two, and only when their exponents spread too wide for that does exact
/// big-number arithmetic decide. Valid for every finite double; NaN or infinite input is a
/// precondition violation (validated types never hold it). The filter is inline (a dozen flops,
/// most calls end here); the exact stages are not (their cost: docs/benchmarks.md).
/// Rules and bounds: docs/robustness.md, "Predicates".
[[nodiscard]] inline Sign orient2d(Vec2 a, Vec2 b, Vec2 c);

namespace detail {
/// The exact stages of `orient2d`, out of line: expansion arithmetic, or big numbers when the
/// input exponents leave its range.
[[nodiscard]] Sign orient2d_exact(Vec2 a, Vec2 b, Vec2 c);
}  // namespace detail

// Filter: Shewchuk's orient2d stage A (pivot c, the same determinant). Without underflow,
// |error| <= (3 + 16 eps) eps (|detleft| + |detright|), the rounding of the bound included; the
// coefficient is raised to (3 + 32 eps) eps to absorb the rounding of the added underflow guard
// DBL_MIN, which covers the absolute error of the two products if they underflow. Overflow
// makes the bound infinite or NaN, and then both comparisons fail. Contraction into FMAs only
// removes roundings, so the bound holds with or without it.
inline Sign orient2d(Vec2 a, Vec2 b, Vec2 c) {
  constexpr double kBound = (3.0 + 32.0 * unit_roundoff<double>)*unit_roundoff<double>;
  const double detleft = (a.x - c.x) * (b.y - c.y);
  const double detright = (a.y - c.y) * (b.x - c.x);
  const double det = detleft - detright;
  const double errbound = kBound * (std::fabs(detleft) + std::fabs(detright)) + DBL_MIN;
  if (det > errbound) return Sign::positive;
  if (-det > errbound) return Sign::negative;
  return detail::orient2d_exact(a, b, c);
}

}  // namespace contain::predicates
