#pragma once
// A floating-point number that carries a proven bound on its distance from the exact value:
// running error analysis (Wilkinson; Higham, "Accuracy and Stability of Numerical Algorithms",
// 2nd ed., section 3.3), the filter of the distance predicates (squared_distance.cpp) and the
// first stage of their correct rounding (rounding.cpp).
//
// Err<F>{v, e}: the exact value x of the expression satisfies |x - v| <= e. Inputs are doubles,
// exact (e = 0). Each operation rounds v once (round to nearest) and adds its own rounding error
// to the propagated ones:
//   a +- b: e = a.e + b.e + u |v|                            (a sum never underflows inexactly)
//   a * b : e = |a.v| b.e + |b.v| a.e + a.e b.e + u |v| + t   (t: absolute error of an underflow)
// with u = unit roundoff of F. The bound itself is computed in F, rounded to nearest: each of its
// at most five roundings loses at most a factor (1 - u), so every bound is multiplied by
// (1 + 8u) >= 1 / (1 - u)^5, and t = 4 * denorm_min also covers the underflow of the bound's own
// products. So e is an upper bound however long the expression. A value computed exactly (both
// operands exact and the result exact: zero products with an exact zero factor, a difference
// that is zero) keeps e = 0, so exact zeros are recognised without the exact stage.
//
// Overflow makes v or e infinite or NaN; `decided` is then false and the caller's exact stage
// answers. With F = long double (x87: 64-bit significand, 15-bit exponent) no polynomial of degree
// <= 16 in doubles overflows or underflows. The answer stays sound on platforms where long double
// is double: u comes from std::numeric_limits<F>.

#include <cmath>
#include <limits>

#include "contain/predicates/sign.h"

namespace contain::predicates::detail {

template <class F>
struct Err {
  F v = 0;
  F e = 0;

  static constexpr F u = std::numeric_limits<F>::epsilon() / 2;
  static constexpr F grow = 1 + 8 * u;
  static constexpr F tiny = 4 * std::numeric_limits<F>::denorm_min();

  Err() = default;
  explicit Err(double x) : v(static_cast<F>(x)) {}
  Err(F value, F error) : v(value), e(error) {}

  friend Err operator+(const Err& a, const Err& b) {
    const F r = a.v + b.v;
    // Exact operands and an exact sum keep e = 0: for |a| >= |b| the difference v - a is
    // computed exactly (Dekker's Fast-Two-Sum), for |b| >= |a| v - b is; so both tests pass only
    // when no rounding happened.
    if (a.e == 0 && b.e == 0 && r - a.v == b.v && r - b.v == a.v) return {r, 0};
    return {r, (a.e + b.e + u * std::fabs(r)) * grow};
  }
  friend Err operator-(const Err& a, const Err& b) { return a + Err{-b.v, b.e}; }
  friend Err operator-(const Err& a) { return {-a.v, a.e}; }
  friend Err operator*(const Err& a, const Err& b) {
    const F r = a.v * b.v;
    if ((a.e == 0 && a.v == 0) || (b.e == 0 && b.v == 0)) return {F(0), F(0)};
    return {r, (std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + u * std::fabs(r) + tiny) *
                   grow};
  }

  /// True when the sign of v is the sign of the exact value (and the bound is finite).
  [[nodiscard]] bool decided() const {
    return std::isfinite(v) && std::isfinite(e) && (e == 0 || std::fabs(v) > e);
  }
  [[nodiscard]] Sign sign() const {
    return v > 0 ? Sign::positive : (v < 0 ? Sign::negative : Sign::zero);
  }
};

}  // namespace contain::predicates::detail
