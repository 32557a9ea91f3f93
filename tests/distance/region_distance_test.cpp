// RegionDistance against a brute-force GMP oracle: the least exact distance over every edge,
// ties to the lowest (ring, edge), rounded once; the sign from the exact location.

#include "contain/distance/region_distance.h"
#include "contain/distance/region_pair_distance.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "scenes/scenes.h"
#include "support/case_budget.h"
#include "support/exact_distance.h"

namespace contain::distance {
namespace {

struct OracleAnswer {
  mpq_class squared_distance;
  test::QVec2 point;
  int ring = -1;
  int edge = -1;
};

OracleAnswer oracle(const std::vector<Ring>& rings, Vec2 p) {
  OracleAnswer best;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    for (std::size_t k = 0; k < rings[r].size(); ++k) {
      const Segment2 s{rings[r][k], rings[r][(k + 1) % rings[r].size()]};
      const test::ExactClosest2 c = test::exact_closest(p, s);
      if (best.ring < 0 || c.squared_distance < best.squared_distance) {
        best = {c.squared_distance, c.point, static_cast<int>(r), static_cast<int>(k)};
      }
    }
  }
  return best;
}

std::string hex2(Vec2 p) {
  char buf[100];
  std::snprintf(buf, sizeof buf, "(%a, %a)", p.x, p.y);
  return buf;
}

int check_region(const std::vector<Ring>& rings, const std::vector<Vec2>& points, Fill fill,
                 bool valid) {
  const RegionDistance prepared(std::span<const Ring>(rings), {.fill = fill});
  int failures = 0;
  for (const Vec2& p : points) {
    const Closest2 got = prepared.distance(p, {.signed_distance = true});
    const OracleAnswer want = oracle(rings, p);
    const double d = test::nearest_double_sqrt(want.squared_distance);
    const Vec2 q{test::nearest_double(want.point.x), test::nearest_double(want.point.y)};
    if (std::fabs(got.distance) != d || got.ring != want.ring || got.edge != want.edge ||
        !(got.point == q)) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "got %a (%d:%d) want %a (%d:%d) at ", got.distance, got.ring,
                    got.edge, d, want.ring, want.edge);
      ADD_FAILURE() << buf << hex2(p) << " point " << hex2(got.point) << " want " << hex2(q);
      if (++failures >= 10) return failures;
      continue;
    }
    const Location where = prepared.index().locate(p);
    EXPECT_EQ(got.location, where);
    if (where == Location::boundary) {
      EXPECT_TRUE(got.distance == 0.0 && !std::signbit(got.distance));
    }
    if (where == Location::inside) {
      EXPECT_LE(got.distance, 0.0);
    }
    if (valid) {
      EXPECT_EQ(where == Location::boundary, want.squared_distance == 0) << hex2(p);
    }
    for (double dd : {d, std::nextafter(d, 0.0), std::nextafter(d, DBL_MAX)}) {
      const mpq_class qd(dd);
      EXPECT_EQ(prepared.within(p, dd), want.squared_distance <= qd * qd) << hex2(p);
    }
  }
  return failures;
}

std::vector<Vec2> probes(const std::vector<Ring>& rings, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Box2 box = bounding_box(rings);
  std::uniform_real_distribution<double> u(-0.2, 1.2), unit(0, 1);
  std::vector<Vec2> out;
  for (int i = 0; i < count; ++i) {
    const Ring& ring = rings[rng() % rings.size()];
    const std::size_t k = rng() % ring.size();
    const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
    switch (i % 4) {
      case 0:
        out.push_back({box.min.x + u(rng) * (box.max.x - box.min.x),
                       box.min.y + u(rng) * (box.max.y - box.min.y)});
        break;
      case 1:
        out.push_back(a);
        break;
      case 2: {
        const double t = unit(rng);
        out.push_back(a + t * (b - a) + 1e-9 * Vec2{unit(rng) - 0.5, unit(rng) - 0.5});
        break;
      }
      default:
        out.push_back(0.5 * (a + b));
    }
  }
  return out;
}

