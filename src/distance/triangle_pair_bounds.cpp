#include "distance/triangle_pair_bounds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "contain/predicates/unit_roundoff.h"
#include "distance/bound_constants.h"
#include "distance/triangle_search.h"

namespace contain::distance::detail {

namespace {

double clamp01(double x) {
  return x > 0 ? (x < 1 ? x : 1.0) : 0.0;  // NaN -> 0
}

template <class V, std::size_t N>
void bounds_from_points(const std::array<V, N>& sa, const std::array<V, N>& sb, V x, V y,
                        double slack, double& lo, double& hi) {
  const V w = x - y;
  const double ww = dot(w, w);
  hi = ww * (1 + 0x1p-19) + slack + 8 * std::numeric_limits<double>::denorm_min();
  if (!std::isfinite(hi)) hi = kInf;
  double amin = kInf, bmax = -kInf;
  for (const V& v : sa)
    amin = std::min(amin, separation_bound(v, y, w, 1.0));
  for (const V& u : sb)
    bmax = std::max(bmax, separation_bound(u, y, w, -1.0));
  lo = squared_separation_lower(amin - bmax, ww);
}

}  // namespace

double squared_separation_lower(double gap, double ww) {
  const double l = gap * (1 - 2 * kEps);  // the subtraction that made the gap
  if (!(l > 0 && ww >= 0x1p-900 && std::isfinite(ww))) return 0.0;
  const double r = l / ww;
  // l^2 / ww with three roundings (quotient, product, the factor); ww's own rounding (3 eps)
  // is inside the 8 eps too.
  return r >= 0x1p-1000 && std::isfinite(r) ? l * r * (1 - 8 * kEps) : 0.0;
}

void approximate_closest_segments(Vec3 p1, Vec3 q1, Vec3 p2, Vec3 q2, Vec3& c1, Vec3& c2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (!(a > 0) && !(e > 0)) {
    s = t = 0;
  } else if (!(a > 0)) {
    t = clamp01(f / e);
  } else {
    const double c = dot(d1, r);
    if (!(e > 0)) {
      s = clamp01(-c / a);
    } else {
      const double b = dot(d1, d2);
      const double denom = a * e - b * b;
      s = denom > 0 ? clamp01((b * f - c * e) / denom) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = clamp01(-c / a);
      } else if (t > 1) {
        t = 1;
        s = clamp01((b - c) / a);
      }
      t = clamp01(t);
    }
  }
  c1 = p1 + s * d1;
  c2 = p2 + t * d2;
}

double triangle_pair_quick_lower(const Triangle3& s, const Triangle3& t) {
  // w's own rounding does not matter: any direction gives a valid bound.
  const Vec3 w = ((s.a + s.b) + s.c) - ((t.a + t.b) + t.c);
  const double amin =
      std::min({separation_bound(s.a, t.a, w, 1.0), separation_bound(s.b, t.a, w, 1.0),
                separation_bound(s.c, t.a, w, 1.0)});
  const double bmax =
      std::max({separation_bound(t.a, t.a, w, -1.0), separation_bound(t.b, t.a, w, -1.0),
                separation_bound(t.c, t.a, w, -1.0)});
  return squared_separation_lower(amin - bmax, dot(w, w));
}

double triangle_sets_quick_lower(std::span<const Triangle3> s, std::span<const Triangle3> t,
                                 Vec3 w) {
  if (s.empty() || t.empty()) return 0.0;
  const Vec3 y = t.front().a;
  double amin = kInf, bmax = -kInf;
  for (const Triangle3& x : s)
    amin = std::min({amin, separation_bound(x.a, y, w, 1.0), separation_bound(x.b, y, w, 1.0),
                     separation_bound(x.c, y, w, 1.0)});
  for (const Triangle3& x : t)
    bmax = std::max({bmax, separation_bound(x.a, y, w, -1.0), separation_bound(x.b, y, w, -1.0),
                     separation_bound(x.c, y, w, -1.0)});
  return squared_separation_lower(amin - bmax, dot(w, w));
}

void triangle_pair_bounds(const Triangle3& s, const Triangle3& t, double slack, double& lo,
                          double& hi) {
  const std::array<Vec3, 3> va{s.a, s.b, s.c}, vb{t.a, t.b, t.c};
  Vec3 bx = s.a, by = t.a;
  double best = kInf;
  auto offer = [&](Vec3 x, Vec3 y) {
    const double d = squared_length(x - y);
    if (d < best) {
      best = d;
      bx = x;
      by = y;
    }
  };
  // vertex-triangle pairs, through the point query's approximate closest point
  for (const Vec3& v : va)
    offer(v, approximate_closest_point(v, t));
  for (const Vec3& v : vb)
    offer(approximate_closest_point(v, s), v);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      Vec3 c1, c2;
      approximate_closest_segments(
          va[static_cast<std::size_t>(i)], va[static_cast<std::size_t>((i + 1) % 3)],
          vb[static_cast<std::size_t>(j)], vb[static_cast<std::size_t>((j + 1) % 3)], c1, c2);
      offer(c1, c2);
    }
  }
  // Both points are computed: twice the slack of one (the slack bounds a squared offset; the
  // offsets add, so (d1 + d2)^2 <= 2 d1^2 + 2 d2^2, whence 4 slack).
  bounds_from_points(va, vb, bx, by, 4 * slack, lo, hi);
}

void segment_pair_bounds(const Segment2& s, const Segment2& t, double slack, double& lo,
                         double& hi) {
  Vec3 c1, c2;
  approximate_closest_segments({s.a.x, s.a.y, 0}, {s.b.x, s.b.y, 0}, {t.a.x, t.a.y, 0},
                               {t.b.x, t.b.y, 0}, c1, c2);
  const std::array<Vec2, 2> sa{s.a, s.b}, sb{t.a, t.b};
  bounds_from_points(sa, sb, Vec2{c1.x, c1.y}, Vec2{c2.x, c2.y}, 4 * slack, lo, hi);
}

}  // namespace contain::distance::detail
