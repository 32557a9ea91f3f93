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

namespace contain::predicates {

namespace {

using LD = long double;
// The stages below rely on the x87 extended format: a rounding midpoint of doubles (54
// significant bits) is exact in LD, and products of up to six doubles neither overflow nor
// underflow in it (15-bit exponent), so `Mag` carries no absolute error term. A long double
// with a wider significand and exponent (IEEE binary128) keeps both properties.
static_assert(
    std::numeric_limits<LD>::digits >= 64 && std::numeric_limits<LD>::max_exponent >= 16384 &&
        std::numeric_limits<LD>::min_exponent <= -16381,
    "rounded_distance.cpp needs long double to be the 64-bit x87 extended format (or wider)");
using ErrLD = BasicBounded<LD>;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr LD kU = unit_roundoff<LD>;

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
  if (!std::isfinite(n.value) || !std::isfinite(n.error) || !std::isfinite(d.value) ||
      !std::isfinite(d.error)) {
    return false;
  }
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

// ---- quotients X / D, D > 0 ------------------------------------------------------------------

// |X - x| for x = n / d as computed (d - e_d > 0): at most (e_n + |n / d| e_d) / (d - e_d) +
// u |x|, with |n / d| <= |x| (1 + u); the factor (1 + 16u) covers the roundings of the bound
// itself.
LD quotient_error(const ErrLD& n, const ErrLD& d, LD x) {
  return ((n.error + std::fabs(x) * (1 + kU) * d.error) / (d.value - d.error) + kU * std::fabs(x)) *
         (1 + 16 * kU);
}

// The double nearest to a value within `bound` of x, when both midpoints to the neighbours of
// c = (double) x are farther than that (the factor covers the rounding of the difference).
bool certify_nearest(LD x, LD bound, double& out) {
  if (!std::isfinite(x) || !std::isfinite(bound)) return false;
  const double c = static_cast<double>(x);
  if (c != -kInf && !((x - lower_mid(c)) > bound * (1 + 4 * kU))) return false;
  if (c != kInf && !((upper_mid(c) - x) > bound * (1 + 4 * kU))) return false;
  out = c;
  return true;
}

bool quotient_stage_a(const ErrLD& n, const ErrLD& d, double& out) {
  if (!std::isfinite(n.value) || !std::isfinite(n.error) || !std::isfinite(d.value) ||
      !std::isfinite(d.error)) {
    return false;
  }
  if (n.value == 0 && n.error == 0) {
    out = 0.0;
    return true;
  }
  if (!(d.value - d.error > 0)) return false;
  const LD x = n.value / d.value;
  return certify_nearest(x, quotient_error(n, d, x), out);
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

// ---- stage 0: values with a priori bounds ----------------------------------------------------

// A long double value with the magnitude of its expression and its rounding depth, for a bound
// computed once at the end instead of carried through each operation (ErrLD): about a third of
// the work, and enough for all but the answers within a few units of 2^-64 of a rounding
// boundary, which go on to the running-error stage and then the exact one.
//
// The analysis (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., 3.1 and 3.3):
// an expression of sums, differences and products evaluated in floating point, k roundings deep
// at most, is within gamma_k = k u / (1 - k u) of its exact value times the exact expression of
// the absolute values of its monomials, M. A difference (or sum) of two input doubles is
// (a - b)(1 + d): it counts as a leaf of magnitude |a - b| with one rounding, so a point far from
// the origin does not inflate M by its coordinates. m is M computed in long double, at least
// M (1 - u)^k, so the error is at most gamma_k (1 - u)^-k m <= (k + 0.01) u m for k <= 16, and
// m (2k + 1) u, rounded once, covers it. Products of doubles cannot overflow or underflow in
// long double (15-bit exponent) at the degrees used here (at most 6), so there is no absolute
// error term; on a platform whose long double is double the values can: `bounded` then gives an
// infinite or NaN bound, which the stages refuse.
struct Mag {
  LD v = 0;
  LD m = 0;
  int k = 0;          // rounding depth
  bool leaf = false;  // an input double, exact

  Mag() = default;
  explicit Mag(double x) : v(x), m(std::fabs(static_cast<LD>(x))), k(0), leaf(true) {}
  Mag(LD value, LD magnitude, int depth) : v(value), m(magnitude), k(depth) {}

  friend Mag operator+(const Mag& a, const Mag& b) {
    const LD r = a.v + b.v;
    if (a.leaf && b.leaf) return {r, std::fabs(r), 1};
    return {r, a.m + b.m, std::max(a.k, b.k) + 1};
  }
  friend Mag operator-(const Mag& a, const Mag& b) {
    const LD r = a.v - b.v;
    if (a.leaf && b.leaf) return {r, std::fabs(r), 1};
    return {r, a.m + b.m, std::max(a.k, b.k) + 1};
  }
  friend Mag operator*(const Mag& a, const Mag& b) {
    return {a.v * b.v, a.m * b.m, std::max(a.k, b.k) + 1};
  }
};

ErrLD bounded(const Mag& x) {
  if (x.k == 0) return {x.v, 0};  // an input double
  if (x.k > 16) return {x.v, std::numeric_limits<LD>::infinity()};
  return {x.v, x.m * (static_cast<LD>(2 * x.k + 1) * kU)};
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

// Stage A for base + sign * OFF / D (D > 0, base and sign exact): y = off / d within
// ey of OFF / D (the bound of quotient_stage_a), x = base + sign y rounded once more (u |x|);
// the factor (1 + 4u) covers the roundings of the bound. An offset exactly 0 leaves base.
bool offset_stage_a(double base, double sign, const ErrLD& off, const ErrLD& d, double& out) {
  if (!std::isfinite(off.value) || !std::isfinite(off.error) || !std::isfinite(d.value) ||
      !std::isfinite(d.error)) {
    return false;
  }
  if (off.value == 0 && off.error == 0) {
    out = base;
    return true;
  }
  if (!(d.value - d.error > 0)) return false;
  const LD y = off.value / d.value;
  const LD x = static_cast<LD>(base) + static_cast<LD>(sign) * y;
  return certify_nearest(x, (quotient_error(off, d, y) + kU * std::fabs(x)) * (1 + 4 * kU), out);
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
