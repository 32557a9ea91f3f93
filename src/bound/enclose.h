// Private: the driver shared by bounding_sphere and bounding_circle: validation, power-of-two
// scaling of extreme inputs, the floating-point search, and the exact containment pass.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "bound/ball_common.h"
#include "bound/min_ball.h"
#include "bound/ritter_ball.h"
#include "contain/bound/sphere_method.h"
#include "contain/core/result.h"
#include "contain/predicates/sign.h"

namespace contain::bound::detail {

// The search runs unscaled when the largest coordinate is within [2^-kScaleLimit, 2^kScaleLimit]:
// squared distances then stay far from overflow and underflow (Gärtner's solve is quadratic).
inline constexpr int kScaleLimit = 300;

/// |p - c| in floating point without overflow or underflow in the squares (power-of-two scaling
/// is exact); within a few ulps of the true distance.
template <class P>
[[nodiscard]] double distance_estimate(P c, P p) {
  const double m = std::max(max_abs(c), max_abs(p));
  if (m == 0.0) return 0.0;
  // Bring the coordinates below 2^kScaleLimit so that the difference cannot overflow.
  const int shift = std::ilogb(m) >= kScaleLimit ? -std::ilogb(m) : 0;
  const P d = scaled(p, shift) - scaled(c, shift);
  const double dm = max_abs(d);
  if (dm == 0.0) return 0.0;
  const int k = std::ilogb(dm);
  return std::ldexp(length(scaled(d, -k)), k - shift);
}

/// The smallest double radius >= `radius` for which `contains(radius)` holds; `contains` must be
/// monotone (a ball with a larger radius around the same center holds more). Infinity when no
/// finite double works. Precondition: radius >= 0 and !contains(radius).
template <class Contains>
[[nodiscard]] double smallest_radius(double radius, double estimate, Contains contains) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double low = radius;
  double high = std::max(radius, estimate);
  // The estimate is within a few ulps; gallop upwards from it, then bisect on the bit patterns
  // (positive doubles are ordered like their bit patterns).
  double gap = std::max(high * 0x1p-50, std::numeric_limits<double>::denorm_min());
  while (!contains(high)) {
    low = std::max(low, high);
    high += gap;
    gap *= 2.0;
    if (!std::isfinite(high)) return kInf;
  }
  const double below = high * (1.0 - 0x1p-50);
  if (below > low && !contains(below)) low = below;
  auto lo_bits = std::bit_cast<std::uint64_t>(low);
  auto hi_bits = std::bit_cast<std::uint64_t>(high);
  while (hi_bits - lo_bits > 1) {
    const std::uint64_t mid = lo_bits + (hi_bits - lo_bits) / 2;
    if (contains(std::bit_cast<double>(mid))) {
      hi_bits = mid;
    } else {
      lo_bits = mid;
    }
  }
  return std::bit_cast<double>(hi_bits);
}

/// Validates `points`, runs the chosen search (on a scaled copy when coordinates are extreme),
/// then makes every point contained exactly: `side(center, radius, p)` is the exact predicate.
template <class P, class Side>
[[nodiscard]] Result<FpBall<P>> enclose(std::span<const P> points, SphereMethod method, Side side) {
  if (points.empty()) return Error{ErrorKind::degenerate, "there are no points to enclose"};
  double largest = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!is_finite(points[i])) {
      return Error{ErrorKind::invalid_value,
                   "point " + std::to_string(i) + " has a NaN or infinite coordinate"};
    }
    largest = std::max(largest, max_abs(points[i]));
  }
  int exponent = 0;
  std::vector<P> copy;
  std::span<const P> search = points;
  if (largest != 0.0) {
    const int e = std::ilogb(largest);
    if (e <= -kScaleLimit || e >= kScaleLimit) {
      exponent = e;
      copy.reserve(points.size());
      for (const P& p : points)
        copy.push_back(scaled(p, -e));
      search = copy;
    }
  }
  FpBall<P> ball = method == SphereMethod::ritter ? ritter_ball(search) : min_ball(search);
  if (exponent != 0) {
    ball.center = scaled(ball.center, exponent);
    ball.radius = std::ldexp(ball.radius, exponent);
  }
  if (!is_finite(ball.center) || !std::isfinite(ball.radius)) {
    return Error{ErrorKind::unsupported, "the bounding radius exceeds the largest double"};
  }
  // The exact pass: the search was floating point, this decides. Raising the radius keeps every
  // point seen before inside, so one pass suffices.
  for (const P& p : points) {
    if (side(ball.center, ball.radius, p) != Sign::negative) continue;
    ball.radius = smallest_radius(ball.radius, distance_estimate(ball.center, p), [&](double r) {
      return side(ball.center, r, p) != Sign::negative;
    });
    if (!std::isfinite(ball.radius)) {
      return Error{ErrorKind::unsupported, "the bounding radius exceeds the largest double"};
    }
  }
  return ball;
}

}  // namespace contain::bound::detail
