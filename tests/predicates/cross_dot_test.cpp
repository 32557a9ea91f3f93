#include "contain/predicates/cross_dot.h"

#include <gtest/gtest.h>

#include "predicates/cases.h"
#include "predicates/stages.h"
#include "support/exact.h"

namespace contain::predicates {
namespace {

using test::Agreement;
using test::CaseRng;
using test::cases;
using test::hex;

std::string describe(Vec3 a, Vec3 b, Vec3 p, Vec3 c) {
  return hex(a) + " " + hex(b) + " p " + hex(p) + " c " + hex(c);
}

void expect_exact(Agreement& agreement, Vec3 a, Vec3 b, Vec3 p, Vec3 c) {
  agreement.check(cross_dot(a, b, p, c), test::exact_cross_dot(a, b, p, c),
                  [&] { return describe(a, b, p, c); });
}

Vec3 uniform_point(CaseRng& rng, double scale) {
  return {rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale};
}
Vec3 lattice(CaseRng& rng, int bits) {
  return {rng.small_integer(bits), rng.small_integer(bits), rng.small_integer(bits)};
}
Vec3 nudged(CaseRng& rng, Vec3 p, int ulps) {
  return {rng.nudge(p.x, ulps), rng.nudge(p.y, ulps), rng.nudge(p.z, ulps)};
}
Vec3 nudged_nonzero(CaseRng& rng, Vec3 p, int ulps) {
  return {rng.nudge_nonzero(p.x, ulps), rng.nudge_nonzero(p.y, ulps), rng.nudge_nonzero(p.z, ulps)};
}

// Inputs on which the expression is exactly zero, on an integer lattice times one power of two
// (the expression is homogeneous of degree 4, so a common scale keeps the zero): p on the line
// a b, c on it, a = b, or p - a in the span of b - a and the triangle's normal (then the two
// cross products are perpendicular).
struct Quadruple {
  Vec3 a, b, p, c;
};
Quadruple exactly_zero(CaseRng& rng, int lo_exp, int hi_exp) {
  const Vec3 a = lattice(rng, 30);
  const Vec3 u = lattice(rng, 6), w = lattice(rng, 6);
  const double s = rng.small_integer(4), t = rng.small_integer(3);
  Quadruple q{a, a + u, a + s * u + t * cross(u, w), a + w};
  switch (rng.integer(0, 5)) {
    case 0:
      q.p = a + s * u;
      break;
    case 1:
      q.c = a + t * u;
      break;
    case 2:
      q.b = a;
      break;
    case 3:
      q.p = rng.coin() ? q.a : q.b;
      break;
    default:
      break;
  }
  const double scale = rng.power_of_two(lo_exp, hi_exp);
  return {q.a * scale, q.b * scale, q.p * scale, q.c * scale};
}

TEST(CrossDot, PositiveWhenPAndCAreOnTheSameSideOfTheLineAB) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  EXPECT_EQ(cross_dot(a, b, {0.5, 0.2, 0}, c), Sign::positive);
  EXPECT_EQ(cross_dot(a, b, {0.5, -0.2, 0}, c), Sign::negative);
  EXPECT_EQ(cross_dot(a, b, {0.5, 0.2, 7}, c), Sign::positive);      // anywhere in the prism
  EXPECT_EQ(cross_dot(a, b, {0.5, 0, 3}, c), Sign::zero);            // plane through ab, normal
  EXPECT_EQ(cross_dot(a, b, {0.3, 0.3, 0}, {2, 0, 0}), Sign::zero);  // degenerate triangle
}

TEST(CrossDot, MatchesOracleOnUniformRandom) {
  CaseRng rng(0xcd01);
  Agreement agreement;
  for (int i = 0; i < cases(150000); ++i) {
    expect_exact(agreement, uniform_point(rng, 1), uniform_point(rng, 1), uniform_point(rng, 1),
                 uniform_point(rng, 1));
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(CrossDot, MatchesOracleNearZero) {
  CaseRng rng(0xcd02);
  Agreement agreement;
  for (int i = 0; i < cases(200000); ++i) {
    Vec3 a, b, p, c;
    if (i % 2 == 0) {  // p rounded onto the plane through a b perpendicular to abc, nudged
      const double scale = i % 8 == 0 ? rng.power_of_two(-240, 240) : rng.power_of_two(-30, 30);
      a = uniform_point(rng, scale);
      b = uniform_point(rng, scale);
      c = uniform_point(rng, scale);
      const double s = rng.uniform(-1, 2), t = rng.uniform(-1, 1) / scale;
      p = nudged(rng, a + s * (b - a) + t * cross(b - a, c - a), 2);
    } else {  // an exact zero on the lattice, nudged
      const Quadruple q = exactly_zero(rng, -60, 60);
      a = nudged(rng, q.a, 1);
      b = q.b;
      p = nudged(rng, q.p, 2);
      c = nudged(rng, q.c, 1);
    }
    expect_exact(agreement, a, b, p, c);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(CrossDot, IsZeroOnExactlyDegenerateInputs) {
  CaseRng rng(0xcd03);
  Agreement agreement;
  for (int i = 0; i < cases(120000); ++i) {
    const Quadruple q = exactly_zero(rng, -1074, 960);
    const Sign got = cross_dot(q.a, q.b, q.p, q.c);
    const auto what = [&] { return describe(q.a, q.b, q.p, q.c); };
    agreement.check(got, test::exact_cross_dot(q.a, q.b, q.p, q.c), what);
    agreement.check(got, Sign::zero, what);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(CrossDot, MatchesOracleOnMixedMagnitudes) {
  CaseRng rng(0xcd04);
  Agreement agreement;
  const auto any = [&] {
    return Vec3{rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
  };
  for (int i = 0; i < cases(12000); ++i) {
    const Vec3 a = any(), b = any(), c = any();
    Vec3 p = any();
    if (i % 4 == 0) p = {a.x, b.y, p.z};
    const Sign want = test::exact_cross_dot(a, b, p, c);
    agreement.check(cross_dot(a, b, p, c), want, [&] { return describe(a, b, p, c); });
    if (i % 2 == 0) {
      agreement.check(detail::cross_dot_big(a, b, p, c), want,
                      [&] { return describe(a, b, p, c); });
    }
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(CrossDot, IsSymmetricInPAndCAndInAAndBAndUnderAxisPermutations) {
  CaseRng rng(0xcd05);
  Agreement agreement;
  for (int i = 0; i < cases(500000); ++i) {
    // Mostly inside the expansion range, one case in eight at any scale.
    const Quadruple q = i % 8 == 0 ? exactly_zero(rng, -1074, 960) : exactly_zero(rng, -100, 100);
    const Vec3 a = q.a, b = q.b, p = nudged(rng, q.p, 1), c = q.c;
    const Sign s = cross_dot(a, b, p, c);
    const auto what = [&] { return describe(a, b, p, c); };
    agreement.check(cross_dot(a, b, c, p), s, what);
    agreement.check(cross_dot(b, a, p, c), s, what);
    agreement.check(cross_dot(-a, -b, -p, -c), s, what);
    const auto rotate = [](Vec3 v) { return Vec3{v.y, v.z, v.x}; };
    agreement.check(cross_dot(rotate(a), rotate(b), rotate(p), rotate(c)), s, what);
    // ((b - a) x (p - a))^2 >= 0, zero exactly when p is on the line a b.
    agreement.check(cross_dot(a, b, p, p) == Sign::negative ? Sign::negative : Sign::zero,
                    Sign::zero, what);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(CrossDot, ExpansionStageIsExactInsideItsRange) {
  CaseRng rng(0xcd06);
  Agreement agreement;
  for (int i = 0; i < cases(40000); ++i) {
    const Quadruple q = exactly_zero(rng, -170, 210);
    const Vec3 a = nudged_nonzero(rng, q.a, 1), b = q.b, p = nudged_nonzero(rng, q.p, 2),
               c = nudged_nonzero(rng, q.c, 1);
    agreement.check(detail::cross_dot_expansion(a, b, p, c), test::exact_cross_dot(a, b, p, c),
                    [&] { return describe(a, b, p, c); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

}  // namespace
}  // namespace contain::predicates
