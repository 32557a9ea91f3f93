// The exact polynomial facility against GMP rationals (tests/support/exact_polynomial.h): signs
// at doubles, root isolation, signs of other polynomials at roots (Tarski queries against the
// oracle's refinement) and rounding of roots to doubles, on random polynomials, planted roots
// (doubles, multiple roots, roots one ulp apart, roots closer than a double apart, roots at the
// interval's ends), quadratics with nearly double roots and mixed magnitudes.

#include "contain/predicates/polynomial.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <optional>
#include <random>
#include <thread>
#include <vector>

#include "contain/predicates/big_float.h"
#include "support/case_budget.h"
#include "support/exact_polynomial.h"

namespace contain::predicates {
namespace {

using test::operator+;
using test::operator-;
using test::operator*;

// A polynomial built by the library and the same one built by the oracle.
struct Both {
  Polynomial p;
  test::QPoly q;
};

Both constant(double c) {
  return {Polynomial::constant(c), test::QPoly{mpq_class(c)}};
}
Both variable() {
  return {Polynomial::linear(0.0, 1.0), test::QPoly{mpq_class(0), mpq_class(1)}};
}
Both operator+(const Both& a, const Both& b) {
  return {a.p + b.p, a.q + b.q};
}
Both operator-(const Both& a, const Both& b) {
  return {a.p - b.p, a.q - b.q};
}
Both operator*(const Both& a, const Both& b) {
  return {a.p * b.p, a.q * b.q};
}
// (t - r), r a double.
Both factor(double r) {
  return variable() - constant(r);
}

class Random {
 public:
  explicit Random(unsigned seed) : rng_(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  double any_magnitude() {
    const double m = uniform(-1.0, 1.0);
    return std::ldexp(m, integer(-60, 60));
  }

 private:
  std::mt19937_64 rng_;
};

// Compares every root in [lo, hi], the signs of `others` at them and their rounding.
void check(const Both& p, double lo, double hi, const std::vector<Both>& others) {
  const std::vector<RealRoot> roots = real_roots(p.p, lo, hi);
  const std::vector<test::QRoot> expected = test::isolate_roots(p.q, lo, hi);
  ASSERT_EQ(roots.size(), expected.size());
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const RealRoot& r = roots[i];
    const test::QRoot& e = expected[i];
    // The library's root is the oracle's: its bracket holds that root and no other.
    ASSERT_LE(test::compare(mpq_class(r.lower()), e), 0);
    ASSERT_GE(test::compare(mpq_class(r.upper()), e), 0);
    EXPECT_EQ(r.is_double(), r.lower() == r.upper());
    const double floor = floor_to_double(r);
    EXPECT_EQ(floor, test::floor_to_double(e));
    const double ceil = ceil_to_double(r);
    EXPECT_GE(test::compare(mpq_class(ceil), e), 0);
    EXPECT_TRUE(ceil == floor || ceil == std::nextafter(floor, INFINITY));
    for (const Both& o : others)
      EXPECT_EQ(sign_at(o.p, r), test::sign_at(o.q, e));
  }
}

TEST(Polynomial, SignAtDoublesEqualsRationalEvaluation) {
  Random rnd(1);
  for (int i = 0; i < test::case_budget(20000, 10); ++i) {
    Both p = constant(rnd.any_magnitude());
    const int degree = rnd.integer(0, 6);
    for (int k = 0; k < degree; ++k)
      p = p * (variable() * constant(rnd.any_magnitude()) + constant(rnd.any_magnitude()));
    const double t = rnd.integer(0, 3) == 0 ? rnd.any_magnitude() : rnd.uniform(-2, 2);
    ASSERT_EQ(p.p.sign_at(t), test::sign_at(p.q, mpq_class(t)));
    EXPECT_EQ(p.p.degree(), test::degree(p.q));
  }
}

TEST(Polynomial, LinearIsTheExactStraightPath) {
  const Polynomial p = Polynomial::linear(1e300, -1e-300);
  EXPECT_EQ(p.sign_at(0.0), Sign::positive);
  EXPECT_EQ(p.sign_at(1.0), Sign::negative);
  EXPECT_EQ(Polynomial::linear(3.0, 3.0).degree(), 0);
  EXPECT_TRUE(Polynomial::linear(0.0, 0.0).is_zero());
  EXPECT_EQ(Polynomial::linear(0.1, 0.3).derivative().coefficient_sign(0), Sign::positive);
}

TEST(Polynomial, PlantedDoubleRootsAreExactAndRoundToThemselves) {
  const Both p = factor(0.25) * factor(0.5) * factor(std::nextafter(0.5, 1.0));
  const std::vector<RealRoot> roots = real_roots(p.p, 0.0, 1.0);
  ASSERT_EQ(roots.size(), 3U);
  EXPECT_EQ(floor_to_double(roots[0]), 0.25);
  EXPECT_EQ(floor_to_double(roots[1]), 0.5);
  EXPECT_EQ(floor_to_double(roots[2]), std::nextafter(0.5, 1.0));
  EXPECT_EQ(ceil_to_double(roots[2]), std::nextafter(0.5, 1.0));
  check(p, 0.0, 1.0, {factor(0.5), factor(0.3), constant(-1)});
}

TEST(Polynomial, MultipleRootsAreReportedOnce) {
  const Both p = factor(0.3) * factor(0.3) * factor(0.3) * factor(0.7) * factor(0.7);
  const std::vector<RealRoot> roots = real_roots(p.p, 0.0, 1.0);
  ASSERT_EQ(roots.size(), 2U);
  check(p, 0.0, 1.0, {factor(0.3), factor(0.7), p, factor(0.5)});
}

TEST(Polynomial, RootsAtTheEndsOfTheIntervalAreExact) {
  const Both p = factor(0.0) * factor(1.0) * factor(0.5);
  const std::vector<RealRoot> roots = real_roots(p.p, 0.0, 1.0);
  ASSERT_EQ(roots.size(), 3U);
  EXPECT_TRUE(roots[0].is_double());
  EXPECT_EQ(roots[0].lower(), 0.0);
  EXPECT_TRUE(roots[2].is_double());
  EXPECT_EQ(roots[2].lower(), 1.0);
  check(p, 0.0, 1.0, {factor(0.0), factor(1.0), factor(0.5)});
  // The interval [x, x].
  EXPECT_EQ(real_roots(factor(0.5).p, 0.5, 0.5).size(), 1U);
  EXPECT_EQ(real_roots(factor(0.5).p, 0.25, 0.25).size(), 0U);
}

TEST(Polynomial, RootsCloserThanADoubleApartAreSeparatedOnDyadicNumbers) {
  // 3t - 3d and 3t - 3d - ulp: roots d and d + ulp/3, both in [d, next(d)).
  const double d = 0.4;
  const double ulp = std::nextafter(d, 1.0) - d;
  const Both a = constant(3) * variable() - constant(3) * constant(d);
  const Both b = a - constant(ulp);
  const Both c = a - constant(2 * ulp);  // d + 2 ulp / 3
  const Both p = a * b * c;
  const std::vector<RealRoot> roots = real_roots(p.p, 0.0, 1.0);
  ASSERT_EQ(roots.size(), 3U);
  EXPECT_EQ(floor_to_double(roots[0]), d);
  EXPECT_EQ(floor_to_double(roots[1]), d);
  EXPECT_EQ(floor_to_double(roots[2]), d);
  EXPECT_EQ(ceil_to_double(roots[1]), std::nextafter(d, 1.0));
  check(p, 0.0, 1.0, {a, b, c, a * c, constant(1)});
}

TEST(Polynomial, RandomPolynomialsAgreeWithTheOracle) {
  Random rnd(2);
  for (int i = 0; i < test::case_budget(800, 10); ++i) {
    const int degree = rnd.integer(1, 4);
    Both p = constant(rnd.uniform(-1, 1));
    for (int k = 0; k < degree; ++k) {
      // Factors with a root in [0, 1] half of the time.
      if (rnd.integer(0, 1) == 0) {
        p = p * factor(rnd.uniform(-0.2, 1.2));
      } else {
        p = p * (variable() * constant(rnd.uniform(-1, 1)) + constant(rnd.uniform(-1, 1)));
      }
    }
    std::vector<Both> others;
    for (int k = 0; k < 3; ++k) {
      Both o = constant(rnd.uniform(-1, 1));
      for (int j = rnd.integer(0, 3); j > 0; --j)
        o = o * (variable() * constant(rnd.uniform(-1, 1)) + constant(rnd.uniform(-1, 1)));
      others.push_back(o);
    }
    others.push_back(p.p.derivative().is_zero() ? constant(1)
                                                : Both{p.p.derivative(), test::derivative(p.q)});
    check(p, 0.0, 1.0, others);
    if (HasFailure()) return;
  }
}

TEST(Polynomial, SharedAndNearlySharedRootsAgreeWithTheOracle) {
  Random rnd(3);
  for (int i = 0; i < test::case_budget(1000, 10); ++i) {
    const double r = rnd.uniform(0.0, 1.0);
    const double s = rnd.uniform(0.0, 1.0);
    const int ulps = rnd.integer(-3, 3);
    double r2 = r;
    for (int k = 0; k < std::abs(ulps); ++k)
      r2 = std::nextafter(r2, ulps > 0 ? 2.0 : -1.0);
    const Both quad = (variable() - constant(r)) * (variable() - constant(s)) +
                      constant(rnd.integer(0, 2) == 0 ? 0.0 : std::ldexp(rnd.uniform(-1, 1), -60));
    const Both p = quad * factor(rnd.uniform(0, 1));
    check(p, 0.0, 1.0, {factor(r), factor(r2), factor(s) * factor(r2), quad});
    if (HasFailure()) return;
  }
}

TEST(Polynomial, MixedMagnitudeCoefficientsAgreeWithTheOracle) {
  Random rnd(4);
  for (int i = 0; i < test::case_budget(250, 10); ++i) {
    Both p = constant(std::ldexp(1.0, rnd.integer(-1000, 1000)));
    for (int k = rnd.integer(1, 4); k > 0; --k)
      p = p * (variable() * constant(rnd.any_magnitude()) + constant(rnd.any_magnitude()));
    const double lo = -std::ldexp(1.0, rnd.integer(-70, 70));
    const double hi = std::ldexp(1.0, rnd.integer(-70, 70));
    check(p, lo, hi, {factor(0.0), constant(std::ldexp(-1.0, rnd.integer(-1000, 1000)))});
    if (HasFailure()) return;
  }
}

TEST(Polynomial, RootsHuggingAnEndFarBelowADoubleApartAgreeWithTheOracle) {
  // Roots 1 - 2^-k / m and 2^-k / m (k up to 1000: no double between them and the end), two or
  // three of them within 2^-900 of each other, shared or nearly shared with the polynomials
  // whose signs are asked: the clusters of hostile continuous-collision queries (1e300 next to
  // 1e-300), which the filters separate in frames moved onto them.
  Random rnd(6);
  const auto near_end = [](bool high, int k, double m) {
    return high ? constant(m) * (variable() - constant(1.0)) + constant(std::ldexp(1.0, -k))
                : constant(m) * variable() - constant(std::ldexp(1.0, -k));
  };
  for (int i = 0; i < test::case_budget(120, 10); ++i) {
    const bool high = rnd.integer(0, 1) == 0;
    const int k = rnd.integer(60, 1000);
    const double m = rnd.integer(1, 7);
    const Both a = near_end(high, k, m);
    const Both b = near_end(high, k + rnd.integer(0, 2), rnd.integer(1, 7));
    const Both c = near_end(high, std::min(1070, k + rnd.integer(1, 60)), m);
    Both p = a * b * (rnd.integer(0, 1) == 0 ? c : factor(rnd.uniform(0.0, 1.0)));
    if (rnd.integer(0, 2) == 0) p = p * constant(std::ldexp(1.0, rnd.integer(-900, 900)));
    const Both nearly_a = a + constant(std::ldexp(1.0, -std::min(1074, k + 40)));
    check(p, 0.0, 1.0, {a, b, c, a * c, nearly_a, near_end(high, k + 1, m), constant(-1)});
    if (HasFailure()) return;
  }
}

TEST(Polynomial, QuadraticsWithNearlyDoubleRootsAgreeWithTheOracle) {
  // Roots d and d + 2^-k: the exact stage splits a pair of roots nearer each other than 2^-64
  // relative (a discriminant 2^-128 below c1^2 or less) between them by long division and signs
  // at them in closed form, others through the filter: k around that bound (d + 2^-k has a
  // discriminant of exponent -2k + 1 next to c1 = -(2d + 2^-k), exponent 1 for d >= 0.5) and far
  // beyond it; the same pairs a third of a ulp apart (roots that are no doubles), a complex pair
  // 2^-k off the axis and a double root.
  Random rnd(7);
  for (int i = 0; i < test::case_budget(160, 10); ++i) {
    const int k = i % 4 == 0 ? rnd.integer(200, 1000) : rnd.integer(58, 70);
    const double d = rnd.uniform(0.5, 0.9);
    const Both delta = constant(std::ldexp(1.0, -k));
    const Both a = factor(d), b = factor(d) - delta;
    const Both thirds = (constant(3) * variable() - constant(3) * constant(d)) *
                        (constant(3) * variable() - constant(3) * constant(d) - delta);
    const Both scale = constant(std::ldexp(rnd.uniform(0.5, 1), rnd.integer(-900, 900)));
    const std::vector<Both> others{a,
                                   b,
                                   factor(d) - constant(std::ldexp(1.0, -k - 1)),
                                   factor(d) - constant(std::ldexp(1.0, -k - 2)),
                                   a * factor(0.7),
                                   constant(3) * variable() - constant(3) * constant(d) - delta,
                                   constant(-2)};
    check(scale * a * b, 0.0, 1.0, others);
    check(a * b, d, 1.0, others);
    check(thirds, 0.0, 1.0, others);
    check(scale * (a * a + delta * delta), 0.0, 1.0, others);
    check(a * a * scale, 0.0, 1.0, others);
    if (HasFailure()) return;
  }
}

TEST(Polynomial, RootsThatAreRootsOfALineGiveTheOraclesSignsAndRounding) {
  // p = (3 t - 1)(t - a)(t - b) scaled by mixed magnitudes: its root 1/3 (no double) is the root
  // of 3 t - 1 and of 3s t - s for any scale s, not of 3 t - 1 - 2^-k (inside the root's bracket
  // for k > 54: there only the exact remainder tells), of t - a (another root of p) or of a line
  // whose root is outside the bracket. Signs at the root through the line, and its rounding,
  // against the oracle.
  Random rnd(8);
  for (int i = 0; i < test::case_budget(200, 10); ++i) {
    const double a = rnd.uniform(0.4, 1.0), b = rnd.uniform(-1.0, 1.0);
    const Both third = constant(3) * variable() - constant(1);
    const Both scale = constant(std::ldexp(rnd.uniform(0.5, 1), rnd.integer(-1000, 1000)));
    const Both p = scale * third * factor(a) * factor(b);
    const std::vector<RealRoot> roots = real_roots(p.p, 0.0, 1.0);
    const std::vector<test::QRoot> expected = test::isolate_roots(p.q, 0.0, 1.0);
    ASSERT_EQ(roots.size(), expected.size());
    std::size_t k = 0;
    while (k < expected.size() && test::compare(mpq_class(1, 3), expected[k]) != 0)
      ++k;
    ASSERT_LT(k, roots.size());
    const int bits = rnd.integer(20, 1000);
    EXPECT_FALSE(as_root_of_linear(roots[k], third.p - constant(std::ldexp(1.0, -bits)).p));
    EXPECT_FALSE(as_root_of_linear(roots[k], factor(a).p));
    EXPECT_FALSE(as_root_of_linear(roots[k], factor(0.9).p));
    EXPECT_FALSE(as_root_of_linear(roots[k], constant(2).p));
    const Both line = scale * third;
    const std::optional<RealRoot> on_line = as_root_of_linear(roots[k], line.p);
    ASSERT_TRUE(on_line);
    EXPECT_EQ(on_line->lower(), roots[k].lower());
    EXPECT_EQ(floor_to_double(*on_line), test::floor_to_double(expected[k]));
    EXPECT_EQ(ceil_to_double(*on_line), ceil_to_double(roots[k]));
    for (const Both& o : {third, third * third, factor(a), factor(1.0 / 3.0), p, constant(-1),
                          third * factor(b) + constant(std::ldexp(1.0, -bits))}) {
      EXPECT_EQ(sign_at(o.p, *on_line), test::sign_at(o.q, expected[k]));
    }
    if (HasFailure()) return;
  }
}

TEST(Polynomial, SignsAtARootThatLearntItsBracketAgreeWithTheOracle) {
  // Sign queries at a root leave what they learnt (a narrower bracket of doubles, the deepest
  // frame refined) for the next query at the same root. Roots 2^-k apart (k up to 1000), signs
  // asked of lines whose roots lie 2^-j from the root (deep refinements) and of shallow ones, in
  // one order, then in the reverse order (every query starting from what the others learnt), on
  // a copy of the root (which shares it), then from several threads at once on fresh roots: the
  // signs and the rounding are the oracle's whatever was learnt before.
  Random rnd(9);
  for (int i = 0; i < test::case_budget(40, 5); ++i) {
    const double m = rnd.integer(3, 9);
    const int k = rnd.integer(60, 1000);
    const Both a = constant(m) * variable() - constant(1.0);  // the root 1 / m
    const Both b = a + constant(std::ldexp(rnd.integer(0, 1) == 0 ? 1.0 : -1.0, -k));
    const Both p = a * b * factor(rnd.uniform(0.0, 1.0));
    std::vector<Both> others{a, b, constant(-2.0), b * factor(0.25)};
    for (int j = 0; j < 6; ++j) {
      const int bits = rnd.integer(1, std::min(1070, k + 60));
      others.push_back(a + constant(std::ldexp(rnd.uniform(-1.0, 1.0), -bits)));
    }
    // The oracle's signs of the others at each exact root.
    const auto oracle_signs = [&](const std::vector<test::QRoot>& exact) {
      std::vector<std::vector<Sign>> signs(exact.size());
      for (std::size_t r = 0; r < exact.size(); ++r) {
        for (const Both& o : others)
          signs[r].push_back(test::sign_at(o.q, exact[r]));
      }
      return signs;
    };
    const std::vector<test::QRoot> expected = test::isolate_roots(p.q, 0.0, 1.0);
    const std::vector<std::vector<Sign>> truth = oracle_signs(expected);
    const std::vector<RealRoot> roots = real_roots(p.p, 0.0, 1.0);
    ASSERT_EQ(roots.size(), expected.size());
    for (std::size_t r = 0; r < roots.size(); ++r) {
      for (std::size_t j = 0; j < others.size(); ++j)
        EXPECT_EQ(sign_at(others[j].p, roots[r]), truth[r][j]) << "forward, query " << j;
      for (std::size_t j = others.size(); j-- > 0;)
        EXPECT_EQ(sign_at(others[j].p, roots[r]), truth[r][j]) << "backward, query " << j;
      const RealRoot copy = roots[r];
      EXPECT_EQ(floor_to_double(copy), test::floor_to_double(expected[r]));
      for (std::size_t j = 0; j < others.size(); ++j)
        EXPECT_EQ(sign_at(others[j].p, copy), truth[r][j]) << "copy, query " << j;
    }
    // Fresh roots of p and of the quadratic a b (closed forms, whose discriminant the root
    // keeps), each queried by three threads in rotated orders (the caches are shared).
    for (const Both& poly : {p, a * b}) {
      const std::vector<test::QRoot> exact = test::isolate_roots(poly.q, 0.0, 1.0);
      const std::vector<std::vector<Sign>> want = oracle_signs(exact);
      const std::vector<RealRoot> fresh = real_roots(poly.p, 0.0, 1.0);
      ASSERT_EQ(fresh.size(), exact.size());
      std::vector<std::vector<std::vector<Sign>>> got(3);
      std::vector<std::thread> threads;
      for (std::size_t t = 0; t < 3; ++t) {
        threads.emplace_back([&, t] {
          got[t].assign(fresh.size(), std::vector<Sign>(others.size(), Sign::zero));
          for (std::size_t r = 0; r < fresh.size(); ++r) {
            for (std::size_t n = 0; n < others.size(); ++n) {
              const std::size_t j = (n + 3 * t) % others.size();
              got[t][r][j] = sign_at(others[j].p, fresh[r]);
            }
          }
        });
      }
      for (std::thread& t : threads)
        t.join();
      for (std::size_t t = 0; t < 3; ++t)
        EXPECT_EQ(got[t], want) << "thread " << t;
    }
    if (HasFailure()) return;
  }
}

TEST(Polynomial, ExactQuotientOfBigFloatsIsTheRationalQuotient) {
  // Products of random doubles divided by one of their factors (and by powers of two times an
  // odd factor), the divisions the subresultant sequences make.
  Random rnd(5);
  for (int i = 0; i < test::case_budget(3000, 10); ++i) {
    const double x = rnd.any_magnitude(), y = rnd.any_magnitude(), z = rnd.any_magnitude();
    const BigFloat bx(x), by(y), bz(z);
    const BigFloat product = bx * by * bz;
    if (y == 0.0) continue;
    const BigFloat q = exact_quotient(product, by);
    ASSERT_TRUE(q == bx * bz) << x << " " << y << " " << z;
    ASSERT_TRUE(exact_quotient(product, by * bz) == bx);
    const double power = std::ldexp(1.0, rnd.integer(-60, 60));
    ASSERT_TRUE(exact_quotient(-product, BigFloat(power) * by) ==
                -(bx * bz) * BigFloat(1.0 / power));
    ASSERT_TRUE(exact_quotient(BigFloat(), by).is_zero());
  }
}

}  // namespace
}  // namespace contain::predicates
