#pragma once
/// \file
/// GJK: the distance between two convex sets given by their support functions, in floating point,
/// with a lower bound and the approximate closest points. The guide of the exact convex queries
/// above it (collide::convex_convex certifies its separating direction; distance::
/// convex_convex keeps only the faces its direction cannot rule out); never a decision by itself.

#include <array>
#include <functional>

#include "contain/values/vec.h"

namespace contain::bound {

/// A support function: a point of the convex set farthest in the direction given (any point of
/// the set for the zero direction).
using Support = std::function<Vec3(Vec3)>;

/// What GJK found about A - B = {a - b}.
struct GjkResult {
  /// The point of A - B closest to the origin found, v = point_a - point_b (floating point).
  Vec3 v{};
  /// Approximate closest points: the same convex combination of the support points of A, of B.
  Vec3 point_a{};
  Vec3 point_b{};
  /// The support points of the final simplex (count of them in `simplex_size`): a closest point
  /// of each set lies in the hull of its points, up to rounding.
  std::array<Vec3, 4> simplex_a{};
  std::array<Vec3, 4> simplex_b{};
  int simplex_size = 0;
  /// max over the iterations of v . w / |v| (w the support point of A - B in -v), in floating
  /// point: a lower bound of the distance up to rounding.
  double lower = 0.0;
  /// The largest |w| met: the scale of the rounding errors.
  double size = 0.0;
  /// The origin was found in A - B (the sets meet, up to rounding).
  bool origin_inside = false;
  int iterations = 0;
};

/// Gilbert, Johnson and Keerthi (1988): the distance iteration on A - B, the closest point of
/// each simplex by trying its faces (Johnson's sub-algorithm in the form of Ericson, "Real-Time
/// Collision Detection" 9.5), run to convergence (upper and lower bounds within 1e-12 relative),
/// no progress, or 64 iterations. Floating point throughout: callers that decide anything must
/// certify its answer exactly. O(iterations x support cost).
[[nodiscard]] GjkResult gjk(const Support& support_a, const Support& support_b);

}  // namespace contain::bound
