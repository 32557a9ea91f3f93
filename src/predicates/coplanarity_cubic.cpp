#include "contain/predicates/coplanarity_cubic.h"

#include <cfloat>
#include <cmath>
#include <cstdint>

#include "contain/predicates/bounded.h"
#include "contain/predicates/unit_roundoff.h"
#include "predicates/double_order.h"
#include "predicates/expansion.h"

namespace contain::predicates {

namespace {

using detail::from_key;
using detail::order_key;

// ---- double-double with running error bounds ------------------------------------------------
//
// A value hi + lo (exact sum of two doubles) and a bound err >= |exact - (hi + lo)|. Each
// operation's own rounding is bounded term by term (Two-Sum and Two-Product are exact; the
// products and sums of the low parts round once each, by at most u times their computed
// magnitude); the bound's own computation is inflated as in `bounded.h` (at most 15 roundings,
// (1 + 16u)(1 - u)^15 >= 1), and DBL_MIN covers every underflow (a Two-Product tail that is not
// representable, a product below the normal range), as in the other filters.

constexpr double kInflateDd = 1.0 + 16.0 * unit_roundoff<double>;

struct Dd {
  double hi = 0.0, lo = 0.0, err = 0.0;
};

Dd exact_difference(double a, double b) {
  Dd r;
  detail::two_diff(a, b, r.hi, r.lo);
  return r;
}

Dd add(const Dd& a, const Dd& b) {
  double s, e;
  detail::two_sum(a.hi, b.hi, s, e);
  const double x1 = a.lo + b.lo;
  const double t = x1 + e;
  Dd r;
  detail::two_sum(s, t, r.hi, r.lo);
  r.err = ((a.err + b.err) + unit_roundoff<double> * (std::fabs(x1) + std::fabs(t))) * kInflateDd;
  return r;
}

Dd negate(const Dd& a) {
  return {-a.hi, -a.lo, a.err};
}

Dd sub(const Dd& a, const Dd& b) {
  return add(a, negate(b));
}

Dd mul(const Dd& a, const Dd& b) {
  double p, e;
  detail::two_product(a.hi, b.hi, p, e);
  const double x1 = a.hi * b.lo;
  const double x2 = a.lo * b.hi;
  const double x3 = x1 + x2;
  const double t = x3 + e;
  Dd r;
  detail::two_sum(p, t, r.hi, r.lo);
  const double av = std::fabs(a.hi) + std::fabs(a.lo);
  const double bv = std::fabs(b.hi) + std::fabs(b.lo);
  r.err = ((av * b.err + bv * a.err) + a.err * b.err + std::fabs(a.lo) * std::fabs(b.lo) +
           unit_roundoff<double> * (std::fabs(x1) + std::fabs(x2) + std::fabs(x3) + std::fabs(t))) *
              kInflateDd +
          4.0 * DBL_MIN;
  return r;
}

Dd mul(const Dd& a, double d) {
  double p, e;
  detail::two_product(a.hi, d, p, e);
  const double x = a.lo * d;
  const double t = x + e;
  Dd r;
  detail::two_sum(p, t, r.hi, r.lo);
  r.err =
      (std::fabs(d) * a.err + unit_roundoff<double> * (std::fabs(x) + std::fabs(t))) * kInflateDd +
      2.0 * DBL_MIN;
  return r;
}

std::optional<Sign> certified_sign(const Dd& a) {
  // hi + lo lies within |lo| of hi; the bound is rounded up.
  const double bound = (2.0 * std::fabs(a.lo) + a.err) * (1.0 + 4.0 * unit_roundoff<double>);
  if (a.hi > bound) return Sign::positive;
  if (-a.hi > bound) return Sign::negative;
  return std::nullopt;
}

// The most sign variations a Bernstein coefficient sequence can have when some interior signs
// are unknown (each may be either sign; a zero would only lower the count). Zero ends skipped.
int max_variations(Sign s0, std::optional<Sign> s1, std::optional<Sign> s2, Sign s3) {
  int best = 0;
  for (int m = 0; m < 4; ++m) {
    const Sign a = s1 ? *s1 : ((m & 1) ? Sign::positive : Sign::negative);
    const Sign b = s2 ? *s2 : ((m & 2) ? Sign::positive : Sign::negative);
    int count = 0;
    Sign last = Sign::zero;
    for (const Sign s : {s0, a, b, s3}) {
      if (s == Sign::zero) continue;
      if (last != Sign::zero && s != last) ++count;
      last = s;
    }
    best = std::max(best, count);
  }
  return best;
}

using Quad = std::array<Bounded, 4>;

const Bounded kHalf = exact(0.5);

// Roots in (lo, hi) of the Bernstein polynomial c on [lo, hi]; false when not certified.
bool isolate(const Quad& c, double lo, double hi, Sign s_lo, Sign s_hi, int depth,
             RootBrackets& out) {
  const int var = max_variations(s_lo, certified_sign(c[1]), certified_sign(c[2]), s_hi);
  if (var == 0) return true;
  if (var == 1 && s_lo != Sign::zero && s_hi == -s_lo) {
    if (out.count == 3) return false;
    out.brackets[static_cast<std::size_t>(out.count++)] = {lo, hi, s_lo};
    return true;
  }
  if (depth >= 12) return false;
  const Bounded b01 = (c[0] + c[1]) * kHalf, b12 = (c[1] + c[2]) * kHalf,
                b23 = (c[2] + c[3]) * kHalf;
  const Bounded b012 = (b01 + b12) * kHalf, b123 = (b12 + b23) * kHalf;
  const Bounded mid_value = (b012 + b123) * kHalf;
  const std::optional<Sign> s_mid = certified_sign(mid_value);
  if (!s_mid || *s_mid == Sign::zero) return false;  // no root on a subdivision point
  const double mid = lo + 0.5 * (hi - lo);           // exact: dyadic ends
  return isolate({c[0], b01, b012, mid_value}, lo, mid, s_lo, *s_mid, depth + 1, out) &&
         isolate({mid_value, b123, b23, c[3]}, mid, hi, *s_mid, s_hi, depth + 1, out);
}

}  // namespace

CoplanarityCubic::CoplanarityCubic(const MovingPoints& points, MotionPolynomial p)
    : points_(points), p_(p) {
  // U = P_j - P_i, V = P_k - P_i, W = P_l - P_i at t = 0 and t = 1 (rounded differences).
  const auto diff = [&](int to, int time, int c) {
    return component(points[static_cast<std::size_t>(to + 4 * time)], c) -
           component(points[static_cast<std::size_t>(p.i + 4 * time)], c);
  };
  double u[2][3], v[2][3], w[2][3];
  for (int time = 0; time < 2; ++time) {
    for (int c = 0; c < 3; ++c) {
      u[time][c] = diff(p.j, time, c);
      v[time][c] = diff(p.k, time, c);
      w[time][c] = diff(p.l, time, c);
    }
  }
  // Cross products V^b x W^c and their permanents.
  double cr[2][2][3], cp[2][2][3];
  for (int b = 0; b < 2; ++b) {
    for (int c = 0; c < 2; ++c) {
      const double *x = v[b], *y = w[c];
      const double p0 = x[1] * y[2], p1 = x[2] * y[1], p2 = x[2] * y[0], p3 = x[0] * y[2],
                   p4 = x[0] * y[1], p5 = x[1] * y[0];
      cr[b][c][0] = p0 - p1;
      cr[b][c][1] = p2 - p3;
      cr[b][c][2] = p4 - p5;
      cp[b][c][0] = std::fabs(p0) + std::fabs(p1);
      cp[b][c][1] = std::fabs(p2) + std::fabs(p3);
      cp[b][c][2] = std::fabs(p4) + std::fabs(p5);
    }
  }
  double d[2][2][2], pd[2][2][2];
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      for (int c = 0; c < 2; ++c) {
        d[a][b][c] = (u[a][0] * cr[b][c][0] + u[a][1] * cr[b][c][1]) + u[a][2] * cr[b][c][2];
        pd[a][b][c] = (std::fabs(u[a][0]) * cp[b][c][0] + std::fabs(u[a][1]) * cp[b][c][1]) +
                      std::fabs(u[a][2]) * cp[b][c][2];
      }
    }
  }
  // A determinant meets at most 8 roundings per monomial (three leaf differences, the minor's
  // product and difference, the product with U, two sums): (8 + 1) u times its permanent; 3 D
  // one more, a sum of three D two more (docs/robustness.md, "the derived bounds (k + 1) eps").
  // An underflowed minor product is multiplied by a component of U: DBL_MIN (1 + |U|_1) per
  // determinant.
  const double guard = 3.0 * DBL_MIN *
                       (1.0 + std::fabs(u[0][0]) + std::fabs(u[0][1]) + std::fabs(u[0][2]) +
                        std::fabs(u[1][0]) + std::fabs(u[1][1]) + std::fabs(u[1][2]));
  bernstein_[0] = {3.0 * d[0][0][0], 10.0 * unit_roundoff<double> * (3.0 * pd[0][0][0]) + guard};
  bernstein_[1] = {
      (d[1][0][0] + d[0][1][0]) + d[0][0][1],
      11.0 * unit_roundoff<double> * ((pd[1][0][0] + pd[0][1][0]) + pd[0][0][1]) + guard};
  bernstein_[2] = {
      (d[1][1][0] + d[1][0][1]) + d[0][1][1],
      11.0 * unit_roundoff<double> * ((pd[1][1][0] + pd[1][0][1]) + pd[0][1][1]) + guard};
  bernstein_[3] = {3.0 * d[1][1][1], 10.0 * unit_roundoff<double> * (3.0 * pd[1][1][1]) + guard};
  double max_error = 0.0, max_value = 0.0;
  for (const Bounded& c : bernstein_) {
    max_error = std::max(max_error, c.error);
    max_value = std::max(max_value, std::fabs(c.value));
  }
  evaluation_error_ = (max_error + 10.0 * unit_roundoff<double> * max_value) *
                      (1.0 + 4.0 * unit_roundoff<double>)+6.0 * DBL_MIN;
}

