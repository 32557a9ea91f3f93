#pragma once
/// \file
/// The largest absolute coordinate of a point or of a set of points: the magnitude every proven
/// error bound of a filter or a slack is scaled by. Exact (a maximum of absolute values rounds
/// nothing), so the order of the coordinates does not matter for finite input.

#include <algorithm>
#include <cmath>
#include <span>

#include "contain/values/vec.h"

namespace contain::values {

/// max(|p.x|, |p.y|). O(1).
[[nodiscard]] inline double max_abs(Vec2 p) {
  return std::max(std::fabs(p.x), std::fabs(p.y));
}

/// max(|p.x|, |p.y|, |p.z|). O(1).
[[nodiscard]] inline double max_abs(Vec3 p) {
  return std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
}

/// The largest absolute coordinate over `points`; 0 for none. O(n).
[[nodiscard]] inline double max_abs(std::span<const Vec2> points) {
  double m = 0.0;
  for (const Vec2& p : points)
    m = std::max(m, max_abs(p));
  return m;
}

/// The largest absolute coordinate over `points`; 0 for none. O(n).
[[nodiscard]] inline double max_abs(std::span<const Vec3> points) {
  double m = 0.0;
  for (const Vec3& p : points)
    m = std::max(m, max_abs(p));
  return m;
}

}  // namespace contain::values

namespace contain {
using values::max_abs;
}  // namespace contain
