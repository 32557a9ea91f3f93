// The one big number (contain/predicates/big_float.h) against GMP rationals: exact sums,
// differences and products of doubles of every magnitude, comparison, negation, and the 3D
// helpers used by the CSG analysis and the perturbed ray.

#include "contain/predicates/big_float.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "support/exact.h"

namespace contain::predicates {
namespace {

using test::sign_of;

// Doubles across the whole range: signs, huge, tiny, subnormal, and random mantissas.
std::vector<double> samples() {
  std::vector<double> v = {
      0.0,    1.0,     -1.0,     0.1,     -0.3,          1e308,
      -1e308, DBL_MAX, -DBL_MAX, DBL_MIN, DBL_TRUE_MIN,  -DBL_TRUE_MIN,
      1e-310, 3.0,     0x1p-60,  0x1p60,  1.0 + 0x1p-52, 0x1.fffffffffffffp1000};
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1070, 1020);
  for (int k = 0; k < 24; ++k)
    v.push_back(std::ldexp(mantissa(rng), exponent(rng)));
  return v;
}

mpq_class q(double x) {
  return mpq_class(x);
}

TEST(BigFloat, SumsDifferencesAndProductsOfDoublesHaveTheExactSign) {
  const auto v = samples();
  for (double a : v) {
    for (double b : v) {
      for (double c : v) {
        const BigFloat x = BigFloat(a) * BigFloat(b) - BigFloat(c);
        ASSERT_EQ(x.sign(), sign_of(q(a) * q(b) - q(c))) << a << " " << b << " " << c;
        const BigFloat y = BigFloat(a) + BigFloat(b) - BigFloat(c);
        ASSERT_EQ(y.sign(), sign_of(q(a) + q(b) - q(c))) << a << " " << b << " " << c;
      }
    }
  }
}

// Sums of doubles of every exponent are numbers of up to ~70 limbs, and their products of
// hundreds: beyond the Karatsuba threshold, balanced and unbalanced.
TEST(BigFloat, ProductsOfLongNumbersAreExact) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1070, 1020), terms(1, 40);
  const auto draw = [&](BigFloat& big, mpq_class& exact) {
    big = BigFloat();
    exact = 0;
    for (int k = terms(rng); k > 0; --k) {
      const double d = std::ldexp(mantissa(rng), exponent(rng));
      big = big + BigFloat(d);
      exact += q(d);
    }
  };
  for (int i = 0; i < 300; ++i) {
    BigFloat a, b, c, d;
    mpq_class qa, qb, qc, qd;
    draw(a, qa);
    draw(b, qb);
    draw(c, qc);
    draw(d, qd);
    ASSERT_EQ((a * b - c * d).sign(), sign_of(qa * qb - qc * qd)) << "case " << i;
    ASSERT_EQ(((a * b) * (c * d) - a * (b * (c * d))).sign(), Sign::zero) << "case " << i;
    ASSERT_EQ(((a + b) * (a - b) - (a * a - b * b)).sign(), Sign::zero) << "case " << i;
    ASSERT_EQ(((a * b) * c - (c * d)).sign(), sign_of(qa * qb * qc - qc * qd)) << "case " << i;
  }
}

// Products by short factors (one or two limbs: a double, a bisection point, the origin of a
// Taylor shift) take a one-pass product, and products of short numbers skip the split into runs:
// both against the general product (a factor made long by a far-away term t, so that
// a s + a t - a (s + t) = 0 exercises both paths) and against GMP, with all-ones limbs for the
// longest carries.
TEST(BigFloat, ProductsByShortFactorsEqualTheGeneralProduct) {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-800, 1000), near(-40, 40), terms(1, 40);
  std::uniform_int_distribution<int> tiny(-1070, -900), pick(0, 3);
  const auto any_mantissa = [&] {
    const double m = pick(rng) == 0 ? 0x1.fffffffffffffp-1 : mantissa(rng);
    return pick(rng) == 0 ? -m : m;
  };
  for (int i = 0; i < 2000; ++i) {
    BigFloat a, s;
    mpq_class qa, qs;
    const int ea = exponent(rng);
    for (int k = terms(rng); k > 0; --k) {
      // Terms 53 bits apart at times: runs of all-ones limbs.
      const double d = std::ldexp(any_mantissa(), pick(rng) == 0 ? ea - 53 * k : exponent(rng));
      a = a + BigFloat(d);
      qa += q(d);
    }
    // s: one double (one or two limbs), or up to four within a few limbs of each other.
    const int es = exponent(rng) - 80;  // es + near stays below 1024
    for (int k = pick(rng) + 1; k > 0; --k) {
      const double d = std::ldexp(any_mantissa(), es + near(rng));
      s = s + BigFloat(d);
      qs += q(d);
    }
    const double t = std::ldexp(any_mantissa(), tiny(rng));
    const BigFloat long_factor = s + BigFloat(t);
    ASSERT_EQ((a * s + a * BigFloat(t) - a * long_factor).sign(), Sign::zero) << "case " << i;
    ASSERT_EQ((s * a + BigFloat(t) * a - long_factor * a).sign(), Sign::zero) << "case " << i;
    ASSERT_EQ((a * s - a * long_factor).sign(), sign_of(-qa * q(t))) << "case " << i;
    ASSERT_EQ((s * s * a - s * (s * a)).sign(), Sign::zero) << "case " << i;
    const double c = std::ldexp(mantissa(rng), exponent(rng));
    ASSERT_EQ((a * s - BigFloat(c)).sign(), sign_of(qa * qs - q(c))) << "case " << i;
  }
}