std::optional<Sign> CoplanarityCubic::sign_on_unit() const {
  bool positive = true, negative = true;
  for (const Bounded& c : bernstein_) {
    positive = positive && c.value > c.error;
    negative = negative && -c.value > c.error;
  }
  if (positive) return Sign::positive;
  if (negative) return Sign::negative;
  return std::nullopt;
}

std::optional<RootBrackets> CoplanarityCubic::roots_in_open_unit(Sign at0, Sign at1) const {
  Quad c;
  for (std::size_t k = 0; k < 4; ++k)
    c[k] = bernstein_[k];
  if (at0 == Sign::zero) c[0] = exact(0.0);
  if (at1 == Sign::zero) c[3] = exact(0.0);
  RootBrackets out;
  if (!isolate(c, 0.0, 1.0, at0, at1, 0, out)) return std::nullopt;
  return out;
}

std::optional<Sign> CoplanarityCubic::sign_at(double t) const {
  // De Casteljau in doubles. Each coefficient's share picks up at most 9 roundings (1 - t, the
  // product and the sum on each of the three levels), and the shares' weights B_k(t) sum to 1,
  // so the value is within gamma_9 max |g_k| of the exact Bernstein sum of the rounded
  // coefficients, itself within max e_k of 3 f(t): `evaluation_error_` holds both (with 10u, and
  // DBL_MIN for the six products' underflow).
  const double s = 1.0 - t;
  double b[4];
  for (std::size_t k = 0; k < 4; ++k)
    b[k] = bernstein_[k].value;
  for (int level = 3; level > 0; --level) {
    for (int k = 0; k < level; ++k)
      b[k] = b[k] * s + b[k + 1] * t;
  }
  if (b[0] > evaluation_error_) return Sign::positive;
  if (-b[0] > evaluation_error_) return Sign::negative;
  return std::nullopt;
}

