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
#include <optional>
#include <random>
#include <vector>

#include "support/exact.h"
#include "support/exact_distance.h"

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
  const std::optional<QVec3> x = exact_segment_plane_crossing(p, q, a, b, c);
  if (!x) return std::nullopt;
  return Known{clip::solid::line_plane(p, q, a, b, c), *x};
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

// Points off the line through p and an implicit point x on it by k steps of one coordinate (k
// from 1 to 2^20): orientations from exactly zero to far beyond the filter's bound, with the
// line's points wide (a midpoint's enclosure is 2^-49 relative) or narrow (a crossing's).
void expect_exact_off_line(const Known& p, const Known& x) {
  const Known on = midpoint(p, x);
  for (double k = 1; k <= 0x1p20; k *= 2) {
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 v = clip::solid::nearest_double(x.point);
      double& c = axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
      for (double step = 0; step < k; ++step)
        c = std::nextafter(c, INFINITY);
      const Known off = plain(v);
      expect_exact(p, on, off);
      expect_exact(on, x, off);
      expect_exact(off, on, x);
    }
  }
}

TEST(SolidExactPoint, OrientationsJustOffALineOfImplicitPointsMatchTheRationalsAtEveryScale) {
  std::mt19937_64 rng(31);
  for (const double s : {1.0, 0x1p-400, 0x1p400}) {
    int tested = 0;
    while (tested < 4) {
      const auto at = [&] { return random_point(rng) * s; };
      const Vec3 p = at(), q = at();
      const std::optional<Known> x = crossing(p, q, at(), at(), at());
      if (!x) continue;
      ++tested;
      expect_exact_off_line(plain(p), *x);
    }
  }
  // Products below the doubles' range (the filter must not take an underflowed zero for a sign)
  // and beyond it (infinite terms decide nothing).
  for (const double s : {0x1p-1040, 0x1p700}) {
    const Known a = plain(Vec3{0.3, -0.7, 0.2} * s), b = plain(Vec3{-0.5, 0.25, 0.9} * s);
    expect_exact_off_line(a, midpoint(a, b));
  }
}

Sign oracle_orient3d(const Known& p, const Known& q, const Known& a, const Known& b) {
  const QVec3 x = qsub(q.q, p.q), y = qsub(a.q, p.q), z = qsub(b.q, p.q);
  return sign_of(qdot(x, qcross(y, z)));
}

// The filter of det[q - p, a - p, b - p] answers only with the rationals' sign.
void expect_orient3d(const Known& p, const Known& q, const Known& a, const Known& b, bool decides) {
  const std::optional<Sign> s = clip::solid::filtered_orient3d(p.point, q.point, a.point, b.point);
  if (decides) {
    EXPECT_TRUE(s.has_value());
  }
  if (s) {
    EXPECT_EQ(*s, oracle_orient3d(p, q, a, b));
  }
}

TEST(SolidExactPoint, FilteredOrient3dAnswersOnlyWithTheRationalsSign) {
  std::mt19937_64 rng(37);
  for (const double s : {1.0, 0x1p-400, 0x1p300}) {
    int tested = 0;
    while (tested < 6) {
      const auto at = [&] { return random_point(rng) * s; };
      const Vec3 p = at(), q = at();
      const std::optional<Known> x = crossing(p, q, at(), at(), at());
      if (!x) continue;
      ++tested;
      const Known kp = plain(p), kq = plain(q), m = midpoint(kp, *x);
      // Random fourth points: far from the plane, the filter decides (not at 2^-400: products
      // of three differences are below the filter's absolute 2^-1000).
      expect_orient3d(kp, *x, plain(at()), plain(at()), s >= 1.0);
      expect_orient3d(m, kq, *x, plain(at()), false);
      // Coplanar exactly (x and m on the line p q) and 1 to 2^20 steps off a plane through it.
      const Known r = plain(at());
      expect_orient3d(kp, *x, m, r, false);
      EXPECT_FALSE(clip::solid::filtered_orient3d(kp.point, x->point, m.point, r.point));
      for (double k = 1; k <= 0x1p20; k *= 4) {
        Vec3 v = clip::solid::nearest_double(midpoint(m, r).point);
        for (double step = 0; step < k; ++step)
          v.z = std::nextafter(v.z, INFINITY);
        expect_orient3d(kp, *x, r, plain(v), false);
        expect_orient3d(m, r, *x, plain(v), false);
      }
    }
  }
  // Products below and beyond the doubles' range.
  for (const double s : {0x1p-1040, 0x1p700}) {
    const Known a = plain(Vec3{0.3, -0.7, 0.2} * s), b = plain(Vec3{-0.5, 0.25, 0.9} * s);
    const Known c = plain(Vec3{0.1, 0.6, -0.4} * s);
    expect_orient3d(a, midpoint(a, b), c, plain(Vec3{0.2, 0.2, 0.2} * s), false);
  }
}

