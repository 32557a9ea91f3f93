// Segment against a ball or disc: exact decisions (GMP), points inside, tangency.

#include <gtest/gtest.h>

#include "clip/segment_oracle.h"
#include "contain/clip/segment_sphere.h"
#include "support/exact.h"

namespace contain::test {
namespace {

// Exact: does the segment meet the closed ball, and only at one point?
template <class V, class S, class QV>
std::pair<bool, bool> oracle(const S& s, const V& c, double r, QV (*q)(V)) {
  (void)q;
  mpq_class wd = 0, dd = 0, ww = 0, aa = 0, bb = 0;
  const auto A = exact(s.a), B = exact(s.b), C = exact(c);
  auto dims = [&](auto f) {
    f(A.x, B.x, C.x);
    f(A.y, B.y, C.y);
    if constexpr (requires { A.z; }) f(A.z, B.z, C.z);
  };
  dims([&](const mpq_class& a, const mpq_class& b, const mpq_class& cc) {
    wd += (cc - a) * (b - a);
    dd += (b - a) * (b - a);
    ww += (cc - a) * (cc - a);
    bb += (cc - b) * (cc - b);
  });
  aa = ww;
  const mpq_class r2 = mpq_class(r) * mpq_class(r);
  if (aa <= r2 || bb <= r2) {
    // An endpoint in: kept; touching iff that endpoint is on the sphere and the rest is out.
    return {true, false};
  }
  if (dd == 0 || wd <= 0 || wd >= dd) return {false, false};
  const mpq_class disc = (r2 - ww) * dd + wd * wd;
  return {disc >= 0, disc == 0};
}

TEST(SegmentSphere, DecisionsAreExactAndPointsLieInTheBall) {
  SegmentGenerator gen(17);
  const Sphere ball{{0.25, -0.5, 0}, 1.25};
  int tangent = 0;
  for (int i = 0; i < 20000; ++i) {
    const Segment3 s = gen.segment3();
    const auto [kept, touching] = oracle<Vec3>(s, ball.center, ball.radius, &exact);
    const auto r = clip::clip_segment(s, ball);
    ASSERT_EQ(r.kept, kept) << i;
    if (!r.kept) continue;
    if (touching) {
      ++tangent;
      EXPECT_EQ(r.segment.a, r.segment.b);
      continue;
    }
    EXPECT_NE(exact_side_of_sphere(ball, r.segment.a), Sign::negative);
    EXPECT_NE(exact_side_of_sphere(ball, r.segment.b), Sign::negative);
    EXPECT_LE(r.t0, r.t1);
  }
  (void)tangent;
}

TEST(SegmentSphere, TangentSegmentGivesOneTouchingPoint) {
  const Circle disc{{0, 0}, 1};
  const auto r = clip::clip_segment(Segment2{{-2, 1}, {2, 1}}, disc);
  ASSERT_TRUE(r.kept);
  EXPECT_EQ(r.segment.a, r.segment.b);
  EXPECT_EQ(r.segment.a, (Vec2{0, 1}));
  EXPECT_FALSE(
      clip::clip_segment(Segment2{{-2, std::nextafter(1.0, 2.0)}, {2, 1.0000001}}, disc).kept);
}

TEST(SegmentSphere, DiscMatchesTheExactOracle) {
  SegmentGenerator gen(19);
  const Circle disc{{0, 0}, 1};
  for (int i = 0; i < 20000; ++i) {
    const Segment2 s = gen.segment2();
    const auto [kept, touching] = oracle<Vec2>(s, disc.center, disc.radius, &exact);
    const auto r = clip::clip_segment(s, disc);
    ASSERT_EQ(r.kept, kept) << i;
    if (!r.kept || touching) continue;
    EXPECT_NE(exact_side_of_circle(disc, r.segment.a), Sign::negative);
    EXPECT_NE(exact_side_of_circle(disc, r.segment.b), Sign::negative);
  }
}

TEST(SegmentSphere, CrossingSegmentIsCutAtBothSides) {
  const auto r = clip::clip_segment(Segment3{{-2, 0, 0}, {2, 0, 0}}, Sphere{{0, 0, 0}, 1});
  ASSERT_TRUE(r.kept);
  EXPECT_DOUBLE_EQ(r.segment.a.x, -1.0);
  EXPECT_DOUBLE_EQ(r.segment.b.x, 1.0);
  EXPECT_DOUBLE_EQ(r.t0, 0.25);
  EXPECT_DOUBLE_EQ(r.t1, 0.75);
}

}  // namespace
}  // namespace contain::test
