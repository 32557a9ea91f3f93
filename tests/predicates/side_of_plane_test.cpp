#include "contain/predicates/side_of_plane.h"

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

std::string describe(const Plane& h, Vec3 p) {
  return "plane " + hex(h.a) + " " + hex(h.b) + " " + hex(h.c) + " " + hex(h.d) + " p " + hex(p);
}
std::string describe(const HalfPlane& h, Vec2 p) {
  return "line " + hex(h.a) + " " + hex(h.b) + " " + hex(h.c) + " p " + hex(p);
}

// A plane and a point on it, exactly: small integers for the normal and the point, the offset
// d = -(n . p) computed exactly, then a power of two per axis moved from the coefficient to the
// coordinate (a 2^-k times x 2^k) and one global power of two on the whole equation.
struct OnPlane {
  Plane plane;
  Vec3 p;
};
OnPlane exactly_on_plane(CaseRng& rng, int lo_exp, int hi_exp) {
  const double a = rng.small_integer(10), b = rng.small_integer(10), c = rng.small_integer(10);
  const double x = rng.small_integer(16), y = rng.small_integer(16), z = rng.small_integer(16);
  const double d = -(a * x + b * y + c * z);
  const double s = rng.power_of_two(lo_exp / 2, hi_exp / 2);
  const double kx = rng.power_of_two(lo_exp / 2, hi_exp / 2);
  const double ky = rng.power_of_two(lo_exp / 2, hi_exp / 2);
  const double kz = rng.power_of_two(lo_exp / 2, hi_exp / 2);
  return {{a * s / kx, b * s / ky, c * s / kz, d * s}, {x * kx, y * ky, z * kz}};
}

TEST(SideOfPlane, PositiveInsideTheClosedHalfSpaceZeroOnItsPlane) {
  const Plane h{0, 0, 1, -2};  // z >= 2
  EXPECT_EQ(side_of_plane(h, {0, 0, 3}), Sign::positive);
  EXPECT_EQ(side_of_plane(h, {5, -7, 2}), Sign::zero);
  EXPECT_EQ(side_of_plane(h, {0, 0, 1}), Sign::negative);
  EXPECT_EQ(side_of_plane({0, 0, 0, 0}, {1, 2, 3}), Sign::zero);
  EXPECT_EQ(side_of_line({1, 0, -2}, {3, 0}), Sign::positive);
  EXPECT_EQ(side_of_line({1, 0, -2}, {2, 9}), Sign::zero);
}

