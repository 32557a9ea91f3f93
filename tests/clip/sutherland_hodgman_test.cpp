// The section's Sutherland-Hodgman on one ring.

#include <gtest/gtest.h>

#include "contain/clip/sutherland_hodgman.h"

namespace contain::test {
namespace {

TEST(SutherlandHodgman, ConvexRingByHalfPlaneKeepsInnerVerticesAndAddsCrossings) {
  const Ring square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  const Ring r = clip::sutherland_hodgman(square, HalfPlane{-1, 0, 1});  // x <= 1
  const Ring expected = {{0, 0}, {1, 0}, {1, 2}, {0, 2}};
  EXPECT_EQ(r, expected);
}

TEST(SutherlandHodgman, ConcaveRingGivesOneRingWithBridgingEdgesOnTheLine) {
  // A U: clipping by y >= 2 separates the two arms; the section's ring joins them along y = 2.
  const Ring u = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  const Ring r = clip::sutherland_hodgman(u, HalfPlane{0, 1, -2});
  ASSERT_EQ(r.size(), 8u);
  int on_line = 0;
  for (const Vec2& p : r)
    on_line += p.y == 2.0;
  EXPECT_EQ(on_line, 4);
  EXPECT_DOUBLE_EQ(0.5 * signed_area2(r), 2.0);  // the bridges cancel out
}

TEST(SutherlandHodgman, RingOutsideVanishesAndRingOnTheLineStays) {
  const Ring tri = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_TRUE(clip::sutherland_hodgman(tri, HalfPlane{1, 0, -5}).empty());
  EXPECT_EQ(clip::sutherland_hodgman(tri, HalfPlane{1, 0, 0}), tri);  // touching x = 0 is in
}

TEST(SutherlandHodgman, ConvexRingClipIsTheSameInEitherDirection) {
  const Ring square = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const Ring window = {{1, -1}, {3, -1}, {3, 5}, {1, 5}};
  const Ring reversed(window.rbegin(), window.rend());
  const Ring a = clip::sutherland_hodgman(square, window);
  EXPECT_DOUBLE_EQ(0.5 * signed_area2(a), 8.0);
  EXPECT_DOUBLE_EQ(0.5 * signed_area2(clip::sutherland_hodgman(square, reversed)), 8.0);
}

TEST(SutherlandHodgman, PlanarPolygonIn3DOnABoxFaceGetsExactCoordinates) {
  const std::vector<Vec3> tri = {{0, 0, 0}, {3, 0, 3}, {0, 3, 3}};
  const auto r = clip::sutherland_hodgman(tri, Plane{-1, 0, 0, 1.0 / 3.0});  // x <= 1/3
  ASSERT_FALSE(r.empty());
  for (const Vec3& p : r)
    EXPECT_LE(p.x, 1.0 / 3.0);
  int on_face = 0;
  for (const Vec3& p : r)
    on_face += p.x == 1.0 / 3.0;
  EXPECT_EQ(on_face, 2);
}

}  // namespace
}  // namespace contain::test
