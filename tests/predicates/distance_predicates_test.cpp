// closest_feature, compare_squared_distance(s) and the rounded distances against the GMP oracle
// of tests/support/exact_distance.h.

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "contain/predicates/closest_feature.h"
#include "contain/predicates/rounded_distance.h"
#include "contain/predicates/squared_distance.h"
#include "predicates/cases.h"
#include "predicates/distance_cases.h"
#include "support/exact.h"
#include "support/exact_distance.h"

namespace contain::predicates {
namespace {

using test::CaseRng;
using test::cases;
using test::hex;
using test::QVec3;

// The squared distance between the flats of a pair, in rationals (from the definitions).
mpq_class exact_flat_distance(const FlatPair3& x) {
  FlatPair3 n = x;
  if (n.a.size > n.b.size) std::swap(n.a, n.b);
  const QVec3 p = test::exact(n.a.points[0]);
  const QVec3 q0 = test::exact(n.b.points[0]);
  if (n.a.size == 1 && n.b.size == 1) {
    const QVec3 d = test::qsub(p, q0);
    return test::qdot(d, d);
  }
  if (n.a.size == 1 && n.b.size == 2) {
    const QVec3 u = test::qsub(test::exact(n.b.points[1]), q0);
    const QVec3 c = test::qcross(test::qsub(p, q0), u);
    return test::qdot(c, c) / test::qdot(u, u);
  }
  if (n.a.size == 1) {
    const QVec3 nn = test::qcross(test::qsub(test::exact(n.b.points[1]), q0),
                                  test::qsub(test::exact(n.b.points[2]), q0));
    const mpq_class s = test::qdot(test::qsub(p, q0), nn);
    return s * s / test::qdot(nn, nn);
  }
  const QVec3 m = test::qcross(test::qsub(test::exact(n.a.points[1]), p),
                               test::qsub(test::exact(n.b.points[1]), q0));
  const mpq_class s = test::qdot(test::qsub(q0, p), m);
  return s * s / test::qdot(m, m);
}

std::string describe(const test::PointTriangleCase& c) {
  return "p " + hex(c.p) + " t " + hex(c.t.a) + " " + hex(c.t.b) + " " + hex(c.t.c);
}

bool same_double(double x, double y) {
  return x == y && std::signbit(x) == std::signbit(y);
}

// The feature closest_feature's contract names, from rationals: `face` where the triangle is
// not degenerate and p projects into it (closed); else the vertex at the exact closest point
// (named by the first corner there), or the first of ab, bc, ca holding it inside.
TriangleFeature contract_feature(const test::PointTriangleCase& c, const QVec3& closest) {
  const QVec3 v[3] = {test::exact(c.t.a), test::exact(c.t.b), test::exact(c.t.c)};
  const QVec3 p = test::exact(c.p);
  const QVec3 n = test::qcross(test::qsub(v[1], v[0]), test::qsub(v[2], v[0]));
  if (test::qdot(n, n) != 0) {
    bool inside = true;
    for (int e = 0; e < 3; ++e) {
      const QVec3 edge = test::qsub(v[(e + 1) % 3], v[e]);
      const QVec3 side = test::qcross(edge, test::qsub(p, v[e]));
      const QVec3 third = test::qcross(edge, test::qsub(v[(e + 2) % 3], v[e]));
      inside = inside && test::qdot(side, third) >= 0;
    }
    if (inside) return TriangleFeature::face;
  }
  for (int k = 0; k < 3; ++k) {
    if (v[k].x == closest.x && v[k].y == closest.y && v[k].z == closest.z) {
      int first = k;
      for (int j = k - 1; j >= 0; --j)
        if (v[j].x == v[k].x && v[j].y == v[k].y && v[j].z == v[k].z) first = j;
      return static_cast<TriangleFeature>(first);
    }
  }
  for (int e = 0; e < 3; ++e) {
    const QVec3 d = test::qsub(v[(e + 1) % 3], v[e]), r = test::qsub(closest, v[e]);
    const QVec3 x = test::qcross(d, r);
    const mpq_class along = test::qdot(r, d);
    if (x.x == 0 && x.y == 0 && x.z == 0 && along > 0 && along < test::qdot(d, d)) {
      return static_cast<TriangleFeature>(static_cast<int>(TriangleFeature::edge_ab) + e);
    }
  }
  return TriangleFeature::face;  // not reached: the closest point is on the boundary
}

// Checks one case: the feature's flat distance is the triangle's exact distance, and the feature
// is the one the contract names; the rounded distance and closest point are the nearest doubles
// of the oracle's.
int check_case(const test::PointTriangleCase& c) {
  const test::ExactClosest3 want = test::exact_closest(c.p, c.t);
  const TriangleFeature f = closest_feature(c.t, c.p);
  const FlatPair3 pair{point_flat(c.p), feature_flat(c.t, f)};
  int failures = 0;
  if (exact_flat_distance(pair) != want.squared_distance) {
    ADD_FAILURE() << "feature " << static_cast<int>(f) << " not closest for " << describe(c);
    return 1;
  }
  const TriangleFeature named = contract_feature(c, want.point);
  if (f != named) {
    ADD_FAILURE() << "feature " << static_cast<int>(f) << " where the contract names "
                  << static_cast<int>(named) << " for " << describe(c);
    return 1;
  }
  const double d = rounded_distance(pair);
  const double want_d = test::nearest_double_sqrt(want.squared_distance);
  if (!same_double(d, want_d)) {
    ADD_FAILURE() << "distance " << hex(d) << " want " << hex(want_d) << " for " << describe(c);
    ++failures;
  }
  const Vec3 q = rounded_closest_points(pair).b;
  const Vec3 want_q{test::nearest_double(want.point.x), test::nearest_double(want.point.y),
                    test::nearest_double(want.point.z)};
  if (!(q == want_q)) {
    ADD_FAILURE() << "closest point " << hex(q) << " want " << hex(want_q) << " for "
                  << describe(c);
    ++failures;
  }
  // The fused call answers exactly what the two separate calls answer.
  const RoundedPointDistance3 both = rounded_point_distance(pair);
  if (!same_double(both.distance, d) || !(both.point == q)) {
    ADD_FAILURE() << "rounded_point_distance " << hex(both.distance) << " " << hex(both.point)
                  << " want " << hex(d) << " " << hex(q) << " for " << describe(c);
    ++failures;
  }
  // within d: exact at d itself and at the neighbours of the rounded distance.
  for (double dd : {d, std::nextafter(d, 0.0), std::nextafter(d, DBL_MAX)}) {
    if (!std::isfinite(dd)) continue;
    const mpq_class qd(dd);
    const Sign want_s = test::sign_of(want.squared_distance - qd * qd);
    if (compare_squared_distance(pair, dd) != want_s) {
      ADD_FAILURE() << "within " << hex(dd) << " for " << describe(c);
      ++failures;
    }
  }
  return failures;
}

TEST(DistancePredicates, ClosestFeatureDistanceAndPointAreExactOnEveryKindOfCase) {
  CaseRng rng(12);
  int failures = 0;
  for (int kind = 0; kind < 12; ++kind) {
    const int n = cases(kind == 11 ? 300 : 3000);
    for (int i = 0; i < n && failures < 10; ++i)
      failures += check_case(test::point_triangle_case(rng, kind));
  }
  EXPECT_EQ(failures, 0);
}

TEST(DistancePredicates, ScaledByPowersOfTwoFrom2PowMinus1000To2Pow900StayExact) {
  CaseRng rng(13);
  int failures = 0;
  const int n = cases(4000);
  for (int i = 0; i < n && failures < 10; ++i) {
    const auto c = test::point_triangle_case(rng, static_cast<int>(rng.integer(0, 10)));
    failures += check_case(test::scaled_case(c, static_cast<int>(rng.integer(-1000, 900))));
  }
  EXPECT_EQ(failures, 0);
}

TEST(DistancePredicates, ComparisonOfTwoTrianglesDistancesIsTheExactSign) {
  CaseRng rng(14);
  int failures = 0;
  const int n = cases(6000);
  for (int i = 0; i < n && failures < 10; ++i) {
    const int kind = static_cast<int>(rng.integer(0, 10));
    const auto c = test::point_triangle_case(rng, kind);
    // A second triangle: random, or the first with one corner moved (shared features, ties).
    Triangle3 u = c.t;
    switch (rng.integer(0, 2)) {
      case 0:
        u = {test::uniform_vec(rng, 1), test::uniform_vec(rng, 1), test::uniform_vec(rng, 1)};
        break;
      case 1:
        u.c = u.c + test::lattice_vec(rng, 3);
        break;
      default:
        u = {c.t.b, c.t.a, c.t.c + c.t.c};
        break;
    }
    const FlatPair3 x{point_flat(c.p), feature_flat(c.t, closest_feature(c.t, c.p))};
    const FlatPair3 y{point_flat(c.p), feature_flat(u, closest_feature(u, c.p))};
    const Sign want = test::sign_of(test::exact_closest(c.p, c.t).squared_distance -
                                    test::exact_closest(c.p, u).squared_distance);
    if (compare_squared_distances(x, y) != want) {
      ADD_FAILURE() << "compare for " << describe(c);
      ++failures;
    }
  }
  EXPECT_EQ(failures, 0);
}

// A pair of flats met twice (a vertex reached from two edges, an edge shared by two triangles)
// is an exact tie that the filter cannot settle; same_flat settles it without arithmetic, in any
// order of the points, and only for the same point set.
TEST(DistancePredicates, PairsOfTheSameFlatsInAnyOrderAreEqualAndOthersAreCompared) {
  const Vec3 p{0.1, 0.2, 0.3}, a{1, 0, 0}, b{0, 1, 0.5}, c{0, 0, 1.25};
  const FlatPair3 x{point_flat(p), plane_flat(a, b, c)};
  const FlatPair3 y{point_flat(p), plane_flat(c, a, b)};
  EXPECT_TRUE(same_flat(x.b, y.b));
  EXPECT_EQ(compare_squared_distances(x, y), Sign::zero);
  EXPECT_EQ(compare_squared_distances(FlatPair3{line_flat(a, b), line_flat(c, p)},
                                      FlatPair3{line_flat(b, a), line_flat(p, c)}),
            Sign::zero);
  // the same points as a line and as a plane, or other points: not the same flat
  EXPECT_FALSE(same_flat(line_flat(a, b), plane_flat(a, b, c)));
  EXPECT_FALSE(same_flat(plane_flat(a, b, c), plane_flat(a, b, p)));
  const FlatPair3 z{point_flat(p), line_flat(a, b)};  // a line of the plane: not farther
  EXPECT_EQ(compare_squared_distances(x, z), Sign::negative);
  EXPECT_TRUE(same_flat(Flat2{{Vec2{1, 2}, Vec2{3, 4}}, 2}, Flat2{{Vec2{3, 4}, Vec2{1, 2}}, 2}));
  EXPECT_FALSE(same_flat(Flat2{{Vec2{1, 2}, Vec2{3, 4}}, 2}, Flat2{{Vec2{1, 2}, Vec2{3, 5}}, 2}));
}

TEST(DistancePredicates, DotSignIsExact) {
  CaseRng rng(15);
  int failures = 0;
  for (int i = 0; i < cases(20000) && failures < 10; ++i) {
    Vec3 a = test::lattice_vec(rng, 20), b = a + test::lattice_vec(rng, 8),
         p = a + cross(b - a, test::lattice_vec(rng, 4));
    if (rng.coin()) p = {rng.nudge(p.x, 2), rng.nudge(p.y, 2), p.z};
    const int family = rng.integer(0, 3);
    if (family == 0) {
      a = {rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
      b = {rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
      p = {rng.any_magnitude(), rng.any_magnitude(), rng.any_magnitude()};
    } else if (family == 1) {
      // Full mantissas, p on the perpendicular plane as rounded: the exact value is a few
      // roundings from 0 and the floating-point sign is often wrong.
      auto any = [&] { return Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)}; };
      a = any() * 1000.0;
      b = a + any();
      p = a + cross(b - a, any());
    }
    const QVec3 qa = test::exact(a);
    const Sign want =
        test::sign_of(test::qdot(test::qsub(test::exact(b), qa), test::qsub(test::exact(p), qa)));
    if (dot_sign(a, b, p) != want) {
      ADD_FAILURE() << "dot_sign " << hex(a) << hex(b) << hex(p);
      ++failures;
    }
  }
  EXPECT_EQ(failures, 0);
}

TEST(DistancePredicates, DistanceBeyondDblMaxRoundsToInfinityAsIeeeDoes) {
  const FlatPair3 far{point_flat({-DBL_MAX, -DBL_MAX, 0}), point_flat({DBL_MAX, DBL_MAX, 0})};
  EXPECT_EQ(rounded_distance(far), std::numeric_limits<double>::infinity());
  const FlatPair3 max{point_flat({0, 0, 0}), point_flat({DBL_MAX, 0, 0})};
  EXPECT_EQ(rounded_distance(max), DBL_MAX);
  EXPECT_EQ(compare_squared_distance(far, DBL_MAX), Sign::positive);
}

TEST(DistancePredicates, SubnormalDistancesRoundToTheNearestSubnormal) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  // sqrt(2) * 3 * 2^-1074 = 4.24... units of 2^-1074: rounds to 4 units.
  const FlatPair3 x{point_flat({0, 0, 0}), point_flat({3 * tiny, 3 * tiny, 0})};
  EXPECT_EQ(rounded_distance(x), 4 * tiny);
  EXPECT_EQ(rounded_distance(FlatPair3{point_flat({0, 0, 0}), point_flat({0, 0, 0})}), 0.0);
}

TEST(DistancePredicates, ExactMidpointTiesGoToEven) {
  // 1 + 2^-53 is the midpoint between 1 and its successor: the distance from 0 to it along x
  // (a point-point pair whose difference is not a double: 1 + 2^-53 - 0 needs 54 bits) cannot be
  // built from doubles directly, so use a difference: (1 + 2^-52) - 2^-53 = 1 + 2^-53.
  const FlatPair3 x{point_flat({0x1p-53, 0, 0}), point_flat({1 + 0x1p-52, 0, 0})};
  EXPECT_EQ(rounded_distance(x), 1.0);  // 1 is even, 1 + 2^-52 odd
  const FlatPair3 y{point_flat({0x1p-53, 0, 0}), point_flat({1 + 0x1p-51, 0, 0})};
  // 1 + 3 * 2^-53: midpoint between 1 + 2^-52 (odd) and 1 + 2^-51 (even).
  EXPECT_EQ(rounded_distance(y), 1 + 0x1p-51);
}

TEST(DistancePredicates, DistancesAHairFromAMidpointRoundToTheSideTheyAreOn) {
  // The distance 1 + 2^-53 -+ 2^-100 lies 2^-100 below or above the midpoint between 1 and
  // 1 + 2^-52: far inside the long double stages' error bounds (2^-64 relative), so only the
  // exact stage can tell the sides apart, and a stage that decided from its rounded values would
  // give one answer for both. The difference (1 + 2^-52) - (2^-53 +- 2^-100) is not exact in
  // long double either. The pairs: from 2^-53 -+ 2^-100 to 1 + 2^-52 along x (a point), and
  // from (1e6, 3, 2^-53 -+ 2^-100) to a line along x and to a plane z = 1 + 2^-52 through points
  // far along them.
  constexpr double kTop = 1 + 0x1p-52;
  const Triangle3 line{{0, 3, kTop}, {1e7, 3, kTop}, {0, 5, kTop}};
  const Triangle3 plane{{0, 0, kTop}, {1e7, 0, kTop}, {0, 1e7, kTop}};
  for (const double h : {0x1p-53 + 0x1p-100, 0x1p-53 - 0x1p-100}) {
    const double want = h < 0x1p-53 ? kTop : 1.0;
    const Vec3 p{1e6, 3, h};
    for (const FlatPair3& pair :
         {FlatPair3{point_flat({h, 0, 0}), point_flat({kTop, 0, 0})},
          FlatPair3{point_flat(p), feature_flat(line, TriangleFeature::edge_ab)},
          FlatPair3{point_flat(p), feature_flat(plane, TriangleFeature::face)}}) {
      EXPECT_EQ(rounded_distance(pair), want) << pair.b.size;
      EXPECT_EQ(rounded_point_distance(pair).distance, want) << pair.b.size;
    }
  }
}

}  // namespace
}  // namespace contain::predicates
