#pragma once
/// \file
/// The minimal enclosing ball by brute force in exact rational arithmetic: an oracle independent
/// of the library's algorithm, for small point sets.

#include <gmpxx.h>

#include <span>
#include <vector>

#include "contain/values/vec.h"

namespace contain::test {

/// A ball with a rational center and squared radius.
struct ExactBall {
  std::vector<mpq_class> center;
  mpq_class squared_radius;
};

/// The minimal enclosing ball of `points` (non-empty, small: O(n^(d+2)) rational operations).
/// Every subset of at most d + 1 affinely independent points defines the smallest ball with those
/// points on its sphere (its center in their affine hull); the minimal enclosing ball is the
/// smallest such ball that holds every point (its support is such a subset).
[[nodiscard]] ExactBall brute_force_min_ball(std::span<const Vec3> points);
[[nodiscard]] ExactBall brute_force_min_ball(std::span<const Vec2> points);

/// r^2 as an exact rational (r is a double).
[[nodiscard]] mpq_class exact_square(double r);

}  // namespace contain::test
