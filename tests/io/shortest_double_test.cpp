// The shortest double writer (src/io/shortest_double.cpp): its table and exponent formulas
// proven exact with GMP, and its text byte for byte std::to_chars(first, last, double)'s on
// random bit patterns and on the classes where a shortest writer goes wrong.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "io/shortest_double.h"
#include "io/shortest_double_table.h"
#include "io/text_scan.h"
#include "support/case_budget.h"

namespace contain::test {
namespace {

using io::detail::write_shortest_double;

std::string standard_text(double value) {
  std::array<char, 64> buffer{};
  return {buffer.data(), std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr};
}

// The writer's text; a failure if it touched a byte past its room (kShortestDoubleRoom).
std::string writer_text(double value) {
  std::array<char, 64> buffer{};
  buffer.fill('#');
  std::string text{buffer.data(), write_shortest_double(buffer.data(), value)};
  for (std::size_t i = io::detail::kShortestDoubleRoom; i < buffer.size(); ++i) {
    if (buffer[i] != '#') {
      ADD_FAILURE() << "wrote past its room at " << i << " for " << text;
      break;
    }
  }
  return text;
}

double from_bits(std::uint64_t bits) {
  return std::bit_cast<double>(bits);
}

// The first few mismatches of a batch, so one failure does not flood the log.
class MismatchLog {
 public:
  void check(double value) {
    ++checked_;
    const std::string expected = standard_text(value);
    const std::string got = writer_text(value);
    if (expected == got) return;
    if (++mismatches_ <= 10) {
      ADD_FAILURE() << "bits 0x" << std::hex << std::bit_cast<std::uint64_t>(value) << std::dec
                    << ": std::to_chars '" << expected << "', writer '" << got << "'";
    }
  }
  // The value, its sign flipped, and `steps` neighbours on each side.
  void check_around(double value, int steps) {
    for (const double sign : {1.0, -1.0}) {
      double below = value;
      double above = value;
      check(sign * value);
      for (int i = 0; i < steps; ++i) {
        below = std::nextafter(below, -std::numeric_limits<double>::infinity());
        above = std::nextafter(above, std::numeric_limits<double>::infinity());
        check(sign * below);
        check(sign * above);
      }
    }
  }
  [[nodiscard]] long mismatches() const { return mismatches_; }
  [[nodiscard]] long checked() const { return checked_; }