TEST(SideOfPlane, MatchesOracleOnUniformRandom) {
  CaseRng rng(0x5101);
  Agreement agreement;
  for (int i = 0; i < cases(200000); ++i) {
    const Plane h{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const Vec3 p{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    agreement.check(side_of_plane(h, p), test::exact_side_of_plane(h, p),
                    [&] { return describe(h, p); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfPlane, MatchesOracleNearThePlane) {
  CaseRng rng(0x5102);
  Agreement agreement;
  for (int i = 0; i < cases(250000); ++i) {
    Plane h;
    Vec3 p;
    if (i % 2 == 0) {  // d rounded so the point is almost on the plane, then nudged, any scale
      const double s = rng.power_of_two(-500, 500);
      h = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), 0};
      p = {rng.uniform(-1, 1) * s, rng.uniform(-1, 1) * s, rng.uniform(-1, 1) * s};
      h.d = rng.nudge(-(h.a * p.x + h.b * p.y + h.c * p.z), 4);
    } else {
      OnPlane g = exactly_on_plane(rng, -100, 100);
      h = g.plane;
      p = {rng.nudge(g.p.x, 2), rng.nudge(g.p.y, 2), rng.nudge(g.p.z, 2)};
      if (rng.coin()) h.d = rng.nudge(h.d, 1);
    }
    agreement.check(side_of_plane(h, p), test::exact_side_of_plane(h, p),
                    [&] { return describe(h, p); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfPlane, IsZeroOnPointsExactlyOnThePlane) {
  CaseRng rng(0x5103);
  Agreement agreement;
  for (int i = 0; i < cases(150000); ++i) {
    const OnPlane g = exactly_on_plane(rng, -1000, 960);
    const Sign got = side_of_plane(g.plane, g.p);
    agreement.check(got, test::exact_side_of_plane(g.plane, g.p),
                    [&] { return describe(g.plane, g.p); });
    agreement.check(got, Sign::zero, [&] { return describe(g.plane, g.p); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfPlane, MatchesOracleOnMixedMagnitudes) {
  CaseRng rng(0x5104);
  Agreement agreement;
  for (int i = 0; i < cases(40000); ++i) {
    const Plane h{rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude(),
                  rng.any_magnitude()};
    const Vec3 p{rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
    agreement.check(side_of_plane(h, p), test::exact_side_of_plane(h, p),
                    [&] { return describe(h, p); });
    agreement.check(detail::side_of_plane_big(h, p), test::exact_side_of_plane(h, p),
                    [&] { return describe(h, p); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfPlane, NegatedCoefficientsFlipAndLinesAgreeWithVerticalPlanes) {
  CaseRng rng(0x5105);
  Agreement agreement;
  for (int i = 0; i < cases(320000); ++i) {
    // Mostly inside the expansion range, one case in eight at any scale.
    const OnPlane g =
        i % 8 == 0 ? exactly_on_plane(rng, -1000, 960) : exactly_on_plane(rng, -400, 400);
    const Plane h = g.plane;
    const Vec3 p{rng.nudge(g.p.x, 1), rng.nudge(g.p.y, 1), rng.nudge(g.p.z, 1)};
    const Sign s = side_of_plane(h, p);
    const auto what = [&] { return describe(h, p); };
    agreement.check(side_of_plane({-h.a, -h.b, -h.c, -h.d}, p), -s, what);
    agreement.check(side_of_plane({h.b, h.c, h.a, h.d}, {p.y, p.z, p.x}), s, what);
    // A half-plane is the half-space of the same equation with c = 0.
    const HalfPlane l{h.a, h.b, h.d};
    const Vec2 q{p.x, p.y};
    agreement.check(side_of_line(l, q), side_of_plane({h.a, h.b, 0.0, h.d}, {p.x, p.y, p.z}), what);
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfPlane, ExpansionStageIsExactInsideItsRange) {
  CaseRng rng(0x5106);
  Agreement agreement;
  for (int i = 0; i < cases(50000); ++i) {
    const OnPlane g = exactly_on_plane(rng, -420, 420);
    Plane h = g.plane;
    const Vec3 p{rng.nudge_nonzero(g.p.x, 2), rng.nudge_nonzero(g.p.y, 2),
                 rng.nudge_nonzero(g.p.z, 2)};
    if (rng.coin()) h.d = rng.nudge_nonzero(h.d, 1);
    agreement.check(detail::side_of_plane_expansion(h, p), test::exact_side_of_plane(h, p),
                    [&] { return describe(h, p); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfLine, MatchesOracleOnUniformNearAndExactlyOnTheLine) {
  CaseRng rng(0x5201);
  Agreement agreement;
  for (int i = 0; i < cases(800000); ++i) {
    HalfPlane h;
    Vec2 p;
    bool on_line = false;
    switch (i % 16 == 7 ? 3 : i % 3) {
      case 0:
        h = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        p = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
        break;
      case 1: {  // offset rounded to pass near the point, nudged, at any scale
        const double s = rng.power_of_two(-500, 500);
        h = {rng.uniform(-1, 1), rng.uniform(-1, 1), 0};
        p = {rng.uniform(-1, 1) * s, rng.uniform(-1, 1) * s};
        h.c = rng.nudge(-(h.a * p.x + h.b * p.y), 4);
        break;
      }
      case 2: {  // exactly on the line, coefficients and coordinates rescaled per axis
        const OnPlane g = exactly_on_plane(rng, -1000, 960);
        h = {g.plane.a, g.plane.b, g.plane.c * g.p.z + g.plane.d};
        p = {g.p.x, g.p.y};
        on_line = (g.plane.c * g.p.z + g.plane.d) == -(g.plane.a * g.p.x + g.plane.b * g.p.y);
        break;
      }
      default:
        h = {rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
        p = {rng.any_magnitude(), rng.any_magnitude()};
        break;
    }
    const Sign got = side_of_line(h, p);
    const Sign want = test::exact_side_of_line(h, p);
    agreement.check(got, want, [&] { return describe(h, p); });
    if (on_line) agreement.check(got, Sign::zero, [&] { return describe(h, p); });
    if (i % 16 == 7) {
      agreement.check(detail::side_of_line_big(h, p), want, [&] { return describe(h, p); });
    }
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

TEST(SideOfLine, ExpansionStageIsExactInsideItsRange) {
  CaseRng rng(0x5202);
  Agreement agreement;
  for (int i = 0; i < cases(50000); ++i) {
    const OnPlane g = exactly_on_plane(rng, -420, 420);
    const HalfPlane h{g.plane.a, g.plane.b, rng.nudge_nonzero(g.plane.d, 1)};
    const Vec2 p{rng.nudge_nonzero(g.p.x, 2), rng.nudge_nonzero(g.p.y, 2)};
    agreement.check(detail::side_of_line_expansion(h, p), test::exact_side_of_line(h, p),
                    [&] { return describe(h, p); });
  }
  EXPECT_EQ(agreement.disagreements(), 0) << "of " << agreement.count();
}

}  // namespace
}  // namespace contain::predicates