TEST(RegionDistance, DemoPolygonWithHolesMatchesTheExactOracle) {
  const Polygon polygon = scenes::demo_polygon();
  EXPECT_EQ(check_region(polygon.rings, probes(polygon.rings, test::case_budget(2000, 5), 1),
                         Fill::even_odd, true),
            0);
}

TEST(RegionDistance, LatticeSquareWithHoleKeepsTheLowestEdgeOnTies) {
  // shell 0..4 counter-clockwise, hole 1..3 clockwise; every half-integer lattice point
  const std::vector<Ring> rings{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {1, 3}, {3, 3}, {3, 1}}};
  std::vector<Vec2> points;
  for (int x = -2; x <= 10; ++x)
    for (int y = -2; y <= 10; ++y)
      points.push_back({0.5 * x, 0.5 * y});
  EXPECT_EQ(check_region(rings, points, Fill::even_odd, true), 0);
}

TEST(RegionDistance, OverlappingRingsUnderNonzeroAndZeroLengthEdges) {
  // Two overlapping squares (buried edges under nonzero), a ring with a repeated vertex.
  const std::vector<Ring> rings{{{0, 0}, {3, 0}, {3, 3}, {0, 3}},
                                {{2, 1}, {5, 1}, {5, 1}, {5, 4}, {2, 4}}};
  std::vector<Vec2> points = probes(rings, test::case_budget(600, 5), 3);
  for (int x = -2; x <= 12; ++x)
    for (int y = -2; y <= 10; ++y)
      points.push_back({0.5 * x, 0.5 * y});
  for (const Fill fill : {Fill::even_odd, Fill::nonzero, Fill::positive, Fill::negative})
    EXPECT_EQ(check_region(rings, points, fill, false), 0);
}

TEST(RegionDistance, SpikyStarAndHugeAndTinyScales) {
  const Ring star = scenes::star_ring(200, {0.5, 0.5}, 0.1, 1.0, 7);
  EXPECT_EQ(
      check_region({star}, probes({star}, test::case_budget(1000, 5), 4), Fill::even_odd, true), 0);
  for (const int k : {-1000, -500, 500, 1000}) {
    const double s = std::ldexp(1.0, k);
    Ring scaled;
    for (const Vec2& v : star)
      scaled.push_back(s * v);
    std::vector<Vec2> points;
    for (const Vec2& p : probes({star}, test::case_budget(200, 25), 5))
      points.push_back(s * p);
    EXPECT_EQ(check_region({scaled}, points, Fill::even_odd, true), 0) << "2^" << k;
  }
}

TEST(RegionDistance, BatchEqualsSingleOnAnyThreadCountAndOneShotEqualsPrepared) {
  const Polygon polygon = scenes::demo_polygon();
  const RegionDistance prepared(polygon);
  const std::vector<Vec2> points = scenes::uniform_points(bounding_box(polygon.rings), 20000, 3);
  std::vector<Closest2> one(points.size()), two(points.size());
  prepared.distance(points, one, {.signed_distance = true}, {.threads = 1});
  prepared.distance(points, two, {.signed_distance = true}, {.threads = 2});
  for (std::size_t i = 0; i < points.size(); i += 7) {
    const Closest2 single = prepared.distance(points[i], {.signed_distance = true});
    ASSERT_EQ(one[i].distance, single.distance);
    ASSERT_EQ(two[i].distance, single.distance);
    ASSERT_EQ(two[i].edge, single.edge);
    ASSERT_EQ(two[i].ring, single.ring);
  }
  const MultiPolygon region{{polygon}};
  for (std::size_t i = 0; i < 50; ++i) {
    const Closest2 a = point_region(region, points[i], {.signed_distance = true});
    EXPECT_EQ(a.distance, one[i].distance);
    EXPECT_EQ(a.point, one[i].point);
  }
}

TEST(RegionDistance, EmptyRegionAndNonFinitePoints) {
  const RegionDistance empty;
  EXPECT_EQ(empty.distance({0, 0}).distance, std::numeric_limits<double>::infinity());
  const RegionDistance square(std::vector<Ring>{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  EXPECT_TRUE(std::isnan(square.distance({std::nan(""), 0}).distance));
  EXPECT_FALSE(square.within({0.5, 0.5}, -1));
  EXPECT_TRUE(square.within({0.5, 0.5}, 0.5));
  EXPECT_FALSE(square.within({0.5, 0.5}, std::nextafter(0.5, 0.0)));
}

}  // namespace
}  // namespace contain::distance

