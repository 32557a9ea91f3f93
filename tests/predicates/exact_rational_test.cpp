// Decimal rationals to doubles (exact_rational.h) against GMP: every double written as an exact
// fraction (scaled by random common factors) reads back as itself; fractions that are not
// doubles (a third, one ulp and a half, beyond DBL_MAX, below the smallest subnormal) give
// nothing; malformed strings and zero denominators give nothing.

#include "contain/predicates/exact_rational.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <string>

#include "predicates/cases.h"
#include "support/exact.h"

namespace contain::predicates {
namespace {

std::optional<double> read(const mpq_class& r, const mpz_class& factor = 1) {
  const mpz_class num = r.get_num() * factor, den = r.get_den() * factor;
  return rational_to_double(num.get_str(), den.get_str());
}

TEST(ExactRational, EveryDoubleReadsBackAsItself) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < test::cases(4000); ++i) {
    const double m = std::uniform_real_distribution<double>(-1, 1)(rng);
    const double d = std::ldexp(m, std::uniform_int_distribution<int>(-1080, 1024)(rng));
    if (!std::isfinite(d)) continue;
    const mpz_class factor = std::uniform_int_distribution<int>(1, 1000)(rng);
    ASSERT_EQ(read(mpq_class(d), factor), d) << std::hexfloat << d;
  }
}

TEST(ExactRational, ExtremeDoublesReadBack) {
  for (const double d : {0.0, 1.0, -1.0, DBL_MAX, -DBL_MAX, DBL_MIN, DBL_TRUE_MIN, -DBL_TRUE_MIN,
                         std::nextafter(1.0, 2.0), std::nextafter(DBL_MIN, 0.0), 0.5, 3.0}) {
    EXPECT_EQ(read(mpq_class(d)), d) << std::hexfloat << d;
    EXPECT_EQ(read(mpq_class(d), mpz_class(7)), d) << std::hexfloat << d;
  }
  EXPECT_EQ(rational_to_double("-0", "5"), 0.0);
  EXPECT_EQ(rational_to_double("+6", "-4"), -1.5);
}

TEST(ExactRational, FractionsThatAreNotDoublesGiveNothing) {
  EXPECT_FALSE(rational_to_double("1", "3").has_value());
  const mpq_class one(1.0), ulp(std::ldexp(1.0, -52));
  EXPECT_FALSE(read(one + ulp / 2).has_value()) << "halfway between 1 and the next double";
  EXPECT_FALSE(read(mpq_class(DBL_MAX) * 2).has_value()) << "beyond DBL_MAX";
  EXPECT_FALSE(read(mpq_class(DBL_TRUE_MIN) / 2).has_value()) << "below the smallest subnormal";
  EXPECT_FALSE(read(mpq_class(DBL_TRUE_MIN) * 3 / 2).has_value());
  std::mt19937_64 rng(2);
  for (int i = 0; i < test::cases(500); ++i) {
    // d + ulp(d) / 3: strictly between two doubles.
    const double d = std::ldexp(std::uniform_real_distribution<double>(0.5, 1)(rng),
                                std::uniform_int_distribution<int>(-1000, 1000)(rng));
    const mpq_class between =
        mpq_class(d) + (mpq_class(std::nextafter(d, 2 * d)) - mpq_class(d)) / 3;
    ASSERT_FALSE(read(between).has_value()) << std::hexfloat << d;
  }
}

TEST(ExactRational, MalformedInputGivesNothing) {
  EXPECT_FALSE(rational_to_double("1", "0").has_value());
  EXPECT_FALSE(rational_to_double("", "1").has_value());
  EXPECT_FALSE(rational_to_double("1.5", "1").has_value());
  EXPECT_FALSE(rational_to_double("1e3", "1").has_value());
  EXPECT_FALSE(rational_to_double("12a", "1").has_value());
  EXPECT_FALSE(rational_to_double("-", "1").has_value());
  EXPECT_FALSE(rational_to_double("1", " 2").has_value());
}

}  // namespace
}  // namespace contain::predicates
