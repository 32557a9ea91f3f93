#pragma once
/// \file
/// Private: the fast way of the point scanners for the numbers most coordinates are written in,
/// plain decimals like "-0.6918522583081116" or "12.5": an optional '-', 1 to 7 digits, a point,
/// 1 or more digits, at most 19 digits in all, no exponent. std::from_chars reads them a byte at
/// a time, with a branch at each byte whose outcome (is the number over?) the processor cannot
/// guess; here the digits are found and valued 8 bytes at a time, with no branch on the number's
/// length, and the double is the decimal's integer m divided by 10^k, proven correctly rounded
/// by an exact integer comparison. Anything else, or a proof that does not go through, declines
/// (false, nothing consumed) and the caller asks std::from_chars.
///
/// The proof: m < 10^19 < 2^64 and 10^k (k <= 18) are exact, so x = double(m) / 10^k is within
/// about an ulp of m / 10^k. With x = X 2^E (2^52 <= X < 2^53), x is m / 10^k correctly rounded
/// when |m 2^(1-E) - 2 X 10^k| < 10^k: the decimal lies within half an ulp of x. (A tie, equality,
/// cannot happen here: it needs 2^(1-E) to divide 10^k, so 1 - E <= k <= 18, while x < 10^7
/// gives E <= -29.) That needs 1 <= 1 - E <= 64 for the left side to fit in 128 bits, and X not
/// 2^52 (below a power of two the ulp halves); otherwise, or when x is not the rounding (about
/// one number in eight with 17 digits: double(m) rounds first), it declines.

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>

namespace contain::io::detail {

/// Bytes parse_plain_decimal may read from where it starts: the caller checks that many remain.
inline constexpr std::ptrdiff_t kPlainDecimalReach = 40;

/// 8 bytes at `p`, the first in the lowest byte.
[[nodiscard]] inline std::uint64_t load_eight(const char* p) {
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, p, 8);
  if constexpr (std::endian::native == std::endian::big) bytes = __builtin_bswap64(bytes);
  return bytes;
}

/// How many of the 8 bytes, from the first, are ASCII digits (0 to 8). A byte below '0' borrows
/// in the subtraction, one above '9' reaches the high bit in the addition; the first such byte
/// gets no carry or borrow from the bytes before it, so its flag is exact (later flags may not
/// be, and are not looked at).
[[nodiscard]] inline int leading_digits(std::uint64_t bytes) {
  const std::uint64_t flags =
      ((bytes + 0x4646464646464646ULL) | (bytes - 0x3030303030303030ULL)) & 0x8080808080808080ULL;
  return std::countr_zero(flags) / 8;
}

/// The value of the first `count` (0 to 8) bytes of `bytes`, all digits: they are moved to the
/// top lanes (the others shifted out, zeros below them: leading zeros), then pairs, fours and
/// the eight are formed, one multiplication each across the lanes (no lane overflows). The
/// subtraction may borrow only upward from the first byte that is not a digit, which is shifted
/// out.
[[nodiscard]] inline std::uint64_t digits_value(std::uint64_t bytes, int count) {
  const int drop = 8 * (8 - count);  // 0 to 64: two shifts, each below 64
  std::uint64_t v = bytes - 0x3030303030303030ULL;
  v = (v << (drop / 2)) << (drop - drop / 2);
  v = (v * 10 + (v >> 8)) & 0x00FF00FF00FF00FFULL;
  v = (v * 100 + (v >> 16)) & 0x0000FFFF0000FFFFULL;
  return (v * 10000 + (v >> 32)) & 0xFFFFFFFFULL;
}

inline constexpr std::uint64_t kPow10Integers[20] = {1ULL,
                                                     10ULL,
                                                     100ULL,
                                                     1000ULL,
                                                     10000ULL,
                                                     100000ULL,
                                                     1000000ULL,
                                                     10000000ULL,
                                                     100000000ULL,
                                                     1000000000ULL,
                                                     10000000000ULL,
                                                     100000000000ULL,
                                                     1000000000000ULL,
                                                     10000000000000ULL,
                                                     100000000000000ULL,
                                                     1000000000000000ULL,
                                                     10000000000000000ULL,
                                                     100000000000000000ULL,
                                                     1000000000000000000ULL,
                                                     10000000000000000000ULL};

inline constexpr double kPow10Doubles[20] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,
                                             1e7,  1e8,  1e9,  1e10, 1e11, 1e12, 1e13,
                                             1e14, 1e15, 1e16, 1e17, 1e18, 1e19};

