#include "contain/bound/bounding_sphere.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "bound/ball_checks.h"
#include "bound/brute_force_ball.h"
#include "bound/generators.h"
#include "contain/predicates/compare_distance.h"

namespace contain::bound {
namespace {

using test::count_outside;
using test::relative_excess;

constexpr double kTight = 1e-12;

// Both methods: every point inside exactly; the exact radius within kTight of the minimum (the
// brute-force minimum, or `known_radius` for large cospherical sets, where the brute force over
// the farthest points would not see the support); Ritter never below the minimum.
void check_both(const std::vector<Vec3>& points, const std::string& what,
                std::optional<double> known_radius = std::nullopt) {
  auto exact = bounding_sphere(points);
  ASSERT_TRUE(exact.ok()) << what;
  EXPECT_EQ(count_outside(*exact, points), 0u) << what;
  if (known_radius) {
    EXPECT_NEAR(exact->radius, *known_radius, kTight * *known_radius) << what;
  } else {
    const double excess = relative_excess(*exact, points);
    EXPECT_GE(excess, 0.0) << what;
    EXPECT_LE(excess, kTight) << what;
  }
  auto ritter = bounding_sphere(points, {.method = SphereMethod::ritter});
  ASSERT_TRUE(ritter.ok()) << what;
  EXPECT_EQ(count_outside(*ritter, points), 0u) << what;
  if (!known_radius) {
    EXPECT_GE(relative_excess(*ritter, points), 0.0) << what;
  }
  EXPECT_GE(ritter->radius, exact->radius * (1.0 - kTight)) << what;
}

TEST(BoundingSphere, EmptyInputIsADegenerateError) {
  auto s = bounding_sphere(std::vector<Vec3>{});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().kind, ErrorKind::degenerate);
  EXPECT_EQ(bounding_sphere(std::vector<Vec3>{}, {.method = SphereMethod::ritter}).error().kind,
            ErrorKind::degenerate);
}

TEST(BoundingSphere, NanOrInfinityIsAnInvalidValueErrorNamingThePoint) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {nan, inf, -inf}) {
    auto s = bounding_sphere(std::vector<Vec3>{{0, 0, 0}, {1, 2, 3}, {0, bad, 0}});
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().kind, ErrorKind::invalid_value);
    EXPECT_NE(s.error().message.find("point 2"), std::string::npos);
  }
}

TEST(BoundingSphere, OnePointIsItsOwnSphereOfRadiusZero) {
  for (SphereMethod method : {SphereMethod::exact, SphereMethod::ritter}) {
    auto s = bounding_sphere(std::vector<Vec3>{{0.1, -7.25, 1e-300}}, {.method = method});
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->center, (Vec3{0.1, -7.25, 1e-300}));
    EXPECT_EQ(s->radius, 0.0);
  }
}

TEST(BoundingSphere, TwoPointsGiveTheirDiametralSphere) {
  const std::vector<Vec3> points{{1, 2, 3}, {4, 6, 15}};  // |b - a| = 13
  auto s = bounding_sphere(points);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->center, (Vec3{2.5, 4, 9}));
  EXPECT_EQ(s->radius, 6.5);
  check_both({{0.1, 0.2, 0.3}, {-0.7, 1e-3, 5.0}}, "two rounded points");
}

TEST(BoundingSphere, SmallRandomSetsMatchTheBruteForceMinimum) {
  std::mt19937_64 rng(1);
  std::uniform_int_distribution<int> small(-3, 3);  // a coarse grid: ties of every kind
  for (int trial = 0; trial < 60; ++trial) {
    const std::size_t n = 1 + static_cast<std::size_t>(trial % 10);
    check_both(test::uniform_cube(n, rng), "cube " + std::to_string(trial));
    check_both(test::gaussian(n, rng), "gaussian " + std::to_string(trial));
    std::vector<Vec3> grid(n);
    for (Vec3& p : grid)
      p = {double(small(rng)), double(small(rng)), double(small(rng))};
    check_both(grid, "grid " + std::to_string(trial));
  }
}

TEST(BoundingSphere, LargeRandomSetsAreContainedAndMinimal) {
  std::mt19937_64 rng(2);
  check_both(test::uniform_ball(40000, rng), "ball");
  check_both(test::uniform_cube(40000, rng), "cube");
  check_both(test::gaussian(40000, rng), "gaussian");
  std::vector<Vec3> slab = test::uniform_cube(40000, rng);
  for (Vec3& p : slab)
    p.z *= 1e-9;
  check_both(slab, "thin slab");
}

TEST(BoundingSphere, IntegerPointsOnASphereGiveExactlyThatSphere) {
  for (int r2 : {3, 9, 25 * 25, 2 * 3 * 5 * 7 * 11}) {
    const std::vector<Vec3> points = test::integer_sphere(r2);
    ASSERT_GE(points.size(), 8u);
    auto s = bounding_sphere(points);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(count_outside(*s, points), 0u);
    const double r = std::sqrt(double(r2));
    EXPECT_NEAR(s->radius, r, kTight * r) << r2;
    EXPECT_LE(length(s->center), kTight * r) << r2;
    check_both(points, "integer sphere " + std::to_string(r2), r);
  }
}

