#pragma once
// Doubles in the order of the reals as 64-bit integers, for bisection on doubles (root
// isolation, rounding a root or a rational to a double): halving the integer distance halves
// the count of doubles in between, whatever their exponents. -0.0 and 0.0 share the key 0;
// NaN has no key. The keys of finite doubles lie in [-(2^63 - 2^52 - 1), 2^63 - 2^52 - 1], so
// the distance of two keys can exceed 2^63 but never 2^64: it is taken unsigned.

#include <bit>
#include <cstdint>

namespace contain::predicates::detail {

[[nodiscard]] inline std::int64_t order_key(double d) {
  const auto bits = std::bit_cast<std::uint64_t>(d);
  const auto magnitude = static_cast<std::int64_t>(bits & 0x7fffffffffffffffULL);
  return (bits >> 63) != 0 ? -magnitude : magnitude;
}

/// The double of a key (0.0 for 0).
[[nodiscard]] inline double from_key(std::int64_t k) {
  if (k >= 0) return std::bit_cast<double>(static_cast<std::uint64_t>(k));
  return std::bit_cast<double>(static_cast<std::uint64_t>(-k) | 0x8000000000000000ULL);
}

/// b - a for keys a <= b: the count of doubles from a's to b's (exact, unsigned).
[[nodiscard]] inline std::uint64_t key_distance(std::int64_t a, std::int64_t b) {
  return static_cast<std::uint64_t>(b) - static_cast<std::uint64_t>(a);
}

/// The key halfway between keys a <= b (rounded towards a).
[[nodiscard]] inline std::int64_t middle_key(std::int64_t a, std::int64_t b) {
  return a + static_cast<std::int64_t>(key_distance(a, b) / 2);
}

}  // namespace contain::predicates::detail
