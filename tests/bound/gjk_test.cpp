#include "contain/bound/gjk.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace contain::bound {
namespace {

Support polytope(std::vector<Vec3> vertices) {
  return [vertices = std::move(vertices)](Vec3 d) {
    Vec3 best = vertices[0];
    for (const Vec3& p : vertices)
      if (dot(d, p) > dot(d, best)) best = p;
    return best;
  };
}

std::vector<Vec3> cube(Vec3 min, double side) {
  std::vector<Vec3> out;
  for (int i = 0; i < 8; ++i)
    out.push_back(
        {min.x + side * (i & 1), min.y + side * ((i >> 1) & 1), min.z + side * ((i >> 2) & 1)});
  return out;
}

TEST(Gjk, SeparatedCubesGiveTheirGapAndClosestPointsOnTheFacingSides) {
  // A = [3, 4]^3 shifted, B = [0, 1]^3: the gap along x is 2 (y and z overlap).
  const GjkResult r = gjk(polytope(cube({3, 0, 0}, 1)), polytope(cube({0, 0, 0}, 1)));
  EXPECT_FALSE(r.origin_inside);
  EXPECT_NEAR(length(r.v), 2.0, 1e-12);
  EXPECT_NEAR(r.lower, 2.0, 1e-12);
  EXPECT_NEAR(r.point_a.x, 3.0, 1e-12);
  EXPECT_NEAR(r.point_b.x, 1.0, 1e-12);
  EXPECT_NEAR(length(r.point_a - r.point_b), 2.0, 1e-12);
  EXPECT_GE(r.simplex_size, 1);
}

TEST(Gjk, DiagonalGapIsReachedFromTheCornersWithALowerBoundBelowIt) {
  // Corner (1, 1, 1) of B against corner (2, 2, 2) of A: distance sqrt(3).
  const GjkResult r = gjk(polytope(cube({2, 2, 2}, 1)), polytope(cube({0, 0, 0}, 1)));
  EXPECT_NEAR(length(r.v), std::sqrt(3.0), 1e-12);
  EXPECT_LE(r.lower, length(r.v) * (1 + 1e-15));
  EXPECT_NEAR(r.point_a.x, 2.0, 1e-12);
  EXPECT_NEAR(r.point_b.z, 1.0, 1e-12);
}

TEST(Gjk, OverlappingSetsFindTheOrigin) {
  const GjkResult r = gjk(polytope(cube({0.5, 0.5, 0.5}, 1)), polytope(cube({0, 0, 0}, 1)));
  EXPECT_TRUE(r.origin_inside);
  EXPECT_EQ(length(r.v), 0.0);
}

TEST(Gjk, SpheresByTheirSupportGiveTheGapBetweenCentresLessTheRadii) {
  const auto ball = [](Vec3 c, double radius) {
    return Support([c, radius](Vec3 d) {
      const double len = length(d);
      return len > 0 ? c + (radius / len) * d : c;
    });
  };
  const GjkResult r = gjk(ball({5, 0, 0}, 1), ball({0, 0, 0}, 2));
  EXPECT_FALSE(r.origin_inside);
  EXPECT_NEAR(length(r.v), 2.0, 1e-6);
  EXPECT_LE(r.lower, 2.0 + 1e-12);
}

}  // namespace
}  // namespace contain::bound