TEST(BigFloat, ComparisonIsExactWhereDoublesWouldRound) {
  const BigFloat one(1.0), tiny(DBL_TRUE_MIN), huge(1e308);
  EXPECT_LT(one, one + tiny);  // 1 + 2^-1074 rounds to 1 in double
  EXPECT_GT(huge + one, huge);
  EXPECT_EQ(huge + one - huge, one);
  EXPECT_EQ(BigFloat(2.0), BigFloat(1.0) + BigFloat(1.0));  // different digits, same value
  EXPECT_LT(-one, BigFloat());
  EXPECT_TRUE((one - one).is_zero());
  EXPECT_EQ((-(one - one)).sign(), Sign::zero);
  EXPECT_EQ((-one).sign(), Sign::negative);
}

TEST(BigFloat, VectorHelpersMatchRationalCrossAndDot) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const Vec3 a{u(rng), u(rng) * 1e200, u(rng) * 1e-200}, b{u(rng), u(rng), u(rng) * 1e-300},
        c{u(rng) * 1e100, u(rng), u(rng)};
    const BigVec3 n = cross(to_big(b) - to_big(a), to_big(c) - to_big(a));
    const auto qa = test::exact(a), qb = test::exact(b), qc = test::exact(c);
    const mpq_class ux = qb.x - qa.x, uy = qb.y - qa.y, uz = qb.z - qa.z;
    const mpq_class wx = qc.x - qa.x, wy = qc.y - qa.y, wz = qc.z - qa.z;
    const mpq_class nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
    ASSERT_EQ(n.x.sign(), sign_of(nx));
    ASSERT_EQ(n.y.sign(), sign_of(ny));
    ASSERT_EQ(n.z.sign(), sign_of(nz));
    ASSERT_EQ(dot(n, to_big(a)).sign(), sign_of(nx * qa.x + ny * qa.y + nz * qa.z));
    ASSERT_EQ((-n).x.sign(), -sign_of(nx));
    ASSERT_TRUE(is_zero(n - n));
  }
}

TEST(BigFloat, ResidueIsTheRationalValueModuloThePrime) {
  // Products of three doubles of every magnitude (numerators of up to 159 bits, denominators
  // powers of two up to 2^3222): num * den^-1 mod p, computed by GMP.
  const std::vector<double> v = samples();
  for (const unsigned long prime : {2147483647UL, 2147483629UL, 3UL, 65537UL}) {
    const mpz_class p(prime);
    for (std::size_t i = 0; i < v.size(); ++i) {
      for (std::size_t j = i; j < v.size(); j += 3) {
        const double z = v[(i + j) % v.size()];
        const BigFloat x = BigFloat(v[i]) * BigFloat(v[j]) * BigFloat(z);
        const mpq_class e = q(v[i]) * q(v[j]) * q(z);
        mpz_class inv;
        ASSERT_NE(mpz_invert(inv.get_mpz_t(), e.get_den_mpz_t(), p.get_mpz_t()), 0);
        mpz_class expected = e.get_num() * inv % p;
        if (expected < 0) expected += p;
        ASSERT_EQ(x.residue(static_cast<std::uint32_t>(prime)), expected.get_ui())
            << v[i] << " " << v[j] << " " << z << " mod " << prime;
      }
    }
  }
}

#ifdef NDEBUG
// Non-finite input breaks the predicates' precondition (debug builds assert); a release build
// must still return rather than loop over the mantissa of frexp(inf).
TEST(BigFloat, InfinityOrNanInAReleaseBuildEndsInsteadOfLooping) {
  EXPECT_TRUE(BigFloat(std::numeric_limits<double>::infinity()).is_zero());
  EXPECT_TRUE(BigFloat(std::numeric_limits<double>::quiet_NaN()).is_zero());
  const double inf = std::numeric_limits<double>::infinity();
  (void)orient2d(Vec2{inf, 0}, Vec2{1, 0}, Vec2{0, 1});
  (void)orient3d(Vec3{inf, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1});
}
#endif

}  // namespace
}  // namespace contain::predicates
