// BigFloat products of numbers that are mostly zero limbs (sums of doubles of far apart
// magnitudes, as the hostile continuous-collision queries of issue 24 give), which are
// multiplied run of nonzero limbs by run: gaps of zero limbs just below, at and above the
// length that splits a run (3 limbs), runs at either end and runs past the Karatsuba threshold,
// against GMP and against the sum of the limb-by-limb products.

#include "contain/predicates/big_float.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "support/exact.h"

namespace contain::predicates {
namespace {

// A number given by its limbs (32 bits each, least significant first), both as a BigFloat and
// as a GMP rational, and the BigFloat of each nonzero limb alone.
struct Limbed {
  BigFloat big;
  mpq_class exact;
  std::vector<BigFloat> terms;
};

Limbed from_limbs(const std::vector<std::uint32_t>& limbs, int shift) {
  Limbed n;
  for (std::size_t i = 0; i < limbs.size(); ++i) {
    if (limbs[i] == 0) continue;
    const auto at = static_cast<std::int64_t>(32 * i) + shift;
    const BigFloat term = BigFloat(static_cast<double>(limbs[i])).scaled(at);
    n.big = n.big + term;
    n.terms.push_back(term);
    mpq_class v(static_cast<unsigned long>(limbs[i]));
    if (at >= 0) {
      mpq_mul_2exp(v.get_mpq_t(), v.get_mpq_t(), static_cast<mp_bitcnt_t>(at));
    } else {
      mpq_div_2exp(v.get_mpq_t(), v.get_mpq_t(), static_cast<mp_bitcnt_t>(-at));
    }
    n.exact += v;
  }
  return n;
}

// Runs of random nonzero limbs (lengths up to `longest`) separated by gaps of `gap` zero limbs
// (0 to 5: a gap below 3 keeps the runs together).
std::vector<std::uint32_t> runs(std::mt19937_64& rng, int count, int longest, int gap) {
  std::uniform_int_distribution<std::uint32_t> limb(1, 0xffffffffU);
  std::uniform_int_distribution<int> length(1, longest);
  std::vector<std::uint32_t> out;
  for (int r = 0; r < count; ++r) {
    if (r > 0) out.insert(out.end(), static_cast<std::size_t>(gap), 0U);
    for (int k = length(rng); k > 0; --k)
      out.push_back(limb(rng));
  }
  return out;
}

TEST(BigFloatRuns, ProductsAcrossGapsOfZeroLimbsAreExact) {
  std::mt19937_64 rng(24);
  std::uniform_int_distribution<int> shift(-2000, 2000), count(1, 5), gap(0, 5);
  for (int i = 0; i < 600; ++i) {
    // Long runs (up to 130 limbs) in one case of six: past the Karatsuba threshold.
    const int longest = i % 6 == 0 ? 130 : 4;
    const Limbed a = from_limbs(runs(rng, count(rng), longest, gap(rng)), shift(rng));
    const Limbed b = from_limbs(runs(rng, count(rng), longest, gap(rng)), shift(rng));
    const BigFloat product = a.big * b.big;
    if (a.terms.size() * b.terms.size() <= 400) {  // the long runs against GMP only
      BigFloat by_terms;
      for (const BigFloat& x : a.terms) {
        for (const BigFloat& y : b.terms)
          by_terms = by_terms + x * y;
      }
      ASSERT_TRUE((product - by_terms).is_zero()) << "case " << i;
    }
    const Limbed c = from_limbs(runs(rng, count(rng), longest, gap(rng)), shift(rng));
    ASSERT_EQ((product - c.big).sign(), test::sign_of(a.exact * b.exact - c.exact)) << "case " << i;
    ASSERT_EQ((product * c.big - a.big * (b.big * c.big)).sign(), Sign::zero) << "case " << i;
  }
}

TEST(BigFloatRuns, SumsOfFarApartDoublesMultiplyExactly) {
  // 1e300 + 1e-300 spans 2000 bits with two nonzero stretches; products of three such sums
  // against GMP, signs of differences that cancel all but the smallest terms.
  std::mt19937_64 rng(25);
  std::uniform_real_distribution<double> mantissa(1.0, 10.0);
  for (int i = 0; i < 300; ++i) {
    BigFloat big[3];
    mpq_class exact[3];
    for (int k = 0; k < 3; ++k) {
      const double hi = mantissa(rng) * 1e299, lo = mantissa(rng) * 1e-301, one = mantissa(rng);
      big[k] = BigFloat(hi) + BigFloat(lo) + BigFloat(one);
      exact[k] = mpq_class(hi) + mpq_class(lo) + mpq_class(one);
    }
    const BigFloat p = big[0] * big[1] * big[2];
    const mpq_class e = exact[0] * exact[1] * exact[2];
    ASSERT_EQ((p - big[0] * (big[1] * big[2])).sign(), Sign::zero);
    const double nudge = std::ldexp(1.0, -1074);
    ASSERT_EQ((p - big[2] * big[1] * big[0] - BigFloat(nudge)).sign(), Sign::negative);
    ASSERT_EQ((p - big[0] * big[0]).sign(), test::sign_of(e - exact[0] * exact[0]));
  }
}

}  // namespace
}  // namespace contain::predicates
