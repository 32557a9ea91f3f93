#include "contain/predicates/rounded_distance.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "contain/predicates/big_float.h"
#include "contain/predicates/bounded.h"
#include "contain/predicates/unit_roundoff.h"
#include "predicates/flat_formulas.h"
#include "predicates/nearest_double.h"

namespace contain::predicates {

namespace {

using detail::bounded;
using detail::ErrLD;
using detail::even_of;
using detail::kInf;
using detail::kU;
using detail::LD;
using detail::lower_mid;
using detail::lower_mid_big;
using detail::Mag;
using detail::next_down;
using detail::next_up;
using detail::offset_stage_a;
using detail::quotient_stage_a;
using detail::quotient_stage_b;
using detail::upper_mid;
using detail::upper_mid_big;

// ---- square roots of N / D -------------------------------------------------------------------

// Stage A: N, D with running error bounds in long double. Returns false when the bounds do not
// settle both rounding boundaries of the candidate.
bool sqrt_stage_a(const ErrLD& n, const ErrLD& d, double& out) {
  if (!detail::all_finite(n, d)) return false;
  if (n.value == 0 && n.error == 0) {
    out = 0.0;
    return true;
  }
  if (!(d.value - d.error > 0) || !(n.value - n.error > 0)) return false;
  // Each bound passes through four roundings to nearest: (1 +- 8u) more than covers them.
  const LD q_lo = (n.value - n.error) / (d.value + d.error) * (1 - 8 * kU);
  const LD q_hi = (n.value + n.error) / (d.value - d.error) * (1 + 8 * kU);
  if (!std::isfinite(q_hi)) return false;
  const double c = static_cast<double>(std::sqrt(n.value / d.value));
  if (c > 0) {
    const LD m = lower_mid(c);
    if (!(m * m * (1 + 4 * kU) < q_lo)) return false;
  }
  if (c != kInf) {
    const LD m = upper_mid(c);
    if (!(m * m * (1 - 4 * kU) > q_hi)) return false;
  }
  out = c;
  return true;
}

// Stage B: exact N >= 0, D > 0.
double sqrt_stage_b(const BigFloat& n, const BigFloat& d) {
  if (n.sign() == Sign::zero) return 0.0;
  std::int64_t en = 0;
  std::int64_t ed = 0;
  const double fn = n.frexp(en);
  const double fd = d.frexp(ed);
  std::int64_t e = en - ed;
  double r = fn / fd;
  if (e % 2 != 0) {
    r *= 2;
    e -= 1;
  }
  const std::int64_t half = e / 2;
  double c =
      std::ldexp(std::sqrt(r), static_cast<int>(std::clamp<std::int64_t>(half, -2000, 2000)));
  // The candidate is within a few ulps (or at the end of the range): step to the nearest.
  for (int step = 0; step < 64; ++step) {
    if (c > 0) {
      const BigFloat m = lower_mid_big(c);
      const Sign s = (n - m * m * d).sign();
      if (s == Sign::negative) {
        c = c == kInf ? DBL_MAX : next_down(c);
        continue;
      }
      if (s == Sign::zero) return even_of(next_down(c), c);
    }
    if (c != kInf) {
      const BigFloat m = upper_mid_big(c);
      const Sign s = (n - m * m * d).sign();
      if (s == Sign::positive) {
        c = c == DBL_MAX ? kInf : next_up(c);
        continue;
      }
      if (s == Sign::zero) return even_of(c, c == DBL_MAX ? kInf : next_up(c));
    }
    return c;
  }
  return c;  // not reached: the candidate starts within a few ulps
}

template <class Pair>
double distance_exact(const Pair& x) {
  const auto exact = detail::squared_distance<BigFloat>(x);
  return sqrt_stage_b(exact.num, exact.den);
}

template <class Pair>
double distance_of(const Pair& x) {
  double out = 0.0;
  const auto fast = detail::squared_distance<Mag>(x);
  if (sqrt_stage_a(bounded(fast.num), bounded(fast.den), out)) return out;
  const auto q = detail::squared_distance<ErrLD>(x);
  if (sqrt_stage_a(q.num, q.den, out)) return out;
  return distance_exact(x);
}

// One long double stage for every coordinate of both closest points (a's, then b's): false
// when one is left open.
template <class T, class Pair, class ToErr, std::size_t N>
bool closest_stage(const Pair& x, ToErr&& to_err, double (&out)[N]) {
  constexpr std::size_t dim = N / 2;
  const auto q = detail::closest_points<T>(x);
  const ErrLD den = to_err(q.den);
  for (std::size_t i = 0; i < dim; ++i) {
    if (!quotient_stage_a(to_err(q.a[i]), den, out[i]) ||
        !quotient_stage_a(to_err(q.b[i]), den, out[dim + i])) {
      return false;
    }
  }
  return true;
}

// The same from the exact stage.
template <class Pair, std::size_t N>
void closest_exact(const Pair& x, double (&out)[N]) {
  constexpr std::size_t dim = N / 2;
  const auto e = detail::closest_points<BigFloat>(x);
  for (std::size_t i = 0; i < dim; ++i) {
    out[i] = quotient_stage_b(e.a[i], e.den);
    out[dim + i] = quotient_stage_b(e.b[i], e.den);
  }
}

// Stage 0, then the running-error stage, then the exact one.
template <class Pair, std::size_t N>
void closest_coordinates(const Pair& x, double (&out)[N]) {
  if (closest_stage<Mag>(x, bounded, out)) return;
  if (closest_stage<ErrLD>(x, std::identity{}, out)) return;
  closest_exact(x, out);
}

// The terms of a point p and a flat q in common between its squared distance N / D and its
// closest point, computed once. The closest point is taken as base + sign * off / D per
// coordinate, base exact doubles: on a line q0 + u t / D (u = q1 - q0, t = (p - q0) . u,
// D = u . u), on a plane p - n s / D (n the normal, s = (p - q0) . n, D = n . n). That is the
// X / D of flat_formulas.h with base * D taken out of X: the offset is as large as the foot's
// distance from q0 or p's from the plane, where X is as large as base * D, so its rounding error
// is that much smaller and the long double stages settle most coordinates that X / D left to the
// exact stage (one closest point in ten on the 100k torus).
template <class T>
struct PointFlatTerms {
  T n, d;
  Vec3 base;
  double sign = 1;
  std::array<T, 3> off;
};
template <class T>
PointFlatTerms<T> point_flat_terms(Vec3 p, const Flat3& flat) {
  const std::array<Vec3, 3>& q = flat.points;
  PointFlatTerms<T> out;
  if (flat.size == 1) {
    const auto w = detail::sub<T>(p, q[0]);
    out.n = detail::dot(w, w);
    out.d = T(1.0);
    out.base = q[0];
    out.off = {T(0.0), T(0.0), T(0.0)};
  } else if (flat.size == 2) {
    const auto u = detail::sub<T>(q[1], q[0]);
    const auto w = detail::sub<T>(p, q[0]);
    const auto c = detail::cross(w, u);
    const T t = detail::dot(w, u);
    out.n = detail::dot(c, c);
    out.d = detail::dot(u, u);
    out.base = q[0];
    out.off = {u.x * t, u.y * t, u.z * t};
  } else {
    const auto normal = detail::cross(detail::sub<T>(q[1], q[0]), detail::sub<T>(q[2], q[0]));
    const T s = detail::dot(detail::sub<T>(p, q[0]), normal);
    out.n = s * s;
    out.d = detail::dot(normal, normal);
    out.base = p;
    out.sign = -1;
    out.off = {normal.x * s, normal.y * s, normal.z * s};
  }
  return out;
}

// One long double stage of rounded_point_distance: settles what is still open of the distance
// and of the closest point (all three coordinates together).
struct Settled {
  bool distance = false;
  bool point = false;
};
template <class T, class ToErr>
void point_flat_stage(Vec3 p, const Flat3& flat, ToErr&& to_err, RoundedPointDistance3& out,
                      Settled& settled) {
  const PointFlatTerms<T> terms = point_flat_terms<T>(p, flat);
  const ErrLD den = to_err(terms.d);
  if (!settled.distance) settled.distance = sqrt_stage_a(to_err(terms.n), den, out.distance);
  if (!settled.point) {
    Vec3 c;
    settled.point = offset_stage_a(terms.base.x, terms.sign, to_err(terms.off[0]), den, c.x) &&
                    offset_stage_a(terms.base.y, terms.sign, to_err(terms.off[1]), den, c.y) &&
                    offset_stage_a(terms.base.z, terms.sign, to_err(terms.off[2]), den, c.z);
    if (settled.point) out.point = c;
  }
}

}  // namespace

double rounded_distance(const FlatPair3& x) {
  return distance_of(x);
}
double rounded_distance(const FlatPair2& x) {
  return distance_of(x);
}

ClosestPoints3 rounded_closest_points(const FlatPair3& x) {
  double out[6];
  closest_coordinates(x, out);
  return {{out[0], out[1], out[2]}, {out[3], out[4], out[5]}};
}

RoundedPointDistance3 rounded_point_distance(const FlatPair3& x) {
  if (x.a.size != 1) return {rounded_distance(x), rounded_closest_points(x).b};
  // A vertex is its own closest point, exactly: only the distance needs rounding.
  if (x.b.size == 1) return {rounded_distance(x), x.b.points[0]};
  const Vec3 p = x.a.points[0];
  RoundedPointDistance3 out{};
  Settled settled;
  point_flat_stage<Mag>(p, x.b, bounded, out, settled);
  if (!settled.distance || !settled.point) {
    point_flat_stage<ErrLD>(p, x.b, std::identity{}, out, settled);
  }
  // Whatever the long double bounds leave open: the exact stages.
  if (!settled.distance) out.distance = distance_exact(x);
  if (!settled.point) {
    double c[6];
    closest_exact(x, c);
    out.point = {c[3], c[4], c[5]};
  }
  return out;
}

ClosestPoints2 rounded_closest_points(const FlatPair2& x) {
  double out[4];
  closest_coordinates(x, out);
  return {{out[0], out[1]}, {out[2], out[3]}};
}

}  // namespace contain::predicates