// A crossing's nearest doubles (the filtered rounding, BigFloat only where it cannot certify)
// against the rationals', and its equality with the same point made another way.
void expect_rounded(const Known& x) {
  const Vec3 got = clip::solid::nearest_double(x.point);
  EXPECT_EQ(got.x, nearest_double(x.q.x));
  EXPECT_EQ(got.y, nearest_double(x.q.y));
  EXPECT_EQ(got.z, nearest_double(x.q.z));
}

TEST(SolidExactPoint, CrossingsRoundToTheNearestDoublesOfTheRationals) {
  std::mt19937_64 rng(13);
  int tested = 0;
  while (tested < 300) {
    const double s = std::ldexp(1.0, static_cast<int>(rng() % 61) - 30);
    const auto at = [&] { return random_point(rng) * s; };
    const Vec3 p = at(), q = at();
    if (const std::optional<Known> x = crossing(p, q, at(), at(), at())) {
      expect_rounded(*x);
      ++tested;
    }
  }
  // Degenerate: through a corner, along an edge, at a double, and at huge and tiny scales.
  for (const double s : {1.0, 1e300, 1e-300, 0x1p-1060}) {
    const Vec3 a{0, 0, 0}, b{s, 0, 0}, c{0, s, 0};
    for (const auto& [p, q] :
         {std::pair{Vec3{0, 0, -s}, Vec3{0, 0, s}},
          std::pair{Vec3{s, 0, -3 * s}, Vec3{s, 0, 0.5 * s}},
          std::pair{Vec3{0.5 * s, 0.25 * s, -s}, Vec3{0.5 * s, 0.5 * s, s}},
          std::pair{Vec3{0.3 * s, -0.2 * s, -s}, Vec3{0.1 * s, 0.7 * s, 3 * s}}}) {
      const std::optional<Known> x = crossing(p, q, a, b, c);
      ASSERT_TRUE(x.has_value()) << s;
      expect_rounded(*x);
      // The same point as the crossing of the reversed segment with the plane's corners in
      // another order (no shortcut: the exact path) and of a second segment through it.
      const std::optional<Known> y = crossing(q, p, c, a, b);
      ASSERT_TRUE(y.has_value());
      EXPECT_TRUE(clip::solid::same_point(x->point, y->point));
      EXPECT_TRUE(clip::solid::same_point(x->point, crossing(q, p, a, b, c)->point));
    }
  }
}

