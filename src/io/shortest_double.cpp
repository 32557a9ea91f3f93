// Shortest round-trip doubles: Schubfach's digits, libstdc++'s layout (src/io/shortest_double.h).
//
// Schubfach (R. Giulietti, "The Schubfach way to render doubles", 2020), in outline. A positive
// double v = c * 2^q rounds back from every real of its rounding interval [v - d-, v + d+]
// (closed when c is even, as round-to-nearest-even reads the ends back as v). Scaled by 4 (so
// the ends are whole: cb = 4c, cbl = cb - 2 or cb - 1 at the narrower gap below a power of two,
// cbr = cb + 2) and by 10^-k, with k = floor(log10(width)) so that the interval holds one or
// two multiples of 10^k and at most one of 10^(k+1):
//   1. vb, vbl, vbr: 4 * v * 10^-k and its ends, each from a 126-bit g ~ 10^-k (the table) and
//      rounded to odd: a rounded-to-odd value is even only when exact, so comparing it with a
//      multiple of 4 gives the exact comparison.
//   2. s = floor(v * 10^-k). If exactly one of the multiples of 10 around s lies in the interval,
//      it is the only decimal of that length or shorter there: the answer (its trailing zeros
//      dropped). Otherwise s or s + 1 is, and if both are, the closer one to v (even on a tie).

#include "io/shortest_double.h"

#include <array>
#include <bit>
#include <cstring>

#include "io/shortest_double_table.h"

