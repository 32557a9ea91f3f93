#include "contain/values/max_abs.h"

#include <gtest/gtest.h>

#include <limits>
#include <span>
#include <vector>

namespace contain {
namespace {

TEST(MaxAbs, IsTheLargestAbsoluteCoordinateOfAPoint) {
  EXPECT_EQ(max_abs(Vec2{-3, 2}), 3);
  EXPECT_EQ(max_abs(Vec2{1, -4}), 4);
  EXPECT_EQ(max_abs(Vec3{1, -2, 0.5}), 2);
  EXPECT_EQ(max_abs(Vec3{0, 0, -7}), 7);
  EXPECT_EQ(max_abs(Vec3{-0.0, 0.0, -0.0}), 0);
}

TEST(MaxAbs, OfASetIsTheLargestOverItsPointsAndZeroForNone) {
  const std::vector<Vec3> points{{1, 2, 3}, {-9, 0, 0}, {0, 4, -5}};
  EXPECT_EQ(max_abs(std::span<const Vec3>(points)), 9);
  const std::vector<Vec2> flat{{0.25, -0.5}, {0.125, 0}};
  EXPECT_EQ(max_abs(std::span<const Vec2>(flat)), 0.5);
  EXPECT_EQ(max_abs(std::span<const Vec3>{}), 0);
  EXPECT_EQ(max_abs(std::span<const Vec2>{}), 0);
}

TEST(MaxAbs, IsExactAtTheEndsOfTheDoubleRange) {
  const double big = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(max_abs(Vec3{tiny, -big, 1}), big);
  EXPECT_EQ(max_abs(Vec2{-tiny, 0}), tiny);
  EXPECT_EQ(max_abs(Vec3{0, std::numeric_limits<double>::infinity(), 1}),
            std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace contain
