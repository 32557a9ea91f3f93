// Orientations of a segment-plane crossing and of a centroid by their defining doubles, against
// GMP rationals: random points (inexact differences: the big numbers), points on a grid of
// tenths (exact differences: the expansions) with crossings that lie on lines and planes of
// the grid by construction (exact zeros), one ulp off them, and magnitudes beyond the
// expansions' range.

#include "contain/predicates/crossing_orientation.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <random>

#include "support/exact.h"

namespace contain::test {
namespace {

const mpq_class& coord(const QVec3& p, int i) {
  return i == 0 ? p.x : (i == 1 ? p.y : p.z);
}

Sign oracle_orient2d(const QVec2& a, const QVec2& b, const QVec2& c) {
  return sign_of((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

int checked = 0;

// Every projection and every pair (a, b) of the given points against the crossing, and the
// coordinate comparisons in their (c, 0), (c, 1) form.
void expect_crossing(Vec3 p, Vec3 q, Vec3 t0, Vec3 t1, Vec3 t2, const std::array<Vec3, 4>& others) {
  const std::optional<QVec3> x = exact_segment_plane_crossing(p, q, t0, t1, t2);
  if (!x) return;
  for (int u = 0; u < 3; ++u) {
    const int v = (u + 1) % 3;
    const QVec2 qx{coord(*x, u), coord(*x, v)};
    const auto at = [&](Vec3 w) {
      return Vec2{u == 0 ? w.x : (u == 1 ? w.y : w.z), v == 0 ? w.x : (v == 1 ? w.y : w.z)};
    };
    for (const Vec3 a : others) {
      for (const Vec3 b : others) {
        EXPECT_EQ(predicates::orient2d_of_crossing(at(a), at(b), p, q, t0, t1, t2, u, v),
                  oracle_orient2d(exact(at(a)), exact(at(b)), qx));
        ++checked;
      }
      const double c = at(a).x;
      EXPECT_EQ(predicates::orient2d_of_crossing({c, 0.0}, {c, 1.0}, p, q, t0, t1, t2, u, v),
                sign_of(mpq_class(c) - qx.x));
    }
  }
}

Vec3 random_point(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  return Vec3{d(rng), d(rng), d(rng)} * scale;
}

// A point of the grid of tenths i / 10 (rounded), |i| <= 40.
Vec3 grid_point(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> d(-40, 40);
  return {d(rng) / 10.0, d(rng) / 10.0, d(rng) / 10.0};
}

// A point of the grid of eighths, |x| <= 5.
Vec3 eighth_point(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> d(-40, 40);
  return {d(rng) / 8.0, d(rng) / 8.0, d(rng) / 8.0};
}

TEST(CrossingOrientation, RandomCrossingsMatchTheRationals) {
  std::mt19937_64 rng(3);
  for (const double s : {1.0, 0x1p-300, 0x1p250}) {
    for (int i = 0; i < 40; ++i) {
      const auto at = [&] { return random_point(rng, s); };
      expect_crossing(at(), at(), at(), at(), at(), {at(), at(), at(), at()});
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(CrossingOrientation, CrossingsOnLinesAndPlanesOfTheGridAreExactZeros) {
  std::mt19937_64 rng(5);
  int zeros = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec3 p = grid_point(rng), q = grid_point(rng);
    // An axis plane through a grid point, as two triangles' worth of corners.
    const Vec3 o = grid_point(rng);
    const int k = i % 3;
    const Vec3 e1 = k == 0 ? Vec3{0, 1, 0} : Vec3{1, 0, 0},
               e2 = k == 2 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
    const std::optional<QVec3> x = exact_segment_plane_crossing(p, q, o, o + e1, o + e2);
    if (!x) continue;
    // Points on the segment's line and on the plane (the crossing is on lines through them),
    // and one ulp off each.
    const Vec3 on_plane = o + e1 * 0.7 + e2 * 0.3;
    const Vec3 off{std::nextafter(p.x, 9.0), p.y, p.z};
    expect_crossing(p, q, o, o + e1, o + e2, {p, q, on_plane, off});
    for (int u = 0; u < 3; ++u) {
      const int v = (u + 1) % 3;
      const auto at = [&](Vec3 w) {
        return Vec2{u == 0 ? w.x : (u == 1 ? w.y : w.z), v == 0 ? w.x : (v == 1 ? w.y : w.z)};
      };
      zeros += predicates::orient2d_of_crossing(at(p), at(q), p, q, o, o + e1, o + e2, u, v) ==
                       Sign::zero
                   ? 1
                   : 0;
    }
  }
  EXPECT_GT(zeros, 300);  // every orientation against the segment's own line
}

TEST(CrossingOrientation, CentroidsMatchTheRationals) {
  std::mt19937_64 rng(9);
  int zeros = 0;
  for (int i = 0; i < 600; ++i) {
    const bool grid = i % 2 == 0;
    const double s = i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 0x1p-600 : 0x1p600);
    // Eighths: 3 a - d0 - d1 below is exact, so the centroid is a itself.
    const auto at = [&] { return grid ? eighth_point(rng) * s : random_point(rng, s); };
    const Vec3 a = at(), b = at(), c = at();
    std::array<Vec3, 3> d = {at(), at(), at()};
    // Every third case: the centroid on the line a b or the plane a b c (the third corner
    // placed by the other two), exactly or one ulp off.
    if (i % 3 == 0) {
      d[2] = a * 3.0 - d[0] - d[1];
      if (i % 2 == 1) d[2].x = std::nextafter(d[2].x, 99.0);
    }
    const QVec3 g{(exact(d[0]).x + exact(d[1]).x + exact(d[2]).x) / 3,
                  (exact(d[0]).y + exact(d[1]).y + exact(d[2]).y) / 3,
                  (exact(d[0]).z + exact(d[1]).z + exact(d[2]).z) / 3};
    const Sign side = sign_of(
        qdot(qcross(qsub(exact(b), exact(a)), qsub(exact(c), exact(a))), qsub(g, exact(a))));
    EXPECT_EQ(predicates::orient3d_of_centroid(a, b, c, d[0], d[1], d[2]), side);
    const Sign turn = oracle_orient2d(exact(Vec2{a.x, a.y}), exact(Vec2{b.x, b.y}), {g.x, g.y});
    EXPECT_EQ(predicates::orient2d_of_centroid({a.x, a.y}, {b.x, b.y}, {d[0].x, d[0].y},
                                               {d[1].x, d[1].y}, {d[2].x, d[2].y}),
              turn);
    zeros += side == Sign::zero ? 1 : 0;
  }
  EXPECT_GT(zeros, 20);
}

}  // namespace
}  // namespace contain::test
