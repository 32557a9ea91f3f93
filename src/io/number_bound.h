#pragma once
/// \file
/// Private: a bound on a decimal number from its first digits, read without parsing the rest.
///
/// For a token of the plain shape `-?D.F` (D: 1 to 7 digits, F: 1 or more digits) let m be the
/// integer D followed by the first 8 digits of F (padded with zeros), so that the decimal value
/// x of the token's magnitude lies in [m / 10^8, (m + 1) / 10^8]. m + 1 < 10^15 < 2^53 is a
/// double exactly. The ends are scaled by a multiply, not a division (a tenth of the read):
/// with u = 2^-53, kLowScale = fl(fl(1e-8) (1 - 2^-50)) <= 10^-8 (1 - 6u) and
/// fl(m kLowScale) <= m kLowScale (1 + u) < m / 10^8; likewise kHighScale >= 10^-8 (1 + 6u) and
/// fl((m + 1) kHighScale) > (m + 1) / 10^8. So lo <= x <= hi with lo and hi doubles, and since
/// rounding to nearest is monotone, the double std::from_chars gives for the whole token (the
/// correctly rounded x, or for underflow parse_double's correctly rounded zero or subnormal)
/// lies in [lo, hi] too. A minus sign mirrors the interval (rounding to nearest is symmetric).
/// The rest of F is only checked to be digits, 8 bytes at a time, and every byte of the token
/// is read: the token ends where from_chars would end it.
///
/// Every other token (no digit before or after the point, more than 7 integer digits, an
/// exponent, a '+', inf or nan) is refused, the pointer left where it was: the caller parses
/// it in full (from_chars stays the parser of record, and of every error).

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace contain::io::detail {

/// The closed interval [lo, hi] holding the double a token denotes.
struct NumberBound {
  double lo = 0.0, hi = 0.0;
};

/// A bit 7 in every byte of `bytes` (8 text bytes, the first in the low byte) that is not a
/// decimal digit. A byte b is a digit iff t = b ^ '0' < 10, iff neither t nor t + 0x76 has bit
/// 7. A carry out of a byte only happens when t >= 0x8a, a byte flagged by t's own bit 7, and
/// only moves up into later bytes, so the first flagged byte is always right.
[[nodiscard]] inline std::uint64_t non_digit_bits(std::uint64_t bytes) {
  const std::uint64_t t = bytes ^ 0x3030303030303030u;
  // Modular (unsigned) arithmetic, wrapping by design.
  return (t | (t + 0x7676767676767676u)) & 0x8080808080808080u;
}

/// The 8 digits in `bytes` (first in the low byte; bytes past a non-digit must be zeroed
/// after subtracting '0', i.e. given as '0') as an integer: the 8-digit multiply of
/// fast_float (Lemire), modular arithmetic by design.
[[nodiscard]] inline std::uint64_t eight_digits(std::uint64_t bytes) {
  constexpr std::uint64_t mask = 0x000000ff000000ffu;
  constexpr std::uint64_t mul1 = 100 + (std::uint64_t{1000000} << 32);
  constexpr std::uint64_t mul2 = 1 + (std::uint64_t{10000} << 32);
  std::uint64_t v = bytes - 0x3030303030303030u;
  v = (v * 10) + (v >> 8);
  return (((v & mask) * mul1) + (((v >> 16) & mask) * mul2)) >> 32;
}

/// The text bytes [p, p + 8) as a little-endian word (the first byte lowest).
[[nodiscard]] inline std::uint64_t load8(const char* p) {
  if constexpr (std::endian::native == std::endian::little) {
    std::uint64_t bytes = 0;
    std::memcpy(&bytes, p, 8);
    return bytes;
  } else {
    std::uint64_t bytes = 0;
    for (int k = 7; k >= 0; --k)
      bytes = bytes << 8 | static_cast<unsigned char>(p[k]);
    return bytes;
  }
}

/// Past the leading digits of [p, end), checked 8 bytes at a time where 8 remain.
[[nodiscard]] inline const char* skip_digits(const char* p, const char* end) {
  while (end - p >= 8) {
    const std::uint64_t flags = non_digit_bits(load8(p));
    if (flags != 0) return p + std::countr_zero(flags) / 8;
    p += 8;
  }
  while (p != end && static_cast<unsigned char>(*p - '0') < 10)
    ++p;
  return p;
}

/// Past the digits that start at `p`: two words at once where 16 bytes remain (the digits left
/// after the first 8 of a shortest round-trip double are fewer than 16, so one step without a
/// loop-exit branch to mispredict), else skip_digits.
[[nodiscard, gnu::always_inline]] inline const char* skip_digits_fast(const char* p,
                                                                      const char* end) {
  if (end - p >= 16) {
    const int first = std::countr_zero(non_digit_bits(load8(p))) / 8;  // 8: all digits
    const int second = std::countr_zero(non_digit_bits(load8(p + 8))) / 8;
    const int count = first < 8 ? first : 8 + second;
    if (count < 16) return p + count;
    return skip_digits(p + 16, end);
  }
  return skip_digits(p, end);
}

/// The scales of bound_from_digits (see the file comment): below and above 10^-8 by more than
/// the roundings of the products they make, shared with the masked scanner's vector loop.
inline constexpr double kLowScale = 1e-8 * (1.0 - 0x1p-50);
inline constexpr double kHighScale = 1e-8 * (1.0 + 0x1p-50);

/// The box of a plain-shape token (see the file comment) from its integer part `whole` (below
/// 10^7), the first 8 digits of its fraction `fraction` (padded with zeros) and its sign: the
/// computation of every reader of plain numbers, so that they give the same bits (the masked
/// scanner's vector loop, io/masked_lines.cpp, does these operations lane by lane).
[[nodiscard, gnu::always_inline]] inline NumberBound bound_from_digits(std::uint64_t whole,
                                                                       std::uint64_t fraction,
                                                                       bool negative) {
  const auto m = static_cast<double>(whole * 100000000u + fraction);
  const double lo = m * kLowScale, hi = (m + 1.0) * kHighScale;
  // The sign without a branch (random signs mispredict half the time): exact products, min/max.
  const double sign = negative ? -1.0 : 1.0;
  return {std::min(sign * lo, sign * hi), std::max(sign * lo, sign * hi)};
}

/// The 8 bytes after a token's point (`bytes`, first in the low byte) of which the first `count`
/// (1 or more) are digits, the rest replaced by '0' characters.
[[nodiscard, gnu::always_inline]] inline std::uint64_t padded_fraction_bytes(std::uint64_t bytes,
                                                                             int count) {
  const std::uint64_t kept = count >= 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (8 * count)) - 1;
  return (bytes & kept) | (0x3030303030303030u & ~kept);
}

