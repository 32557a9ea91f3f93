#include "contain/clip/segment_sphere.h"

#include <algorithm>
#include <cmath>

#include "clip/segment_common.h"
#include "contain/predicates/compare_distance.h"
#include "contain/predicates/halfspace_function.h"

namespace contain::clip {
namespace {

Sign side(const Sphere& s, Vec3 p) {
  return predicates::side_of_sphere(s, p);
}
Sign side(const Circle& s, Vec2 p) {
  return predicates::side_of_circle(s, p);
}

// Exact w.d, d.d - w.d and (r^2 - w.w) d.d + (w.d)^2 with w = c - a, d = b - a.
struct Tangency {
  Sign wd;
  Sign dd_minus_wd;
  Sign discriminant;
};

template <class V>
Tangency tangency(const V& a, const V& b, const V& c, double radius) {
  using predicates::BigFloat;
  BigFloat wd, dd, ww;
  for (int k = 0; k < detail::dimension<V>; ++k) {
    const auto w = BigFloat(detail::coord(c, k)) - BigFloat(detail::coord(a, k));
    const auto d = BigFloat(detail::coord(b, k)) - BigFloat(detail::coord(a, k));
    wd = wd + w * d;
    dd = dd + d * d;
    ww = ww + w * w;
  }
  const auto r2 = BigFloat(radius) * BigFloat(radius);
  return {wd.sign(), (dd - wd).sign(), ((r2 - ww) * dd + wd * wd).sign()};
}

template <class V, class Ball>
typename detail::SegmentOf<V>::Clipped clip_to_ball(const V& a, const V& b, const Ball& ball) {
  const bool in_a = side(ball, a) != Sign::negative, in_b = side(ball, b) != Sign::negative;
  if (in_a && in_b) return detail::kept(a, b, 0.0, 1.0);
  const V d = b - a, w = ball.center - a;
  const double dd = dot(d, d), wd = dot(w, d);
  if (!in_a && !in_b) {
    if (a == b) return detail::nothing<V>();
    const Tangency t = tangency(a, b, ball.center, ball.radius);
    if (t.wd != Sign::positive || t.dd_minus_wd != Sign::positive ||
        t.discriminant == Sign::negative) {
      return detail::nothing<V>();
    }
    if (t.discriminant == Sign::zero) {
      const double tt = std::clamp(wd / dd, 0.0, 1.0);
      const V p = detail::point_at(a, b, tt);
      return detail::kept(p, p, tt, tt);
    }
  }
  // Roots of dd t^2 - 2 wd t + (ww - r^2) = 0 without cancellation: q = wd + sign(wd) sqrt(D),
  // roots q / dd and (ww - r^2) / q.
  const double r = std::fabs(ball.radius);
  const double ww = dot(w, w);
  const double c0 = (std::sqrt(ww) - r) * (std::sqrt(ww) + r);
  const double disc = std::max(0.0, wd * wd - dd * c0);
  const double q = wd + std::copysign(std::sqrt(disc), wd);
  double lo = 0.0, hi = 1.0;
  if (q != 0.0) {
    const double r1 = q / dd, r2 = c0 / q;
    lo = std::min(r1, r2);
    hi = std::max(r1, r2);
  }
  double t0 = in_a ? 0.0 : std::clamp(lo, 0.0, 1.0);
  double t1 = in_b ? 1.0 : std::clamp(hi, 0.0, 1.0);
  if (!std::isfinite(t0)) t0 = 0.0;
  if (!std::isfinite(t1)) t1 = 1.0;
  if (t1 < t0) t0 = t1 = 0.5 * (t0 + t1);
  V p0 = detail::point_at(a, b, t0), p1 = detail::point_at(a, b, t1);
  auto inside = [&](const V& p) { return side(ball, p) != Sign::negative; };
  if (!in_a) t0 = detail::adjust_inward(a, b, t0, in_b ? 1.0 : t1, p0, inside);
  if (!in_b) t1 = detail::adjust_inward(a, b, t1, in_a ? 0.0 : t0, p1, inside);
  return detail::kept(p0, p1, t0, std::max(t0, t1));
}

}  // namespace

ClippedSegment3 clip_segment(const Segment3& segment, const Sphere& ball) {
  return clip_to_ball(segment.a, segment.b, ball);
}
ClippedSegment2 clip_segment(const Segment2& segment, const Circle& disc) {
  return clip_to_ball(segment.a, segment.b, disc);
}

}  // namespace contain::clip
