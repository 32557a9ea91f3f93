#include "contain/predicates/orient2d.h"

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

std::string describe(Vec2 a, Vec2 b, Vec2 c) {
  return hex(a) + " " + hex(b) + " " + hex(c);
}

void expect_exact(Agreement& agreement, Vec2 a, Vec2 b, Vec2 c) {
  agreement.check(orient2d(a, b, c), test::exact_orient2d(a, b, c),
                  [&] { return describe(a, b, c); });
}

// Three points on one line through exact arithmetic: integers times a power of two per axis
// (an independent scale per axis keeps lines lines), so every coordinate is an exact double.
struct Collinear {
  Vec2 a, b, c;
};
Collinear exactly_collinear(CaseRng& rng, int lo_exp, int hi_exp) {
  const double ax = rng.small_integer(20), ay = rng.small_integer(20);
  const double dx = rng.small_integer(12), dy = rng.small_integer(12);
  const double k = rng.small_integer(5), m = rng.small_integer(5);
  const double sx = rng.power_of_two(lo_exp, hi_exp), sy = rng.power_of_two(lo_exp, hi_exp);
  return {{ax * sx, ay * sy},
          {(ax + k * dx) * sx, (ay + k * dy) * sy},
          {(ax + m * dx) * sx, (ay + m * dy) * sy}};
}

TEST(Orient2d, SignConventionIsCounterClockwisePositive) {
  EXPECT_EQ(orient2d({0, 0}, {1, 0}, {0, 1}), Sign::positive);
  EXPECT_EQ(orient2d({0, 0}, {0, 1}, {1, 0}), Sign::negative);
  EXPECT_EQ(orient2d({0, 0}, {1, 1}, {2, 2}), Sign::zero);
  EXPECT_EQ(orient2d({1, 1}, {1, 1}, {1, 1}), Sign::zero);
  EXPECT_EQ(orient2d({-0.0, 0.0}, {0.0, -0.0}, {5, 7}), Sign::zero);
}

