#pragma once
// Private: Ritter's approximate bounding ball in floating point (the exact pass follows in
// enclose.h).

#include <cmath>
#include <span>

#include "bound/ball_common.h"

namespace contain::bound::detail {

/// J. Ritter, "An efficient bounding sphere", Graphics Gems (1990): a far pair (the point farthest
/// from the first point, and the point farthest from that) gives the initial diameter; one pass
/// then grows the ball around each point outside it, keeping the old ball inside the new one
/// (the new ball touches the old one on the side away from the point). Precondition: non-empty,
/// finite, coordinates small enough that squared distances do not overflow.
template <class P>
[[nodiscard]] FpBall<P> ritter_ball(std::span<const P> points) {
  const P y = farthest_from(points, points.front());
  const P z = farthest_from(points, y);
  P center = 0.5 * (y + z);
  double radius = 0.5 * length(z - y);
  double r2 = radius * radius;
  for (const P& p : points) {
    const double d2 = squared_length(p - center);
    // Only steers the growth; containment is decided by the exact pass afterwards.
    if (d2 > r2) {
      const double d = std::sqrt(d2);
      const double grown = 0.5 * (radius + d);
      center = p + (center - p) * (grown / d);
      radius = grown;
      r2 = radius * radius;
    }
  }
  return {center, radius};
}

}  // namespace contain::bound::detail
