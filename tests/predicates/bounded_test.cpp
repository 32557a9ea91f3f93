// Running error bounds (bounded.h) against GMP rationals: on random expressions, exact zeros,
// underflowing and overflowing products, in double and in long double, the exact value always
// lies within value +- error, and a certified sign is the exact sign.

#include "contain/predicates/bounded.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

#include "predicates/cases.h"
#include "support/exact.h"

namespace contain::predicates {
namespace {

// x as an exact rational: x = m 2^e with m an integer of at most 64 bits (finite x).
mpq_class exact_of(long double x) {
  int e = 0;
  const long double f = std::frexp(x, &e);  // |f| in [0.5, 1), 64 significant bits
  const auto m = static_cast<long long>(std::ldexp(f, 62));
  const long double rest = std::ldexp(f, 62) - static_cast<long double>(m);  // the last 2 bits
  mpq_class q = mpq_class(mpz_class(static_cast<long>(m))) + mpq_class(static_cast<double>(rest));
  e -= 62;
  if (e >= 0) {
    mpz_mul_2exp(q.get_num_mpz_t(), q.get_num_mpz_t(), static_cast<unsigned long>(e));
  } else {
    mpz_mul_2exp(q.get_den_mpz_t(), q.get_den_mpz_t(), static_cast<unsigned long>(-e));
  }
  q.canonicalize();
  return q;
}

// The exact value lies in [value - error, value + error] (infinite bounds hold vacuously).
template <class F>
void expect_encloses(const BasicBounded<F>& b, const mpq_class& exact) {
  if (!std::isfinite(b.value) || !std::isfinite(b.error)) return;
  const mpq_class distance = abs(exact - exact_of(b.value));
  EXPECT_LE(cmp(distance, exact_of(b.error)), 0)
      << "value " << static_cast<double>(b.value) << " error " << static_cast<double>(b.error);
  if (const std::optional<Sign> s = certified_sign(b)) {
    EXPECT_EQ(*s, test::sign_of(exact));
  }
}

struct Pair {
  mpq_class exact;
  Bounded d;
  BasicBounded<long double> l;
};

Pair leaf(double x) {
  return {mpq_class(x), Bounded(x), BasicBounded<long double>(x)};
}

// A random expression tree over leaves drawn by `draw`, both evaluations side by side.
template <class Draw>
Pair expression(std::mt19937_64& rng, int depth, Draw& draw) {
  if (depth == 0) return leaf(draw());
  const Pair a = expression(rng, depth - 1, draw);
  const Pair b = expression(rng, depth - 1, draw);
  switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
    case 0:
      return {a.exact + b.exact, a.d + b.d, a.l + b.l};
    case 1:
      return {a.exact - b.exact, a.d - b.d, a.l - b.l};
    default:
      return {a.exact * b.exact, a.d * b.d, a.l * b.l};
  }
}

template <class Draw>
void check_random_expressions(unsigned seed, Draw draw) {
  std::mt19937_64 rng(seed);
  for (int i = 0; i < test::cases(3000); ++i) {
    const int depth = std::uniform_int_distribution<int>(1, 4)(rng);
    const auto leaf_draw = [&] { return draw(rng); };
    const Pair p = expression(rng, depth, leaf_draw);
    expect_encloses(p.d, p.exact);
    expect_encloses(p.l, p.exact);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(Bounded, RandomExpressionsEncloseTheExactValue) {
  check_random_expressions(
      1, [](std::mt19937_64& rng) { return std::uniform_real_distribution<double>(-1, 1)(rng); });
}

TEST(Bounded, HugeAndTinyExponentsEncloseTheExactValue) {
  check_random_expressions(2, [](std::mt19937_64& rng) {
    const double m = std::uniform_real_distribution<double>(-1, 1)(rng);
    return std::ldexp(m, std::uniform_int_distribution<int>(-1074, 1000)(rng));
  });
}

TEST(Bounded, SmallIntegersGiveExactZerosWithoutError) {
  // Cancelling sums of small integers are exact: error 0, so the zero is certified.
  check_random_expressions(3, [](std::mt19937_64& rng) {
    return static_cast<double>(std::uniform_int_distribution<int>(-2, 2)(rng));
  });
  const Bounded x(0.1), y(0.3);
  const Bounded zero = x * y - x * y;
  EXPECT_EQ(zero.value, 0.0);
  EXPECT_GT(zero.error, 0.0) << "rounded products are not exact";
  EXPECT_FALSE(certified_sign(zero).has_value());
  const Bounded exact_zero = (Bounded(3.0) - Bounded(3.0)) * x;
  EXPECT_EQ(exact_zero.error, 0.0);
  EXPECT_EQ(certified_sign(exact_zero), Sign::zero);
}

TEST(Bounded, UnderflowingProductsStayEnclosed) {
  const Bounded a(0x1p-600), b(0x1.8p-600);
  const Bounded p = a * b;  // 1.5 * 2^-1200: underflows to 0
  EXPECT_EQ(p.value, 0.0);
  expect_encloses(p, mpq_class(0x1p-600) * mpq_class(0x1.8p-600));
  EXPECT_FALSE(certified_sign(p).has_value()) << "the sign of an underflowed product is unknown";
  // In long double the same product is exact enough to certify.
  const BasicBounded<long double> q =
      BasicBounded<long double>(0x1p-600) * BasicBounded<long double>(0x1.8p-600);
  EXPECT_EQ(certified_sign(q), Sign::positive);
}

TEST(Bounded, OverflowCertifiesNoSign) {
  const Bounded big(DBL_MAX);
  EXPECT_FALSE(certified_sign(big * big).has_value());
  EXPECT_FALSE(certified_sign(big + big).has_value());
  EXPECT_FALSE(certified_sign(big * big - big * big).has_value());
  const BasicBounded<long double> wide =
      BasicBounded<long double>(DBL_MAX) * BasicBounded<long double>(DBL_MAX);
  EXPECT_EQ(certified_sign(wide), Sign::positive) << "long double holds DBL_MAX squared";
}

}  // namespace
}  // namespace contain::predicates
