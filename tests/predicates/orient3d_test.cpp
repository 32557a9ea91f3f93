#include "contain/predicates/orient3d.h"

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

std::string describe(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return hex(a) + " " + hex(b) + " " + hex(c) + " " + hex(d);
}

void expect_exact(Agreement& agreement, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  agreement.check(orient3d(a, b, c, d), test::exact_orient3d(a, b, c, d),
                  [&] { return describe(a, b, c, d); });
}

Vec3 uniform_point(CaseRng& rng, double scale) {
  return {rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale};
}

Vec3 nudged(CaseRng& rng, Vec3 p, int ulps) {
  return {rng.nudge(p.x, ulps), rng.nudge(p.y, ulps), rng.nudge(p.z, ulps)};
}
Vec3 nudged_nonzero(CaseRng& rng, Vec3 p, int ulps) {
  return {rng.nudge_nonzero(p.x, ulps), rng.nudge_nonzero(p.y, ulps), rng.nudge_nonzero(p.z, ulps)};
}

// Four points of one plane through exact arithmetic: small integers a, a + u, a + v,
// a + s u + t v, then a power of two per axis (per-axis scaling maps planes to planes).
struct Coplanar {
  Vec3 a, b, c, d;
};
Coplanar exactly_coplanar(CaseRng& rng, int lo_exp, int hi_exp) {
  const Vec3 a{rng.small_integer(16), rng.small_integer(16), rng.small_integer(16)};
  const Vec3 u{rng.small_integer(8), rng.small_integer(8), rng.small_integer(8)};
  const Vec3 v{rng.small_integer(8), rng.small_integer(8), rng.small_integer(8)};
  const double s = rng.small_integer(4), t = rng.small_integer(4);
  const Vec3 scale{rng.power_of_two(lo_exp, hi_exp), rng.power_of_two(lo_exp, hi_exp),
                   rng.power_of_two(lo_exp, hi_exp)};
  const auto scaled = [&](Vec3 p) { return Vec3{p.x * scale.x, p.y * scale.y, p.z * scale.z}; };
  return {scaled(a), scaled(a + u), scaled(a + v), scaled(a + s * u + t * v)};
}

TEST(Orient3d, SignIsPositiveWhereTheNormalOfCounterClockwiseABCPoints) {
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), Sign::positive);
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}), Sign::negative);
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 7, 0}), Sign::zero);
  EXPECT_EQ(orient3d({1, 2, 3}, {1, 2, 3}, {4, 5, 6}, {7, 8, 10}), Sign::zero);
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 0, 9}), Sign::zero);
}

