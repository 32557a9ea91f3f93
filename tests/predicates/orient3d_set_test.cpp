#include "contain/predicates/orient3d_set.h"

#include <gtest/gtest.h>

#include "predicates/cases.h"
#include "support/exact.h"

namespace contain::predicates {
namespace {

using test::Agreement;
using test::CaseRng;
using test::cases;
using test::hex;

using Points = std::array<Vec3, 6>;

std::string describe(const Points& p, std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
  std::string s;
  for (const Vec3& x : p)
    s += hex(x) + " ";
  return s + "indices " + std::to_string(a) + std::to_string(b) + std::to_string(c) +
         std::to_string(d);
}

// Eight random index quadruples of the set (repeats allowed: degenerate planes and queries on
// a defining point), each checked against the oracle both through a shared plane and through
// `orient3d`; returns the signs.
std::array<Sign, 8> expect_exact(Agreement& agreement, CaseRng& rng, const Points& p) {
  const Orient3dSet<6> set(p);
  std::array<Sign, 8> got{};
  for (int k = 0; k < 8; ++k) {
    const auto pick = [&] { return static_cast<std::size_t>(rng.integer(0, 5)); };
    const std::size_t a = pick(), b = pick(), c = pick(), d = pick();
    const auto plane = set.plane(a, b, c);
    got[static_cast<std::size_t>(k)] = set.sign(plane, d);
    const auto what = [&] { return describe(p, a, b, c, d); };
    agreement.check(got[static_cast<std::size_t>(k)], test::exact_orient3d(p[a], p[b], p[c], p[d]),
                    what);
    agreement.check(set.orient3d(a, b, c, d), got[static_cast<std::size_t>(k)], what);
  }
  return got;
}

Vec3 uniform_point(CaseRng& rng, double scale) {
  return {rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale};
}
Vec3 nudged(CaseRng& rng, Vec3 p, int ulps) {
  return {rng.nudge(p.x, ulps), rng.nudge(p.y, ulps), rng.nudge(p.z, ulps)};
}

TEST(Orient3dSet, SignIsOrient3dOfTheIndexedPoints) {
  const Orient3dSet<4> set({Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}});
  EXPECT_EQ(set.orient3d(0, 1, 2, 3), Sign::positive);
  EXPECT_EQ(set.orient3d(0, 2, 1, 3), Sign::negative);
  EXPECT_EQ(set.orient3d(0, 1, 2, 1), Sign::zero);  // a defining point
  EXPECT_EQ(set.orient3d(0, 0, 2, 3), Sign::zero);  // a degenerate plane
  const auto plane = set.plane(1, 2, 3);
  EXPECT_EQ(set.sign(plane, 0), Sign::negative);
  EXPECT_EQ(set.point(3), (Vec3{0, 0, 1}));
}

TEST(Orient3dSet, MatchesOracleOnUniformRandom) {
  CaseRng rng(0x3f01);
  Agreement agreement;
  for (int i = 0; i < cases(25000); ++i) {
    Points p;
    for (Vec3& x : p)
      x = uniform_point(rng, 1);
    expect_exact(agreement, rng, p);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3dSet, MatchesOracleNearCoplanarAtEveryScale) {
  CaseRng rng(0x3f02);
  Agreement agreement;
  for (int i = 0; i < cases(45000); ++i) {
    // Rounded points of a random plane moved by a few ulps; one case in four has two points
    // far off the plane, so that the set's bound is loose for the near-coplanar quadruples.
    const double scale = i % 8 == 0 ? rng.power_of_two(-1000, 1000) : rng.power_of_two(-30, 30);
    const Vec3 a = uniform_point(rng, scale), b = uniform_point(rng, scale),
               c = uniform_point(rng, scale);
    Points p;
    for (Vec3& x : p) {
      const double s = rng.uniform(-1, 2), t = rng.uniform(-1, 2);
      x = nudged(rng, a + s * (b - a) + t * (c - a), 3);
    }
    if (i % 4 == 3) {
      p[4] = uniform_point(rng, scale * 64);
      p[5] = uniform_point(rng, scale * 64);
    }
    expect_exact(agreement, rng, p);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3dSet, IsZeroOnExactlyCoplanarSets) {
  CaseRng rng(0x3f03);
  Agreement agreement;
  for (int i = 0; i < cases(25000); ++i) {
    // Lattice points a + s u + t v, scaled per axis by powers of two (a plane stays a plane),
    // at any exponent; one case in three on a line.
    const Vec3 a{rng.small_integer(16), rng.small_integer(16), rng.small_integer(16)};
    const Vec3 u{rng.small_integer(8), rng.small_integer(8), rng.small_integer(8)};
    const Vec3 v = i % 3 == 0
                       ? Vec3{0, 0, 0}
                       : Vec3{rng.small_integer(8), rng.small_integer(8), rng.small_integer(8)};
    const Vec3 scale{rng.power_of_two(-1074, 990), rng.power_of_two(-1074, 990),
                     rng.power_of_two(-1074, 990)};
    Points p;
    for (Vec3& x : p) {
      const Vec3 y = a + rng.small_integer(4) * u + rng.small_integer(4) * v;
      x = {y.x * scale.x, y.y * scale.y, y.z * scale.z};
    }
    for (const Sign s : expect_exact(agreement, rng, p)) {
      agreement.check(s, Sign::zero, [&] { return describe(p, 0, 0, 0, 0); });
    }
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3dSet, MatchesOracleOnMixedMagnitudesAndHugeExtents) {
  CaseRng rng(0x3f04);
  Agreement agreement;
  for (int i = 0; i < cases(30000); ++i) {
    Points p;
    if (i % 2 == 0) {  // any doubles: overflow, underflow, subnormals, shared coordinates
      for (Vec3& x : p)
        x = {rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
      if (i % 4 == 0) p[5] = {p[0].x, p[1].y, p[2].z};
    } else {  // one axis near the 2^340 extent limit, the others small
      const double big = rng.power_of_two(320, 360);
      for (Vec3& x : p)
        x = {rng.uniform(-1, 1) * big, rng.uniform(-1, 1) * 0x1p-300, rng.uniform(-1, 1)};
    }
    expect_exact(agreement, rng, p);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

}  // namespace
}  // namespace contain::predicates
