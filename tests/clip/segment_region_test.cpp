#include "contain/clip/segment_region.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <vector>

#include "contain/clip/box_halfspaces.h"
#include "contain/clip/clip_segments.h"
#include "contain/clip/cohen_sutherland.h"
#include "contain/clip/cyrus_beck.h"
#include "contain/clip/liang_barsky.h"
#include "scenes/scenes.h"

namespace contain::clip {
namespace {

// Segments from a box twice the size of the unit region, so that most cross it, plus ones that
// touch a corner, lie on a face and have zero length.
std::vector<Segment2> segments2() {
  std::vector<Segment2> s = scenes::uniform_segments(Box2{{-2, -2}, {2, 2}}, 3000, 11);
  s.push_back({{-1, 1}, {1, 1}});
  s.push_back({{1, 1}, {2, 2}});
  s.push_back({{0.5, 0.5}, {0.5, 0.5}});
  return s;
}
std::vector<Segment3> segments3() {
  std::vector<Segment3> s = scenes::uniform_segments(Box3{{-2, -2, -2}, {2, 2, 2}}, 3000, 12);
  s.push_back({{-1, 1, 1}, {1, 1, 1}});
  s.push_back({{1, 1, 1}, {2, 2, 2}});
  s.push_back({{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}});
  return s;
}

template <class S>
struct Clipped {
  std::vector<S> out;
  std::vector<std::uint8_t> kept;

