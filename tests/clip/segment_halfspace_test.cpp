// A segment against one half-space: the section's three cases, the parameter, exact sides.

#include <gtest/gtest.h>

#include "clip/segment_oracle.h"
#include "contain/clip/segment_halfspace.h"
#include "support/exact.h"

namespace contain::test {
namespace {

TEST(SegmentHalfspace, TheSectionsThreeCases) {
  const Plane x_ge_0{1, 0, 0, 0};
  EXPECT_EQ(clip::segment_case(Segment3{{1, 0, 0}, {2, 5, 0}}, x_ge_0), clip::SegmentCase::inside);
  EXPECT_EQ(clip::segment_case(Segment3{{-1, 0, 0}, {-2, 5, 0}}, x_ge_0),
            clip::SegmentCase::outside);
  EXPECT_EQ(clip::segment_case(Segment3{{-1, 0, 0}, {3, 0, 0}}, x_ge_0),
            clip::SegmentCase::crossing);
  EXPECT_EQ(clip::segment_case(Segment3{{0, 0, 0}, {3, 0, 0}}, x_ge_0),
            clip::SegmentCase::inside);  // on the plane counts as in
  EXPECT_DOUBLE_EQ(clip::crossing_parameter(Segment3{{-1, 0, 0}, {3, 0, 0}}, x_ge_0), 0.25);
  const auto r = clip::clip_segment(Segment3{{-1, 0, 0}, {3, 0, 0}}, x_ge_0);
  ASSERT_TRUE(r.kept);
  EXPECT_EQ(r.segment.a, (Vec3{0, 0, 0}));
  EXPECT_EQ(r.segment.b, (Vec3{3, 0, 0}));
}

TEST(SegmentHalfspace, EndpointOnThePlaneWithTheOtherOutTouches) {
  const auto r = clip::clip_segment(Segment2{{0, 1}, {-2, 3}}, HalfPlane{1, 0, 0});
  ASSERT_TRUE(r.kept);
  EXPECT_EQ(r.segment.a, r.segment.b);
  EXPECT_EQ(r.segment.a, (Vec2{0, 1}));
  EXPECT_EQ(r.t0, 0.0);
  EXPECT_EQ(r.t1, 0.0);
}

TEST(SegmentHalfspace, RandomPlanesMatchTheOracleAndClippedPointsAreInside) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  SegmentGenerator gen(5);
  for (int i = 0; i < 20000; ++i) {
    const Plane p{u(rng), u(rng), u(rng), u(rng)};
    const Segment3 s = gen.segment3();
    const std::vector<Plane> one{p};
    const OracleClip o = oracle_clip(s, one);
    const auto r = clip::clip_segment(s, p);
    ASSERT_EQ(r.kept, o.kept);
    if (!r.kept) continue;
    EXPECT_EQ(r.t0 == r.t1 && s.a != s.b, o.touching);
    EXPECT_NE(exact_side_of_plane(p, r.segment.a), Sign::negative);
    EXPECT_NE(exact_side_of_plane(p, r.segment.b), Sign::negative);
    EXPECT_NEAR(r.t0, to_double(o.t0), 1e-12);
    EXPECT_NEAR(r.t1, to_double(o.t1), 1e-12);
  }
}

TEST(SegmentHalfspace, ZeroNormalIsAllOrNothing) {
  const Segment2 s{{0, 0}, {1, 1}};
  EXPECT_TRUE(clip::clip_segment(s, HalfPlane{0, 0, 1}).kept);
  EXPECT_TRUE(clip::clip_segment(s, HalfPlane{0, 0, 0}).kept);
  EXPECT_FALSE(clip::clip_segment(s, HalfPlane{0, 0, -1}).kept);
}

}  // namespace
}  // namespace contain::test
