#pragma once
/// \file
/// Distances and closest points rounded once: the double nearest to the exact value.
///
/// The exact squared distance between two flats is a quotient N / D of polynomials in the input
/// doubles (`squared_distance.h`); its square root is in general irrational and the closest
/// points' coordinates are quotients too. Each is rounded to the nearest double (ties to even), as
/// IEEE 754 rounds a single operation: the result is never more than half an ulp from the exact
/// value. Method: N, D (and the coordinate numerators) are evaluated with a running error bound
/// in extended precision, the candidate double c is read off, and the two rounding boundaries of
/// c (the midpoints to its neighbours, m) are checked against the value: m^2 D < N < m'^2 D for a
/// square root, m D < X < m' D for a quotient X / D. When the bound does not settle a side (the
/// value within ~2^-60 relative of a boundary, or exactly on one), the same comparisons are made
/// exactly in big-number arithmetic, stepping c by one ulp until both hold; an exact tie goes to
/// the even neighbour. Derivation: docs/robustness.md, "Distance".

#include "contain/predicates/squared_distance.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// The double nearest to the exact distance between the two flats of `x` (ties to even): 0
/// exactly where they meet; +infinity where the exact distance is at least DBL_MAX + ulp/2 (as
/// IEEE 754 rounds an overflowing result). Preconditions as `FlatPair3`. O(1).
[[nodiscard]] double rounded_distance(const FlatPair3& x);
[[nodiscard]] double rounded_distance(const FlatPair2& x);

/// The closest pair of points of the two flats, each coordinate the double nearest to the exact
/// coordinate (for a point flat: the point itself). For point-line and point-plane pairs, the
/// projection of the point; for two lines, the feet of their common perpendicular. These points
/// lie within half an ulp per coordinate of the exact ones (not necessarily on the flat).
struct ClosestPoints3 {
  Vec3 a;  ///< on x.a
  Vec3 b;  ///< on x.b
};
struct ClosestPoints2 {
  Vec2 a;
  Vec2 b;
};
[[nodiscard]] ClosestPoints3 rounded_closest_points(const FlatPair3& x);
[[nodiscard]] ClosestPoints2 rounded_closest_points(const FlatPair2& x);

/// A point's rounded distance to a flat and the rounded closest point of the flat, together:
/// exactly `rounded_distance(x)` and `rounded_closest_points(x).b`, for a pair whose first flat
/// is a point (any other pair is passed on to those two). The squared distance and the closest
/// point share their terms (the line's direction or the plane's normal, the denominator), so
/// this costs about half of the two calls.
struct RoundedPointDistance3 {
  double distance;
  Vec3 point;  ///< on x.b
};
[[nodiscard]] RoundedPointDistance3 rounded_point_distance(const FlatPair3& x);

}  // namespace contain::predicates