/// The fraction's first 8 digits of a token from the 8 bytes after its point, of which the
/// first `count` are digits: the rest read as zeros.
[[nodiscard, gnu::always_inline]] inline std::uint64_t leading_fraction(std::uint64_t bytes,
                                                                        int count) {
  return eight_digits(padded_fraction_bytes(bytes, count));
}

/// Bounds the plain-shape number at `p` (see the file comment), advancing `p` past its token;
/// false, with `p` unchanged, for any other token (the caller parses it in full).
[[nodiscard, gnu::always_inline]] inline bool bound_plain_number(const char*& p, const char* end,
                                                                 NumberBound& out) {
  const char* q = p;
  const bool negative = q != end && *q == '-';
  if (negative) ++q;
  std::uint64_t whole = 0;
  const char* digits = q;
  while (q != end && static_cast<unsigned char>(*q - '0') < 10 && q - digits < 8) {
    whole = 10 * whole + static_cast<std::uint64_t>(*q - '0');
    ++q;
  }
  if (q == digits || q - digits > 7 || q == end || *q != '.') return false;
  ++q;
  std::uint64_t fraction = 0;   // the first 8 digits of F, padded with zeros
  const char* after = nullptr;  // past F
  if (end - q >= 8) {
    const std::uint64_t bytes = load8(q);
    const std::uint64_t flags = non_digit_bits(bytes);
    const int count = flags == 0 ? 8 : std::countr_zero(flags) / 8;
    if (count == 0) return false;
    fraction = leading_fraction(bytes, count);
    after = count == 8 ? skip_digits_fast(q + 8, end) : q + count;
  } else {
    after = skip_digits(q, end);
    if (after == q) return false;
    const auto count = after - q;  // fewer than 8
    for (std::ptrdiff_t k = 0; k < 8; ++k) {
      fraction = 10 * fraction + (k < count ? static_cast<std::uint64_t>(q[k] - '0') : 0);
    }
  }
  // An exponent changes the value: from_chars reads it (or decides it is not one).
  if (after != end && (*after == 'e' || *after == 'E')) return false;
  out = bound_from_digits(whole, fraction, negative);
  p = after;
  return true;
}

}  // namespace contain::io::detail