// The enclosed crossing of the check (line_plane_enclosed) holds the rational point in every
// coordinate, and its comparisons with the rounded crossing and with points of doubles are the
// rationals' signs: on random crossings, on segments nearly parallel to the plane (turned by
// 1e-9, where the quotient amplifies the rounding errors) and at huge and tiny scales.
void expect_enclosed(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  const std::optional<Known> x = crossing(p, q, a, b, c);
  if (!x) return;
  const ExactPoint e = clip::solid::line_plane_enclosed(p, q, a, b, c);
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_LE(mpq_class(e.enclosure().lo[k]), coord(x->q, i)) << i;
    EXPECT_GE(mpq_class(e.enclosure().hi[k]), coord(x->q, i)) << i;
    EXPECT_EQ(clip::solid::compare_coordinate(e, x->point, i), Sign::zero) << i;
    for (const Vec3 v : {p, q, a}) {
      EXPECT_EQ(clip::solid::compare_coordinate(e, clip::solid::exact_point(v), i),
                sign_of(coord(x->q, i) - coord(exact(v), i)))
          << i;
    }
  }
}

TEST(SolidExactPoint, EnclosedCrossingsHoldTheRationalPoint) {
  std::mt19937_64 rng(29);
  for (int trial = 0; trial < 300; ++trial) {
    const double s = std::ldexp(1.0, static_cast<int>(rng() % 61) - 30);
    const auto at = [&] { return random_point(rng) * s; };
    expect_enclosed(at(), at(), at(), at(), at());
    // A segment nearly in the plane: its ends 1e-9 s off it, on both sides.
    const Vec3 a = at(), b = at(), c = at();
    const Vec3 n = cross(b - a, c - a);
    const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (len == 0.0) continue;
    const Vec3 off = n * (1e-9 * s / len);
    const Vec3 m = a + (b - a) * 0.25 + (c - a) * 0.25;
    expect_enclosed(m + off + (b - a) * 0.3, m - off - (c - a) * 0.2, a, b, c);
  }
  for (const double s : {1.0, 1e300, 1e-300, 0x1p-1060}) {
    expect_enclosed({0.3 * s, -0.2 * s, -s}, {0.1 * s, 0.7 * s, 3 * s}, {0, 0, 0}, {s, 0, 0},
                    {0, s, 0});
  }
}

// The filter of the intersection line's direction against the exact cross product of the exact
// normals: when it answers, its axis is the first non-zero component.
void expect_line_axis(const std::array<Vec3, 3>& t, const std::array<Vec3, 3>& u, bool decides) {
  const QVec3 nt = qcross(qsub(exact(t[1]), exact(t[0])), qsub(exact(t[2]), exact(t[0])));
  const QVec3 nu = qcross(qsub(exact(u[1]), exact(u[0])), qsub(exact(u[2]), exact(u[0])));
  const QVec3 line = qcross(nt, nu);
  const std::optional<int> k = clip::solid::filtered_line_axis(t, u);
  if (decides) {
    EXPECT_TRUE(k.has_value());
  }
  if (!k) return;
  for (int i = 0; i < *k; ++i)
    EXPECT_EQ(sgn(coord(line, i)), 0) << "axis " << *k << " is not the first non-zero one";
  EXPECT_NE(sgn(coord(line, *k)), 0) << "axis " << *k << " is zero";
}

TEST(SolidExactPoint, FilteredLineAxisIsTheFirstNonZeroComponentOfTheExactDirection) {
  std::mt19937_64 rng(17);
  for (int i = 0; i < 300; ++i) {
    const std::array<Vec3, 3> t{random_point(rng), random_point(rng), random_point(rng)};
    const std::array<Vec3, 3> u{random_point(rng), random_point(rng), random_point(rng)};
    expect_line_axis(t, u, true);  // random planes: far from parallel, the filter decides
  }
  // Directions with exactly zero components: planes z = 0 and x = 0 meet along y (x and z
  // components zero); planes z = 0 and y = x meet along z = 0, (1, 1, 0).
  const std::array<Vec3, 3> flat{Vec3{0.1, 0.2, 0}, Vec3{1.3, 0.7, 0}, Vec3{0.4, 1.9, 0}};
  expect_line_axis(flat, {Vec3{0, 0.3, 0.1}, Vec3{0, 1.1, -0.4}, Vec3{0, -0.2, 0.9}}, true);
  expect_line_axis(flat, {Vec3{0.3, 0.3, 0.1}, Vec3{1.1, 1.1, -0.4}, Vec3{-0.2, -0.2, 0.9}}, false);
  // Nearly parallel planes (a direction below the filter's resolution) and 1e+-300: the filter
  // answers rightly or not at all.
  const double tilt = 0x1p-60;
  expect_line_axis(flat, {Vec3{0.1, 0.2, tilt}, Vec3{1.3, 0.7, 0}, Vec3{0.4, 1.9, -tilt}}, false);
  for (const double s : {1e300, 1e-300, 1e50, 1e-50}) {
    const std::array<Vec3, 3> t{flat[0] * s, flat[1] * s, flat[2] * s};
    expect_line_axis(t, {Vec3{0, 0.3, 0.1} * s, Vec3{0, 1.1, -0.4} * s, Vec3{0, -0.2, 0.9} * s},
                     s == 1e50 || s == 1e-50);
  }
}

