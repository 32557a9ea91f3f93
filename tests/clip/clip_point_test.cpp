// Point clipping keeps exactly the points of the closed region.

#include <gtest/gtest.h>

#include "contain/clip/clip_point.h"

namespace contain::test {
namespace {

TEST(ClipPoint, KeepsPointsOfTheClosedRegionAndRemovesTheOthers) {
  EXPECT_TRUE(clip::clip_point(Vec3{1, 0, 0}, Box3{{0, 0, 0}, {1, 1, 1}}).has_value());
  EXPECT_FALSE(clip::clip_point(Vec3{1.5, 0, 0}, Box3{{0, 0, 0}, {1, 1, 1}}).has_value());
  EXPECT_TRUE(clip::clip_point(Vec2{0, 0}, HalfPlane{1, 1, 0}).has_value());
  EXPECT_FALSE(clip::clip_point(Vec2{-0.1, 0}, HalfPlane{1, 1, 0}).has_value());
  EXPECT_TRUE(clip::clip_point(Vec3{0, 3, 4}, Sphere{{0, 0, 0}, 5}).has_value());
  EXPECT_FALSE(clip::clip_point(Vec2{3, 4.0000001}, Circle{{0, 0}, 5}).has_value());
  const Polygon square{{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}}};
  EXPECT_TRUE(clip::clip_point(Vec2{2, 1}, square).has_value());
  EXPECT_FALSE(clip::clip_point(Vec2{3, 1}, square).has_value());
  const auto cube = ConvexPolyhedron::from_planes({{1, 0, 0, 0}, {-1, 0, 0, 1}});
  ASSERT_TRUE(cube.ok());
  EXPECT_EQ(clip::clip_point(Vec3{0.5, 9, 9}, *cube), (Vec3{0.5, 9, 9}));
}

}  // namespace
}  // namespace contain::test