namespace contain::io::detail {
namespace {

// The shortest decimal `digits` * 10^`exponent` in the rounding interval of a positive finite
// double, the closest to it among those of that length (the even one on a tie): Ryu's,
// Dragonbox's and Schubfach's common answer. `digits` has no trailing zero; `length` is its
// number of decimal digits.
struct ShortestDecimal {
  std::uint64_t digits;
  int exponent;
  int length;
};

__extension__ typedef unsigned __int128 UInt128;

constexpr std::uint64_t kHiddenBit = std::uint64_t{1} << 52;

// A 192-bit product: bits [0, 128) and [128, 192).
struct Wide {
  UInt128 low;
  std::uint64_t high;
};

Wide times(const Pow10Bits& g, std::uint64_t cp) {
  const UInt128 low = static_cast<UInt128>(g.low) * cp;
  const UInt128 middle = static_cast<UInt128>(g.high) * cp + (low >> 64);  // < 2^123
  return {(middle << 64) | static_cast<std::uint64_t>(low),
          static_cast<std::uint64_t>(middle >> 64)};
}

// g * 2^shift, shift in [3, 7].
Wide shifted(const Pow10Bits& g, int shift) {
  const UInt128 value = (static_cast<UInt128>(g.high) << 64) | g.low;
  return {value << shift, g.high >> (64 - shift)};
}

Wide plus(const Wide& a, const Wide& b) {
  const UInt128 low = a.low + b.low;
  return {low, a.high + b.high + static_cast<std::uint64_t>(low < a.low)};
}

Wide minus(const Wide& a, const Wide& b) {
  return {a.low - b.low, a.high - b.high - static_cast<std::uint64_t>(a.low < b.low)};
}

// floor(x / 2^128), its lowest bit set when bits [64, 128) of x are not all zero (round to
// odd). Bits [0, 64) are left out: g's excess over 10^-k (under 1) times the significand
// (under 2^61) lies in them, so an exact 4 * v * 10^-k (a tie between two decimals) still gives
// an even result (Giulietti's rop).
std::uint64_t round_to_odd(const Wide& x) {
  return x.high | static_cast<std::uint64_t>(static_cast<std::uint64_t>(x.low >> 64) != 0);
}

constexpr std::uint64_t kPowersOfTen[20] = {1ULL,
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

// The number of decimal digits of n > 0.
int decimal_length(std::uint64_t n) {
  // bit_width * log10(2), rounded down, is the length or one less.
  const int guess = (std::bit_width(n) * 1233) >> 12;
  return guess + static_cast<int>(n >= kPowersOfTen[guess]);
}

ShortestDecimal without_trailing_zeros(std::uint64_t digits, int exponent) {
  // A shortest decimal from the coarse step (a multiple of 10^(k+1), at most 16 digits) has at
  // most 15 trailing zeros: 8 + 4 + 2 + 1.
  if (digits % 100000000 == 0) {
    digits /= 100000000;
    exponent += 8;
  }
  if (digits % 10000 == 0) {
    digits /= 10000;
    exponent += 4;
  }
  if (digits % 100 == 0) {
    digits /= 100;
    exponent += 2;
  }
  if (digits % 10 == 0) {
    digits /= 10;
    exponent += 1;
  }
  return {digits, exponent, decimal_length(digits)};
}

// The shortest decimal of the double c * 2^q, c in [1, 2^53), q in [-1074, 971] (a positive
// finite double's integer significand and exponent); inlined into the writer.
[[gnu::always_inline]] inline ShortestDecimal decimal_of(std::uint64_t c, int q) {
  // The gap below v is half the gap above only at a power of two that is a normal double
  // (the smallest normal has a subnormal below it at the same spacing).
  const bool regular = c != kHiddenBit || q == -1074;
  const std::uint64_t open = c & 1;  // odd c: the ends round to the neighbours, not to v
  const std::uint64_t cb = c << 2;
  const int k = regular ? floor_log10_pow2(q) : floor_log10_three_quarters_pow2(q);
  // 10^-k = g * 2^(floor_log2_pow10(-k) - 125); the products are taken over 2^128, so the
  // significands are shifted by h (3 to 6: cb << h < 2^61).
  const int h = q + floor_log2_pow10(-k) + 3;
  const Pow10Bits& g = kPow10Table[static_cast<std::size_t>(-k - kPow10MinExponent)];
  // One product: the ends are g * cb * 2^h -+ g * 2 * 2^h (g * 2^h below a power of two).
  const Wide middle = times(g, cb << h);
  const Wide half_width = shifted(g, h + 1);
  const std::uint64_t vb = round_to_odd(middle);
  const std::uint64_t vbl = round_to_odd(minus(middle, regular ? half_width : shifted(g, h)));
  const std::uint64_t vbr = round_to_odd(plus(middle, half_width));

  const std::uint64_t s = vb >> 2;
  // The multiples of 10^(k+1) around v: the interval (narrower than 10^(k+1)) holds at most one.
  // If it holds one, that is the answer (coarse); else s or s + 1 (fine; the interval is at
  // least 10^k wide, so one is in, and neither is a multiple of 10). Both answers are computed
  // and one taken without a branch: the coarse one is the answer for about a third of all
  // doubles, a branch that would often be mispredicted.
  const std::uint64_t s_tenth = s / 10;
  const bool sp10_in = vbl + open <= s_tenth * 40;
  const bool tp10_in = (s_tenth + 1) * 40 + open <= vbr;
  const bool coarse = sp10_in != tp10_in;
  const std::uint64_t coarse_digits = s_tenth + static_cast<std::uint64_t>(!sp10_in);

  const bool s_in = vbl + open <= s << 2;
  const bool t_in = ((s + 1) << 2) + open <= vbr;
  // Both in: the closer to v; on a tie (vb exactly at the midpoint 4s + 2) the even one.
  const std::uint64_t midpoint = (s << 2) + 2;
  const bool s_closer = (vb < midpoint) | ((vb == midpoint) & ((s & 1) == 0));
  const bool take_s = s_in & (!t_in | s_closer);
  const std::uint64_t fine_digits = s + static_cast<std::uint64_t>(!take_s);

  const std::uint64_t digits = coarse ? coarse_digits : fine_digits;
  const int exponent = k + static_cast<int>(coarse);
  // Rare (a coarse answer ending in 0): drop the zeros.
  if (coarse && coarse_digits % 10 == 0) return without_trailing_zeros(coarse_digits, k + 1);
  // A normal double's s is in [2^52, 10 * 2^53): 16 or 17 digits, one fewer for the coarse
  // answer (which is s / 10 or s / 10 + 1, the latter a power of ten only with a zero).
  constexpr std::uint64_t e16 = 10000000000000000;
  const int length = c >= kHiddenBit ? 16 + static_cast<int>(s >= e16) - static_cast<int>(coarse)
                                     : decimal_length(digits);
  return {digits, exponent, length};
}

constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

[[gnu::always_inline]] inline void write_pair(char* at, std::uint32_t pair) {
  std::memcpy(at, kDigitPairs + 2 * pair, 2);
}

// The eight digits of `n` < 10^8 (leading zeros included) as the bytes of a little-endian
// word, first digit lowest: two four-digit halves in 32-bit lanes, each split into pairs in
// 16-bit lanes, each pair into digits in bytes, with multiplications by reciprocals exact for
// those ranges (x * 10486 >> 20 is x / 100 for x < 10^4, x * 103 >> 10 is x / 10 for x < 100).
[[gnu::always_inline]] inline std::uint64_t eight_digit_bytes(std::uint32_t n) {
  const std::uint64_t halves = (n / 10000) | (static_cast<std::uint64_t>(n % 10000) << 32);
  const std::uint64_t hundreds = ((halves * 10486) >> 20) & 0x0000007f0000007fULL;
  const std::uint64_t pairs = hundreds | ((halves - hundreds * 100) << 16);
  const std::uint64_t tens = ((pairs * 103) >> 10) & 0x000f000f000f000fULL;
  const std::uint64_t digits = tens | ((pairs - tens * 10) << 8);
  return digits + 0x3030303030303030ULL;
}

[[gnu::always_inline]] inline void write_eight(char* at, std::uint32_t n) {
  if constexpr (std::endian::native == std::endian::little) {
    const std::uint64_t bytes = eight_digit_bytes(n);
    std::memcpy(at, &bytes, 8);
  } else {
    const std::uint32_t high = n / 10000;
    const std::uint32_t low = n % 10000;
    write_pair(at, high / 100);
    write_pair(at + 2, high % 100);
    write_pair(at + 4, low / 100);
    write_pair(at + 6, low % 100);
  }
}

// The last `length` (1 to 8) digits of `n` < 10^length at `at`, and scratch up to at + 8.
[[gnu::always_inline]] inline void write_up_to_eight(char* at, std::uint32_t n, int length) {
  if constexpr (std::endian::native == std::endian::little) {
    // The leading zeros are the low bytes: shift them out.
    const std::uint64_t bytes = eight_digit_bytes(n) >> (8 * (8 - length));
    std::memcpy(at, &bytes, 8);
  } else {
    std::array<char, 8> all{};
    write_eight(all.data(), n);
    std::memcpy(at, all.data() + 8 - length, static_cast<std::size_t>(length));
  }
}

// The `length` digits of n (its decimal length, at most 20) at `at`, and scratch up to
// at + max(length, 8).
[[gnu::always_inline]] inline void write_digits(char* at, std::uint64_t n, int length) {
  constexpr std::uint64_t e8 = 100000000;
  if (length <= 8) {
    write_up_to_eight(at, static_cast<std::uint32_t>(n), length);
    return;
  }
  // The last 16 digits as two words of eight, the first (one digit for most doubles) apart.
  const std::uint64_t head = n / (e8 * e8);
  const std::uint64_t rest = n % (e8 * e8);
  if (length < 16) {
    // The head is zero: the first word has the leading digits.
    write_up_to_eight(at, static_cast<std::uint32_t>(rest / e8), length - 8);
    write_eight(at + length - 8, static_cast<std::uint32_t>(rest % e8));
    return;
  }
  if (length <= 17) {
    // 16 or 17 digits, about as likely as each other: the head digit (0 for 16 digits) written
    // first and overwritten by the rest when there are 16, without a branch.
    *at = static_cast<char>('0' + head);
    char* rest_at = at + (length - 16);
    write_eight(rest_at, static_cast<std::uint32_t>(rest / e8));
    write_eight(rest_at + 8, static_cast<std::uint32_t>(rest % e8));
    return;
  }
  write_up_to_eight(at, static_cast<std::uint32_t>(head), length - 16);
  write_eight(at + length - 16, static_cast<std::uint32_t>(rest / e8));
  write_eight(at + length - 8, static_cast<std::uint32_t>(rest % e8));
}

char* write_integer(char* at, std::uint64_t n) {
  const int length = n == 0 ? 1 : decimal_length(n);
  write_digits(at, n, length);
  return at + length;
}

// The whole number c * 2^q (q >= -52, v >= 1 and whole) in plain digits: what printf's "%.0f"
// writes, and so libstdc++ for the whole numbers it puts in fixed notation (below 10^23).
char* write_whole(char* at, std::uint64_t c, int q) {
  if (q <= 0) return write_integer(at, c >> -q);
  const UInt128 value = static_cast<UInt128>(c) << q;
  const auto high = static_cast<std::uint64_t>(value / kPowersOfTen[19]);
  const auto low = static_cast<std::uint64_t>(value % kPowersOfTen[19]);
  if (high == 0) return write_integer(at, low);
  at = write_integer(at, high);
  // The 19 digits of `low`, leading zeros included.
  write_eight(at + 11, static_cast<std::uint32_t>(low % 100000000));
  write_eight(at + 3, static_cast<std::uint32_t>(low / 100000000 % 100000000));
  const auto top = static_cast<std::uint32_t>(low / 10000000000000000);
  at[0] = static_cast<char>('0' + top / 100);
  write_pair(at + 1, top % 100);
  return at + 19;
}

char* write_exponent(char* at, int exponent) {
  *at++ = 'e';
  *at++ = exponent < 0 ? '-' : '+';
  const auto magnitude = static_cast<std::uint32_t>(exponent < 0 ? -exponent : exponent);
  if (magnitude >= 100) {
    *at++ = static_cast<char>('0' + magnitude / 100);
    write_pair(at, magnitude % 100);
  } else {
    write_pair(at, magnitude);
  }
  return at + 2;
}

}  // namespace

char* write_shortest_double(char* at, double value) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  const bool negative = (bits >> 63) != 0;
  const auto biased_exponent = static_cast<int>((bits >> 52) & 0x7ff);
  const std::uint64_t fraction = bits & (kHiddenBit - 1);
  if (negative) *at++ = '-';
  if (biased_exponent == 0x7ff) {
    std::memcpy(at, fraction == 0 ? "inf" : "nan", 3);
    return at + 3;
  }
  if (biased_exponent == 0 && fraction == 0) {
    *at = '0';
    return at + 1;
  }
  const std::uint64_t c = biased_exponent == 0 ? fraction : fraction | kHiddenBit;
  const int q = biased_exponent == 0 ? -1074 : biased_exponent - 1075;
  const ShortestDecimal decimal = decimal_of(c, q);
  const int length = decimal.length;
  const int exponent = decimal.exponent;

