#pragma once
/// \file
/// Floating-point values with a proven error bound (running error analysis): the one
/// value-with-error-bound type of contain. Filters written once over a number type (the distance
/// predicates, their correct rounding), the motion polynomials of continuous collision over an
/// interval of time, the half-space values of the clippers: anything that is not worth a
/// hand-derived static bound.
///
/// A `BasicBounded<F>` holds a `value` and an `error` of type F such that the exact real quantity
/// it stands for lies in [value - error, value + error]. `Bounded` (F = double) is the filter;
/// F = long double (x87: 64-bit significand, 15-bit exponent, no polynomial of degree <= 16 in
/// doubles overflows or underflows) is the finer stage of correct rounding. Reference: Higham,
/// "Accuracy and Stability of Numerical Algorithms", 2nd ed., section 3.3; derivation in
/// docs/robustness.md ("Running error bounds").
///
/// Each operation rounds `value` once (to nearest) and adds its own rounding error to the
/// propagated ones, with u = unit_roundoff<F>:
///   a +- b: e = (a.e + b.e + u |v|) (1 + 8u)                  (a sum never underflows inexactly)
///   a * b : e = (|a.v| b.e + |b.v| a.e + a.e b.e + u |v| + t) (1 + 8u)
/// t = 4 denorm_min<F> covers the absolute error of an underflowed product and the underflow of
/// the bound's own products; (1 + 8u) >= 1 / (1 - u)^7 covers the roundings of the bound's own
/// computation. A value computed exactly (exact operands and an exact sum, or a product with an
/// exact zero factor) keeps error 0, so exact zeros are recognised without an exact stage.
/// Overflow makes the value or the bound infinite or NaN: then no sign is certified, never a
/// wrong one.

#include <cmath>
#include <limits>
#include <optional>

#include "contain/predicates/sign.h"
#include "contain/predicates/unit_roundoff.h"

namespace contain::predicates {

template <class F>
struct BasicBounded {
  F value = 0;
  F error = 0;

  static constexpr F grow = 1 + 8 * unit_roundoff<F>;
  static constexpr F tiny = 4 * std::numeric_limits<F>::denorm_min();

  constexpr BasicBounded() = default;
  /// The double x, exactly.
  explicit constexpr BasicBounded(double x) : value(static_cast<F>(x)) {}
  constexpr BasicBounded(F v, F e) : value(v), error(e) {}

  /// True when the sign of `value` is the sign of the exact quantity (and the bound is finite).
  [[nodiscard]] bool decided() const {
    return std::isfinite(value) && std::isfinite(error) && (error == 0 || std::fabs(value) > error);
  }
  /// The sign of `value` (the exact sign when `decided()`).
  [[nodiscard]] Sign sign() const {
    return value > 0 ? Sign::positive : (value < 0 ? Sign::negative : Sign::zero);
  }

  friend BasicBounded operator+(const BasicBounded& a, const BasicBounded& b) {
    const F r = a.value + b.value;
    // Exact operands and an exact sum keep error 0: for |a| >= |b| the difference r - a is
    // computed exactly (Dekker's Fast-Two-Sum), for |b| >= |a| r - b is; so both tests pass only
    // when no rounding happened.
    if (a.error == 0 && b.error == 0 && r - a.value == b.value && r - b.value == a.value) {
      return {r, 0};
    }
    return {r, (a.error + b.error + unit_roundoff<F> * std::fabs(r)) * grow};
  }
  friend BasicBounded operator-(const BasicBounded& a, const BasicBounded& b) {
    return a + BasicBounded{-b.value, b.error};
  }
  friend BasicBounded operator-(const BasicBounded& a) { return {-a.value, a.error}; }
  friend BasicBounded operator*(const BasicBounded& a, const BasicBounded& b) {
    if ((a.error == 0 && a.value == 0) || (b.error == 0 && b.value == 0)) return {F(0), F(0)};
    const F r = a.value * b.value;
    return {r, (std::fabs(a.value) * b.error + std::fabs(b.value) * a.error + a.error * b.error +
                unit_roundoff<F> * std::fabs(r) + tiny) *
                   grow};
  }
};

/// The filter's number: a double and its bound.
using Bounded = BasicBounded<double>;

/// The double x, exactly.
[[nodiscard]] constexpr Bounded exact(double x) {
  return Bounded(x);
}

/// The exact sign of the quantity when the bound certifies it (`value` farther from 0 than
/// `error`, or an exact value); nothing otherwise (also for NaN or infinite values and bounds).
template <class F>
[[nodiscard]] std::optional<Sign> certified_sign(const BasicBounded<F>& a) {
  if (!a.decided()) return std::nullopt;
  return a.sign();
}

}  // namespace contain::predicates
