#include "contain/inside/point_in_convex_polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "contain/inside/point_in_polygon.h"
#include "inside/polygon_oracle.h"

namespace contain::inside {
namespace {

TEST(PointInConvexPolygon, SameSideOfEveryEdgeIsInside) {
  const Ring square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_EQ(point_in_convex_polygon(square, {1, 1}), Location::inside);
  EXPECT_EQ(point_in_convex_polygon(square, {1, 0}), Location::boundary);
  EXPECT_EQ(point_in_convex_polygon(square, {2, 2}), Location::boundary);
  EXPECT_EQ(point_in_convex_polygon(square, {3, 0}), Location::outside);  // on an edge's line
  EXPECT_EQ(point_in_convex_polygon(square, {-1, 1}), Location::outside);
}

TEST(PointInConvexPolygon, ClockwiseRingsFollowTheFillRule) {
  const Ring cw{{0, 0}, {0, 2}, {2, 2}, {2, 0}};
  EXPECT_EQ(point_in_convex_polygon(cw, {1, 1}), Location::inside);
  EXPECT_EQ(point_in_convex_polygon(cw, {1, 1}, {.fill = Fill::negative}), Location::inside);
  EXPECT_EQ(point_in_convex_polygon(cw, {1, 1}, {.fill = Fill::positive}), Location::outside);
  EXPECT_EQ(point_in_convex_polygon(cw, {1, 0}, {.fill = Fill::positive}), Location::outside);
}

TEST(PointInConvexPolygon, CollinearAndRepeatedVerticesAreSkipped) {
  const Ring ring{{0, 0}, {0, 0}, {1, 0}, {2, 0}, {2, 2}, {2, 2}, {0, 2}};
  EXPECT_EQ(point_in_convex_polygon(ring, {1, 0}), Location::boundary);
  EXPECT_EQ(point_in_convex_polygon(ring, {3, 0}), Location::outside);
  EXPECT_EQ(point_in_convex_polygon(ring, {-1, 0}), Location::outside);
  EXPECT_EQ(point_in_convex_polygon(ring, {1, 1}), Location::inside);
}

TEST(PointInConvexPolygon, ZeroAreaRingEnclosesNothing) {
  const Ring line{{0, 0}, {1, 1}, {2, 2}};
  EXPECT_EQ(point_in_convex_polygon(line, {1, 1}), Location::outside);
  EXPECT_EQ(point_in_convex_polygon(line, {0, 1}), Location::outside);
  EXPECT_EQ(point_in_convex_polygon(Ring{}, {0, 0}), Location::outside);
}

TEST(PointInConvexPolygon, MatchesExactOracleOnRandomConvexRings) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586), t(0.0, 1.0);
  std::uniform_int_distribution<int> small(-3, 3);
  for (int round = 0; round < 100; ++round) {
    // Points on a circle in angular order form a convex ring; half the rounds are clockwise.
    std::vector<double> angles(3 + round % 8);
    for (double& a : angles)
      a = angle(rng);
    std::sort(angles.begin(), angles.end());
    Ring ring;
    for (double a : angles)
      ring.push_back({std::cos(a), std::sin(a)});
    if (round % 2 == 1) std::reverse(ring.begin(), ring.end());
    std::vector<Vec2> points;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      const double s = t(rng);
      points.push_back(a);
      points.push_back({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)});
      points.push_back({2 * a.x - b.x, 2 * a.y - b.y});
    }
    for (int k = 0; k < 20; ++k)
      points.push_back({small(rng) / 3.0, small(rng) / 3.0});
    for (Fill fill : {Fill::even_odd, Fill::nonzero, Fill::positive, Fill::negative}) {
      const std::vector<Ring> rings{ring};
      for (const Vec2& p : points) {
        ASSERT_EQ(point_in_convex_polygon(ring, p, {.fill = fill}),
                  test::oracle_point_in_polygon(rings, p, fill));
      }
    }
  }
}

}  // namespace
}  // namespace contain::inside