TEST(BoundingSphere, RoundedPointsOnTheUnitSphereGiveTheUnitSphere) {
  std::mt19937_64 rng(3);
  const std::vector<Vec3> points = test::rounded_unit_sphere(20000, rng);
  auto s = bounding_sphere(points);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(count_outside(*s, points), 0u);
  EXPECT_NEAR(s->radius, 1.0, kTight);
  auto ritter = bounding_sphere(points, {.method = SphereMethod::ritter});
  ASSERT_TRUE(ritter.ok());
  EXPECT_EQ(count_outside(*ritter, points), 0u);
  EXPECT_GE(ritter->radius, s->radius * (1.0 - kTight));
}

TEST(BoundingSphere, DuplicatesDoNotChangeTheSphere) {
  std::mt19937_64 rng(4);
  const std::vector<Vec3> base = test::gaussian(9, rng);
  std::vector<Vec3> repeated;
  for (int k = 0; k < 200; ++k)
    repeated.insert(repeated.end(), base.begin(), base.end());
  std::shuffle(repeated.begin(), repeated.end(), rng);
  auto a = bounding_sphere(base);
  auto b = bounding_sphere(repeated);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(count_outside(*b, repeated), 0u);
  EXPECT_LE(relative_excess(*b, base), kTight);
  EXPECT_NEAR(a->radius, b->radius, kTight * a->radius);
  check_both(std::vector<Vec3>(1000, Vec3{3, -1, 2}), "one point 1000 times");
}

TEST(BoundingSphere, CollinearPointsGiveTheDiametralSphereOfTheExtremes) {
  std::vector<Vec3> line;
  for (int t = -500; t <= 700; t += 3)
    line.push_back({double(t), 2.0 * t, -3.0 * t});
  std::mt19937_64 rng(5);
  std::shuffle(line.begin(), line.end(), rng);
  auto s = bounding_sphere(line);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(count_outside(*s, line), 0u);
  const Vec3 a{-500, -1000, 1500};
  const Vec3 b{700, 1400, -2100};
  EXPECT_NEAR(s->radius, 0.5 * length(b - a), kTight * s->radius);
  check_both(line, "collinear", 0.5 * length(b - a));
}

TEST(BoundingSphere, CoplanarAndCocircularSetsMatchTheBruteForceMinimum) {
  std::mt19937_64 rng(6);
  std::uniform_int_distribution<int> coord(-20, 20);
  for (int trial = 0; trial < 15; ++trial) {
    // Exactly on the plane x + y + z = 7.
    std::vector<Vec3> plane;
    for (int i = 0; i < 10; ++i) {
      const int x = coord(rng);
      const int y = coord(rng);
      plane.push_back({double(x), double(y), double(7 - x - y)});
    }
    check_both(plane, "tilted plane " + std::to_string(trial));
    std::vector<Vec3> flat = test::uniform_cube(12, rng);
    for (Vec3& p : flat)
      p.z = 0.25;
    check_both(flat, "z = 0.25 " + std::to_string(trial));
  }
  // Integer points on a circle in the plane z = 5 (x^2 + y^2 = 65^2 has 36 of them).
  std::vector<Vec3> ring;
  for (int x = -65; x <= 65; ++x) {
    for (int y = -65; y <= 65; ++y) {
      if (x * x + y * y == 65 * 65) ring.push_back({double(x), double(y), 5.0});
    }
  }
  auto s = bounding_sphere(ring);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(count_outside(*s, ring), 0u);
  EXPECT_NEAR(s->radius, 65.0, kTight * 65.0);
  check_both(ring, "cocircular", 65.0);
}

TEST(BoundingSphere, CubeCornersAndTheOctahedronGiveTheirCircumsphere) {
  std::vector<Vec3> cube;
  for (int i = 0; i < 8; ++i)
    cube.push_back({double(i & 1), double((i >> 1) & 1), double(i >> 2)});
  auto s = bounding_sphere(cube);
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s->radius, std::sqrt(3.0) / 2.0, kTight);
  check_both(cube, "cube corners");
  check_both({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}, "octahedron");
  check_both({{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}}, "square");
}

TEST(BoundingSphere, PowerOfTwoScalingScalesTheAnswerExactly) {
  std::mt19937_64 rng(7);
  std::vector<Vec3> base = test::gaussian(3000, rng);
  base.push_back({0, 0, 0});
  auto expected = bounding_sphere(base);
  ASSERT_TRUE(expected.ok());
  for (int e : {900, -900, 200, -200}) {
    std::vector<Vec3> scaled;
    for (const Vec3& p : base)
      scaled.push_back(std::ldexp(1.0, e) * p);
    auto s = bounding_sphere(scaled);
    ASSERT_TRUE(s.ok()) << e;
    EXPECT_EQ(count_outside(*s, scaled), 0u) << e;
    EXPECT_EQ(s->center, std::ldexp(1.0, e) * expected->center) << e;
    EXPECT_EQ(s->radius, std::ldexp(expected->radius, e)) << e;
    auto ritter = bounding_sphere(scaled, {.method = SphereMethod::ritter});
    ASSERT_TRUE(ritter.ok());
    EXPECT_EQ(count_outside(*ritter, scaled), 0u) << e;
  }
}

