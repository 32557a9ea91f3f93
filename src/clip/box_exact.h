#pragma once
// Exact parameter comparisons for clipping a segment a->b by an axis-aligned box, shared by
// Cohen-Sutherland, Liang-Barsky and the batch kernel's fallback.
//
// A parameter on the segment's line is t = 0 (a), t = 1 (b), or the crossing with a face plane
// x_k = v, t = (v - a_k) / d_k with d_k = b_k - a_k != 0. Never rounding t:
//   face(k, v) vs 0:        sign(v - a_k) sign(d_k)
//   face(k, v) vs 1:        sign(v - b_k) sign(d_k)
//   face(k, v) vs face(k, w): sign(v - w) sign(d_k)
//   face(k, v) vs face(j, w): t - u = [(v - a_k) d_j - (w - a_j) d_k] / (d_k d_j), and the
//     numerator is -orient2d(A, B, C) in the (k, j) coordinate plane with A = (a_k, a_j),
//     B = (b_k, b_j), C = (v, w): exact on the original endpoints.
// The coordinate j of the true crossing q with face(k, v) compares with w by
//   sign(q_j - w) = -orient2d(A, B, C) sign(d_k),
// which gives Cohen-Sutherland exact code words for computed points.

#include <algorithm>

#include "clip/segment_common.h"
#include "contain/predicates/orient2d.h"
#include "contain/values/box.h"

namespace contain::clip::detail {

template <class V>
struct BoxOf;
template <>
struct BoxOf<Vec2> {
  using Box = Box2;
};
template <>
struct BoxOf<Vec3> {
  using Box = Box3;
};

/// t = 0 (axis -1, value 0), t = 1 (axis -1, value 1) or the face x_axis = value.
struct BoxParam {
  int axis = -1;
  double value = 0.0;
  [[nodiscard]] bool is_face() const { return axis >= 0; }
};

inline constexpr BoxParam start_param{-1, 0.0};
inline constexpr BoxParam end_param{-1, 1.0};

[[nodiscard]] constexpr int sign3(double x, double y) {
  return (x > y) - (x < y);
}

template <class V>
class BoxLine {
 public:
  BoxLine(const V& a, const V& b) : a_(a), b_(b) {}

  [[nodiscard]] int dir_sign(int k) const { return sign3(coord(b_, k), coord(a_, k)); }

  /// sign(t_p - t_q), exactly.
  [[nodiscard]] int compare(const BoxParam& p, const BoxParam& q) const {
    if (!p.is_face() && !q.is_face()) return sign3(p.value, q.value);
    if (!p.is_face()) return -compare(q, p);
    const int sk = dir_sign(p.axis);
    if (!q.is_face()) {
      const double end = q.value == 0.0 ? coord(a_, p.axis) : coord(b_, p.axis);
      return sign3(p.value, end) * sk;
    }
    if (q.axis == p.axis) return sign3(p.value, q.value) * sk;
    return -to_int(orient(p, q)) * sk * dir_sign(q.axis);
  }

  /// sign(q_j - w) for the true crossing q of the segment's line with face p (j != p.axis).
  [[nodiscard]] int crossing_coord_sign(const BoxParam& p, int j, double w) const {
    return -to_int(orient(p, BoxParam{j, w})) * dir_sign(p.axis);
  }

  /// The point of a parameter: the endpoint, or the crossing with the face coordinate set to
  /// the face value and the others computed and clamped into the box (where the true point is
  /// when the caller calls this for a kept parameter).
  template <class Box>
  [[nodiscard]] V point(const BoxParam& p, const Box& box, double& t) const {
    if (!p.is_face()) {
      t = p.value;
      return p.value == 0.0 ? a_ : b_;
    }
    const int k = p.axis;
    // A face through an endpoint is t = 0 or 1 exactly: return the endpoint bit for bit (the
    // formula below can lose a far-away coordinate's small part; found by fuzz_clip_segments).
    if (p.value == coord(a_, k)) {
      t = 0.0;
      return a_;
    }
    if (p.value == coord(b_, k)) {
      t = 1.0;
      return b_;
    }
    t = (p.value - coord(a_, k)) / (coord(b_, k) - coord(a_, k));
    t = std::clamp(t, 0.0, 1.0);
    V q = a_;
    for (int j = 0; j < dimension<V>; ++j) {
      if (j == k) {
        set_coord(q, j, p.value);
      } else {
        const double x = coord(a_, j) + t * (coord(b_, j) - coord(a_, j));
        set_coord(q, j, std::clamp(x, coord(box.min, j), coord(box.max, j)));
      }
    }
    return q;
  }

  [[nodiscard]] const V& a() const { return a_; }
  [[nodiscard]] const V& b() const { return b_; }

 private:
  [[nodiscard]] Sign orient(const BoxParam& p, const BoxParam& q) const {
    const int k = p.axis, j = q.axis;
    return predicates::orient2d({coord(a_, k), coord(a_, j)}, {coord(b_, k), coord(b_, j)},
                                {p.value, q.value});
  }

  V a_;
  V b_;
};

/// The two kept parameters as points, with a touching result collapsed onto one point.
template <class V, class Box>
[[nodiscard]] typename SegmentOf<V>::Clipped box_result(const BoxLine<V>& line, const Box& box,
                                                        const BoxParam& lo, const BoxParam& hi) {
  const int order = line.compare(lo, hi);
  if (order > 0) return nothing<V>();
  double t0 = 0.0, t1 = 0.0;
  const V p0 = line.point(lo, box, t0);
  if (order == 0) return kept(p0, p0, t0, t0);
  const V p1 = line.point(hi, box, t1);
  return kept(p0, p1, t0, std::max(t0, t1));
}

/// Exact Liang-Barsky.
template <class V, class Box>
[[nodiscard]] typename SegmentOf<V>::Clipped liang_barsky_exact(const V& a, const V& b,
                                                                const Box& box) {
  if (box.empty()) return nothing<V>();
  const BoxLine<V> line(a, b);
  BoxParam lo = start_param, hi = end_param;
  for (int k = 0; k < dimension<V>; ++k) {
    const double lo_k = coord(box.min, k), hi_k = coord(box.max, k);
    const int s = line.dir_sign(k);
    if (s == 0) {
      const double x = coord(a, k);
      if (x < lo_k || x > hi_k) return nothing<V>();
      continue;
    }
    const BoxParam enter{k, s > 0 ? lo_k : hi_k};
    const BoxParam exit{k, s > 0 ? hi_k : lo_k};
    if (line.compare(enter, lo) > 0) lo = enter;
    if (line.compare(exit, hi) < 0) hi = exit;
  }
  return box_result(line, box, lo, hi);
}

}  // namespace contain::clip::detail
