#include "contain/predicates/rounded_distance.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>

#include "contain/predicates/big_float.h"
#include "predicates/flat_formulas.h"
#include "predicates/running_error.h"

namespace contain::predicates {

namespace {

using detail::Err;
using LD = long double;
using ErrLD = Err<LD>;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr LD kU = ErrLD::u;

// Rounding boundaries of a candidate c: the midpoints to its neighbours. Beyond +-DBL_MAX the
// boundary is DBL_MAX + 2^970 (half an ulp of DBL_MAX), where IEEE 754 starts rounding to
// infinity. Each midpoint has at most 54 significant bits, so it is exact in long double
// (64-bit significand) and in BigFloat.
double next_up(double c) {
  return std::nextafter(c, kInf);
}
double next_down(double c) {
  return std::nextafter(c, -kInf);
}
constexpr double kHalfUlpOfMax = 0x1p970;

// The midpoint between c and its neighbour above (c < +inf).
LD upper_mid(double c) {
  if (c == DBL_MAX) return static_cast<LD>(DBL_MAX) + static_cast<LD>(kHalfUlpOfMax);
  if (c == -kInf) return -(static_cast<LD>(DBL_MAX) + static_cast<LD>(kHalfUlpOfMax));
  return (static_cast<LD>(c) + static_cast<LD>(next_up(c))) / 2;
}
LD lower_mid(double c) {
  return -upper_mid(-c);
}
BigFloat upper_mid_big(double c) {
  if (c == DBL_MAX) return BigFloat(DBL_MAX) + BigFloat(kHalfUlpOfMax);
  if (c == -kInf) return BigFloat() - (BigFloat(DBL_MAX) + BigFloat(kHalfUlpOfMax));
  return (BigFloat(c) + BigFloat(next_up(c))).scaled(-1);
}
BigFloat lower_mid_big(double c) {
  return BigFloat() - upper_mid_big(-c);
}

// Of two neighbouring doubles (or DBL_MAX and infinity), the one with an even significand.
double even_of(double x, double y) {
  return (std::bit_cast<std::uint64_t>(x) & 1U) == 0 ? x : y;
}

// ---- square roots of N / D -------------------------------------------------------------------

// Stage A: N, D with running error bounds in long double. Returns false when the bounds do not
// settle both rounding boundaries of the candidate.
bool sqrt_stage_a(const ErrLD& n, const ErrLD& d, double& out) {
  if (!std::isfinite(n.v) || !std::isfinite(n.e) || !std::isfinite(d.v) || !std::isfinite(d.e)) {
    return false;
  }
  if (n.v == 0 && n.e == 0) {
    out = 0.0;
    return true;
  }
  if (!(d.v - d.e > 0) || !(n.v - n.e > 0)) return false;
  // Each bound passes through four roundings to nearest: (1 +- 8u) more than covers them.
  const LD q_lo = (n.v - n.e) / (d.v + d.e) * (1 - 8 * kU);
  const LD q_hi = (n.v + n.e) / (d.v - d.e) * (1 + 8 * kU);
  if (!std::isfinite(q_hi)) return false;
  const double c = static_cast<double>(std::sqrt(n.v / d.v));
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

// ---- quotients X / D, D > 0 ------------------------------------------------------------------

bool quotient_stage_a(const ErrLD& n, const ErrLD& d, double& out) {
  if (!std::isfinite(n.v) || !std::isfinite(n.e) || !std::isfinite(d.v) || !std::isfinite(d.e)) {
    return false;
  }
  if (n.v == 0 && n.e == 0) {
    out = 0.0;
    return true;
  }
  if (!(d.v - d.e > 0)) return false;
  const LD x = n.v / d.v;
  // |X - x| <= (e_n + |n / d| e_d) / (d - e_d) + u |x|, with |n / d| <= |x| (1 + u); the
  // factor (1 + 16u) covers the roundings of the bound itself.
  const LD bound =
      ((n.e + std::fabs(x) * (1 + kU) * d.e) / (d.v - d.e) + kU * std::fabs(x)) * (1 + 16 * kU);
  if (!std::isfinite(x) || !std::isfinite(bound)) return false;
  const double c = static_cast<double>(x);
  if (c != -kInf && !((x - lower_mid(c)) > bound * (1 + 4 * kU))) return false;
  if (c != kInf && !((upper_mid(c) - x) > bound * (1 + 4 * kU))) return false;
  out = c;
  return true;
}

double quotient_stage_b(const BigFloat& n, const BigFloat& d) {
  if (n.sign() == Sign::zero) return 0.0;
  std::int64_t en = 0;
  std::int64_t ed = 0;
  const double fn = n.frexp(en);
  const double fd = d.frexp(ed);
  double c = std::ldexp(fn / fd, static_cast<int>(std::clamp<std::int64_t>(en - ed, -2200, 2200)));
  for (int step = 0; step < 64; ++step) {
    if (c != -kInf) {
      const Sign s = (n - lower_mid_big(c) * d).sign();
      if (s == Sign::negative) {
        c = c == kInf ? DBL_MAX : next_down(c);
        continue;
      }
      if (s == Sign::zero) return even_of(c == -DBL_MAX ? -kInf : next_down(c), c);
    }
    if (c != kInf) {
      const Sign s = (n - upper_mid_big(c) * d).sign();
      if (s == Sign::positive) {
        c = c == -kInf ? -DBL_MAX : next_up(c);
        continue;
      }
      if (s == Sign::zero) return even_of(c, c == DBL_MAX ? kInf : next_up(c));
    }
    return c;
  }
  return c;
}

template <class Pair>
double distance_of(const Pair& x) {
  const auto q = detail::squared_distance<ErrLD>(x);
  double out = 0.0;
  if (sqrt_stage_a(q.num, q.den, out)) return out;
  const auto exact = detail::squared_distance<BigFloat>(x);
  return sqrt_stage_b(exact.num, exact.den);
}

}  // namespace

double rounded_distance(const FlatPair3& x) {
  return distance_of(x);
}
double rounded_distance(const FlatPair2& x) {
  return distance_of(x);
}

ClosestPoints3 rounded_closest_points(const FlatPair3& x) {
  const auto q = detail::closest_points<ErrLD>(x);
  double out[6];
  bool exact_needed = false;
  for (int i = 0; i < 3; ++i) {
    exact_needed |= !quotient_stage_a(q.a[static_cast<std::size_t>(i)], q.den, out[i]);
    exact_needed |= !quotient_stage_a(q.b[static_cast<std::size_t>(i)], q.den, out[3 + i]);
  }
  if (exact_needed) {
    const auto e = detail::closest_points<BigFloat>(x);
    for (int i = 0; i < 3; ++i) {
      out[i] = quotient_stage_b(e.a[static_cast<std::size_t>(i)], e.den);
      out[3 + i] = quotient_stage_b(e.b[static_cast<std::size_t>(i)], e.den);
    }
  }
  return {{out[0], out[1], out[2]}, {out[3], out[4], out[5]}};
}

RoundedPointDistance3 rounded_point_distance(const FlatPair3& x) {
  if (x.a.size != 1) return {rounded_distance(x), rounded_closest_points(x).b};
  // The formulas of flat_formulas.h for a point p and a flat q, with the terms in common
  // computed once: N / D is the squared distance, X / D the closest point of the flat.
  const Vec3 p = x.a.points[0];
  const std::array<Vec3, 3>& q = x.b.points;
  ErrLD n, d;
  std::array<ErrLD, 3> point;
  if (x.b.size == 1) {
    const auto w = detail::sub<ErrLD>(p, q[0]);
    n = detail::dot(w, w);
    d = ErrLD(1.0);
    point = {ErrLD(q[0].x), ErrLD(q[0].y), ErrLD(q[0].z)};
  } else if (x.b.size == 2) {
    const auto u = detail::sub<ErrLD>(q[1], q[0]);
    const auto w = detail::sub<ErrLD>(p, q[0]);
    const auto c = detail::cross(w, u);
    const ErrLD t = detail::dot(w, u);
    n = detail::dot(c, c);
    d = detail::dot(u, u);
    point = {ErrLD(q[0].x) * d + u.x * t, ErrLD(q[0].y) * d + u.y * t, ErrLD(q[0].z) * d + u.z * t};
  } else {
    const auto normal =
        detail::cross(detail::sub<ErrLD>(q[1], q[0]), detail::sub<ErrLD>(q[2], q[0]));
    const ErrLD s = detail::dot(detail::sub<ErrLD>(p, q[0]), normal);
    n = s * s;
    d = detail::dot(normal, normal);
    point = {ErrLD(p.x) * d - normal.x * s, ErrLD(p.y) * d - normal.y * s,
             ErrLD(p.z) * d - normal.z * s};
  }
  RoundedPointDistance3 out{};
  // Any side the long double bounds leave open: the exact stages of the two functions.
  if (!sqrt_stage_a(n, d, out.distance)) out.distance = rounded_distance(x);
  if (!quotient_stage_a(point[0], d, out.point.x) || !quotient_stage_a(point[1], d, out.point.y) ||
      !quotient_stage_a(point[2], d, out.point.z)) {
    out.point = rounded_closest_points(x).b;
  }
  return out;
}

ClosestPoints2 rounded_closest_points(const FlatPair2& x) {
  const auto q = detail::closest_points<ErrLD>(x);
  double out[4];
  bool exact_needed = false;
  for (int i = 0; i < 2; ++i) {
    exact_needed |= !quotient_stage_a(q.a[static_cast<std::size_t>(i)], q.den, out[i]);
    exact_needed |= !quotient_stage_a(q.b[static_cast<std::size_t>(i)], q.den, out[2 + i]);
  }
  if (exact_needed) {
    const auto e = detail::closest_points<BigFloat>(x);
    for (int i = 0; i < 2; ++i) {
      out[i] = quotient_stage_b(e.a[static_cast<std::size_t>(i)], e.den);
      out[2 + i] = quotient_stage_b(e.b[static_cast<std::size_t>(i)], e.den);
    }
  }
  return {{out[0], out[1]}, {out[2], out[3]}};
}

}  // namespace contain::predicates