RootBracket CoplanarityCubic::narrow(RootBracket r, double width) const {
  // Plain double values of 3 f and its derivative, for Newton's guesses only.
  const auto newton = [&](double t) {
    double b[4];
    for (std::size_t k = 0; k < 4; ++k)
      b[k] = bernstein_[k].value;
    const double s = 1.0 - t;
    const double d0 = b[1] - b[0], d1 = b[2] - b[1], d2 = b[3] - b[2];
    const double df = 3.0 * ((d0 * s + d1 * t) * s + (d1 * s + d2 * t) * t);
    for (int level = 3; level > 0; --level) {
      for (int k = 0; k < level; ++k)
        b[k] = b[k] * s + b[k + 1] * t;
    }
    return t - b[0] / df;
  };
  double guess = r.lo + 0.5 * (r.hi - r.lo);
  for (int step = 0; step < 16; ++step) {
    if (r.hi - r.lo <= width || order_key(r.hi) - order_key(r.lo) <= 1) return r;
    double t = newton(guess);
    if (!(t > r.lo && t < r.hi)) t = r.lo + 0.5 * (r.hi - r.lo);
    const std::optional<Sign> s = sign_at(t);
    if (s) {
      // Newton lands on one side; a step of its last correction past the root usually lands
      // on the other, which halves nothing but closes the bracket quadratically.
      (*s == r.sign_lo ? r.lo : r.hi) = t;
      const double other = t + (t - guess);
      if (other > r.lo && other < r.hi) {
        const std::optional<Sign> so = sign_at(other);
        if (so) (*so == r.sign_lo ? r.lo : r.hi) = other;
      }
      guess = t;
      continue;
    }
    // t is within the filter's uncertainty of the root: certify a few ulps on either side,
    // widening until both sides are certified or the bracket is reached.
    double w = std::max(std::fabs(t) * 4.0 * unit_roundoff<double>, DBL_MIN);
    for (int k = 0; k < 10; ++k, w *= 8.0) {
      const double a = t - w, b = t + w;
      bool done = true;
      if (a > r.lo) {
        if (sign_at(a) == r.sign_lo) {
          r.lo = a;
        } else {
          done = false;
        }
      }
      if (b < r.hi) {
        if (sign_at(b) == -r.sign_lo) {
          r.hi = b;
        } else {
          done = false;
        }
      }
      if (done) break;
    }
    return r;
  }
  return r;
}

