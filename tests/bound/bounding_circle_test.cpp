#include "contain/bound/bounding_circle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "bound/ball_checks.h"
#include "bound/generators.h"

namespace contain::bound {
namespace {

using test::count_outside;
using test::relative_excess;

constexpr double kCircleTight = 1e-12;

// Both methods: every point inside exactly; the exact radius within kCircleTight of the minimum
// (the brute-force minimum, or `known_radius` for large cospherical sets, where the brute force
// over the farthest points would not see the support); Ritter never below the minimum.
void check_both(const std::vector<Vec2>& points, const std::string& what,
                std::optional<double> known_radius = std::nullopt) {
  auto exact = bounding_circle(points);
  ASSERT_TRUE(exact.ok()) << what;
  EXPECT_EQ(count_outside(*exact, points), 0u) << what;
  if (known_radius) {
    EXPECT_NEAR(exact->radius, *known_radius, kCircleTight * *known_radius) << what;
  } else {
    const double excess = relative_excess(*exact, points);
    EXPECT_GE(excess, 0.0) << what;
    EXPECT_LE(excess, kCircleTight) << what;
  }
  auto ritter = bounding_circle(points, {.method = SphereMethod::ritter});
  ASSERT_TRUE(ritter.ok()) << what;
  EXPECT_EQ(count_outside(*ritter, points), 0u) << what;
  if (!known_radius) {
    EXPECT_GE(relative_excess(*ritter, points), 0.0) << what;
  }
  EXPECT_GE(ritter->radius, exact->radius * (1.0 - kCircleTight)) << what;
}

std::vector<Vec2> random_points(std::size_t n, std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  std::vector<Vec2> out(n);
  for (Vec2& p : out)
    p = {g(rng), g(rng)};
  return out;
}

TEST(BoundingCircle, EmptyInputAndNanAreErrors) {
  EXPECT_EQ(bounding_circle(std::vector<Vec2>{}).error().kind, ErrorKind::degenerate);
  auto nan = bounding_circle(std::vector<Vec2>{{0, std::numeric_limits<double>::quiet_NaN()}});
  ASSERT_FALSE(nan.ok());
  EXPECT_EQ(nan.error().kind, ErrorKind::invalid_value);
  EXPECT_EQ(bounding_circle(Polygon{}).error().kind, ErrorKind::degenerate);
}

TEST(BoundingCircle, OneAndTwoPointsGiveTheExpectedCircle) {
  auto one = bounding_circle(std::vector<Vec2>{{3, 4}});
  ASSERT_TRUE(one.ok());
  EXPECT_EQ(*one, (Circle{{3, 4}, 0.0}));
  auto two = bounding_circle(std::vector<Vec2>{{0, 0}, {6, 8}});
  ASSERT_TRUE(two.ok());
  EXPECT_EQ(*two, (Circle{{3, 4}, 5.0}));
}

TEST(BoundingCircle, SmallRandomAndGridSetsMatchTheBruteForceMinimum) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> small(-3, 3);
  for (int trial = 0; trial < 96; ++trial) {
    const std::size_t n = 1 + static_cast<std::size_t>(trial % 12);
    check_both(random_points(n, rng), "gaussian " + std::to_string(trial));
    std::vector<Vec2> grid(n);
    for (Vec2& p : grid)
      p = {double(small(rng)), double(small(rng))};
    check_both(grid, "grid " + std::to_string(trial));
  }
}

TEST(BoundingCircle, LargeRandomSetsAreContainedAndMinimal) {
  std::mt19937_64 rng(12);
  check_both(random_points(50000, rng), "gaussian");
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec2> square(50000);
  for (Vec2& p : square)
    p = {u(rng), u(rng)};
  check_both(square, "square");
}

TEST(BoundingCircle, CocircularIntegerPointsGiveExactlyTheirCircle) {
  for (int r2 : {25, 65 * 65, 5 * 5 * 13 * 13 * 17 * 17}) {
    const std::vector<Vec2> points = test::integer_circle(r2);
    auto c = bounding_circle(points);
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(count_outside(*c, points), 0u);
    const double r = std::sqrt(double(r2));
    EXPECT_NEAR(c->radius, r, kCircleTight * r);
    check_both(points, "integer circle " + std::to_string(r2), r);
  }
}

TEST(BoundingCircle, CollinearAndDuplicatePointsAreHandled) {
  std::vector<Vec2> line;
  for (int t = -40; t <= 90; ++t)
    line.push_back({double(t), 3.0 * t - 1.0});
  for (int k = 0; k < 5; ++k)
    line.push_back({0.0, -1.0});
  check_both(line, "collinear with duplicates");
  check_both(std::vector<Vec2>(500, Vec2{1e-310, -2.0}), "one point 500 times");
}

TEST(BoundingCircle, PowerOfTwoScalingScalesTheAnswerExactly) {
  std::mt19937_64 rng(13);
  const std::vector<Vec2> base = random_points(2000, rng);
  auto expected = bounding_circle(base);
  ASSERT_TRUE(expected.ok());
  for (int e : {950, -950}) {
    std::vector<Vec2> scaled;
    for (const Vec2& p : base)
      scaled.push_back(std::ldexp(1.0, e) * p);
    auto c = bounding_circle(scaled);
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(count_outside(*c, scaled), 0u);
    EXPECT_EQ(c->radius, std::ldexp(expected->radius, e));
  }
}

TEST(BoundingCircle, PolygonEnclosesEveryRingPoint) {
  auto polygon =
      Polygon::from_rings({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 2}, {3, 2}, {3, 3}}});
  ASSERT_TRUE(polygon.ok());
  auto c = bounding_circle(*polygon);
  ASSERT_TRUE(c.ok());
  EXPECT_NEAR(c->radius, std::sqrt(50.0), kCircleTight);
  EXPECT_EQ(c->center, (Vec2{5, 5}));
  auto far = Polygon::from_rings({{{30, 0}, {31, 0}, {30, 1}}});
  ASSERT_TRUE(far.ok());
  auto both = bounding_circle(MultiPolygon{{*polygon, *far}});
  ASSERT_TRUE(both.ok());
  EXPECT_NEAR(both->radius, 0.5 * std::hypot(31.0, 10.0), kCircleTight);
  EXPECT_EQ(bounding_circle(MultiPolygon{}).error().kind, ErrorKind::degenerate);
}

}  // namespace
}  // namespace contain::bound