TEST(BoundingSphere, HugeAndTinyCoordinatesTogetherAreContained) {
  const double big = 1e300;
  const std::vector<Vec3> points{
      {big, 0, 0}, {-big, 1e-300, 0}, {0, 0.5 * big, 4e-320}, {5e-324, 0, 0}, {0, 0, 0.7 * big}};
  check_both(points, "mixed magnitudes");
}

TEST(BoundingSphere, SubnormalCoordinatesAreEnclosedWithinAFewSpacings) {
  // Subnormal spacing is absolute (denorm_min), so the center cannot be placed to a relative
  // accuracy: containment is exact, the radius within a few spacings of the true minimum.
  const double d = std::numeric_limits<double>::denorm_min();
  const std::vector<std::vector<Vec3>> sets{
      {{0, 0, 0}, {d, 0, 0}}, {{0, 0, 0}, {5 * d, 0, 0}, {0, 1e-320, 0}, {0, 0, -3e-321}}};
  for (const std::vector<Vec3>& points : sets) {
    // Squares of subnormals underflow any double: compare in rationals.
    const mpq_class minimum2 =
        test::brute_force_min_ball(std::span<const Vec3>(points)).squared_radius;
    for (SphereMethod method : {SphereMethod::exact, SphereMethod::ritter}) {
      auto s = bounding_sphere(points, {.method = method});
      ASSERT_TRUE(s.ok());
      EXPECT_EQ(count_outside(*s, points), 0u);
      if (method == SphereMethod::exact) {
        const double below = s->radius - 4 * d;  // exact: subnormals share one spacing
        EXPECT_TRUE(below <= 0 || test::exact_square(below) <= minimum2);
      }
    }
  }
  auto s = bounding_sphere(std::vector<Vec3>{{0, 0, 0}, {2 * d, 0, 0}});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->center, (Vec3{d, 0, 0}));
  EXPECT_EQ(s->radius, d);
}

TEST(BoundingSphere, RadiusBeyondTheLargestDoubleIsUnsupported) {
  const double m = std::numeric_limits<double>::max();
  auto s = bounding_sphere(std::vector<Vec3>{{m, m, m}, {-m, -m, -m}});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().kind, ErrorKind::unsupported);
  auto fits = bounding_sphere(std::vector<Vec3>{{m, 0, 0}, {-m, 0, 0}});
  ASSERT_TRUE(fits.ok());
  EXPECT_EQ(fits->radius, m);
}

TEST(BoundingSphere, SetsFarFromTheOriginStayAccurate) {
  std::mt19937_64 rng(8);
  std::vector<Vec3> points = test::uniform_ball(5000, rng);
  for (Vec3& p : points)
    p = p + Vec3{100.0, -60.0, 30.0};
  check_both(points, "offset ball");
}

TEST(BoundingSphere, AMillionSortedPointsNeedNoDeepRecursion) {
  // Sorted input is the worst order for Welzl without shuffling; recursion depth stays <= 4.
  std::mt19937_64 rng(10);
  std::vector<Vec3> points = test::uniform_cube(1'000'000, rng);
  for (int i = 0; i < 8; ++i) {
    points.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  }
  std::sort(points.begin(), points.end(), [](Vec3 a, Vec3 b) { return a.x < b.x; });
  auto s = bounding_sphere(points);
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s->radius, std::sqrt(3.0), kTight);
  std::size_t outside = 0;
  for (const Vec3& p : points) {
    outside += predicates::side_of_sphere(*s, p) == Sign::negative ? 1 : 0;
  }
  EXPECT_EQ(outside, 0u);
}

TEST(BoundingSphere, IsDeterministic) {
  std::mt19937_64 rng(9);
  const std::vector<Vec3> points = test::uniform_ball(20000, rng);
  auto a = bounding_sphere(points);
  auto b = bounding_sphere(points);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(*a, *b);
}

TEST(BoundingSphere, MeshEnclosesReferencedVerticesUnlessAllAreAsked) {
  auto mesh = Mesh::from_arrays({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {50, 50, 50}},
                                {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  ASSERT_TRUE(mesh.ok());
  auto referenced = bounding_sphere(*mesh);
  ASSERT_TRUE(referenced.ok());
  EXPECT_LT(referenced->radius, 1.0);
  auto all = bounding_sphere(*mesh, {.vertices = MeshVertices::all});
  ASSERT_TRUE(all.ok());
  EXPECT_GT(all->radius, 40.0);
  EXPECT_EQ(count_outside(*all, mesh->vertices), 0u);
  auto bare = Mesh::from_arrays({{0, 0, 0}}, {});
  ASSERT_TRUE(bare.ok());
  EXPECT_EQ(bounding_sphere(*bare).error().kind, ErrorKind::degenerate);
  EXPECT_TRUE(bounding_sphere(*bare, {.vertices = MeshVertices::all}).ok());
}

}  // namespace
}  // namespace contain::bound
