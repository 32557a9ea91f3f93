// Crossings of segments with axis-aligned planes, rounded once, against GMP rationals.

#include "contain/predicates/rounded_crossing.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/case_budget.h"

namespace contain::test {
namespace {

double coord(Vec3 p, int i) {
  return i == 0 ? p.x : (i == 1 ? p.y : p.z);
}

// True when x is a double nearest to the rational q (no neighbour of x is strictly nearer).
bool is_nearest(double x, const mpq_class& q) {
  const mpq_class err = abs(mpq_class(x) - q);
  for (const double n : {std::nextafter(x, -INFINITY), std::nextafter(x, INFINITY)}) {
    if (std::isfinite(n) && abs(mpq_class(n) - q) < err) return false;
  }
  return true;
}

void expect_nearest(Vec3 a, Vec3 b, int axis, double c) {
  const Vec3 got = predicates::rounded_axis_crossing(a, b, axis, c);
  EXPECT_EQ(coord(got, axis), c);
  const mpq_class t =
      (mpq_class(c) - coord(a, axis)) / (mpq_class(coord(b, axis)) - coord(a, axis));
  for (int j = 0; j < 3; ++j) {
    if (j == axis) continue;
    const mpq_class exact = mpq_class(coord(a, j)) + t * (mpq_class(coord(b, j)) - coord(a, j));
    EXPECT_TRUE(is_nearest(coord(got, j), exact))
        << "coordinate " << j << " of the crossing of (" << a.x << " " << a.y << " " << a.z << ") ("
        << b.x << " " << b.y << " " << b.z << ") with " << c;
  }
  const Vec3 back = predicates::rounded_axis_crossing(b, a, axis, c);
  EXPECT_TRUE(back == got) << "not symmetric";
}

TEST(RoundedAxisCrossing, RandomSegmentsGiveTheNearestDoubles) {
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  const int cases = case_budget(20000, 10);
  for (int i = 0; i < cases; ++i) {
    const double s = std::ldexp(1.0, exponent(rng));
    const Vec3 a{s * unit(rng), s * unit(rng), s * unit(rng)};
    const Vec3 b{s * unit(rng), s * unit(rng), s * unit(rng)};
    const int axis = i % 3;
    if (coord(a, axis) == coord(b, axis)) continue;
    const double f = 0.5 + 0.5 * unit(rng);
    const double c = coord(a, axis) + f * (coord(b, axis) - coord(a, axis));
    if (c < std::min(coord(a, axis), coord(b, axis)) ||
        c > std::max(coord(a, axis), coord(b, axis))) {
      continue;
    }
    expect_nearest(a, b, axis, c);
  }
}

TEST(RoundedAxisCrossing, HardCasesNearTiesAndTinyRisesAreExact) {
  // A rise of one ulp over a long run: the quotient's error bound is loose, the exact stage
  // decides.
  const double z0 = 1.0;
  const double z1 = std::nextafter(1.0, 2.0);
  expect_nearest({0, 0, z0}, {1e10, -3e9, z1}, 2, z0);
  expect_nearest({0.1, 0.7, z0}, {1e10 + 0.3, -3e9, z1}, 2, z1);
  // Crossings at exact midpoints between doubles (ties go to even), and far from the origin.
  expect_nearest({0, 0, 0}, {std::ldexp(1.0, -52) * 3, 1, 2}, 2, 1);
  expect_nearest({1e15, -1e15, -1}, {1e15 + 3, 7, 1}, 2, 0);
  expect_nearest({1e-300, 2e-300, -1e-300}, {3e-300, -5e-300, 1e-300}, 2, 1e-301);
  expect_nearest({1e200, 2e200, -1e200}, {-3e200, 5e200, 1e200}, 2, 1e199);
  // Endpoints on the plane are returned bit for bit.
  const Vec3 a{0.1, 0.2, 0.3};
  const Vec3 b{1.1, 1.2, 1.3};
  EXPECT_TRUE(predicates::rounded_axis_crossing(a, b, 2, 0.3) == a);
  EXPECT_TRUE(predicates::rounded_axis_crossing(a, b, 0, 1.1) == b);
}

}  // namespace
}  // namespace contain::test