double CoplanarityCubic::floor(RootBracket r) const {
  // f(t) = (U(t) x V(t)) . W(t) with U(t) = U0 + t (U1 - U0) etc., every difference of two
  // input doubles exact in double-double, the rest with running bounds; bisection on the
  // doubles of the bracket.
  const MotionPolynomial& p = p_;
  Dd u0[3], du[3], v0[3], dv[3], w0[3], dw[3];
  for (int c = 0; c < 3; ++c) {
    const auto diff = [&](int to, int time) {
      return exact_difference(component(points_[static_cast<std::size_t>(to + 4 * time)], c),
                              component(points_[static_cast<std::size_t>(p.i + 4 * time)], c));
    };
    u0[c] = diff(p.j, 0);
    du[c] = sub(diff(p.j, 1), u0[c]);
    v0[c] = diff(p.k, 0);
    dv[c] = sub(diff(p.k, 1), v0[c]);
    w0[c] = diff(p.l, 0);
    dw[c] = sub(diff(p.l, 1), w0[c]);
  }
  const auto sign_at_dd = [&](double t) {
    Dd u[3], v[3], w[3];
    for (int c = 0; c < 3; ++c) {
      u[c] = add(u0[c], mul(du[c], t));
      v[c] = add(v0[c], mul(dv[c], t));
      w[c] = add(w0[c], mul(dw[c], t));
    }
    const Dd x = sub(mul(v[1], w[2]), mul(v[2], w[1]));
    const Dd y = sub(mul(v[2], w[0]), mul(v[0], w[2]));
    const Dd z = sub(mul(v[0], w[1]), mul(v[1], w[0]));
    return certified_sign(add(add(mul(u[0], x), mul(u[1], y)), mul(u[2], z)));
  };
  // Where double-double does not decide (a root exactly at a double, typical of hand-made and
  // lattice input, or within ~2^-100 of one), the exact polynomial does, built once.
  std::optional<Polynomial> exact;
  std::int64_t lo = order_key(r.lo), hi = order_key(r.hi);
  while (hi - lo >= 2) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    const double t = from_key(mid);
    std::optional<Sign> s = sign_at_dd(t);
    if (!s) {
      if (!exact) exact = exact_polynomial(points_, p_);
      s = exact->sign_at(t);
      if (*s == Sign::zero) return t;  // the root is this double
    }
    (*s == r.sign_lo ? lo : hi) = mid;
  }
  return from_key(lo);
}

}  // namespace contain::predicates
