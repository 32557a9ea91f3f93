// The search's floating-point bounds on a triangle's squared distance (triangle_search.h) against
// the GMP oracle: each lower bound is at most the exact value and each upper bound at least it,
// on random, lattice (degenerate, coplanar, on-vertex, on-edge) and sliver triangles, points on
// and a hair off the plane, and coordinates scaled to 2^-300 and 2^300.

#include "distance/triangle_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/case_budget.h"
#include "support/exact_distance.h"

namespace contain::distance::detail {
namespace {

// Sanitizer builds run a fifth of the cases (support/case_budget.h).
constexpr int kCases = test::case_budget(20000, 5);

Vec3 scaled(Vec3 v, double s) {
  return {v.x * s, v.y * s, v.z * s};
}

Triangle3 scaled(const Triangle3& t, double s) {
  return {scaled(t.a, s), scaled(t.b, s), scaled(t.c, s)};
}

mpq_class exact_d2(Vec3 p, const Triangle3& t) {
  return test::exact_closest(p, t).squared_distance;
}

// A triangle and a point from one of the families, at unit scale.
struct Case {
  Triangle3 t;
  Vec3 p;
};

Case make_case(std::mt19937_64& rng, int i) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> lattice(-3, 3);
  auto random = [&] { return Vec3{u(rng), u(rng), u(rng)}; };
  auto on_lattice = [&] {
    return Vec3{0.5 * lattice(rng), 0.5 * lattice(rng), 0.5 * lattice(rng)};
  };
  switch (i % 5) {
    case 0:
      return {{random(), random(), random()}, random()};
    case 1:  // lattice: repeated and collinear corners, points on corners, edges and the plane
      return {{on_lattice(), on_lattice(), on_lattice()}, on_lattice()};
    case 2: {  // a point a hair off the plane, above the face or beside it
      const Triangle3 t{random(), random(), random()};
      const Vec3 n = cross(t.b - t.a, t.c - t.a);
      const double s = std::uniform_real_distribution<double>(0, 1)(rng);
      const double r = std::uniform_real_distribution<double>(0, 1 - s)(rng);
      const double out = (i % 10 == 2) ? 0.0 : 0.5;  // half of them off the face
      const Vec3 on = t.a + (t.b - t.a) * (s + out) + (t.c - t.a) * r;
      return {t, on + n * (1e-9 * (i % 3 - 1))};
    }
    case 3: {  // a sliver: the third corner a hair off the line of the first two
      const Vec3 a = random(), b = random();
      const Vec3 c = a + (b - a) * 0.3 + Vec3{1e-12, -1e-13, 2e-12};
      return {{a, b, c}, random()};
    }
    default: {  // a point straight above the face, where the plane bound is tight
      const Triangle3 t{random(), random(), random()};
      const Vec3 n = cross(t.b - t.a, t.c - t.a);
      const Vec3 centre = (t.a + t.b + t.c) * (1.0 / 3);
      return {t, centre + n * u(rng)};
    }
  }
}

TEST(TriangleSearchBounds, PlaneBoundNeverExceedsTheExactSquaredDistance) {
  std::mt19937_64 rng(11);
  int tight = 0, above_face = 0;
  for (int i = 0; i < kCases; ++i) {
    const Case c = make_case(rng, i);
    for (const double s : {1.0, 0x1p-300, 0x1p300}) {
      const Triangle3 t = scaled(c.t, s);
      const Vec3 p = scaled(c.p, s);
      const double lower = PlaneBound(t).lower(p);
      ASSERT_GE(lower, 0.0);
      const mpq_class exact = exact_d2(p, t);
      ASSERT_LE(mpq_class(lower), exact) << "case " << i << " scale " << s;
      if (i % 5 == 4 && s == 1.0 && exact > 0) {
        ++above_face;
        // Straight above the face the plane is the whole distance: the bound is within a
        // relative 2^-40 of it unless the triangle is too thin for its normal to be rounded.
        if (mpq_class(lower) >= exact * mpq_class(1 - 0x1p-40)) ++tight;
      }
    }
  }
  // The bound is of use: nearly every point straight above a face is put at its distance.
  EXPECT_GE(tight, above_face * 99 / 100);
}

TEST(TriangleSearchBounds, TriangleBoundsEncloseTheExactSquaredDistance) {
  std::mt19937_64 rng(12);
  for (int i = 0; i < kCases; ++i) {
    const Case c = make_case(rng, i);
    for (const double s : {1.0, 0x1p-300, 0x1p300}) {
      const Triangle3 t = scaled(c.t, s);
      const Vec3 p = scaled(c.p, s);
      const double max_abs = std::max({std::fabs(t.a.x), std::fabs(t.a.y), std::fabs(t.a.z),
                                       std::fabs(t.b.x), std::fabs(t.b.y), std::fabs(t.b.z),
                                       std::fabs(t.c.x), std::fabs(t.c.y), std::fabs(t.c.z)});
      double lo = 0.0, hi = 0.0;
      triangle_bounds(p, t, triangle_slack(max_abs), lo, hi);
      const mpq_class exact = exact_d2(p, t);
      ASSERT_LE(mpq_class(lo), exact) << "case " << i << " scale " << s;
      if (std::isfinite(hi)) {
        ASSERT_GE(mpq_class(hi), exact) << "case " << i << " scale " << s;
      }
    }
  }
}

TEST(TriangleSearchBounds, HalfSpaceTestPutsOutOnlyTrianglesFartherThanTheBound) {
  // The test's direction comes from another triangle's approximate closest point and the bound
  // is that triangle's upper bound, as in the search; a triangle put out must be farther.
  std::mt19937_64 rng(13);
  int put_out = 0;
  for (int i = 0; i < kCases; ++i) {
    const Case c = make_case(rng, i);
    const Case other = make_case(rng, i + 1);
    for (const double s : {1.0, 0x1p-300, 0x1p300}) {
      const Triangle3 t = scaled(c.t, s);
      const Triangle3 near = scaled(other.t, s);
      const Vec3 p = scaled(c.p, s);
      const double max_abs = 4 * s;
      double lo = 0.0, hi = 0.0;
      const Vec3 w = triangle_bounds(p, near, triangle_slack(max_abs), lo, hi);
      if (!std::isfinite(hi)) continue;
      if (!HalfSpaceTest(p, w, hi, max_abs)(t)) continue;
      ++put_out;
      ASSERT_GT(exact_d2(p, t), mpq_class(hi)) << "case " << i << " scale " << s;
    }
  }
  EXPECT_GT(put_out, kCases / 20);  // the test does put triangles out
}

}  // namespace
}  // namespace contain::distance::detail
