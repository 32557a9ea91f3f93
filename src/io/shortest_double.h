#pragma once
/// \file
/// The shortest decimal that reads back as a given double, written byte for byte as
/// std::to_chars(first, last, double) writes it (the plain overload of libstdc++), several times
/// faster. The digits come from Schubfach (R. Giulietti, "The Schubfach way to render doubles",
/// 2020): one 126-bit power of ten per double, three products rounded to odd, and at most two
/// candidate decimals to compare with the rounding interval. The layout is libstdc++'s:
/// fixed notation when it is not longer than scientific, "e+XX"/"e-XX" exponents of at least
/// two digits, whole numbers in fixed notation as their exact value (as printf's "%.0f"), "-0",
/// "inf", "-inf", "nan", "-nan".

#include <cstdint>

namespace contain::io::detail {

/// floor(log10(2^q)), exact for |q| <= 1100 (proven in the test over the range the writer uses).
[[nodiscard]] constexpr int floor_log10_pow2(int q) {
  return (q * 315653) >> 20;
}

/// floor(log10(3/4 * 2^q)), exact for q in [-1074, 971] (proven in the test).
[[nodiscard]] constexpr int floor_log10_three_quarters_pow2(int q) {
  return (q * 315653 - 131007) >> 20;
}

/// floor(log2(10^e)), exact for |e| <= 330 (proven in the test).
[[nodiscard]] constexpr int floor_log2_pow10(int e) {
  return (e * 1741647) >> 19;
}

/// Room the writer needs at `at`: the longest form, "-2.2250738585072014e-308" or a sign and
/// 22 whole digits, is 24 characters; the rest is scratch for fixed-size (inlined) copies.
inline constexpr int kShortestDoubleRoom = 40;

/// Writes `value` at `at` (room for kShortestDoubleRoom characters) as std::to_chars(first,
/// last, value) does; returns the end of the text. Bytes past it up to the room may change.
char* write_shortest_double(char* at, double value);

}  // namespace contain::io::detail
