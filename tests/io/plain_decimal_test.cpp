// The fast way of reading plain decimals (src/io/plain_decimal.h) against std::from_chars, which
// it stands in for: where it takes a number it must stop where from_chars stops and give the
// same double bit for bit; everything else it must decline without consuming anything.

#include "io/plain_decimal.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace contain::io {
namespace {

// Room after the number: parse_plain_decimal reads up to kPlainDecimalReach bytes ahead.
const std::string kPlainPadding = " 1 2 3 4 5 6 7 8 9 0 1 2 3 4 5 6 7 8 9 0 1 2 3 4 5 6";

enum class PlainOutcome : std::uint8_t { declined, agreed, disagreed };

// Parses `number` (followed by a blank and more numbers) both ways.
PlainOutcome plain_compare(const std::string& number, std::string* why = nullptr) {
  const std::string text = number + kPlainPadding;
  const char* const end = text.data() + text.size();
  double expected = 0;
  const auto [stop, ec] = std::from_chars(text.data(), end, expected);
  const char* p = text.data();
  double value = 0;
  if (!detail::parse_plain_decimal(p, value)) {
    return p == text.data() ? PlainOutcome::declined : PlainOutcome::disagreed;
  }
  if (ec == std::errc{} && p == stop &&
      std::bit_cast<std::uint64_t>(value) == std::bit_cast<std::uint64_t>(expected)) {
    return PlainOutcome::agreed;
  }
  if (why != nullptr) {
    char line[160];
    std::snprintf(line, sizeof line, "'%s': %.17g after %td bytes, from_chars %.17g after %td",
                  number.c_str(), value, p - text.data(), expected, stop - text.data());
    *why = line;
  }
  return PlainOutcome::disagreed;
}

// Every number of `numbers` agrees or is declined; returns how many were taken.
std::size_t expect_plain_agreement(const std::vector<std::string>& numbers) {
  std::size_t taken = 0;
  for (const std::string& number : numbers) {
    std::string why;
    const PlainOutcome outcome = plain_compare(number, &why);
    EXPECT_NE(outcome, PlainOutcome::disagreed) << why;
    if (outcome == PlainOutcome::disagreed) break;
    taken += outcome == PlainOutcome::agreed ? 1 : 0;
  }
  return taken;
}

std::string shortest_text(double value) {
  char text[64];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return {text, end};
}

std::string fixed_text(double value, int digits) {
  char text[96];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

TEST(PlainDecimal, RandomCoordinatesInShortestAndFixedFormsReadAsFromCharsReadsThem) {
  std::mt19937_64 rng(27);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::string> numbers;
  for (int i = 0; i < 200000; ++i) {
    const double scale = std::pow(10.0, static_cast<double>(rng() % 14) - 6.0);
    const double value = unit(rng) * scale;
    numbers.push_back(shortest_text(value));
    numbers.push_back(fixed_text(value, 1 + static_cast<int>(rng() % 19)));
  }
  const std::size_t taken = expect_plain_agreement(numbers);
  // Most of them are plain decimals of at most 19 digits: the fast way was taken, not skipped.
  EXPECT_GT(taken, numbers.size() / 2);
}

TEST(PlainDecimal, RandomDigitStringsOfEveryLengthReadAsFromCharsReadsThem) {
  std::mt19937_64 rng(2027);
  std::vector<std::string> numbers;
  for (int i = 0; i < 300000; ++i) {
    std::string number = rng() % 2 == 0 ? "-" : "";
    const int integer_digits = 1 + static_cast<int>(rng() % 9);
    for (int k = 0; k < integer_digits; ++k)
      number += static_cast<char>('0' + rng() % 10);
    if (rng() % 8 != 0) {
      number += '.';
      const int fraction_digits = static_cast<int>(rng() % 24);
      // Runs of 9s and 0s as well as random digits: carries and leading zeros.
      const int style = static_cast<int>(rng() % 3);
      for (int k = 0; k < fraction_digits; ++k) {
        number += style == 0   ? static_cast<char>('0' + rng() % 10)
                  : style == 1 ? (rng() % 4 == 0 ? '0' : '9')
                               : (rng() % 4 == 0 ? '1' : '0');
      }
    }
    numbers.push_back(number);
  }
  EXPECT_GT(expect_plain_agreement(numbers), numbers.size() / 4);
}

TEST(PlainDecimal, NeighboursOfPowersOfTwoReadAsFromCharsReadsThem) {
  // Below a power of two the ulp halves: the proof must not round across the binade's end.
  std::vector<std::string> numbers;
  for (int e = -12; e <= 24; ++e) {
    double value = std::ldexp(1.0, e);
    for (int k = 0; k < 30; ++k)
      value = std::nextafter(value, 0.0);
    for (int k = 0; k < 60; ++k) {
      numbers.push_back(shortest_text(value));
      for (int digits = 14; digits <= 19; ++digits)
        numbers.push_back(fixed_text(value, digits));
      value = std::nextafter(value, 1e300);
    }
  }
  EXPECT_GT(expect_plain_agreement(numbers), numbers.size() / 4);
}

TEST(PlainDecimal, SignificandsAround2To53ReadAsFromCharsReadsThem) {
  // Up to 2^53 the division is exact; above it the integer proof decides.
  std::vector<std::string> numbers;
  for (int point = 1; point <= 7; ++point) {
    for (int delta = -500; delta <= 500; ++delta) {
      const std::string digits = std::to_string((std::uint64_t{1} << 53) + delta);
      numbers.push_back(digits.substr(0, point) + "." + digits.substr(point));
      numbers.push_back("-" + numbers.back());
    }
  }
  EXPECT_EQ(expect_plain_agreement(numbers), numbers.size());
}

TEST(PlainDecimal, DeclinesExponentsLongNumbersAndOtherTextWithoutConsuming) {
  for (const std::string number : {"1e5",
                                   "1.5e-3",
                                   "2.5E+7",
                                   "0.5e",
                                   "12345678.5",
                                   "1.2345678901234567890",
                                   "5",
                                   "-7",
                                   "5.",
                                   ".5",
                                   "-.5",
                                   "+1.5",
                                   "--1.5",
                                   "nan",
                                   "inf",
                                   "-infinity",
                                   "0x1.8p1",
                                   "1.x",
                                   "",
                                   "-",
                                   "x1.5",
                                   " 1.5",
                                   "0.00000000000000000001"}) {
    EXPECT_EQ(plain_compare(number), PlainOutcome::declined) << "'" << number << "'";
  }
}

TEST(PlainDecimal, StopsWhereFromCharsStopsBeforeGluedText) {
  // What follows the number is the caller's: from_chars stops at the same byte.
  EXPECT_EQ(expect_plain_agreement({"1.5x", "1.5.3", "1.5,2", "0.25#c", "3.75\r", "2.5\t", "-0.0",
                                    "0.0", "9999999.999999999999", "1.100000000000000001"}),
            10U);
  // Just above 1, rounding to 1: correct, but a power of two, whose lower ulp is half the upper;
  // declined (from_chars reads it), never misread.
  EXPECT_EQ(plain_compare("1.000000000000000001"), PlainOutcome::declined);
  const std::string text = "-0.0" + kPlainPadding;
  const char* p = text.data();
  double value = 1;
  ASSERT_TRUE(detail::parse_plain_decimal(p, value));
  EXPECT_TRUE(std::signbit(value));
}

}  // namespace
}  // namespace contain::io
