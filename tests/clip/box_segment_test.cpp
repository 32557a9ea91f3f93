// Cohen-Sutherland, Liang-Barsky and Cyrus-Beck on a box agree with each other and with the
// exact oracle, on random segments rich in degenerate positions and on the named cases.

#include <gtest/gtest.h>

#include <cmath>

#include "clip/segment_oracle.h"
#include "contain/clip/box_halfspaces.h"
#include "contain/clip/cohen_sutherland.h"
#include "contain/clip/cyrus_beck.h"
#include "contain/clip/liang_barsky.h"

namespace contain::test {
namespace {

const Box3 unit_box{{-1, -1, -1}, {1, 1, 1}};
const Box2 unit_square{{-1, -1}, {1, 1}};

// The claims every box clipper must meet against the oracle.
template <class S, class Box, class R>
void expect_matches_oracle(const S& s, const Box& box, const R& r, const OracleClip& o,
                           const char* name) {
  ASSERT_EQ(r.kept, o.kept) << name;
  if (!r.kept) return;
  EXPECT_TRUE(box.contains(r.segment.a)) << name;
  EXPECT_TRUE(box.contains(r.segment.b)) << name;
  EXPECT_EQ(r.t0 == r.t1 && s.a != s.b, o.touching) << name;
  if (o.touching) {
    EXPECT_EQ(r.segment.a, r.segment.b) << name;
  }
  EXPECT_NEAR(r.t0, to_double(o.t0), 1e-14) << name;
  EXPECT_NEAR(r.t1, to_double(o.t1), 1e-14) << name;
  if (o.t0 == 0) {
    EXPECT_EQ(r.segment.a, s.a) << name;
  }
  if (o.t1 == 1 && !o.touching) {
    EXPECT_EQ(r.segment.b, s.b) << name;
  }
}

TEST(BoxSegmentClip, AllThreeAlgorithmsMatchTheExactOracleIn3D) {
  SegmentGenerator gen(41);
  const auto planes = clip::box_halfspaces(unit_box);
  int touching = 0;
  for (int i = 0; i < 20000; ++i) {
    const Segment3 s = gen.segment3();
    const OracleClip o = oracle_clip(s, unit_box);
    touching += o.touching;
    expect_matches_oracle(s, unit_box, clip::cohen_sutherland(s, unit_box), o, "cohen_sutherland");
    expect_matches_oracle(s, unit_box, clip::liang_barsky(s, unit_box), o, "liang_barsky");
    expect_matches_oracle(s, unit_box, clip::cyrus_beck(s, planes), o, "cyrus_beck");
    if (HasFatalFailure()) FAIL() << "segment " << i;
  }
  EXPECT_GT(touching, 20);  // the generator does reach the degenerate cases
}

TEST(BoxSegmentClip, AllThreeAlgorithmsMatchTheExactOracleIn2D) {
  SegmentGenerator gen(43);
  const auto planes = clip::box_halfspaces(unit_square);
  for (int i = 0; i < 20000; ++i) {
    const Segment2 s = gen.segment2();
    const OracleClip o = oracle_clip(s, unit_square);
    expect_matches_oracle(s, unit_square, clip::cohen_sutherland(s, unit_square), o, "cs");
    expect_matches_oracle(s, unit_square, clip::liang_barsky(s, unit_square), o, "lb");
    expect_matches_oracle(s, unit_square, clip::cyrus_beck(s, planes), o, "cb");
    if (HasFatalFailure()) FAIL() << "segment " << i;
  }
}

struct Named {
  const char* name;
  Segment3 s;
  bool kept;
  bool touching;
};

TEST(BoxSegmentClip, DegenerateCasesGiveTheExactAnswer) {
  const Named cases[] = {
      {"inside", {{-0.5, 0, 0}, {0.5, 0, 0}}, true, false},
      {"lying in a face", {{-2, 1, 0}, {2, 1, 0}}, true, false},
      {"along an edge", {{-2, 1, 1}, {2, 1, 1}}, true, false},
      {"through a corner (diagonal)", {{-2, -2, -2}, {2, 2, 2}}, true, false},
      {"touching a corner", {{0, 2, 2}, {2, 0, 2}}, false, false},
      {"from a corner along an edge", {{-1, 2, 1}, {-1, 0, 1}}, true, false},
      {"corner touched from outside", {{-2, 0, 1}, {0, 2, 1}}, true, true},
      {"edge touched from outside", {{-2, 0, 0}, {0, 0, 2}}, true, true},
      {"parallel to a face, outside", {{-2, 1.5, 0}, {2, 1.5, 0}}, false, false},
      {"nearly parallel, one ulp outside",
       {{-2, std::nextafter(1.0, 2.0), 0}, {2, 1, 0}},
       false,
       false},
      {"on a face plane beside the face", {{2, 1, 0}, {3, 1, 0}}, false, false},
      {"zero length inside", {{0.25, 0.25, 0.25}, {0.25, 0.25, 0.25}}, true, false},
      {"zero length on a face", {{1, 0.25, 0.25}, {1, 0.25, 0.25}}, true, false},
      {"zero length outside", {{1.5, 0, 0}, {1.5, 0, 0}}, false, false},
      {"ending on a face from outside", {{3, 0, 0}, {1, 0, 0}}, true, true},
      {"far away", {{5, 5, 5}, {6, 7, 8}}, false, false},
  };
  for (const Named& c : cases) {
    const OracleClip o = oracle_clip(c.s, unit_box);
    ASSERT_EQ(o.kept, c.kept) << c.name << " (the oracle disagrees with the case's label)";
    ASSERT_EQ(o.touching, c.touching) << c.name;
    const auto planes = clip::box_halfspaces(unit_box);
    expect_matches_oracle(c.s, unit_box, clip::cohen_sutherland(c.s, unit_box), o, c.name);
    expect_matches_oracle(c.s, unit_box, clip::liang_barsky(c.s, unit_box), o, c.name);
    expect_matches_oracle(c.s, unit_box, clip::cyrus_beck(c.s, planes), o, c.name);
  }
}

TEST(BoxSegmentClip, CoordinateOnTheClippingFaceIsTheFaceValueExactly) {
  const Segment3 s{{-3, 0.1, 0.3}, {3, 0.7, -0.2}};
  const auto r = clip::liang_barsky(s, unit_box);
  ASSERT_TRUE(r.kept);
  EXPECT_EQ(r.segment.a.x, -1.0);
  EXPECT_EQ(r.segment.b.x, 1.0);
  const auto c = clip::cohen_sutherland(s, unit_box);
  EXPECT_EQ(c.segment.a.x, -1.0);
  EXPECT_EQ(c.segment.b.x, 1.0);
}

TEST(BoxSegmentClip, OutcodesFollowTheSectionsBits) {
  EXPECT_EQ(clip::outcode(Vec3{0, 0, 0}, unit_box), 0);
  EXPECT_EQ(clip::outcode(Vec3{1, -1, 1}, unit_box), 0);  // faces are inside
  EXPECT_EQ(clip::outcode(Vec3{-2, 0, 0}, unit_box), clip::outcode_x_min);
  EXPECT_EQ(clip::outcode(Vec3{2, 2, -2}, unit_box),
            clip::outcode_x_max | clip::outcode_y_max | clip::outcode_z_min);
  EXPECT_EQ(clip::outcode(Vec2{0, -3}, unit_square), clip::outcode_y_min);
}

TEST(BoxSegmentClip, EmptyBoxKeepsNothing) {
  const Box3 empty;
  EXPECT_FALSE(clip::cohen_sutherland(Segment3{{0, 0, 0}, {1, 1, 1}}, empty).kept);
  EXPECT_FALSE(clip::liang_barsky(Segment3{{0, 0, 0}, {1, 1, 1}}, empty).kept);
}

// Regression (found by fuzz/fuzz_clip_segments): the segment touches the box only at its end b,
// which lies on the face x = 1; the face crossing was computed as a + 1 * (b - a), whose y lost
// b's -2 against a.y ~ -1e281, so the touching point came back as (1, 0) instead of b.
TEST(BoxSegmentClip, TouchAtAnInsideEndpointReturnsThatEndpointBitForBit) {
  const Segment2 s{{0x1.3cdcp+16, -0x1.ba4a02289a725p+934}, {1, -2}};
  const Box2 box{{-0x1.ed25eefffffdcp-739, -0x1.ba47efa6fac29p+934}, {1, 0x1.0444p+16}};
  for (const clip::ClippedSegment2 r :
       {clip::cohen_sutherland(s, box), clip::liang_barsky(s, box)}) {
    ASSERT_TRUE(r.kept);
    EXPECT_EQ(r.t0, 1.0);
    EXPECT_EQ(r.t1, 1.0);
    EXPECT_EQ(r.segment.a, s.b);
    EXPECT_EQ(r.segment.b, s.b);
  }
}

}  // namespace
}  // namespace contain::test
