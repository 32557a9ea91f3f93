// Cyrus-Beck on random convex regions: exact decisions against the oracle, points inside.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "clip/segment_oracle.h"
#include "contain/clip/cyrus_beck.h"
#include "contain/clip/liang_barsky.h"
#include "scenes/scenes.h"
#include "support/exact.h"

namespace contain::test {
namespace {

TEST(CyrusBeck, RandomHalfSpacesMatchTheOracleAndKeepPointsInside) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  SegmentGenerator gen(9);
  int kept = 0;
  for (int region = 0; region < 200; ++region) {
    std::vector<Plane> planes;
    for (int i = 0; i < 6; ++i)
      planes.push_back({u(rng), u(rng), u(rng), 1.0 + u(rng) * 0.5});
    for (int i = 0; i < 50; ++i) {
      const Segment3 s = gen.segment3();
      const OracleClip o = oracle_clip(s, planes);
      const auto r = clip::cyrus_beck(s, planes);
      ASSERT_EQ(r.kept, o.kept);
      if (!r.kept) continue;
      ++kept;
      EXPECT_EQ(r.t0 == r.t1 && s.a != s.b, o.touching);
      EXPECT_NEAR(r.t0, to_double(o.t0), 1e-12);
      EXPECT_NEAR(r.t1, to_double(o.t1), 1e-12);
      if (o.touching) continue;  // the one touching point may miss by rounding (documented)
      for (const Plane& p : planes) {
        EXPECT_NE(exact_side_of_plane(p, r.segment.a), Sign::negative);
        EXPECT_NE(exact_side_of_plane(p, r.segment.b), Sign::negative);
      }
    }
  }
  EXPECT_GT(kept, 1000);
}

TEST(CyrusBeck, ConvexRingMatchesTheOracleInBothOrientations) {
  Ring ring;
  for (int i = 0; i < 7; ++i) {
    const double a = 2 * std::numbers::pi * i / 7;
    ring.push_back({std::cos(a), std::sin(a)});
  }
  ring.push_back(ring.back());  // a repeated vertex is allowed
  Ring reversed(ring.rbegin(), ring.rend());
  SegmentGenerator gen(11);
  for (int i = 0; i < 5000; ++i) {
    const Segment2 s = gen.segment2();
    const OracleClip o = oracle_clip_ring(s, ring);
    for (const Ring* r : {&ring, &reversed}) {
      const auto c = clip::cyrus_beck(s, *r);
      ASSERT_EQ(c.kept, o.kept);
      if (!c.kept) continue;
      EXPECT_EQ(c.t0 == c.t1 && s.a != s.b, o.touching);
      EXPECT_NEAR(c.t0, to_double(o.t0), 1e-12);
      EXPECT_NEAR(c.t1, to_double(o.t1), 1e-12);
    }
  }
}

TEST(CyrusBeck, FlatRingKeepsNothing) {
  const Ring flat = {{0, 0}, {1, 1}, {2, 2}};
  EXPECT_FALSE(clip::cyrus_beck(Segment2{{0, 0}, {2, 2}}, flat).kept);
}

TEST(CyrusBeck, CubeMeshAgreesWithLiangBarskyOnTheSameBox) {
  const Box3 box{{0, 0, 0}, {1, 1, 1}};
  const Mesh cube = scenes::box_mesh(box);
  const auto solid = ConvexPolyhedron::from_mesh(cube);
  ASSERT_TRUE(solid.ok());
  SegmentGenerator gen(13);
  for (int i = 0; i < 5000; ++i) {
    Segment3 s = gen.segment3();
    s.a = 0.5 * s.a + Vec3{0.5, 0.5, 0.5};
    s.b = 0.5 * s.b + Vec3{0.5, 0.5, 0.5};
    const auto c = clip::cyrus_beck(s, *solid);
    const auto l = clip::liang_barsky(s, box);
    ASSERT_EQ(c.kept, l.kept);
    if (!c.kept) continue;
    EXPECT_EQ(c.t0 == c.t1, l.t0 == l.t1);
    EXPECT_NEAR(c.t0, l.t0, 1e-12);
    EXPECT_NEAR(c.t1, l.t1, 1e-12);
  }
}

}  // namespace
}  // namespace contain::test
