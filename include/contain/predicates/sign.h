#pragma once
/// \file
/// The result type of every exact predicate.

#include <cstdint>

namespace contain {

/// The exact sign of a polynomial in the input doubles.
enum class Sign : std::int8_t { negative = -1, zero = 0, positive = 1 };

[[nodiscard]] constexpr Sign operator-(Sign s) {
  return static_cast<Sign>(-static_cast<std::int8_t>(s));
}
[[nodiscard]] constexpr int to_int(Sign s) {
  return static_cast<int>(s);
}
[[nodiscard]] constexpr Sign sign_of(double v) {
  return v > 0 ? Sign::positive : (v < 0 ? Sign::negative : Sign::zero);
}

}  // namespace contain