  explicit Clipped(std::size_t n) : out(n), kept(n, 7) {}
  // Kept flags equal, and kept segments equal bit for bit.
  friend bool operator==(const Clipped& x, const Clipped& y) {
    if (x.kept != y.kept) return false;
    for (std::size_t i = 0; i < x.kept.size(); ++i) {
      if (x.kept[i] && std::memcmp(&x.out[i], &y.out[i], sizeof(S)) != 0) return false;
    }
    return true;
  }
};

template <class S, class Region>
Clipped<S> by_region(const std::vector<S>& in, const Region& region, SegmentClipOptions options,
                     BatchOptions batch = {}) {
  Clipped<S> c(in.size());
  const Status s = clip_segments(std::span<const S>(in), region, std::span<S>(c.out),
                                 std::span<std::uint8_t>(c.kept), options, batch);
  EXPECT_TRUE(s.ok()) << s.error().what();
  return c;
}

template <class S, class Clip>
Clipped<S> one_by_one(const std::vector<S>& in, Clip clip) {
  Clipped<S> c(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    const auto r = clip(in[i]);
    c.kept[i] = r.kept ? 1 : 0;
    if (r.kept) c.out[i] = r.segment;
  }
  return c;
}

template <class S, class Region>
Clipped<S> by_batch(const std::vector<S>& in, const Region& region) {
  Clipped<S> c(in.size());
  clip_segments(std::span<const S>(in), region, std::span<S>(c.out),
                std::span<std::uint8_t>(c.kept), BatchOptions{.threads = 1});
  return c;
}

TEST(SegmentRegion, AutomaticGivesTheRegionsOwnBatchCallBitForBit) {
  const auto s2 = segments2();
  const auto s3 = segments3();
  const Box2 box2{{-1, -1}, {1, 1}};
  const Box3 box3{{-1, -1, -1}, {1, 1, 1}};
  const HalfPlane h{1, 2, -0.5};
  const Plane p{1, -1, 2, 0.25};
  const Circle disc{{0.25, 0}, 1};
  const Sphere ball{{0, 0.25, 0}, 1};
  const Ring diamond{{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  const auto cube = ConvexPolyhedron::from_planes(box_halfspaces(box3));
  ASSERT_TRUE(cube.ok());
  EXPECT_TRUE(by_region(s2, SegmentRegion2(box2), {}) == by_batch(s2, box2));
  EXPECT_TRUE(by_region(s3, SegmentRegion3(box3), {}) == by_batch(s3, box3));
  EXPECT_TRUE(by_region(s2, SegmentRegion2(std::vector<HalfPlane>{h}), {}) == by_batch(s2, h));
  EXPECT_TRUE(by_region(s3, SegmentRegion3(std::vector<Plane>{p}), {}) == by_batch(s3, p));
  EXPECT_TRUE(by_region(s2, SegmentRegion2(disc), {}) == by_batch(s2, disc));
  EXPECT_TRUE(by_region(s3, SegmentRegion3(ball), {}) == by_batch(s3, ball));
  EXPECT_TRUE(by_region(s2, SegmentRegion2(diamond), {}) == by_batch(s2, diamond));
  EXPECT_TRUE(by_region(s3, SegmentRegion3(*cube), {}) == by_batch(s3, *cube));
}

TEST(SegmentRegion, SeveralHalfSpacesGoThroughCyrusBeck) {
  const auto s2 = segments2();
  const auto s3 = segments3();
  const std::vector<HalfPlane> strip{{1, 0, 1}, {-1, 0, 1}, {1, 1, 0}};
  const std::vector<Plane> slab{{0, 0, 1, 1}, {0, 0, -1, 1}, {1, 1, 1, 0}};
  EXPECT_TRUE(by_region(s2, SegmentRegion2(strip), {}) == one_by_one(s2, [&](const Segment2& s) {
                return cyrus_beck(s, std::span<const HalfPlane>(strip));
              }));
  EXPECT_TRUE(by_region(s3, SegmentRegion3(slab), {.clipper = SegmentClipper::cyrus_beck}) ==
              one_by_one(s3, [&](const Segment3& s) {
                return cyrus_beck(s, std::span<const Plane>(slab));
              }));
}

TEST(SegmentRegion, EachClipperOfABoxGivesItsOneSegmentFunctionBitForBit) {
  const auto s2 = segments2();
  const auto s3 = segments3();
  const Box2 b2{{-1, -0.5}, {1, 0.75}};
  const Box3 b3{{-1, -0.5, 0}, {1, 0.75, 1.5}};
  using enum SegmentClipper;
  EXPECT_TRUE(by_region(s2, SegmentRegion2(b2), {.clipper = cohen_sutherland}) ==
              one_by_one(s2, [&](const Segment2& s) { return clip::cohen_sutherland(s, b2); }));
  EXPECT_TRUE(by_region(s3, SegmentRegion3(b3), {.clipper = cohen_sutherland}) ==
              one_by_one(s3, [&](const Segment3& s) { return clip::cohen_sutherland(s, b3); }));
  EXPECT_TRUE(by_region(s2, SegmentRegion2(b2), {.clipper = liang_barsky}) ==
              one_by_one(s2, [&](const Segment2& s) { return clip::liang_barsky(s, b2); }));
  EXPECT_TRUE(by_region(s3, SegmentRegion3(b3), {.clipper = liang_barsky}) ==
              one_by_one(s3, [&](const Segment3& s) { return clip::liang_barsky(s, b3); }));
  const auto h2 = box_halfspaces(b2);
  const auto h3 = box_halfspaces(b3);
  EXPECT_TRUE(by_region(s2, SegmentRegion2(b2), {.clipper = cyrus_beck}) ==
              one_by_one(s2, [&](const Segment2& s) {
                return clip::cyrus_beck(s, std::span<const HalfPlane>(h2));
              }));
  EXPECT_TRUE(by_region(s3, SegmentRegion3(b3), {.clipper = cyrus_beck}) ==
              one_by_one(s3, [&](const Segment3& s) {
                return clip::cyrus_beck(s, std::span<const Plane>(h3));
              }));
}

TEST(SegmentRegion, AnswersDoNotDependOnTheThreadCount) {
  const auto s3 = segments3();
  const SegmentRegion3 box(Box3{{-1, -1, -1}, {1, 1, 1}});
  for (SegmentClipper clipper : {SegmentClipper::automatic, SegmentClipper::cohen_sutherland,
                                 SegmentClipper::liang_barsky, SegmentClipper::cyrus_beck}) {
    const auto one = by_region(s3, box, {.clipper = clipper}, {.threads = 1});
    EXPECT_TRUE(by_region(s3, box, {.clipper = clipper}, {.threads = 2}) == one);
    EXPECT_TRUE(by_region(s3, box, {.clipper = clipper}, {.threads = 3}) == one);
  }
}

TEST(SegmentRegion, OutcodeAndParametricClippersRefuseRegionsThatAreNotBoxes) {
  const auto s2 = segments2();
  Clipped<Segment2> c(s2.size());
  for (SegmentClipper clipper : {SegmentClipper::cohen_sutherland, SegmentClipper::liang_barsky}) {
    const Status s = clip_segments(std::span<const Segment2>(s2), SegmentRegion2(Circle{{0, 0}, 1}),
                                   std::span<Segment2>(c.out), std::span<std::uint8_t>(c.kept),
                                   {.clipper = clipper});
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().kind, ErrorKind::usage);
    EXPECT_NE(s.error().message.find("clips by a box only"), std::string::npos);
    EXPECT_EQ(c.kept, std::vector<std::uint8_t>(s2.size(), 7)) << "nothing is written";
  }
}

TEST(SegmentRegion, OutputsOfAnotherSizeAreAUsageError) {
  const auto s3 = segments3();
  std::vector<Segment3> out(s3.size() - 1);
  std::vector<std::uint8_t> kept(s3.size());
  const Status s =
      clip_segments(std::span<const Segment3>(s3), SegmentRegion3(Sphere{{0, 0, 0}, 1}),
                    std::span<Segment3>(out), std::span<std::uint8_t>(kept));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().kind, ErrorKind::usage);
}

TEST(SegmentRegion, NanOrInfinityInASegmentOrTheRegionIsInvalidAndNamesTheSegment) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<Segment2> s2 = segments2();
  Clipped<Segment2> c(s2.size());
  auto run = [&](const SegmentRegion2& region) {
    return clip_segments(std::span<const Segment2>(s2), region, std::span<Segment2>(c.out),
                         std::span<std::uint8_t>(c.kept));
  };
  const Status bad_region = run(SegmentRegion2(std::vector<HalfPlane>{{1, 0, inf}}));
  ASSERT_FALSE(bad_region.ok());
  EXPECT_EQ(bad_region.error().kind, ErrorKind::invalid_value);
  EXPECT_FALSE(run(SegmentRegion2(Circle{{0, nan}, 1})).ok());
  s2[17].b.y = nan;
  const Status bad_segment = run(SegmentRegion2(Box2{{0, 0}, {1, 1}}));
  ASSERT_FALSE(bad_segment.ok());
  EXPECT_EQ(bad_segment.error().kind, ErrorKind::invalid_value);
  EXPECT_NE(bad_segment.error().message.find("segment 17"), std::string::npos);
  EXPECT_EQ(c.kept, std::vector<std::uint8_t>(s2.size(), 7)) << "nothing is written";
}

}  // namespace
}  // namespace contain::clip
