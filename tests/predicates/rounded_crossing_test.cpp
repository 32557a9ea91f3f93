// Crossings of segments with axis-aligned planes and with the planes of triangles, rounded
// once, against GMP rationals.

#include "contain/predicates/rounded_crossing.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "support/case_budget.h"
#include "support/exact.h"

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

// ---- segments through the planes of triangles --------------------------------------------------

// The nearest double with ties to even: is_nearest, and on a tie the even neighbour.
bool is_rounded(double x, const mpq_class& q) {
  if (!is_nearest(x, q)) return false;
  const mpq_class err = abs(mpq_class(x) - q);
  for (const double n : {std::nextafter(x, -INFINITY), std::nextafter(x, INFINITY)}) {
    if (std::isfinite(n) && abs(mpq_class(n) - q) == err) {
      return (std::bit_cast<std::uint64_t>(x) & 1U) == 0;
    }
  }
  return true;
}

// Checks the crossing against the rationals; false (nothing checked) when p and q are not
// strictly on opposite sides of the plane (the precondition).
bool expect_plane_crossing(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  const QVec3 n = qcross(qsub(exact(b), exact(a)), qsub(exact(c), exact(a)));
  const mpq_class dp = qdot(n, qsub(exact(p), exact(a))), dq = qdot(n, qsub(exact(q), exact(a)));
  if (sgn(dp) * sgn(dq) >= 0) return false;
  const mpq_class t = dp / (dp - dq);
  const Vec3 got = predicates::rounded_plane_crossing(p, q, a, b, c);
  for (int j = 0; j < 3; ++j) {
    const mpq_class x = mpq_class(coord(p, j)) + t * (mpq_class(coord(q, j)) - coord(p, j));
    EXPECT_TRUE(is_rounded(coord(got, j), x))
        << "coordinate " << j << " of (" << p.x << " " << p.y << " " << p.z << ") (" << q.x << " "
        << q.y << " " << q.z << ") through (" << a.x << " " << a.y << " " << a.z << ") ...";
  }
  EXPECT_TRUE(predicates::rounded_plane_crossing(q, p, a, b, c) == got) << "not symmetric";
  EXPECT_TRUE(predicates::rounded_plane_crossing(p, q, b, c, a) == got) << "depends on a b c";
  return true;
}

Vec3 scaled(Vec3 v, double s) {
  return {v.x * s, v.y * s, v.z * s};
}

TEST(RoundedPlaneCrossing, RandomSegmentsAndTrianglesGiveTheNearestDoubles) {
  std::mt19937_64 rng(27);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  const auto point = [&](double s) { return Vec3{s * unit(rng), s * unit(rng), s * unit(rng)}; };
  const int cases = case_budget(4000, 10);
  int checked = 0;
  for (int i = 0; i < cases; ++i) {
    const double s = std::ldexp(1.0, exponent(rng));
    // A far-off plane makes cancellation in d_p and d_q: some in each regime.
    const Vec3 shift = i % 4 == 0 ? point(1e6 * s) : Vec3{0, 0, 0};
    const Vec3 a = point(s) + shift, b = point(s) + shift, c = point(s) + shift;
    checked += expect_plane_crossing(point(s) + shift, point(s) + shift, a, b, c) ? 1 : 0;
  }
  EXPECT_GT(checked, cases / 4);
}

TEST(RoundedPlaneCrossing, DegenerateCrossingsAreExact) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  // Through a corner of the triangle, through its edges, through an exactly representable point
  // (the exact path must give it back bit for bit), and at exact midpoints between doubles.
  EXPECT_TRUE(expect_plane_crossing({0, 0, -1}, {0, 0, 1}, a, b, c));
  EXPECT_TRUE(expect_plane_crossing({1, 0, -3}, {1, 0, 0.5}, a, b, c));
  EXPECT_TRUE(expect_plane_crossing({0.5, 0.5, -1}, {0.5, 0.5, 1}, a, b, c));
  EXPECT_TRUE(expect_plane_crossing({0.3, -0.2, -1}, {0.1, 0.7, 3}, a, b, c));
  const double tie = 1.0 + 0x1p-53;  // the midpoint of 1 and its successor
  EXPECT_TRUE(expect_plane_crossing({1, 1, -1}, {1 + 0x1p-52, 3, 1}, a, b, c));
  EXPECT_TRUE(expect_plane_crossing({0, 0, -1}, {2 * tie, 2, 1}, a, b, c));
  EXPECT_TRUE(expect_plane_crossing({1 + 0x1p-52, 0, -1}, {1 + 0x1p-51, 2, 1}, a, b, c));
  // A tilted plane through input doubles, crossed at one of its corners and along an edge.
  const Vec3 d{0.1, 0.2, 0.3}, e{1.7, -0.4, 0.9}, f{-0.6, 1.3, 2.2};
  const Vec3 off{0.31, -0.77, 0.5};
  EXPECT_TRUE(expect_plane_crossing(d + off, d - off, d, e, f));
  EXPECT_TRUE(expect_plane_crossing(e + off, scaled(e + d, 0.5) - off, d, e, f));
  // A nearly parallel segment: one ulp of rise over a long run.
  EXPECT_TRUE(expect_plane_crossing({0, 0, -0x1p-52}, {1e10, 3e9, 0x1p-52}, a, b, c));
}

TEST(RoundedPlaneCrossing, HugeAndTinyCoordinatesAreExact) {
  for (const double s : {1e300, 1e-300, 1e150, 1e-150, 0x1p-1060}) {
    const Vec3 a{0.1 * s, 0.2 * s, -0.3 * s}, b{1.7 * s, -0.4 * s, 0.9 * s};
    const Vec3 c{-0.6 * s, 1.3 * s, 2.2 * s};
    EXPECT_TRUE(
        expect_plane_crossing({0.3 * s, 0.1 * s, -2 * s}, {-0.2 * s, 0.4 * s, 3 * s}, a, b, c))
        << s;
    EXPECT_TRUE(expect_plane_crossing(scaled(a, 1.0) + Vec3{0, 0, s}, a - Vec3{0, 0, s}, a, b, c))
        << s;
  }
  // Huge plane, tiny segment offsets: far from the origin, small relative differences.
  const Vec3 a{1e300, 1e300, 0}, b{-1e300, 1e300, 1e-300}, c{0, -1e300, 2e-300};
  EXPECT_TRUE(expect_plane_crossing({1e-300, 3e-301, -1e-290}, {2e-300, -5e-301, 1e-290}, a, b, c));
}

}  // namespace
}  // namespace contain::test
