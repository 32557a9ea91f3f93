// Batch forms: the branch-free box kernel decides exactly as the exact Liang-Barsky, whatever
// the thread count; the other regions match their one-shot clippers.

#include <gtest/gtest.h>

#include "clip/segment_oracle.h"
#include "contain/clip/clip_segments.h"
#include "contain/clip/cyrus_beck.h"
#include "contain/clip/liang_barsky.h"
#include "contain/clip/segment_sphere.h"

namespace contain::test {
namespace {

TEST(ClipSegments, BoxKernelDecidesExactlyAsLiangBarskyOnDegenerateInput) {
  SegmentGenerator gen(23);
  std::vector<Segment3> in(30000);
  for (auto& s : in)
    s = gen.segment3();
  // Tiny and huge coordinates send segments to the exact path too.
  in[0] = {{1e-310, 0, 0}, {2e-310, 0, 0}};
  in[1] = {{-1e305, 0.5, 0.5}, {1e305, 0.5, 0.5}};
  const Box3 box{{-1, -1, -1}, {1, 1, 1}};
  for (int threads : {1, 2, 3}) {
    std::vector<Segment3> out(in.size());
    std::vector<std::uint8_t> kept(in.size());
    clip::clip_segments(in, box, out, kept, {.threads = threads});
    for (std::size_t i = 0; i < in.size(); ++i) {
      const auto r = clip::liang_barsky(in[i], box);
      ASSERT_EQ(kept[i], r.kept ? 1 : 0) << i;
      if (!r.kept) continue;
      EXPECT_TRUE(box.contains(out[i].a) && box.contains(out[i].b)) << i;
      EXPECT_EQ(out[i].a == out[i].b, r.segment.a == r.segment.b) << i;
      EXPECT_NEAR(out[i].a.x, r.segment.a.x, 1e-14 * 2e305);
      if (i > 1) {
        EXPECT_NEAR(out[i].a.y, r.segment.a.y, 1e-14) << i;
        EXPECT_NEAR(out[i].b.z, r.segment.b.z, 1e-14) << i;
      }
    }
  }
}

TEST(ClipSegments, Box2DKernelMatchesLiangBarsky) {
  SegmentGenerator gen(29);
  std::vector<Segment2> in(20000);
  for (auto& s : in)
    s = gen.segment2();
  const Box2 box{{-1, -0.5}, {1, 1}};
  std::vector<Segment2> out(in.size());
  std::vector<std::uint8_t> kept(in.size());
  clip::clip_segments(in, box, out, kept);
  for (std::size_t i = 0; i < in.size(); ++i) {
    const auto r = clip::liang_barsky(in[i], box);
    ASSERT_EQ(kept[i], r.kept ? 1 : 0) << i;
    if (r.kept) {
      EXPECT_NEAR(out[i].b.x, r.segment.b.x, 1e-14);
    }
  }
}

TEST(ClipSegments, OtherRegionsMatchTheOneShotClippers) {
  SegmentGenerator gen(31);
  std::vector<Segment3> in(3000);
  for (auto& s : in)
    s = gen.segment3();
  std::vector<Segment3> out(in.size());
  std::vector<std::uint8_t> kept(in.size());
  const Sphere ball{{0, 0, 0}, 1};
  clip::clip_segments(in, ball, out, kept, {.threads = 2});
  for (std::size_t i = 0; i < in.size(); ++i) {
    const auto r = clip::segment_sphere(in[i], ball);
    ASSERT_EQ(kept[i], r.kept ? 1 : 0);
    if (r.kept) {
      EXPECT_EQ(out[i], r.segment);
    }
  }
  const auto poly =
      inside::ConvexPolyhedron::from_planes({{1, 1, 0, 1}, {-1, 0, 0, 1}, {0, -1, 1, 1}});
  ASSERT_TRUE(poly.ok());
  clip::clip_segments(in, *poly, out, kept, {.threads = 2});
  for (std::size_t i = 0; i < in.size(); ++i) {
    const auto r = clip::cyrus_beck(in[i], *poly);
    ASSERT_EQ(kept[i], r.kept ? 1 : 0);
    if (r.kept) {
      EXPECT_EQ(out[i], r.segment);
    }
  }
}

}  // namespace
}  // namespace contain::test
