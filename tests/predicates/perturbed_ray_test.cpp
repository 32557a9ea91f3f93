// The perturbed +x ray of point in polyhedron (contain/predicates/perturbed_ray.h) against the
// GMP oracle, on random and on constructed degenerate configurations.

#include "contain/predicates/perturbed_ray.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "support/perturbed_ray_oracle.h"

namespace contain::predicates {
namespace {

using test::oracle_on_triangle;
using test::oracle_ray_crosses;

bool crosses(const Triangle3& t, Vec3 q) {
  return perturbed_ray_crosses(t.a, t.b, t.c, q);
}

TEST(PerturbedRay, RandomTrianglesAndPointsMatchTheExactOracle) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int crossings = 0;
  for (int k = 0; k < 3000; ++k) {
    const Triangle3 t{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
    const Vec3 q{u(rng) - 0.5, 0.5 * u(rng), 0.5 * u(rng)};
    ASSERT_EQ(crosses(t, q), oracle_ray_crosses(t, q)) << k;
    crossings += crosses(t, q);
  }
  EXPECT_GT(crossings, 100);
}

TEST(PerturbedRay, RaysThroughVerticesEdgesAndCoplanarTrianglesMatchTheExactOracle) {
  // Vertices on a small integer grid, query points on the half-integer grid: the rays run
  // through vertices, along edges and in the planes of triangles, over and over.
  std::mt19937_64 rng(12);
  std::uniform_int_distribution<int> vi(0, 3), qi(-1, 7);
  int checked = 0, crossings = 0;
  for (int k = 0; k < 20000; ++k) {
    auto v = [&] { return Vec3{double(vi(rng)), double(vi(rng)), double(vi(rng))}; };
    const Triangle3 t{v(), v(), v()};
    const Vec3 q{0.5 * qi(rng), 0.5 * qi(rng), 0.5 * qi(rng)};
    if (oracle_on_triangle(t, q)) continue;  // precondition: q not on the triangle
    ASSERT_EQ(crosses(t, q), oracle_ray_crosses(t, q)) << k;
    ++checked;
    crossings += crosses(t, q);
  }
  EXPECT_GT(checked, 15000);
  EXPECT_GT(crossings, 500);
}

TEST(PerturbedRay, ARayThroughASharedEdgeCrossesExactlyOneOfItsTwoTriangles) {
  // A square in the plane x = 1 split along its diagonal a-c.
  const Vec3 a{1, 0, 0}, b{1, 2, 0}, c{1, 2, 2}, d{1, 0, 2};
  for (double s : {0.25, 0.5, 1.0, 1.5}) {
    const Vec3 q{0, s, s};  // (y, z) on the diagonal a-c
    EXPECT_EQ(crosses({a, b, c}, q) + crosses({a, c, d}, q), 1) << s;
  }
}

TEST(PerturbedRay, ARayThroughAFanVertexCrossesExactlyOneTriangleOfTheFan) {
  // Six triangles around the centre (1, 1, 1) of a hexagon in the plane x = 1 (tilted fans too).
  for (double tilt : {0.0, 0.25, -1.0}) {
    const Vec3 centre{1, 1, 1};
    std::vector<Vec3> ring;
    const double ys[6] = {2, 1.5, 0.5, 0, 0.5, 1.5}, zs[6] = {1, 2, 2, 1, 0, 0};
    for (int i = 0; i < 6; ++i)
      ring.push_back({1 + tilt * (ys[i] - 1), ys[i], zs[i]});
    int count = 0;
    const Vec3 q{-3, 1, 1};
    for (int i = 0; i < 6; ++i) {
      const Triangle3 t{centre, ring[static_cast<std::size_t>(i)],
                        ring[static_cast<std::size_t>((i + 1) % 6)]};
      EXPECT_EQ(crosses(t, q), oracle_ray_crosses(t, q));
      count += crosses(t, q);
    }
    EXPECT_EQ(count, 1) << tilt;
  }
}

TEST(PerturbedRay, TrianglesParallelToTheRayAreNeverCrossed) {
  const Triangle3 t{{0, 0, 0}, {4, 0, 0}, {0, 0, 4}};  // the plane y = 0 contains +x
  for (double z : {-1.0, 0.0, 1.0, 2.0})
    EXPECT_FALSE(crosses(t, {-1, 0, z}));
}

TEST(PerturbedRay, HitSideOnAGridPlaneIsTheLimitOfTheHitsAroundIt) {
  // A triangle through x = 2 at (y, z) = (1, 1): the hit of the line at (., 1, 1) is x = 2
  // exactly; the perturbed hit lies beyond or before x = 2 by the triangle's slope, consistently.
  const Vec3 a{2, 0, 0}, b{2, 3, 0}, c{2 + 3, 0, 3};  // x = 2 + z
  const Sign s = projected_sign(a, b, c);
  ASSERT_NE(s, Sign::zero);
  EXPECT_TRUE(perturbed_line_hits(a, b, c, s, {0, 1, 1}));
  // x(e) = 2 + (1 + e^2) > 3 = m.x? At m.x = 3: hit exactly at 3 + e^2: beyond.
  EXPECT_EQ(hit_side(a, b, c, s, {3, 1, 1}), 1);
  EXPECT_EQ(hit_side(a, b, c, s, {3.0000000000000004, 1, 1}), -1);
  // A triangle in the plane x = 3: the hit is at 3 exactly, whatever the perturbation.
  EXPECT_EQ(hit_side({3, 0, 0}, {3, 3, 0}, {3, 0, 3},
                     projected_sign({3, 0, 0}, {3, 3, 0}, {3, 0, 3}), {3, 1, 1}),
            0);
}

}  // namespace
}  // namespace contain::predicates