TEST(Orient3d, MatchesOracleOnUniformRandom) {
  CaseRng rng(0x3d01);
  Agreement agreement;
  for (int i = 0; i < cases(150000); ++i) {
    expect_exact(agreement, uniform_point(rng, 1), uniform_point(rng, 1), uniform_point(rng, 1),
                 uniform_point(rng, 1));
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3d, MatchesOracleNearCoplanar) {
  CaseRng rng(0x3d02);
  Agreement agreement;
  for (int i = 0; i < cases(200000); ++i) {
    Vec3 a, b, c, d;
    if (i % 2 == 0) {  // a rounded point of a random plane, moved by a few ulps, at any scale
      const double scale = i % 8 == 0 ? rng.power_of_two(-1000, 1000) : rng.power_of_two(-30, 30);
      a = uniform_point(rng, scale);
      b = uniform_point(rng, scale);
      c = uniform_point(rng, scale);
      const double s = rng.uniform(-1, 2), t = rng.uniform(-1, 2);
      d = nudged(rng, a + s * (b - a) + t * (c - a), 3);
    } else {  // an exactly coplanar lattice quadruple, every point nudged or offset on a grid
      const Coplanar g = exactly_coplanar(rng, -40, 40);
      a = nudged(rng, g.a, 2);
      b = nudged(rng, g.b, 2);
      c = nudged(rng, g.c, 2);
      d = g.d;
      d.z += rng.small_integer(3) * 0x1p-45 * (g.b.z - g.a.z);
    }
    expect_exact(agreement, a, b, c, d);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3d, IsZeroOnExactlyCoplanarAndDuplicatedPoints) {
  CaseRng rng(0x3d03);
  Agreement agreement;
  for (int i = 0; i < cases(120000); ++i) {
    Coplanar g = exactly_coplanar(rng, -1074, 990);
    if (i % 5 == 4) {  // a duplicated point among arbitrary doubles
      g.a = {rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
      g.b = {rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
      g.c = {rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
      g.d = rng.coin() ? g.a : g.c;
    }
    const Sign got = orient3d(g.a, g.b, g.c, g.d);
    const auto what = [&] { return describe(g.a, g.b, g.c, g.d); };
    agreement.check(got, test::exact_orient3d(g.a, g.b, g.c, g.d), what);
    agreement.check(got, Sign::zero, what);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3d, MatchesOracleOnMixedMagnitudes) {
  CaseRng rng(0x3d04);
  Agreement agreement;
  const auto any = [&] {
    return Vec3{rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
  };
  for (int i = 0; i < cases(15000); ++i) {
    const Vec3 a = any(), b = any(), c = any();
    Vec3 d = any();
    if (i % 4 == 0) d = {a.x, b.y, c.z};  // shared coordinates: exact cancellations
    expect_exact(agreement, a, b, c, d);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3d, EvenPermutationsKeepAndOddPermutationsFlipTheSign) {
  CaseRng rng(0x3d05);
  Agreement agreement;
  for (int i = 0; i < cases(480000); ++i) {
    // Mostly inside the expansion range, one case in eight at any scale.
    const Coplanar g =
        i % 8 == 0 ? exactly_coplanar(rng, -1074, 990) : exactly_coplanar(rng, -150, 150);
    const Vec3 a = g.a, b = g.b, c = g.c, d = nudged(rng, g.d, 1);
    const Sign s = orient3d(a, b, c, d);
    const auto what = [&] { return describe(a, b, c, d); };
    agreement.check(orient3d(b, c, a, d), s, what);
    agreement.check(orient3d(b, a, d, c), s, what);
    agreement.check(orient3d(d, c, b, a), s, what);
    agreement.check(orient3d(b, a, c, d), -s, what);
    agreement.check(orient3d(a, b, d, c), -s, what);
    agreement.check(orient3d(d, b, c, a), -s, what);
    const auto mirror = [](Vec3 p) { return Vec3{p.x, p.y, -p.z}; };
    agreement.check(orient3d(mirror(a), mirror(b), mirror(c), mirror(d)), -s, what);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3d, ExpansionStageIsExactInsideItsRange) {
  CaseRng rng(0x3d06);
  Agreement agreement;
  for (int i = 0; i < cases(40000); ++i) {
    const Coplanar g = exactly_coplanar(rng, -250, 300);
    const Vec3 a = nudged_nonzero(rng, g.a, 2), b = nudged_nonzero(rng, g.b, 2),
               c = nudged_nonzero(rng, g.c, 2), d = nudged_nonzero(rng, g.d, 2);
    agreement.check(detail::orient3d_expansion(a, b, c, d), test::exact_orient3d(a, b, c, d),
                    [&] { return describe(a, b, c, d); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3d, BigStageIsExactForEveryFiniteInput) {
  CaseRng rng(0x3d07);
  Agreement agreement;
  const auto any = [&] {
    return Vec3{rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
  };
  for (int i = 0; i < cases(10000); ++i) {
    Vec3 a = any(), b = any(), c = any(), d = any();
    if (i % 2 == 0) {
      const Coplanar g = exactly_coplanar(rng, -1074, 990);
      a = g.a;
      b = g.b;
      c = g.c;
      d = nudged(rng, g.d, 1);
    }
    agreement.check(detail::orient3d_big(a, b, c, d), test::exact_orient3d(a, b, c, d),
                    [&] { return describe(a, b, c, d); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

}  // namespace
}  // namespace contain::predicates
