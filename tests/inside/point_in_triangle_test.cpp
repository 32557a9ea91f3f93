#include "contain/inside/point_in_triangle.h"

#include <gtest/gtest.h>

#include <random>

#include "support/exact.h"

namespace contain::inside {
namespace {

constexpr PointInTriangleOptions kSameSide{.method = TriangleMethod::same_side};
constexpr PointInTriangleOptions kProjected{.method = TriangleMethod::projected};

// The truth for a point in the triangle's plane (or its prism), from GMP rationals.
Location oracle(const Triangle3& t, Vec3 p) {
  const Sign s[3] = {test::exact_cross_dot(t.a, t.b, p, t.c),
                     test::exact_cross_dot(t.b, t.c, p, t.a),
                     test::exact_cross_dot(t.c, t.a, p, t.b)};
  for (Sign x : s) {
    if (x == Sign::negative) return Location::outside;
  }
  for (Sign x : s) {
    if (x == Sign::zero) return Location::boundary;
  }
  return Location::inside;
}

TEST(PointInTriangle, BothMethodsClassifyInteriorEdgesVerticesAndOutside) {
  const Triangle3 t{{0, 0, 0}, {4, 0, 0}, {0, 4, 4}};
  for (const PointInTriangleOptions& o : {kSameSide, kProjected}) {
    EXPECT_EQ(point_in_triangle(t, {1, 1, 1}, o), Location::inside);
    EXPECT_EQ(point_in_triangle(t, {2, 0, 0}, o), Location::boundary);  // edge ab
    EXPECT_EQ(point_in_triangle(t, {2, 2, 2}, o), Location::boundary);  // edge bc
    EXPECT_EQ(point_in_triangle(t, {0, 2, 2}, o), Location::boundary);  // edge ca
    EXPECT_EQ(point_in_triangle(t, {4, 0, 0}, o), Location::boundary);  // vertex
    EXPECT_EQ(point_in_triangle(t, {3, 3, 3}, o), Location::outside);
    EXPECT_EQ(point_in_triangle(t, {-1, 1, 1}, o), Location::outside);
  }
}

TEST(PointInTriangle, WindingOfTheVerticesDoesNotMatter) {
  const Triangle3 ccw{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}, cw{{0, 0, 1}, {0, 1, 1}, {1, 0, 1}};
  for (const PointInTriangleOptions& o : {kSameSide, kProjected}) {
    EXPECT_EQ(point_in_triangle(ccw, {0.25, 0.25, 1}, o), Location::inside);
    EXPECT_EQ(point_in_triangle(cw, {0.25, 0.25, 1}, o), Location::inside);
    EXPECT_EQ(point_in_triangle(cw, {0.5, 0.5, 1}, o), Location::boundary);
  }
}

TEST(PointInTriangle, SameSideAnswersForTheOrthogonalProjectionInThePrism) {
  const Triangle3 t{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  EXPECT_EQ(point_in_triangle(t, {1, 1, 7}, kSameSide), Location::inside);
  EXPECT_EQ(point_in_triangle(t, {2, 2, -3}, kSameSide), Location::boundary);
  EXPECT_EQ(point_in_triangle(t, {3, 3, 1}, kSameSide), Location::outside);
}

TEST(PointInTriangle, DegenerateTriangleIsItsSegment) {
  const Triangle3 t{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}};
  for (const PointInTriangleOptions& o : {kSameSide, kProjected}) {
    EXPECT_EQ(point_in_triangle(t, {2, 2, 2}, o), Location::boundary);
    EXPECT_EQ(point_in_triangle(t, {4, 4, 4}, o), Location::outside);
    EXPECT_EQ(point_in_triangle(t, {1, 1, 0}, o), Location::outside);
  }
  const Triangle3 point{{1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
  EXPECT_EQ(point_in_triangle(point, {1, 2, 3}), Location::boundary);
  EXPECT_EQ(point_in_triangle(point, {1, 2, 3.5}), Location::outside);
}

TEST(PointInTriangle, ProjectedSkipsAnAxisAlongWhichTheTriangleIsASegment) {
  // Normal (0, 0, 1) exactly, but also a triangle whose float normal is tiny and the exact
  // projection along the float's largest axis could vanish: vertical triangles in x = const.
  const Triangle3 t{{2, 0, 0}, {2, 1, 0}, {2, 0, 1}};
  EXPECT_EQ(point_in_triangle(t, {2, 0.25, 0.25}, kProjected), Location::inside);
  EXPECT_EQ(point_in_triangle(t, {2, 0.5, 0.5}, kProjected), Location::boundary);
  EXPECT_EQ(point_in_triangle(t, {2, 0.75, 0.5}, kProjected), Location::outside);
}

// Points exactly in the plane: lattice points a + (i/16)(b - a) + (j/16)(c - a) of an integer
// triangle are exact doubles and include edge and vertex cases.
TEST(PointInTriangle, BothMethodsAgreeWithTheGmpOracleOnExactInPlaneLatticePoints) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> coord(-50, 50);
  int boundary = 0, inside = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Vec3 a{double(coord(rng)), double(coord(rng)), double(coord(rng))};
    const Vec3 b{double(coord(rng)), double(coord(rng)), double(coord(rng))};
    const Vec3 c{double(coord(rng)), double(coord(rng)), double(coord(rng))};
    const Triangle3 t{a, b, c};
    for (int i = -4; i <= 20; i += 2) {
      for (int j = -4; j <= 20; j += 2) {
        const Vec3 p = a + (i / 16.0) * (b - a) + (j / 16.0) * (c - a);
        ASSERT_EQ(test::exact_orient3d(a, b, c, p), Sign::zero);  // really in the plane
        const Location truth = oracle(t, p);
        boundary += truth == Location::boundary;
        inside += truth == Location::inside;
        EXPECT_EQ(point_in_triangle(t, p, kSameSide), truth);
        EXPECT_EQ(point_in_triangle(t, p, kProjected), truth);
      }
    }
  }
  EXPECT_GT(boundary, 100);
  EXPECT_GT(inside, 100);
}

// Random doubles in an axis plane z = const are exactly in the triangle's plane; near-edge points
// (rounded onto the edge) make the floating-point formulas unreliable.
TEST(PointInTriangle, BothMethodsAgreeWithTheGmpOracleOnNearEdgePointsOfTiltedAndFlatTriangles) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 3000; ++trial) {
    const double z = u(rng);
    const Triangle3 t{{u(rng), u(rng), z}, {u(rng), u(rng), z}, {u(rng), u(rng), z}};
    const double s = 0.5 + 0.5 * u(rng);
    Vec3 p = t.a + s * (t.b - t.a);  // on edge ab up to rounding
    p.z = z;
    p.x = std::nextafter(p.x, trial % 3 == 0 ? 2.0 : (trial % 3 == 1 ? -2.0 : p.x));
    const Location truth = oracle(t, p);
    EXPECT_EQ(point_in_triangle(t, p, kSameSide), truth);
    EXPECT_EQ(point_in_triangle(t, p, kProjected), truth);
  }
}

// Tilted plane x + y + z = 1 (multiples of 2^-k keep the points exactly in it).
TEST(PointInTriangle, ProjectedAgreesWithTheOracleOnTheTiltedPlaneWithEqualNormalComponents) {
  const Triangle3 t{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = -2; i <= 34; ++i) {
    for (int j = -2; j <= 34 - i; ++j) {
      const Vec3 p{i / 32.0, j / 32.0, 1 - i / 32.0 - j / 32.0};
      ASSERT_EQ(test::exact_orient3d(t.a, t.b, t.c, p), Sign::zero);
      EXPECT_EQ(point_in_triangle(t, p, kProjected), oracle(t, p)) << i << " " << j;
      EXPECT_EQ(point_in_triangle(t, p, kSameSide), oracle(t, p)) << i << " " << j;
    }
  }
}

}  // namespace
}  // namespace contain::inside