// The filter of a triangle's projection against the exact normal: when it answers, its axis's
// component is strictly the largest in magnitude (by GMP) and its sense that component's sign.
void expect_projection(Vec3 a, Vec3 b, Vec3 c, bool decides, int& answered) {
  const QVec3 n = qcross(qsub(exact(b), exact(a)), qsub(exact(c), exact(a)));
  const std::optional<clip::solid::Projection> p = clip::solid::filtered_projection(a, b, c);
  if (decides) {
    EXPECT_TRUE(p.has_value());
  }
  if (!p) return;
  ++answered;
  const mpq_class largest = abs(coord(n, p->axis));
  for (int k = 0; k < 3; ++k) {
    if (k != p->axis) {
      EXPECT_GT(largest, abs(coord(n, k))) << "axis " << p->axis << " is not the largest";
    }
  }
  EXPECT_EQ(p->sense, sign_of(coord(n, p->axis)));
}

TEST(SolidExactPoint, FilteredProjectionIsTheExactNormalsLargestComponentAndItsSign) {
  std::mt19937_64 rng(29);
  int answered = 0;
  for (int i = 0; i < 300; ++i)
    expect_projection(random_point(rng), random_point(rng), random_point(rng), true, answered);
  // Slivers: c a few ulps off the line a b, every normal component a cancellation, at scales
  // 2^-400..2^300 (the extremes beyond the filter's range: the exact normal decides).
  std::uniform_real_distribution<double> along(-0.5, 1.5);
  std::uniform_int_distribution<int> steps(-4, 4);
  for (int e = -400; e <= 300; e += 50) {
    for (int i = 0; i < 200; ++i) {
      const Vec3 a = random_point(rng) * std::ldexp(1.0, e);
      const Vec3 b = random_point(rng) * std::ldexp(1.0, e);
      const double t = along(rng);
      Vec3 c = a + (b - a) * t;
      for (double* x : {&c.x, &c.y, &c.z}) {
        for (int s = steps(rng); s != 0; s += s > 0 ? -1 : 1)
          *x = std::nextafter(*x, s > 0 ? 1e308 : -1e308);
      }
      expect_projection(a, b, c, false, answered);
    }
  }
  // Exact ties: planes x = y and x = z (|n_x| = |n_y|, |n_x| = |n_z|), and all three equal:
  // the filter must leave them to the exact normal (`dropped_axis` takes the first).
  expect_projection({0.25, 0.25, 0.5}, {1.5, 1.5, -0.75}, {0.5, 0.5, 3.0}, false, answered);
  expect_projection({0.25, 0.5, 0.25}, {1.5, -0.75, 1.5}, {0.5, 3.0, 0.5}, false, answered);
  expect_projection({1, 0, 0}, {0, 1, 0}, {0, 0, 1}, false, answered);
  EXPECT_GT(answered, 300);  // the slivers are decided in part, not all handed over
}

}  // namespace
}  // namespace contain::test
