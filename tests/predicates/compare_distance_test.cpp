#include "contain/predicates/compare_distance.h"

#include <gtest/gtest.h>

#include <array>

#include "predicates/cases.h"
#include "predicates/stages.h"
#include "support/exact.h"

namespace contain::predicates {
namespace {

using test::Agreement;
using test::CaseRng;
using test::cases;
using test::hex;

std::string describe(const Sphere& s, Vec3 p) {
  return "sphere " + hex(s.center) + " r " + hex(s.radius) + " p " + hex(p);
}
std::string describe(const Circle& s, Vec2 p) {
  return "circle " + hex(s.center) + " r " + hex(s.radius) + " p " + hex(p);
}

// Integer points on integer spheres: x^2 + y^2 + z^2 = r^2.
constexpr std::array<std::array<int, 4>, 12> kQuadruples{{{3, 4, 0, 5},
                                                          {1, 2, 2, 3},
                                                          {2, 3, 6, 7},
                                                          {1, 4, 8, 9},
                                                          {4, 4, 7, 9},
                                                          {2, 6, 9, 11},
                                                          {6, 6, 7, 11},
                                                          {3, 4, 12, 13},
                                                          {2, 10, 11, 15},
                                                          {1, 12, 12, 17},
                                                          {8, 9, 12, 17},
                                                          {5, 12, 0, 13}}};

// A sphere and a point exactly on it: an integer centre and a Pythagorean quadruple as the
// offset (coordinates permuted, signs random), everything times one power of two.
struct OnSphere {
  Sphere sphere;
  Vec3 p;
};
OnSphere exactly_on_sphere(CaseRng& rng, int lo_exp, int hi_exp) {
  const auto& q = kQuadruples[static_cast<std::size_t>(rng.integer(0, kQuadruples.size() - 1))];
  const auto sign = [&] { return rng.coin() ? 1.0 : -1.0; };
  std::array<double, 3> off{sign() * q[0], sign() * q[1], sign() * q[2]};
  const auto rot = static_cast<std::size_t>(rng.integer(0, 2));
  off = {off[rot], off[(rot + 1) % 3], off[(rot + 2) % 3]};
  if (rng.coin()) std::swap(off[0], off[1]);
  const double s = rng.power_of_two(lo_exp, hi_exp);
  const Vec3 c{rng.small_integer(24), rng.small_integer(24), rng.small_integer(24)};
  return {{c * s, sign() * q[3] * s}, {(c.x + off[0]) * s, (c.y + off[1]) * s, (c.z + off[2]) * s}};
}

TEST(SideOfSphere, PositiveInsideZeroOnTheSphereNegativeOutside) {
  const Sphere s{{0, 0, 0}, 5};
  EXPECT_EQ(side_of_sphere(s, {1, 1, 1}), Sign::positive);
  EXPECT_EQ(side_of_sphere(s, {3, 4, 0}), Sign::zero);
  EXPECT_EQ(side_of_sphere(s, {3, 4, 0.1}), Sign::negative);
  EXPECT_EQ(side_of_sphere({{1, 1, 1}, -5}, {4, 5, 1}), Sign::zero);  // |radius| is used
  EXPECT_EQ(side_of_sphere({{1, 1, 1}, 0}, {1, 1, 1}), Sign::zero);
  EXPECT_EQ(side_of_circle({{0, 0}, 5}, {3, 4}), Sign::zero);
  EXPECT_EQ(side_of_circle({{0, 0}, 5}, {3, 3.9}), Sign::positive);
  // 0.1 is not exact: the centre (0.1, 0) and the point (0.1 + 3, 4) are not 5 apart exactly.
  EXPECT_EQ(side_of_circle({{0.1, 0}, 5}, {0.1 + 3, 4}),
            test::exact_side_of_circle({{0.1, 0}, 5}, {0.1 + 3, 4}));
}

TEST(SideOfSphere, MatchesOracleOnUniformRandom) {
  CaseRng rng(0x5301);
  Agreement agreement;
  for (int i = 0; i < cases(150000); ++i) {
    const Sphere s{{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)}, rng.uniform(0, 2)};
    const Vec3 p{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    agreement.check(side_of_sphere(s, p), test::exact_side_of_sphere(s, p),
                    [&] { return describe(s, p); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfSphere, MatchesOracleNearTheSphere) {
  CaseRng rng(0x5302);
  Agreement agreement;
  for (int i = 0; i < cases(250000); ++i) {
    Sphere s;
    Vec3 p;
    if (i % 2 == 0) {  // a rounded point of the sphere, nudged, at any scale
      const double scale = rng.power_of_two(-500, 500);
      s = {{rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale},
           rng.uniform(0.1, 1) * scale};
      Vec3 dir{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
      dir = (1.0 / length(dir)) * dir;
      p = s.center + s.radius * dir;
      p = {rng.nudge(p.x, 2), rng.nudge(p.y, 2), rng.nudge(p.z, 2)};
    } else {  // an exact lattice point of the sphere, nudged
      const OnSphere g = exactly_on_sphere(rng, -300, 300);
      s = g.sphere;
      p = {rng.nudge(g.p.x, 1), rng.nudge(g.p.y, 1), rng.nudge(g.p.z, 1)};
      if (rng.coin()) s.radius = rng.nudge(s.radius, 1);
    }
    agreement.check(side_of_sphere(s, p), test::exact_side_of_sphere(s, p),
                    [&] { return describe(s, p); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfSphere, IsZeroOnPointsExactlyOnTheSphere) {
  CaseRng rng(0x5303);
  Agreement agreement;
  for (int i = 0; i < cases(150000); ++i) {
    const OnSphere g = exactly_on_sphere(rng, -1074, 990);
    const Sign got = side_of_sphere(g.sphere, g.p);
    const auto what = [&] { return describe(g.sphere, g.p); };
    agreement.check(got, test::exact_side_of_sphere(g.sphere, g.p), what);
    agreement.check(got, Sign::zero, what);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfSphere, MatchesOracleOnMixedMagnitudes) {
  CaseRng rng(0x5304);
  Agreement agreement;
  for (int i = 0; i < cases(30000); ++i) {
    const Sphere s{{rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()},
                   rng.any_magnitude()};
    Vec3 p{rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
    if (i % 4 == 0) p = {s.center.x, s.center.y, p.z};
    const Sign want = test::exact_side_of_sphere(s, p);
    agreement.check(side_of_sphere(s, p), want, [&] { return describe(s, p); });
    agreement.check(detail::side_of_sphere_big(s, p), want, [&] { return describe(s, p); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfSphere, IgnoresRadiusSignAndCoordinateOrderAndReflection) {
  CaseRng rng(0x5305);
  Agreement agreement;
  for (int i = 0; i < cases(400000); ++i) {
    // Mostly inside the expansion range, one case in eight at any scale.
    const OnSphere g =
        i % 8 == 0 ? exactly_on_sphere(rng, -1074, 990) : exactly_on_sphere(rng, -400, 400);
    const Sphere s = g.sphere;
    const Vec3 p{rng.nudge(g.p.x, 1), rng.nudge(g.p.y, 1), rng.nudge(g.p.z, 1)};
    const Sign sign = side_of_sphere(s, p);
    const auto what = [&] { return describe(s, p); };
    agreement.check(side_of_sphere({s.center, -s.radius}, p), sign, what);
    agreement.check(
        side_of_sphere({{s.center.z, s.center.x, s.center.y}, s.radius}, {p.z, p.x, p.y}), sign,
        what);
    agreement.check(side_of_sphere({-s.center, s.radius}, -p), sign, what);
    // A circle is the sphere's section through the centre's z.
    agreement.check(side_of_circle({{s.center.x, s.center.y}, s.radius}, {p.x, p.y}),
                    side_of_sphere(s, {p.x, p.y, s.center.z}), what);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfSphere, ExpansionStageIsExactInsideItsRange) {
  CaseRng rng(0x5306);
  Agreement agreement;
  for (int i = 0; i < cases(50000); ++i) {
    const OnSphere g = exactly_on_sphere(rng, -420, 470);
    Sphere s = g.sphere;
    const Vec3 p{rng.nudge_nonzero(g.p.x, 2), rng.nudge_nonzero(g.p.y, 2),
                 rng.nudge_nonzero(g.p.z, 2)};
    if (rng.coin()) s.radius = rng.nudge_nonzero(s.radius, 1);
    agreement.check(detail::side_of_sphere_expansion(s, p), test::exact_side_of_sphere(s, p),
                    [&] { return describe(s, p); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfCircle, MatchesOracleOnUniformNearExactAndMixedInputs) {
  CaseRng rng(0x5401);
  Agreement agreement;
  for (int i = 0; i < cases(800000); ++i) {
    Circle s;
    Vec2 p;
    bool on_circle = false;
    switch (i % 16 == 7 ? 3 : i % 3) {
      case 0:
        s = {{rng.uniform(-1, 1), rng.uniform(-1, 1)}, rng.uniform(0, 2)};
        p = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
        break;
      case 1: {  // a rounded point of the circle, nudged, at any scale
        const double scale = rng.power_of_two(-500, 500);
        s = {{rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale}, rng.uniform(0.1, 1) * scale};
        const double t = rng.uniform(0, 6.283185307179586);
        p = {rng.nudge(s.center.x + s.radius * std::cos(t), 2),
             rng.nudge(s.center.y + s.radius * std::sin(t), 2)};
        break;
      }
      case 2: {  // Pythagorean triples (the quadruples with a zero), exactly on the circle
        OnSphere g = exactly_on_sphere(rng, -1074, 990);
        while (g.p.z != g.sphere.center.z)
          g = exactly_on_sphere(rng, -1074, 990);
        s = {{g.sphere.center.x, g.sphere.center.y}, g.sphere.radius};
        p = {g.p.x, g.p.y};
        on_circle = true;
        if (rng.coin()) {
          p = {rng.nudge(p.x, 1), rng.nudge(p.y, 1)};
          on_circle = p == Vec2{g.p.x, g.p.y};
        }
        break;
      }
      default:
        s = {{rng.any_magnitude(), rng.any_magnitude()}, rng.any_magnitude()};
        p = {rng.any_magnitude(), rng.any_magnitude()};
        if (rng.coin()) p.x = s.center.x;
        break;
    }
    const Sign got = side_of_circle(s, p);
    const Sign want = test::exact_side_of_circle(s, p);
    agreement.check(got, want, [&] { return describe(s, p); });
    if (on_circle) agreement.check(got, Sign::zero, [&] { return describe(s, p); });
    if (i % 16 == 7) {
      agreement.check(detail::side_of_circle_big(s, p), want, [&] { return describe(s, p); });
    }
    if (i % 8 == 2) {
      agreement.check(side_of_circle({s.center, -s.radius}, p), want,
                      [&] { return describe(s, p); });
    }
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfCircle, ExpansionStageIsExactInsideItsRange) {
  CaseRng rng(0x5402);
  Agreement agreement;
  for (int i = 0; i < cases(50000); ++i) {
    const OnSphere g = exactly_on_sphere(rng, -420, 470);
    const Circle s{{g.sphere.center.x, g.sphere.center.y}, rng.nudge_nonzero(g.sphere.radius, 1)};
    const Vec2 p{rng.nudge_nonzero(g.p.x, 2), rng.nudge_nonzero(g.p.y, 2)};
    agreement.check(detail::side_of_circle_expansion(s, p), test::exact_side_of_circle(s, p),
                    [&] { return describe(s, p); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

}  // namespace
}  // namespace contain::predicates
