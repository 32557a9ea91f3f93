#pragma once
/// \file
/// What a point distance query computes.

namespace contain::distance {

/// Options of a point distance query.
struct PointQuery {
  /// Signed distance: negative inside, exactly 0 on the boundary, positive outside, the sign from
  /// the shape's exact containment (`Closest3::location` / `Closest2::location` filled in).
  /// Unsigned (default): the distance to the boundary, never negative.
  bool signed_distance = false;
  /// Round and return the closest point (three more correctly rounded quotients); false leaves
  /// `point` at 0.
  bool closest_point = true;
};

}  // namespace contain::distance