  // libstdc++'s choice: fixed notation unless scientific is shorter, where scientific writes
  // a point only after a first digit that has others behind it.
  const int lowest_fixed = length == 1 ? -3 : -(length + 3);
  const int highest_fixed = length == 1 ? 4 : 5;
  if (exponent < lowest_fixed || exponent > highest_fixed) {
    // d.ddde+XX: the digits one place right, then the first moved in front of the point.
    write_digits(at + 1, decimal.digits, length);
    at[0] = at[1];
    if (length == 1) return write_exponent(at + 1, exponent);
    at[1] = '.';
    return write_exponent(at + length + 1, exponent + length - 1);
  }
  if (exponent >= 0) {
    // Whole: the digits and zeros while that is below 2^53 (every such whole number is a
    // double and its own shortest form), else the exact value, whose last digits may differ.
    if (length + exponent <= 15) {
      write_digits(at, decimal.digits, length);
      std::memcpy(at + length, "00000000", 8);  // exponent <= 5 of them count
      return at + length + exponent;
    }
    return write_whole(at, c, q);
  }
  const int whole_digits = length + exponent;
  if (whole_digits <= 0) {
    // 0.000ddd: at most 3 zeros after the point (-whole_digits), then the digits over the rest.
    std::memcpy(at, "0.000", 5);
    write_digits(at + 2 - whole_digits, decimal.digits, length);
    return at + 2 - exponent;
  }
  // ddd.ddd: the fraction (at most 16 digits) moved one place right for the point. Fixed-size
  // copies, inlined, where a copy of the exact length would call the C library.
  write_digits(at, decimal.digits, length);
  std::array<char, 16> fraction_digits{};
  std::memcpy(fraction_digits.data(), at + whole_digits, 16);
  std::memcpy(at + whole_digits + 1, fraction_digits.data(), 16);
  at[whole_digits] = '.';
  return at + length + 1;
}

}  // namespace contain::io::detail
