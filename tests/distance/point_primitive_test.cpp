// point_triangle, point_segment and point_box against the GMP oracle.

#include "contain/distance/point_primitive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/exact_distance.h"

namespace contain::distance {
namespace {

Vec3 lattice(std::mt19937_64& rng, int n) {
  std::uniform_int_distribution<int> d(-n, n);
  return {0.5 * d(rng), 0.5 * d(rng), 0.5 * d(rng)};
}

TEST(PointPrimitive, TriangleAndSegmentMatchTheOracleOnLatticeAndRandomPoints) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 3000; ++i) {
    const bool on_lattice = i % 2 == 0;
    auto pick = [&] { return on_lattice ? lattice(rng, 4) : Vec3{u(rng), u(rng), u(rng)}; };
    const Triangle3 t{pick(), pick(), pick()};
    const Vec3 p = pick();
    const test::ExactClosest3 want = test::exact_closest(p, t);
    const Closest3 got = point_triangle(t, p);
    ASSERT_EQ(got.distance, test::nearest_double_sqrt(want.squared_distance));
    ASSERT_EQ(got.point.x, test::nearest_double(want.point.x));
    ASSERT_EQ(got.point.y, test::nearest_double(want.point.y));
    ASSERT_EQ(got.point.z, test::nearest_double(want.point.z));
    const Segment3 s{t.a, t.b};
    const test::ExactClosest3 ws = test::exact_closest(p, s);
    const Closest3 gs = point_segment(s, p);
    ASSERT_EQ(gs.distance, test::nearest_double_sqrt(ws.squared_distance));
    ASSERT_EQ(gs.point.z, test::nearest_double(ws.point.z));
    const Segment2 s2{{t.a.x, t.a.y}, {t.b.x, t.b.y}};
    const test::ExactClosest2 w2 = test::exact_closest(Vec2{p.x, p.y}, s2);
    const Closest2 g2 = point_segment(s2, Vec2{p.x, p.y});
    ASSERT_EQ(g2.distance, test::nearest_double_sqrt(w2.squared_distance));
    ASSERT_EQ(g2.point.x, test::nearest_double(w2.point.x));
  }
}

TEST(PointPrimitive, BoxDistanceSignAndNearestFaceWithTiesToTheLowestFace) {
  const Box3 box{{-1, -2, -3}, {1, 2, 3}};
  std::mt19937_64 rng(4);
  for (int i = 0; i < 4000; ++i) {
    const Vec3 p =
        i % 2 == 0 ? lattice(rng, 8) : Vec3{std::ldexp(lattice(rng, 8).x, -3), 1.25, -0.5};
    const Closest3 got = point_box(box, p, {.signed_distance = true});
    const bool in = box.contains(p);
    if (!in) {
      const Vec3 c{std::clamp(p.x, -1.0, 1.0), std::clamp(p.y, -2.0, 2.0),
                   std::clamp(p.z, -3.0, 3.0)};
      const test::QVec3 d = test::qsub(test::exact(p), test::exact(c));
      ASSERT_EQ(got.distance, test::nearest_double_sqrt(test::qdot(d, d)));
      ASSERT_EQ(got.point, c);
      ASSERT_EQ(got.location, Location::outside);
      ASSERT_EQ(got.feature, -1);
      continue;
    }
    const double gaps[6] = {p.x + 1, 1 - p.x, p.y + 2, 2 - p.y, p.z + 3, 3 - p.z};
    int best = 0;
    for (int f = 1; f < 6; ++f)
      if (gaps[f] < gaps[best]) best = f;
    ASSERT_EQ(got.feature, best) << p.x << " " << p.y << " " << p.z;
    if (gaps[best] == 0) {
      ASSERT_EQ(got.location, Location::boundary);
      ASSERT_EQ(got.distance, 0.0);
    } else {
      ASSERT_EQ(got.location, Location::inside);
      ASSERT_EQ(got.distance, -gaps[best]);  // exact differences of these lattice values
    }
  }
}

}  // namespace
}  // namespace contain::distance
