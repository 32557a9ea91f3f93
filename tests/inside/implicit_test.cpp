#include "contain/inside/implicit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "support/exact.h"

namespace contain::inside {
namespace {

TEST(PointInSphere, PointAtDistanceExactlyRadiusIsBoundary) {
  const Sphere s{{0, 0, 0}, 5};
  EXPECT_EQ(point_in_sphere(s, {3, 4, 0}), Location::boundary);
  EXPECT_EQ(point_in_sphere(s, {0, -3, 4}), Location::boundary);
  EXPECT_EQ(point_in_sphere(s, {3, 4, 1e-300}), Location::outside);
  EXPECT_EQ(point_in_sphere(s, {3, 3.9999999999999996, 0}), Location::inside);
}

TEST(PointInSphere, AgreesWithTheExactOracleOnRandomAndNearSurfacePoints) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int i = 0; i < 2000; ++i) {
    const Sphere s{{u(rng), u(rng), u(rng)}, std::fabs(u(rng))};
    Vec3 p{u(rng), u(rng), u(rng)};
    if (i % 2 == 0) {  // push p onto the surface in floating point: near-ties
      const Vec3 d = p - s.center;
      p = s.center + (s.radius / length(d)) * d;
    }
    const Sign truth = test::exact_side_of_sphere(s, p);
    EXPECT_EQ(static_cast<int>(point_in_sphere(s, p)), to_int(truth));
  }
}

TEST(PointInHalfspace, SignOfTheExpressionDecides) {
  const Plane h{1, 1, 1, -1};  // x + y + z >= 1
  EXPECT_EQ(point_in_halfspace(h, {1, 0, 0}), Location::boundary);
  EXPECT_EQ(point_in_halfspace(h, {1, 1, 0}), Location::inside);
  EXPECT_EQ(point_in_halfspace(h, {0, 0, 0}), Location::outside);
  // 0.1 + 0.2 + 0.7 rounds to 1 in floating point but is not 1 exactly.
  EXPECT_EQ(static_cast<int>(point_in_halfspace(h, {0.1, 0.2, 0.7})),
            to_int(test::exact_side_of_plane(h, {0.1, 0.2, 0.7})));
}

TEST(PointInHalfspace, AgreesWithTheExactOracle) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 2000; ++i) {
    const Plane h{u(rng), u(rng), u(rng), 0};
    Vec3 p{u(rng), u(rng), u(rng)};
    const Plane hp{h.a, h.b, h.c, -(h.a * p.x + h.b * p.y + h.c * p.z)};  // nearly through p
    EXPECT_EQ(static_cast<int>(point_in_halfspace(hp, p)),
              to_int(test::exact_side_of_plane(hp, p)));
  }
}

TEST(PointInBox, FacesEdgesAndCornersAreBoundary) {
  const Box3 b{{0, 0, 0}, {1, 2, 3}};
  EXPECT_EQ(point_in_box(b, {0.5, 1, 1}), Location::inside);
  EXPECT_EQ(point_in_box(b, {0, 1, 1}), Location::boundary);  // face
  EXPECT_EQ(point_in_box(b, {1, 2, 1}), Location::boundary);  // edge
  EXPECT_EQ(point_in_box(b, {1, 2, 3}), Location::boundary);  // corner
  EXPECT_EQ(point_in_box(b, {1, 2, 3.0000000000000004}), Location::outside);
  EXPECT_EQ(point_in_box(b, {-1e-300, 1, 1}), Location::outside);
}

TEST(PointInBox, FlatBoxHasOnlyBoundaryAndEmptyBoxNothing) {
  EXPECT_EQ(point_in_box({{0, 0, 0}, {1, 1, 0}}, {0.5, 0.5, 0}), Location::boundary);
  EXPECT_EQ(point_in_box(Box3{}, {0, 0, 0}), Location::outside);
}

TEST(PointInImplicit, BoundaryExactlyWhereTheEvaluatedValueIsZero) {
  const ImplicitFunction ball = [](Vec3 p) { return 1 - p.x * p.x - p.y * p.y - p.z * p.z; };
  EXPECT_EQ(point_in_implicit(ball, {0, 0, 0}), Location::inside);
  EXPECT_EQ(point_in_implicit(ball, {1, 0, 0}), Location::boundary);
  // Evaluated, 1 - 0.6^2 - 0.8^2 is -1.1e-16: the answer is only as exact as the evaluation.
  EXPECT_EQ(point_in_implicit(ball, {0.6, 0.8, 0}), Location::outside);
  EXPECT_EQ(point_in_implicit(ball, {2, 0, 0}), Location::outside);
}

TEST(PointInImplicit, NanIsOutside) {
  const ImplicitFunction f = [](Vec3) { return std::numeric_limits<double>::quiet_NaN(); };
  EXPECT_EQ(point_in_implicit(f, {0, 0, 0}), Location::outside);
}

}  // namespace
}  // namespace contain::inside
