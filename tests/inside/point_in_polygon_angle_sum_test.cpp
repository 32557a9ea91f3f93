#include "contain/inside/point_in_polygon_angle_sum.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "contain/inside/point_in_polygon.h"
#include "inside/polygon_oracle.h"
#include "inside/polygon_random.h"

namespace contain::inside {
namespace {

TEST(PointInPolygonAngleSum, AgreesWithRayCrossingAwayFromTheBoundary) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-1.2, 1.2);
  for (int round = 0; round < 20; ++round) {
    const std::vector<Ring> rings{test::random_star(rng, 20, 0, 0, 1.0),
                                  test::random_star(rng, 8, 0.3, -0.2, 0.7)};
    for (Fill fill : {Fill::even_odd, Fill::nonzero, Fill::positive, Fill::negative}) {
      for (int k = 0; k < 200; ++k) {
        const Vec2 p{coordinate(rng), coordinate(rng)};
        ASSERT_EQ(point_in_polygon_angle_sum(std::span<const Ring>(rings), p, {.fill = fill}),
                  point_in_polygon(std::span<const Ring>(rings), p, {.fill = fill}));
      }
    }
  }
}

TEST(PointInPolygonAngleSum, NeverMisreportsBoundaryPoints) {
  // On edges and vertices the angle sum is ill-conditioned (an edge subtends pi); the exact
  // on-edge test answers there, buried edges included.
  std::mt19937_64 rng(12);
  const std::vector<Ring> rings{test::random_star(rng, 10, 0, 0, 1.0)};
  int on_boundary = 0;
  for (const Vec2& p : test::points_near_rings(rng, rings, 3)) {
    // Only points exactly on an edge: one ulp off a vertex the float sum may well be wrong.
    if (!test::oracle_on_edge(rings, p)) continue;
    ++on_boundary;
    EXPECT_EQ(point_in_polygon_angle_sum(std::span<const Ring>(rings), p),
              point_in_polygon(std::span<const Ring>(rings), p));
  }
  EXPECT_GE(on_boundary, 10);  // at least every vertex
  const std::vector<Ring> pair{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{1, 0}, {2, 0}, {2, 1}, {1, 1}}};
  EXPECT_EQ(point_in_polygon_angle_sum(std::span<const Ring>(pair), {1, 0.5}), Location::inside);
  EXPECT_EQ(point_in_polygon_angle_sum(std::span<const Ring>(pair), {1, 0}), Location::boundary);
}

TEST(PointInPolygonAngleSum, CountsWindingNumbersOfSelfIntersectingRings) {
  const Polygon star{{{{0, 10}, {6, -8}, {-10, 3}, {10, 3}, {-6, -8}}}};
  EXPECT_EQ(point_in_polygon_angle_sum(star, {0, 0}), Location::outside);
  EXPECT_EQ(point_in_polygon_angle_sum(star, {0, 0}, {.fill = Fill::nonzero}), Location::inside);
  EXPECT_EQ(point_in_polygon_angle_sum(star, {0, 8}), Location::inside);
}

}  // namespace
}  // namespace contain::inside