TEST(Orient2d, MatchesOracleOnUniformRandom) {
  CaseRng rng(0x2d01);
  Agreement agreement;
  for (int i = 0; i < cases(200000); ++i) {
    const Vec2 a{rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const Vec2 b{rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const Vec2 c{rng.uniform(-1, 1), rng.uniform(-1, 1)};
    expect_exact(agreement, a, b, c);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

// The "classroom example" of Kettner et al. (2008): p = (0.5 + x u, 0.5 + y u), q = (12, 12),
// r = (24, 24) with u = 2^-53, where the naive determinant gets the sign wrong for many (x, y).
TEST(Orient2d, MatchesOracleOnUlpGridNearTheDiagonal) {
  Agreement agreement;
  const int side = cases(65536) >= 65536 ? 256 : 64;
  for (int x = 0; x < side; ++x) {
    for (int y = 0; y < side; ++y) {
      const Vec2 p{0.5 + x * 0x1p-53, 0.5 + y * 0x1p-53};
      expect_exact(agreement, p, {12, 12}, {24, 24});
      expect_exact(agreement, {12, 12}, {24, 24}, p);
    }
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient2d, MatchesOracleNearCollinear) {
  CaseRng rng(0x2d02);
  Agreement agreement;
  for (int i = 0; i < cases(300000); ++i) {
    Vec2 a, b, c;
    switch (i % 3) {
      case 0: {  // a rounded point of a random line, moved by a few ulps, at any scale
        const double s = rng.power_of_two(-1000, 1000);
        a = {rng.uniform(-1, 1) * s, rng.uniform(-1, 1) * s};
        b = {rng.uniform(-1, 1) * s, rng.uniform(-1, 1) * s};
        const double t = rng.uniform(-2, 3);
        c = {rng.nudge(a.x + t * (b.x - a.x), 3), rng.nudge(a.y + t * (b.y - a.y), 3)};
        break;
      }
      case 1: {  // integer grid line plus a tiny offset
        const Collinear g = exactly_collinear(rng, 0, 0);
        a = g.a;
        b = g.b;
        c = {g.c.x + rng.small_integer(3) * 0x1p-40, g.c.y + rng.small_integer(3) * 0x1p-40};
        break;
      }
      default: {  // an exactly collinear triple at a moderate scale, every point nudged
        const Collinear g = exactly_collinear(rng, -60, 60);
        a = {rng.nudge(g.a.x, 2), rng.nudge(g.a.y, 2)};
        b = {rng.nudge(g.b.x, 2), rng.nudge(g.b.y, 2)};
        c = {rng.nudge(g.c.x, 2), rng.nudge(g.c.y, 2)};
        break;
      }
    }
    expect_exact(agreement, a, b, c);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient2d, IsZeroOnExactlyCollinearAndDuplicatedPoints) {
  CaseRng rng(0x2d03);
  Agreement agreement;
  for (int i = 0; i < cases(150000); ++i) {
    Vec2 a, b, c;
    if (i % 5 == 4) {  // a duplicated point
      a = {rng.any_magnitude(), rng.any_magnitude()};
      b = {rng.any_magnitude(), rng.any_magnitude()};
      c = rng.coin() ? a : b;
    } else {  // scales from subnormal to near DBL_MAX, independently per axis
      const Collinear g = exactly_collinear(rng, -1074, 990);
      a = g.a;
      b = g.b;
      c = g.c;
    }
    const Sign got = orient2d(a, b, c);
    agreement.check(got, test::exact_orient2d(a, b, c), [&] { return describe(a, b, c); });
    agreement.check(got, Sign::zero, [&] { return describe(a, b, c); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient2d, MatchesOracleOnMixedMagnitudes) {
  CaseRng rng(0x2d04);
  Agreement agreement;
  for (int i = 0; i < cases(50000); ++i) {
    const Vec2 a{rng.any_magnitude(), rng.any_magnitude()};
    const Vec2 b{rng.any_magnitude(), rng.any_magnitude()};
    Vec2 c{rng.any_magnitude(), rng.any_magnitude()};
    if (i % 4 == 0) c = {a.x, b.y};  // shares coordinates: many exact cancellations
    expect_exact(agreement, a, b, c);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient2d, EvenPermutationsKeepAndOddPermutationsFlipTheSign) {
  CaseRng rng(0x2d05);
  Agreement agreement;
  for (int i = 0; i < cases(150000); ++i) {
    // Mostly inside the expansion range, one case in four at any scale.
    const Collinear g =
        i % 4 == 0 ? exactly_collinear(rng, -1074, 990) : exactly_collinear(rng, -200, 200);
    const Vec2 a = g.a, b = g.b;
    const Vec2 c{rng.nudge(g.c.x, 1), rng.nudge(g.c.y, 1)};
    const Sign s = orient2d(a, b, c);
    const auto what = [&] { return describe(a, b, c); };
    agreement.check(orient2d(b, c, a), s, what);
    agreement.check(orient2d(c, a, b), s, what);
    agreement.check(orient2d(b, a, c), -s, what);
    agreement.check(orient2d(a, c, b), -s, what);
    agreement.check(orient2d(c, b, a), -s, what);
    agreement.check(orient2d({-a.x, a.y}, {-b.x, b.y}, {-c.x, c.y}), -s, what);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

// Each exact stage on its own, so that the filter cannot hide a wrong fallback.
TEST(Orient2d, ExpansionStageIsExactInsideItsRange) {
  CaseRng rng(0x2d06);
  Agreement agreement;
  for (int i = 0; i < cases(50000); ++i) {
    const Collinear g = exactly_collinear(rng, -400, 470);
    const Vec2 a{rng.nudge_nonzero(g.a.x, 2), rng.nudge_nonzero(g.a.y, 2)};
    const Vec2 b{rng.nudge_nonzero(g.b.x, 2), rng.nudge_nonzero(g.b.y, 2)};
    const Vec2 c{rng.nudge_nonzero(g.c.x, 2), rng.nudge_nonzero(g.c.y, 2)};
    agreement.check(detail::orient2d_expansion(a, b, c), test::exact_orient2d(a, b, c),
                    [&] { return describe(a, b, c); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient2d, BigStageIsExactForEveryFiniteInput) {
  CaseRng rng(0x2d07);
  Agreement agreement;
  for (int i = 0; i < cases(20000); ++i) {
    Vec2 a{rng.any_magnitude(), rng.any_magnitude()};
    Vec2 b{rng.any_magnitude(), rng.any_magnitude()};
    Vec2 c{rng.any_magnitude(), rng.any_magnitude()};
    if (i % 2 == 0) {
      const Collinear g = exactly_collinear(rng, -1074, 990);
      a = g.a;
      b = g.b;
      c = {rng.nudge(g.c.x, 1), rng.nudge(g.c.y, 1)};
    }
    agreement.check(detail::orient2d_big(a, b, c), test::exact_orient2d(a, b, c),
                    [&] { return describe(a, b, c); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

}  // namespace
}  // namespace contain::predicates
