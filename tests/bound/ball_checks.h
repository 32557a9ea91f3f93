#pragma once
/// \file
/// Checks shared by the bounding-ball tests: exact containment (GMP oracle) and the radius
/// against the brute-force minimal ball.

#include <cstddef>
#include <span>

#include "contain/values/sphere.h"
#include "contain/values/vec.h"

namespace contain::test {

/// How many points lie strictly outside the ball, decided exactly in rationals.
[[nodiscard]] std::size_t count_outside(const Sphere& sphere, std::span<const Vec3> points);
[[nodiscard]] std::size_t count_outside(const Circle& circle, std::span<const Vec2> points);

/// r / r_min - 1, where r_min is the exact minimal radius of the points by brute force: over all
/// distinct points when there are at most 14, else over the 12 distinct points farthest from the
/// ball's center.
/// For a ball that contains every point the candidates' r_min <= the true r_min <= r, so a small
/// result proves r within that much of the true minimum, whichever candidates were taken.
/// Negative only if the ball is smaller than the candidates' minimal ball (a containment bug).
[[nodiscard]] double relative_excess(const Sphere& sphere, std::span<const Vec3> points);
[[nodiscard]] double relative_excess(const Circle& circle, std::span<const Vec2> points);

}  // namespace contain::test
