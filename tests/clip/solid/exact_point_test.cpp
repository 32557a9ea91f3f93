// The floating-point filter of the mesh boolean's exact points (src/clip/solid/exact_point.cpp)
// against GMP rationals: orientations, coordinate comparisons and equality of implicit points
// (edges through planes, their midpoints) mixed with points of doubles, on random points and on
// exactly degenerate ones (collinear, coincident, one ulp away), where the filter must hand over
// to the big numbers.

#include "clip/solid/exact_point.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "support/exact.h"

namespace contain::test {
namespace {

using clip::solid::ExactPoint;

// A point and its exact rational coordinates.
struct Known {
  ExactPoint point;
  QVec3 q;
};

const mpq_class& coord(const QVec3& p, int i) {
  return i == 0 ? p.x : (i == 1 ? p.y : p.z);
}

Known plain(Vec3 v) {
  return {clip::solid::exact_point(v), exact(v)};
}

// Where segment p q crosses the plane of a b c, or nothing when it does not cross strictly.
std::optional<Known> crossing(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  const QVec3 n = qcross(qsub(exact(b), exact(a)), qsub(exact(c), exact(a)));
  const mpq_class dp = qdot(n, qsub(exact(p), exact(a))), dq = qdot(n, qsub(exact(q), exact(a)));
  if (sgn(dp) * sgn(dq) >= 0) return std::nullopt;
  const mpq_class t = dp / (dp - dq);
  const QVec3 qp = exact(p), qq = exact(q);
  const QVec3 x{qp.x + t * (qq.x - qp.x), qp.y + t * (qq.y - qp.y), qp.z + t * (qq.z - qp.z)};
  return Known{clip::solid::line_plane(p, q, a, b, c), x};
}

Known midpoint(const Known& a, const Known& b) {
  return {clip::solid::midpoint(a.point, b.point),
          {(a.q.x + b.q.x) / 2, (a.q.y + b.q.y) / 2, (a.q.z + b.q.z) / 2}};
}

Sign oracle_orient(const Known& a, const Known& b, const Known& c, int axis) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const mpq_class d = (coord(b.q, u) - coord(a.q, u)) * (coord(c.q, v) - coord(a.q, v)) -
                      (coord(b.q, v) - coord(a.q, v)) * (coord(c.q, u) - coord(a.q, u));
  return sign_of(d);
}

// Every predicate of the filter on the triple, against the oracle.
void expect_exact(const Known& a, const Known& b, const Known& c) {
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(clip::solid::orient2d_dropped(a.point, b.point, c.point, axis),
              oracle_orient(a, b, c, axis))
        << "axis " << axis;
    EXPECT_EQ(clip::solid::compare_coordinate(a.point, b.point, axis),
              sign_of(coord(a.q, axis) - coord(b.q, axis)))
        << "axis " << axis;
  }
  EXPECT_EQ(clip::solid::same_point(a.point, b.point),
            a.q.x == b.q.x && a.q.y == b.q.y && a.q.z == b.q.z);
}

Vec3 random_point(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return {u(rng), u(rng), u(rng)};
}

TEST(SolidExactPoint, FilteredPredicatesOnRandomImplicitPointsMatchTheRationals) {
  std::mt19937_64 rng(7);
  std::vector<Known> points;
  while (points.size() < 60) {
    const Vec3 p = random_point(rng), q = random_point(rng);
    if (std::optional<Known> x =
            crossing(p, q, random_point(rng), random_point(rng), random_point(rng))) {
      points.push_back(std::move(*x));
      points.push_back(plain(p));
    }
  }
  points.push_back(midpoint(points[0], points[2]));
  for (std::size_t i = 0; i + 2 < points.size(); ++i)
    expect_exact(points[i], points[i + 1], points[i + 2]);
}

TEST(SolidExactPoint, DegenerateImplicitPointsFallBackToExactZeros) {
  std::mt19937_64 rng(11);
  int tested = 0;
  while (tested < 40) {
    const Vec3 p = random_point(rng), q = random_point(rng);
    const std::optional<Known> x =
        crossing(p, q, random_point(rng), random_point(rng), random_point(rng));
    if (!x) continue;
    ++tested;
    const Known kp = plain(p), kq = plain(q);
    // On segment p q exactly: every orientation is zero, only the big numbers can say so.
    expect_exact(kp, kq, *x);
    expect_exact(*x, midpoint(kp, *x), kq);
    // The plane z = 0 crossed by p q and by q p: one point in two representations.
    const Vec3 o{0, 0, 0}, ex{1, 0, 0}, ey{0, 1, 0};
    const std::optional<Known> forward = crossing(p, q, o, ex, ey),
                               backward = crossing(q, p, o, ey, ex);
    ASSERT_EQ(forward.has_value(), backward.has_value());
    if (forward) {
      EXPECT_TRUE(clip::solid::same_point(forward->point, backward->point));
      expect_exact(*forward, *backward, *x);
    }
    // One ulp off the line: an orientation far below the filter's resolution of the crossing.
    const Known off = plain({std::nextafter(q.x, 2.0), q.y, q.z});
    expect_exact(kp, off, *x);
    expect_exact(*x, kp, off);
  }
}

}  // namespace
}  // namespace contain::test