 private:
  long mismatches_ = 0;
  long checked_ = 0;
};

double parse(const std::string& text) {
  double value = 0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

// floor(log2(10^e)) from exact integers.
long exact_floor_log2_pow10(int e) {
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), 10, static_cast<unsigned long>(e < 0 ? -e : e));
  const auto bits = static_cast<long>(mpz_sizeinbase(power.get_mpz_t(), 2));
  // 10^n is a power of two only for n = 0.
  return e >= 0 ? bits - 1 : -bits;
}

// floor(log10(x)) of a positive rational near 2^q, by comparison with exact powers of ten.
long exact_floor_log10(const mpq_class& x, int q) {
  long k = static_cast<long>(std::floor(q * std::log10(2.0)));  // within two of the answer
  auto power = [](long n) {
    mpz_class p;
    mpz_ui_pow_ui(p.get_mpz_t(), 10, static_cast<unsigned long>(n < 0 ? -n : n));
    return n >= 0 ? mpq_class(p) : mpq_class(mpz_class(1), p);
  };
  while (power(k) > x)
    --k;
  while (power(k + 1) <= x)
    ++k;
  return k;
}

mpq_class power_of_two(int q) {
  mpz_class p = 1;
  p <<= static_cast<unsigned long>(q < 0 ? -q : q);
  return q >= 0 ? mpq_class(p) : mpq_class(mpz_class(1), p);
}

TEST(ShortestDoubleTable, EveryEntryIsTheFloorOfThePowerOfTenScaledTo126BitsPlusOne) {
  for (int e = io::detail::kPow10MinExponent; e <= io::detail::kPow10MaxExponent; ++e) {
    const long shift = 125 - exact_floor_log2_pow10(e);
    mpz_class ten_power;
    mpz_ui_pow_ui(ten_power.get_mpz_t(), 10, static_cast<unsigned long>(e < 0 ? -e : e));
    mpz_class scaled;
    if (e >= 0) {
      scaled = shift >= 0 ? mpz_class(ten_power << static_cast<unsigned long>(shift))
                          : mpz_class(ten_power >> static_cast<unsigned long>(-shift));
    } else {
      scaled = (mpz_class(1) << static_cast<unsigned long>(shift)) / ten_power;  // floor
    }
    const mpz_class expected = scaled + 1;
    const auto& entry =
        io::detail::kPow10Table[static_cast<std::size_t>(e - io::detail::kPow10MinExponent)];
    mpz_class stored = mpz_class(static_cast<unsigned long>(entry.high));
    stored <<= 64;
    stored += mpz_class(static_cast<unsigned long>(entry.low));
    ASSERT_EQ(stored, expected) << "10^" << e;
    EXPECT_GT(stored, mpz_class(1) << 125) << "10^" << e;
    EXPECT_LT(stored, mpz_class(1) << 126) << "10^" << e;
  }
}

TEST(ShortestDoubleTable, ExponentFormulasAreExactOverEveryBinaryExponentOfADouble) {
  for (int q = -1074; q <= 971; ++q) {
    const mpq_class two_q = power_of_two(q);
    ASSERT_EQ(io::detail::floor_log10_pow2(q), exact_floor_log10(two_q, q)) << q;
    ASSERT_EQ(io::detail::floor_log10_three_quarters_pow2(q),
              exact_floor_log10(mpq_class(3, 4) * two_q, q))
        << q;
    // The table covers every 10^-k the writer asks for, and the shifted significands fit.
    for (const int k :
         {io::detail::floor_log10_pow2(q), io::detail::floor_log10_three_quarters_pow2(q)}) {
      ASSERT_GE(-k, io::detail::kPow10MinExponent) << q;
      ASSERT_LE(-k, io::detail::kPow10MaxExponent) << q;
      const int h = q + io::detail::floor_log2_pow10(-k) + 3;
      ASSERT_GE(h, 3) << q;  // g * 2^(h + 1) and g * 2^h: shifts in [3, 7]
      ASSERT_LE(h, 6) << q;  // (4 * 2^53 + 2) << 6 < 2^64
    }
  }
  for (int e = -330; e <= 330; ++e) {
    ASSERT_EQ(io::detail::floor_log2_pow10(e), exact_floor_log2_pow10(e)) << e;
  }
}

TEST(ShortestDouble, SpecialValuesAsStdToChars) {
  MismatchLog log;
  for (const double value :
       {0.0, -0.0, std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(),
        -std::numeric_limits<double>::quiet_NaN(), from_bits(0x7ff0000000000001ULL),
        from_bits(0xfff8000000000123ULL)}) {
    log.check(value);
  }
  EXPECT_EQ(log.mismatches(), 0);
  EXPECT_EQ(writer_text(-0.0), "-0");
  EXPECT_EQ(writer_text(-std::numeric_limits<double>::infinity()), "-inf");
}

TEST(ShortestDouble, TenMillionRandomBitPatternsAsStdToChars) {
  std::mt19937_64 rng(26);
  MismatchLog log;
  const int count = case_budget(10'000'000, 20);
  for (int i = 0; i < count; ++i)
    log.check(from_bits(rng()));
  EXPECT_EQ(log.mismatches(), 0) << "of " << log.checked();
}

TEST(ShortestDouble, EveryBinaryExponentWithRandomSignificandsAsStdToChars) {
  std::mt19937_64 rng(2026);
  MismatchLog log;
  const int per_exponent = case_budget(1000, 20);
  for (std::uint64_t exponent = 0; exponent < 0x7ff; ++exponent) {
    for (int i = 0; i < per_exponent; ++i) {
      log.check(from_bits((exponent << 52) | (rng() >> 12)));
    }
  }
  EXPECT_EQ(log.mismatches(), 0) << "of " << log.checked();
}

TEST(ShortestDouble, SmallestSubnormalsAndExtremesAsStdToChars) {
  MismatchLog log;
  const int count = case_budget(1 << 20, 20);
  for (int c = 1; c <= count; ++c)
    log.check(from_bits(static_cast<std::uint64_t>(c)));
  for (const double value : {DBL_MIN, std::numeric_limits<double>::denorm_min(), DBL_MAX,
                             std::nextafter(DBL_MIN, 0.0), DBL_EPSILON}) {
    log.check_around(value, 50);
  }
  EXPECT_EQ(log.mismatches(), 0) << "of " << log.checked();
  EXPECT_EQ(writer_text(std::numeric_limits<double>::denorm_min()), "5e-324");
  EXPECT_EQ(writer_text(DBL_MAX), "1.7976931348623157e+308");
  EXPECT_EQ(writer_text(DBL_MIN), "2.2250738585072014e-308");
}

TEST(ShortestDouble, PowersOfTwoAndTheirNeighboursAsStdToChars) {
  // At a power of two the gap below is half the gap above: the interval's irregular case.
  MismatchLog log;
  for (int e = -1074; e <= 1023; ++e)
    log.check_around(std::ldexp(1.0, e), 4);
  EXPECT_EQ(log.mismatches(), 0) << "of " << log.checked();
}

TEST(ShortestDouble, PowersOfTenAndTheirNeighboursAsStdToChars) {
  MismatchLog log;
  for (int e = -324; e <= 308; ++e) {
    for (const char* lead : {"1", "9", "5", "2"}) {
      log.check_around(parse(std::string(lead) + "e" + std::to_string(e)), 4);
    }
  }
  EXPECT_EQ(log.mismatches(), 0) << "of " << log.checked();
}

TEST(ShortestDouble, IntegersUpTo2To53AndAround1e15To1e17AsStdToChars) {
  MismatchLog log;
  const int small = case_budget(1'000'000, 20);
  for (int n = 0; n <= small; ++n)
    log.check(static_cast<double>(n));
  std::mt19937_64 rng(53);
  const int per_width = case_budget(20'000, 20);
  for (int width = 1; width <= 53; ++width) {
    for (int i = 0; i < per_width; ++i) {
      const std::uint64_t n = (rng() >> (64 - width)) | (std::uint64_t{1} << (width - 1));
      log.check(static_cast<double>(n));
    }
  }
  // Whole numbers past 2^53 are written in full in fixed notation up to 22 digits, digits that
  // the shortest decimal does not have.
  for (const double center : {1e15, 1e16, 1e17, 9007199254740992.0, 1e18, 1e19, 1e20, 1e21, 1e22,
                              1e23, 0x1p60, 0x1p64, 0x1p70, 0x1p73, 0x1p76}) {
    log.check_around(center, 2000);
  }
  for (int i = 0; i < per_width * 5; ++i) {
    log.check(std::ldexp(static_cast<double>(rng() >> 11), 1 + static_cast<int>(rng() % 24)));
  }
  EXPECT_EQ(log.mismatches(), 0) << "of " << log.checked();
}

TEST(ShortestDouble, LengthsWhereFixedAndScientificNotationTieAsStdToChars) {
  // d digits at every decimal exponent around the bounds of fixed notation (ties go to fixed),
  // and the doubles beside each.
  std::mt19937_64 rng(5);
  MismatchLog log;
  const int per_case = case_budget(40, 10);
  for (int digits = 1; digits <= 17; ++digits) {
    for (int exponent = -(digits + 6); exponent <= 8; ++exponent) {
      for (int i = 0; i < per_case; ++i) {
        std::string text = std::to_string(1 + rng() % 9);
        for (int j = 1; j < digits; ++j)
          text += static_cast<char>('0' + rng() % 10);
        log.check_around(parse(text + "e" + std::to_string(exponent)), 1);
      }
    }
  }
  EXPECT_EQ(log.mismatches(), 0) << "of " << log.checked();
  EXPECT_EQ(writer_text(1e15), "1e+15");
  EXPECT_EQ(writer_text(123456.0), "123456");
  EXPECT_EQ(writer_text(1200000.0), "1200000");  // 7 characters either way: fixed
  EXPECT_EQ(writer_text(0.001), "0.001");        // 5 characters either way: fixed
  EXPECT_EQ(writer_text(0.0001), "1e-04");
}

TEST(ShortestDouble, ShortestOnlyAtTheClosedEndOfAnEvenSignificandsIntervalAsStdToChars) {
  // A decimal exactly halfway between two doubles reads back as the even one, so that double's
  // shortest form may be the end of its (closed) interval: 5e22 is 5^23 * 2^22, and 5^23 needs
  // 54 bits. The family: midpoints x * 2^p with x an odd multiple of 5^j of 54 bits, which are
  // short decimals (x / 5^j) * 2^(p - j) * 10^j.
  MismatchLog log;
  std::mt19937_64 rng(22);
  for (int j = 0; j <= 23; ++j) {
    mpz_class five_j;
    mpz_ui_pow_ui(five_j.get_mpz_t(), 5, static_cast<unsigned long>(j));
    const double five = five_j.get_d();
    for (int i = 0; i < 200; ++i) {
      // An odd multiple of 5^j in [2^53, 2^54).
      const double low = std::ceil(0x1p53 / five);
      const double high = std::floor(0x1p54 / five);
      if (low > high) break;
      auto m =
          static_cast<std::uint64_t>(low) + rng() % (static_cast<std::uint64_t>(high - low) + 1);
      if (m % 2 == 0) m = m + 1 <= static_cast<std::uint64_t>(high) ? m + 1 : m - 1;
      const mpz_class x = five_j * mpz_class(static_cast<unsigned long>(m));
      for (int p = j - 3; p <= j + 3; ++p) {
        // The midpoint, parsed from its exact decimal, and the doubles on each side.
        mpq_class midpoint = mpq_class(x) * power_of_two(p);
        midpoint.canonicalize();
        std::string text;
        if (p >= 0) {
          text = mpz_class(midpoint.get_num()).get_str();
        } else {
          // x * 2^p = x * 5^-p / 10^-p.
          mpz_class scaled;
          mpz_ui_pow_ui(scaled.get_mpz_t(), 5, static_cast<unsigned long>(-p));
          text = mpz_class(x * scaled).get_str() + "e" + std::to_string(p);
        }
        log.check_around(parse(text), 2);
      }
    }
  }
  EXPECT_EQ(log.mismatches(), 0) << "of " << log.checked();
  EXPECT_EQ(writer_text(5e22), "5e+22");
  EXPECT_EQ(writer_text(9007199254740993.0), "9007199254740992");
}

TEST(ShortestDouble, SumsAndQuotientsOfShortDecimalsAsStdToChars) {
  MismatchLog log;
  for (const double value : {0.1 + 0.2, 0.3, 0.1 * 3, 1.0 / 3, 2.0 / 3, 1.1 * 1.1, 0.7 + 0.1,
                             100.0 / 3, 1e-7 / 3, 123.456, 5e-324 * 3, 1.0 - 1e-16}) {
    log.check_around(value, 3);
  }
  std::mt19937_64 rng(3);
  const int count = case_budget(200'000, 20);
  for (int i = 0; i < count; ++i) {
    const double a = static_cast<double>(rng() % 1000) / 10.0;
    const double b = static_cast<double>(rng() % 1000) / 100.0;
    log.check(a + b);
    log.check(a - b);
    log.check(a * b);
    if (b != 0) log.check(a / b);
  }
  EXPECT_EQ(log.mismatches(), 0) << "of " << log.checked();
  EXPECT_EQ(writer_text(0.1 + 0.2), "0.30000000000000004");
}

TEST(ShortestDouble, CoordinatesInTheUnitRangeAsStdToChars) {
  // The slicer's crossings: doubles of [-1, 1] with every number of leading zeros.
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  MismatchLog log;
  const int count = case_budget(1'000'000, 20);
  for (int i = 0; i < count; ++i) {
    const double x = unit(rng);
    log.check(x);
    log.check(std::ldexp(x, -static_cast<int>(rng() % 40)));
  }
  EXPECT_EQ(log.mismatches(), 0) << "of " << log.checked();
}

TEST(ShortestDouble, WriteDoubleAndAppendDoubleGiveStdToCharsText) {
  std::array<char, io::detail::kMaxDoubleChars> buffer{};
  for (const double value : {-0.0, 0.30000000000000004, 1e15, 0x1p70, -5e-324}) {
    EXPECT_EQ(std::string(buffer.data(), io::detail::write_double(buffer.data(), value)),
              standard_text(value));
    std::string appended = "x";
    io::detail::append_double(appended, value);
    EXPECT_EQ(appended, "x" + standard_text(value));
  }
}

}  // namespace
}  // namespace contain::test
