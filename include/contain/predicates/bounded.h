#pragma once
/// \file
/// Doubles with a proven error bound (running error analysis): the building block of filters
/// for polynomials that are not worth a hand-derived static bound, such as the motion
/// polynomials of continuous collision evaluated over an interval of time.
///
/// A `Bounded` holds a double `value` and a double `error` such that the exact real quantity it
/// stands for lies in [value - error, value + error]. Every operation rounds its value once and
/// adds to the error the propagated errors of its operands and a bound on its own rounding,
/// computed so that the bound's own roundings never make it too small (derivation in
/// docs/robustness.md, "Running error bounds"). `certified_sign` is the exact sign of the real
/// quantity when the interval excludes zero. Overflow makes the error infinite or NaN and every
/// sign uncertain, never wrong.

#include <cfloat>
#include <cmath>
#include <optional>

#include "contain/predicates/sign.h"

namespace contain::predicates {

struct Bounded {
  double value = 0.0;
  double error = 0.0;
};

namespace detail {
inline constexpr double kUnit = 0x1p-53;
// Applied to every newly computed bound: covers the at most 7 roundings of its own computation,
// each by a factor of at least (1 - u): (1 + 8u)(1 - u)^8 >= 1.
inline constexpr double kInflate = 1.0 + 8.0 * kUnit;
}  // namespace detail

/// The double x, exactly.
[[nodiscard]] constexpr Bounded exact(double x) {
  return {x, 0.0};
}

/// |a + b - fl(a.v + b.v)| <= a.e + b.e + u |fl(a.v + b.v)|. A sum whose u |v| underflows is
/// exact (both operands are multiples of 2^-1074 and the result has at most 53 bits), so sums
/// need no underflow guard.
[[nodiscard]] inline Bounded operator+(Bounded a, Bounded b) {
  const double v = a.value + b.value;
  return {v, ((a.error + b.error) + detail::kUnit * std::fabs(v)) * detail::kInflate};
}

[[nodiscard]] inline Bounded operator-(Bounded a, Bounded b) {
  const double v = a.value - b.value;
  return {v, ((a.error + b.error) + detail::kUnit * std::fabs(v)) * detail::kInflate};
}

[[nodiscard]] inline Bounded operator-(Bounded a) {
  return {-a.value, a.error};
}

/// |ab - fl(a.v b.v)| <= |a.v| b.e + |b.v| a.e + a.e b.e + u |fl(a.v b.v)| + 2^-1075 (a product
/// that underflows has an absolute error of at most half the smallest subnormal); DBL_MIN also
/// covers the underflow of the bound's own products.
[[nodiscard]] inline Bounded operator*(Bounded a, Bounded b) {
  const double v = a.value * b.value;
  const double e = ((std::fabs(a.value) * b.error + std::fabs(b.value) * a.error) +
                    (a.error * b.error + detail::kUnit * std::fabs(v))) *
                       detail::kInflate +
                   DBL_MIN;
  return {v, e};
}

/// The exact sign of the quantity when `value` is farther from 0 than `error`; nothing
/// otherwise (also for NaN or infinite values and bounds).
[[nodiscard]] inline std::optional<Sign> certified_sign(Bounded a) {
  if (a.value > a.error) return Sign::positive;
  if (-a.value > a.error) return Sign::negative;
  return std::nullopt;
}

}  // namespace contain::predicates
