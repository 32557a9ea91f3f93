#pragma once
/// \file
/// The neighbours of a double, as std::nextafter(x, +-infinity) but inline: interval arithmetic
/// rounds each end outward by one step, and a call into libm per end was a few percent of a
/// mesh boolean. Inlined by force: gcc kept next_down as a call in the exact points' filters
/// (1.6% of the 2k sphere union).

#include <bit>
#include <cstdint>
#include <limits>

namespace contain {

/// The least double above x: exactly `std::nextafter(x, +infinity)` (both zeros give the least
/// subnormal, the negative least subnormal gives -0.0, -infinity gives -DBL_MAX, DBL_MAX gives
/// +infinity, +infinity and NaN give themselves). Does not set errno.
[[nodiscard, gnu::always_inline]] constexpr double next_up(double x) {
  if (x != x || x == std::numeric_limits<double>::infinity()) return x;  // NaN, +inf
  if (x == 0.0) return std::numeric_limits<double>::denorm_min();        // +0 or -0
  const auto bits = std::bit_cast<std::uint64_t>(x);
  // The bit patterns of positive doubles ascend with their values, those of negative doubles
  // descend: one step of the pattern is one step of the value.
  return std::bit_cast<double>(x > 0.0 ? bits + 1U : bits - 1U);
}

/// The greatest double below x: exactly `std::nextafter(x, -infinity)` (-next_up(-x)).
[[nodiscard, gnu::always_inline]] constexpr double next_down(double x) {
  return -next_up(-x);
}

}  // namespace contain
