#pragma once
// The tests of one noding round (noding.cpp): a pair of pieces by the four exact orient2d signs,
// and a piece against a hot pixel; with the crossing point and the order of splits along a
// piece. Private to the boolean engine.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "contain/predicates/orient2d.h"
#include "contain/values/vec.h"

namespace contain::clip::detail::pieces {
using predicates::orient2d;

struct Split {
  std::uint32_t piece;  // index in points of the piece's first point
  Vec2 at;
};

// orient2d, without its exact fallback when c is an endpoint (pieces sharing an endpoint are the
// most common pair, and their zero determinant is the filter's worst case).
[[gnu::always_inline]] inline Sign orient(Vec2 a, Vec2 b, Vec2 c) {
  if (c == a || c == b) return Sign::zero;
  return orient2d(a, b, c);
}

inline bool lex_less(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// x strictly between a and b, given that a, b, x are collinear.
inline bool strictly_inside(Vec2 a, Vec2 b, Vec2 x) {
  if (x == a || x == b) return false;
  return lex_less(a, b) ? (lex_less(a, x) && lex_less(x, b)) : (lex_less(b, x) && lex_less(x, a));
}

// p before q on the way from a to b, for points on (or rounded next to) the piece: compared on
// the axis along which the piece moves most, then on the other one, without products (a dot
// product with the direction underflows to zero for coordinates below 2^-511 and would leave
// the order to lex_less, which zigzags a chain going the other way: fuzz finding
// hang_at_scale_2pow-904, docs/robustness.md).
inline bool before_along(Vec2 a, Vec2 b, Vec2 p, Vec2 q) {
  const bool by_x = std::fabs(b.x - a.x) >= std::fabs(b.y - a.y);
  const double pu = by_x ? p.x : p.y, qu = by_x ? q.x : q.y;
  const double pv = by_x ? p.y : p.x, qv = by_x ? q.y : q.x;
  const bool u_up = by_x ? a.x < b.x : a.y < b.y;
  const bool v_up = by_x ? a.y < b.y : a.x < b.x;
  if (pu != qu) return u_up ? pu < qu : pu > qu;
  if (pv != qv) return v_up ? pv < qv : pv > qv;
  return false;
}

inline Vec2 crossing_point(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) {
  // The rounded point depends on the order and direction of the segments: put them in a
  // canonical order, so that equal segments (A and B both holding an edge, a ring edge traversed
  // both ways) are split at equal points and cancel exactly (fuzz finding sliver_in_a_minus_a).
  if (lex_less(p1, p0)) std::swap(p0, p1);
  if (lex_less(q1, q0)) std::swap(q0, q1);
  if (lex_less(q0, p0) || (q0 == p0 && lex_less(q1, p1))) {
    std::swap(p0, q0);
    std::swap(p1, q1);
  }
  using L = long double;
  const L dpx = L(p1.x) - L(p0.x), dpy = L(p1.y) - L(p0.y);
  const L dqx = L(q1.x) - L(q0.x), dqy = L(q1.y) - L(q0.y);
  const L den = dpx * dqy - dpy * dqx;
  const L num = (L(q0.x) - L(p0.x)) * dqy - (L(q0.y) - L(p0.y)) * dqx;
  // The rounded denominator can vanish (or the quotient overflow) for nearly parallel pieces
  // that the exact signs say cross, and NaN would pass the clamps below: then any point of both
  // boxes serves, as the pieces are tested again (fuzz_polygon_boolean, NaN into orient2d).
  L t = num / den;
  if (!std::isfinite(t)) t = 0.5L;
  Vec2 x{static_cast<double>(L(p0.x) + t * dpx), static_cast<double>(L(p0.y) + t * dpy)};
  // The exact crossing lies in both boxes; keep the rounded one there too.
  const double lox = std::max(std::min(p0.x, p1.x), std::min(q0.x, q1.x));
  const double hix = std::min(std::max(p0.x, p1.x), std::max(q0.x, q1.x));
  const double loy = std::max(std::min(p0.y, p1.y), std::min(q0.y, q1.y));
  const double hiy = std::min(std::max(p0.y, p1.y), std::max(q0.y, q1.y));
  x.x = std::clamp(x.x, lox, hix);
  x.y = std::clamp(x.y, loy, hiy);
  return x;
}

// The sides of a hot pixel, clamped to the finite doubles: x +- radius overflows next to
// DBL_MAX, and no piece reaches beyond it, so the clamped square meets the same pieces.
inline double pixel_lo(double v, double radius) {
  return std::max(v - radius, std::numeric_limits<double>::lowest());
}
inline double pixel_hi(double v, double radius) {
  return std::min(v + radius, std::numeric_limits<double>::max());
}

inline bool within(Vec2 a, Vec2 b, double radius) {
  return std::fabs(a.x - b.x) <= radius && std::fabs(a.y - b.y) <= radius;
}

// A piece that passes through the hot pixel of a crossing point x (the square of half-side
// `radius` around it) is split at x, as in snap rounding (Hobby 1999; Hershberger 2013): pieces
// that pass within rounding distance of each other then share the vertex instead of crossing again
// and again near it. The test is exact on the doubles of the square's corners.
inline void test_pixel(const std::vector<Vec2>& pts, std::uint32_t s, Vec2 x, double radius,
                       std::vector<Split>& splits) {
  const Vec2 a = pts[s], b = pts[s + 1];
  // A piece with an endpoint in the pixel already passes through it; its crossings there snap to
  // endpoints (see test_pair).
  if (within(a, x, radius) || within(b, x, radius)) return;
  // Only where x lies in the piece's box, as (unsnapped) crossing points do: a split outside the
  // box turns the chain back, and pixels can then split each other's pieces for ever (a -> b
  // split at x behind a gives x -> b, which passes through the pixel of a and is split there,
  // giving a -> b again; fuzz_polygon_boolean, docs/robustness.md).
  if (x.x < std::min(a.x, b.x) || x.x > std::max(a.x, b.x) || x.y < std::min(a.y, b.y) ||
      x.y > std::max(a.y, b.y))
    return;
  // The line misses the square when all four corners lie strictly on one side. orient2d(a, b, c)
  // is the sign of an affine function of c whose gradient is (-(b.y - a.y), b.x - a.x): over the
  // square it is smallest at the corner that gradient points away from and largest at the
  // opposite one, so those two corners decide exactly what the four would.
  const double x0 = pixel_lo(x.x, radius), x1 = pixel_hi(x.x, radius);
  const double y0 = pixel_lo(x.y, radius), y1 = pixel_hi(x.y, radius);
  const bool rises = b.y > a.y, rightward = b.x > a.x;
  const Vec2 low{rises ? x1 : x0, rightward ? y0 : y1};
  const Vec2 high{rises ? x0 : x1, rightward ? y1 : y0};
  if (orient2d(a, b, low) == Sign::positive || orient2d(a, b, high) == Sign::negative) return;
  splits.push_back({s, x});
}

// Marks point k as a vertex of the arrangement (Noded::event).
struct Marks {
  std::vector<char>& event;
  void operator()(std::uint32_t k) const { event[k] = 1; }
};

// x on the closed piece a b, given that a, b, x are collinear.
inline bool on_piece(Vec2 a, Vec2 b, Vec2 x) {
  return x == a || x == b || strictly_inside(a, b, x);
}

// `linked`: t is the piece after s on a linked path (t == s + 2, points[s + 1] the joint); their
// common joint is then no event.
// o1, o2: the sides of q0 and q1 of the line p0 p1, not both the same strict side (the caller
// rejects most pairs with them).
[[gnu::noinline]] inline void test_pair(const std::vector<Vec2>& pts, std::uint32_t s,
                                        std::uint32_t t, Sign o1, Sign o2, double radius,
                                        std::vector<Split>& splits, std::vector<Vec2>& hot,
                                        std::int64_t& crossings, const Marks& mark, bool linked) {
  const Vec2 p0 = pts[s], p1 = pts[s + 1], q0 = pts[t], q1 = pts[t + 1];
  // Pieces sharing an endpoint, the other one off the line: that endpoint is all they share.
  if (o1 == Sign::zero && o2 != Sign::zero && (q0 == p0 || q0 == p1)) {
    if (!(linked && q0 == p1)) {
      mark(t);
      mark(q0 == p0 ? s : s + 1);
    }
    return;
  }
  if (o2 == Sign::zero && o1 != Sign::zero && (q1 == p0 || q1 == p1)) {
    mark(t + 1);
    mark(q1 == p0 ? s : s + 1);
    return;
  }
  const Sign o3 = orient(q0, q1, p0);
  const Sign o4 = orient(q0, q1, p1);
  if (o3 == o4 && o3 != Sign::zero) return;
  if (o1 == Sign::zero && o2 == Sign::zero) {
    // Collinear: boxes overlap (the caller checked), so the pieces overlap or touch. Every
    // endpoint on the other piece is a vertex, but for the joint of a straight linked path.
    const bool q0_on = on_piece(p0, p1, q0), q1_on = on_piece(p0, p1, q1);
    const bool p0_on = on_piece(q0, q1, p0), p1_on = on_piece(q0, q1, p1);
    if (linked && !q1_on && !p0_on) return;
    if (q0_on) mark(t);
    if (q1_on) mark(t + 1);
    if (p0_on) mark(s);
    if (p1_on) mark(s + 1);
    if (strictly_inside(p0, p1, q0)) splits.push_back({s, q0});
    if (strictly_inside(p0, p1, q1)) splits.push_back({s, q1});
    if (strictly_inside(q0, q1, p0)) splits.push_back({t, p0});
    if (strictly_inside(q0, q1, p1)) splits.push_back({t, p1});
    return;
  }
  // Not parallel. A zero sign puts that endpoint on the other piece (the opposite pair of signs
  // is not of one strict sign), and that endpoint is the only common point.
  bool touched = false;
  if (o1 == Sign::zero) {
    touched = true;
    mark(t);
    if (q0 == p0) mark(s);
    if (q0 == p1) mark(s + 1);
    if (q0 != p0 && q0 != p1) splits.push_back({s, q0});
  }
  if (o2 == Sign::zero) {
    touched = true;
    mark(t + 1);
    if (q1 == p0) mark(s);
    if (q1 == p1) mark(s + 1);
    if (q1 != p0 && q1 != p1) splits.push_back({s, q1});
  }
  if (o3 == Sign::zero) {
    touched = true;
    mark(s);
    if (p0 != q0 && p0 != q1) splits.push_back({t, p0});
  }
  if (o4 == Sign::zero) {
    touched = true;
    mark(s + 1);
    if (p1 != q0 && p1 != q1) splits.push_back({t, p1});
  }
  if (touched) return;
  Vec2 x = crossing_point(p0, p1, q0, q1);
  ++crossings;
  // A crossing within a pixel of an endpoint is that endpoint: no sliver pieces. Of several, the
  // lowest in (x, y) order, the same choice whichever pair of pieces meets there. Only endpoints
  // in both pieces' boxes: a piece split outside its box turns back, and where pixels are large
  // against the pieces (a coordinate of 1.4e16 beside pieces a few units long) such splits
  // undid each other round after round (fuzz_polygon_boolean, docs/robustness.md).
  const double lox = std::max(std::min(p0.x, p1.x), std::min(q0.x, q1.x));
  const double hix = std::min(std::max(p0.x, p1.x), std::max(q0.x, q1.x));
  const double loy = std::max(std::min(p0.y, p1.y), std::min(q0.y, q1.y));
  const double hiy = std::min(std::max(p0.y, p1.y), std::max(q0.y, q1.y));
  bool snapped = false;
  Vec2 best{};
  for (const Vec2 e : {p0, p1, q0, q1}) {
    if (e.x < lox || e.x > hix || e.y < loy || e.y > hiy) continue;
    if (within(x, e, radius) && (!snapped || lex_less(e, best))) {
      best = e;
      snapped = true;
    }
  }
  if (snapped) {
    x = best;
    const std::uint32_t ends[4] = {s, s + 1, t, t + 1};
    for (const std::uint32_t k : ends) {
      if (pts[k] == x) mark(k);
    }
  }
  hot.push_back(x);
  if (x != p0 && x != p1) splits.push_back({s, x});
  if (x != q0 && x != q1) splits.push_back({t, x});
}

}  // namespace contain::clip::detail::pieces