/// m / 10^k correctly rounded (m < 10^19, k <= 18, m / 10^k < 10^7), or false when the file's
/// proof does not go through. No branch on the data: every way is computed, one test decides.
[[nodiscard]] inline bool divide_by_pow10(std::uint64_t m, int k, double& out) {
  __extension__ typedef unsigned __int128 Wide;
  const double x = static_cast<double>(m) / kPow10Doubles[k];
  // m <= 2^53: m and 10^k are exact, one division, one rounding.
  const bool exact_operands = m <= (std::uint64_t{1} << 53);
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const auto biased = static_cast<int>(bits >> 52);
  constexpr std::uint64_t kHidden = std::uint64_t{1} << 52;
  const std::uint64_t significand = (bits & (kHidden - 1)) | kHidden;
  const int shift = 1076 - biased;  // 1 - E
  const int clamped = std::min(std::max(shift, 1), 64);
  // d = m 2^(1-E) - 2 X 10^k = 2 10^k t, t = m / 10^k / 2^E - X how far the decimal is from x
  // in ulps. Each rounding (double(m), the division) is at most half an ulp of a value below
  // 2^(E+53): |t| <= 2 (1 + 2^-52), so |d| < 5 10^k < 2^63 and d is its own value modulo 2^64:
  // the low halves of the 128-bit products suffice. (When the shift was clamped, d is garbage
  // and the case is refused below.)
  const Wide difference =
      (static_cast<Wide>(m) << clamped) - static_cast<Wide>(2 * significand) * kPow10Integers[k];
  const auto d = static_cast<std::int64_t>(static_cast<std::uint64_t>(difference));
  const auto p = static_cast<std::int64_t>(kPow10Integers[k]);
  // The nearest integer to t (no ties: see the file's comment).
  const int step = static_cast<int>(d > p) + static_cast<int>(d > 3 * p) -
                   static_cast<int>(d < -p) - static_cast<int>(d < -3 * p);
  const std::uint64_t nearest = significand + static_cast<std::uint64_t>(step);
  // `&`, not `&&`: each test is cheap, and a branch on them would be a guess. The nearest
  // significand must stay inside the binade, off its lower end (below 2^52 the ulp halves).
  const bool proven = (biased != 0) & (shift == clamped) & (d < 5 * p) & (d > -5 * p) &
                      (nearest > kHidden) & (nearest < 2 * kHidden);
  // The choice made on the bits, with a mask: a `?:` on doubles becomes a branch, and whether
  // m fits in 53 bits is a coin toss for 17-digit coordinates.
  const std::uint64_t rounded = (static_cast<std::uint64_t>(biased) << 52) | (nearest - kHidden);
  const std::uint64_t keep = std::uint64_t{0} - static_cast<std::uint64_t>(exact_operands);
  out = std::bit_cast<double>((bits & keep) | (rounded & ~keep));
  return exact_operands | proven;
}

/// Reads a plain decimal at `p` (see the file's comment; at least kPlainDecimalReach bytes must
/// be readable from `p`): on success `p` is where std::from_chars stops and `out` its value;
/// false, nothing consumed, for any other text.
[[nodiscard]] inline bool parse_plain_decimal(const char*& p, double& out) {
  constexpr int kMostDigits = 19;
  const bool negative = *p == '-';
  const char* const whole = p + (negative ? 1 : 0);
  const std::uint64_t head = load_eight(whole);
  const int integer_digits = leading_digits(head);
  if (integer_digits == 0 || integer_digits == 8 || whole[integer_digits] != '.') return false;
  const char* const fraction = whole + integer_digits + 1;
  // The integer part is one digit in most coordinates (|x| < 10): its byte is its value.
  std::uint64_t m = integer_digits == 1 ? static_cast<std::uint64_t>(head & 0x0F)
                                        : digits_value(head, integer_digits);
  // The fraction 8 digits at a time while they are whole eights (a branch the data decides the
  // same way line after line), the last part valued by its length, without a branch on it.
  const std::uint64_t f0 = load_eight(fraction);
  const int c0 = leading_digits(f0);
  int k = c0;
  if (c0 == 8) {
    m = 100000000 * m + digits_value(f0, 8);
    const std::uint64_t f1 = load_eight(fraction + 8);
    const int c1 = leading_digits(f1);
    k += c1;
    if (c1 == 8) {
      m = 100000000 * m + digits_value(f1, 8);
      const std::uint64_t f2 = load_eight(fraction + 16);
      const int c2 = leading_digits(f2);
      if (integer_digits + 16 + c2 > kMostDigits) return false;
      k += c2;
      m = m * kPow10Integers[c2] + digits_value(f2, c2);
    } else {
      m = m * kPow10Integers[c1] + digits_value(f1, c1);
    }
  } else {
    if (c0 == 0) return false;
    m = m * kPow10Integers[c0] + digits_value(f0, c0);
  }
  if (integer_digits + k > kMostDigits) return false;
  const char* const stop = fraction + k;
  if ((*stop | 0x20) == 'e') return false;  // an exponent: from_chars reads it
  double value = 0;
  if (!divide_by_pow10(m, k, value)) return false;
  // The sign on the bits: a `?:` would be a branch, and the sign is a coin toss too.
  out = std::bit_cast<double>(std::bit_cast<std::uint64_t>(value) |
                              (static_cast<std::uint64_t>(negative) << 63));
  p = stop;
  return true;
}

}  // namespace contain::io::detail