namespace contain::distance {
namespace {

Polygon square(double x0, double y0, double side) {
  return {{{{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}}}};
}

TEST(RegionPairDistance, SeparatedTouchingCrossingAndNestedSquares) {
  const MultiPolygon big{{square(0, 0, 4)}};
  EXPECT_EQ(region_region(big, MultiPolygon{{square(6, 0, 1)}}).distance, 2.0);
  const PairDistance2 touch = region_region(big, MultiPolygon{{square(4, 1, 1)}});
  EXPECT_EQ(touch.distance, 0.0);
  EXPECT_EQ(touch.contact, inside::PairWitness::edges);
  const PairDistance2 cross = region_region(big, MultiPolygon{{square(3.5, 1, 1)}});
  EXPECT_EQ(cross.contact, inside::PairWitness::edges);
  const PairDistance2 nested = region_region(big, MultiPolygon{{square(1, 1, 1)}});
  EXPECT_EQ(nested.contact, inside::PairWitness::vertex_of_b_in_a);
  EXPECT_EQ(nested.distance, 0.0);
  EXPECT_EQ(region_region(MultiPolygon{{square(1, 1, 1)}}, big).contact,
            inside::PairWitness::vertex_of_a_in_b);
  // inside the hole: not nested, the distance to the hole's ring
  Polygon holed = square(0, 0, 10);
  holed.rings.push_back({{2, 2}, {2, 8}, {8, 8}, {8, 2}});
  const PairDistance2 in_hole =
      region_region(MultiPolygon{{holed}}, MultiPolygon{{square(4, 4, 1)}});
  EXPECT_EQ(in_hole.distance, 2.0);
  EXPECT_EQ(in_hole.ring_a, 1);
  EXPECT_TRUE(region_region_within(MultiPolygon{{holed}}, MultiPolygon{{square(4, 4, 1)}}, 2.0));
  EXPECT_FALSE(region_region_within(MultiPolygon{{holed}}, MultiPolygon{{square(4, 4, 1)}},
                                    std::nextafter(2.0, 0.0)));
  EXPECT_TRUE(region_region_within(big, MultiPolygon{{square(1, 1, 1)}}, 0.0));
}

TEST(RegionPairDistance, RandomStarsMatchTheExactOracle) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int i = 0; i < 60; ++i) {
    const Ring ra = scenes::star_ring(12, {0, 0}, 0.4, 1.0, static_cast<std::uint64_t>(i));
    const Ring rb =
        scenes::star_ring(9, {u(rng), u(rng)}, 0.3, 0.8, static_cast<std::uint64_t>(i + 100));
    const PairDistance2 got =
        region_region(MultiPolygon{{Polygon{{ra}}}}, MultiPolygon{{Polygon{{rb}}}});
    mpq_class best = -1;
    int ka = -1, kb = -1;
    for (std::size_t x = 0; x < ra.size(); ++x) {
      for (std::size_t y = 0; y < rb.size(); ++y) {
        const mpq_class d = test::exact_squared_distance(Segment2{ra[x], ra[(x + 1) % ra.size()]},
                                                         Segment2{rb[y], rb[(y + 1) % rb.size()]});
        if (best < 0 || d < best) {
          best = d;
          ka = static_cast<int>(x);
          kb = static_cast<int>(y);
        }
      }
    }
    const inside::PolygonIndex ia(std::vector<Ring>{ra}), ib(std::vector<Ring>{rb});
    const bool nested =
        best > 0 && (ia.locate(rb[0]) == Location::inside || ib.locate(ra[0]) == Location::inside);
    ASSERT_EQ(got.distance, nested ? 0.0 : test::nearest_double_sqrt(best)) << i;
    if (!nested) {
      ASSERT_EQ(got.edge_a, ka) << i;
      ASSERT_EQ(got.edge_b, kb) << i;
    }
  }
}

}  // namespace
}  // namespace contain::distance
