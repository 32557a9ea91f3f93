#include "contain/predicates/orient3d_plane.h"

#include <gtest/gtest.h>

#include "predicates/cases.h"
#include "support/exact.h"

namespace contain::predicates {
namespace {

using test::Agreement;
using test::CaseRng;
using test::cases;
using test::hex;

// Checks the three queries of one plane against the oracle (and against `orient3d`, whose
// answer the class promises to equal); returns the three signs.
std::array<Sign, 3> expect_exact(Agreement& agreement, Vec3 a, Vec3 b, Vec3 c, Vec3 p, Vec3 q,
                                 Vec3 r) {
  const Orient3dPlane plane(a, b, c);
  const std::array<Sign, 3> got = plane.signs(p, q, r);
  const Vec3 points[3] = {p, q, r};
  for (int i = 0; i < 3; ++i) {
    const auto what = [&] {
      return hex(a) + " " + hex(b) + " " + hex(c) + " point " + hex(points[i]);
    };
    agreement.check(got[i], test::exact_orient3d(a, b, c, points[i]), what);
    agreement.check(plane.sign(points[i]), got[i], what);
  }
  return got;
}

Vec3 uniform_point(CaseRng& rng, double scale) {
  return {rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale};
}
Vec3 any_point(CaseRng& rng) {
  return {rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
}
Vec3 nudged(CaseRng& rng, Vec3 p, int ulps) {
  return {rng.nudge(p.x, ulps), rng.nudge(p.y, ulps), rng.nudge(p.z, ulps)};
}

// Points a + s u + t v of one lattice plane, scaled by a power of two per axis (per-axis scaling
// maps planes to planes): exactly coplanar doubles.
struct LatticePlane {
  Vec3 a, u, v, scale;
  Vec3 point(CaseRng& rng) const {
    const double s = rng.small_integer(4), t = rng.small_integer(4);
    const Vec3 p = a + s * u + t * v;
    return {p.x * scale.x, p.y * scale.y, p.z * scale.z};
  }
};
LatticePlane lattice_plane(CaseRng& rng, int lo_exp, int hi_exp) {
  return {{rng.small_integer(16), rng.small_integer(16), rng.small_integer(16)},
          {rng.small_integer(8), rng.small_integer(8), rng.small_integer(8)},
          {rng.small_integer(8), rng.small_integer(8), rng.small_integer(8)},
          {rng.power_of_two(lo_exp, hi_exp), rng.power_of_two(lo_exp, hi_exp),
           rng.power_of_two(lo_exp, hi_exp)}};
}

TEST(Orient3dPlane, SignIsOrient3dOfThePlanesPointsAndTheQuery) {
  const Orient3dPlane plane({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_EQ(plane.sign({0, 0, 1}), Sign::positive);
  EXPECT_EQ(plane.sign({3, -2, -1}), Sign::negative);
  EXPECT_EQ(plane.sign({5, 7, 0}), Sign::zero);
  const std::array<Sign, 3> want = {Sign::positive, Sign::zero, Sign::negative};
  EXPECT_EQ(plane.signs({0, 0, 2}, {1, 1, 0}, {0, 0, -0.5}), want);
  // Collinear or coincident defining points: every point is "coplanar".
  EXPECT_EQ(Orient3dPlane({1, 2, 3}, {2, 4, 6}, {3, 6, 9}).sign({0, 0, 1}), Sign::zero);
  EXPECT_EQ(Orient3dPlane({1, 2, 3}, {1, 2, 3}, {1, 2, 3}).sign({7, 0, 1}), Sign::zero);
}

TEST(Orient3dPlane, MatchesOracleOnUniformRandom) {
  CaseRng rng(0x3e01);
  Agreement agreement;
  for (int i = 0; i < cases(50000); ++i) {
    expect_exact(agreement, uniform_point(rng, 1), uniform_point(rng, 1), uniform_point(rng, 1),
                 uniform_point(rng, 1), uniform_point(rng, 1), uniform_point(rng, 1));
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3dPlane, MatchesOracleNearCoplanarAtEveryScale) {
  CaseRng rng(0x3e02);
  Agreement agreement;
  for (int i = 0; i < cases(75000); ++i) {
    Vec3 a, b, c, p[3];
    if (i % 2 == 0) {  // rounded points of a random plane moved by a few ulps, any scale
      const double scale = i % 8 == 0 ? rng.power_of_two(-1000, 1000) : rng.power_of_two(-30, 30);
      a = uniform_point(rng, scale);
      b = uniform_point(rng, scale);
      c = uniform_point(rng, scale);
      for (Vec3& x : p) {
        const double s = rng.uniform(-1, 2), t = rng.uniform(-1, 2);
        x = nudged(rng, a + s * (b - a) + t * (c - a), 3);
      }
    } else {  // a lattice plane with nudged defining points, queries on or one grid step off it
      const LatticePlane g = lattice_plane(rng, -40, 40);
      a = nudged(rng, g.point(rng), 2);
      b = nudged(rng, g.point(rng), 2);
      c = nudged(rng, g.point(rng), 2);
      for (Vec3& x : p) {
        x = g.point(rng);
        x.z += rng.small_integer(2) * 0x1p-45 * g.scale.z;
      }
    }
    expect_exact(agreement, a, b, c, p[0], p[1], p[2]);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3dPlane, IsZeroOnExactlyCoplanarPointsAndDegeneratePlanes) {
  CaseRng rng(0x3e03);
  Agreement agreement;
  for (int i = 0; i < cases(30000); ++i) {
    const LatticePlane g = lattice_plane(rng, -1074, 990);
    Vec3 a = g.point(rng), b = g.point(rng), c = g.point(rng);
    Vec3 p = g.point(rng), q = g.point(rng), r = g.point(rng);
    if (i % 3 == 2) {  // a degenerate plane: a repeated point, or three points of one line
      if (rng.coin()) {
        a = any_point(rng);
        b = any_point(rng);
        c = rng.coin() ? a : b;
      } else {
        const double s = rng.small_integer(4), t = rng.small_integer(4);
        b = g.a + s * g.u;
        c = g.a + t * g.u;
        a = g.a;
        const auto scaled = [&](Vec3 x) {
          return Vec3{x.x * g.scale.x, x.y * g.scale.y, x.z * g.scale.z};
        };
        a = scaled(a);
        b = scaled(b);
        c = scaled(c);
      }
      p = any_point(rng);
      q = uniform_point(rng, 1);
    }
    const std::array<Sign, 3> got = expect_exact(agreement, a, b, c, p, q, r);
    for (const Sign s : got) {
      agreement.check(s, Sign::zero, [&] { return hex(a) + " " + hex(b) + " " + hex(c); });
    }
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(Orient3dPlane, MatchesOracleOnMixedMagnitudesWithOverflowAndUnderflow) {
  CaseRng rng(0x3e04);
  Agreement agreement;
  for (int i = 0; i < cases(15000); ++i) {
    const Vec3 a = any_point(rng), b = any_point(rng), c = any_point(rng);
    Vec3 p = any_point(rng), q = any_point(rng), r = any_point(rng);
    if (i % 4 == 0) p = {a.x, b.y, c.z};  // shared coordinates: exact cancellations
    if (i % 4 == 1) q = a;
    expect_exact(agreement, a, b, c, p, q, r);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

}  // namespace
}  // namespace contain::predicates
