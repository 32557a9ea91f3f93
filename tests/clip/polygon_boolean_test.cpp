#include "contain/clip/polygon_boolean.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "clip/boolean_checks.h"
#include "contain/inside/point_in_polygon.h"
#include "contain/predicates/orient2d.h"

namespace contain::clip {
namespace {

using test::exact_signed_area;
using test::is_valid_ogc;

Ring box(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

MultiPolygon region(std::vector<Ring> rings) {
  return MultiPolygon{{Polygon{std::move(rings)}}};
}

double area(const MultiPolygon& m) {
  return exact_signed_area(m).get_d();
}

MultiPolygon run(const std::vector<Ring>& a, const std::vector<Ring>& b, Op op,
                 Fill fill = Fill::even_odd) {
  return polygon_boolean(a, b, {.op = op, .fill = fill});
}

// A star-shaped ring around (cx, cy): n vertices at random radii in [r0, r1], counter-clockwise.
Ring star(std::mt19937_64& rng, int n, double cx, double cy, double r0, double r1) {
  std::uniform_real_distribution<double> radius(r0, r1);
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n, r = radius(rng);
    ring.push_back({cx + r * std::cos(t), cy + r * std::sin(t)});
  }
  return ring;
}

// A smooth ring of n vertices around (cx, cy) (radius 1 + a few low harmonics, counter-clockwise):
// long monotone chains, so the first noding round works on chains and most vertices end inside
// runs of the arrangement (one graph edge each).
Ring blob(std::mt19937_64& rng, int n, double cx, double cy, double scale) {
  std::uniform_real_distribution<double> u(0, 1);
  double amp[6], phase[6];
  for (int k = 0; k < 6; ++k) {
    amp[k] = u(rng);
    phase[k] = 2 * M_PI * u(rng);
  }
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    double r = 1.0;
    for (int k = 0; k < 6; ++k)
      r += (0.25 / (k + 2)) * amp[k] * std::sin((k + 2) * t + phase[k]);
    ring.push_back({cx + scale * r * std::cos(t), cy + scale * r * std::sin(t)});
  }
  return ring;
}

// A random closed path of n vertices in [0, 1]^2: self-intersecting almost surely.
Ring scribble(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> u(0, 1);
  Ring ring;
  for (int i = 0; i < n; ++i)
    ring.push_back({u(rng), u(rng)});
  return ring;
}

TEST(PolygonBoolean, OverlappingSquaresGiveExactAreasForEveryOp) {
  const std::vector<Ring> a{box(0, 0, 2, 2)}, b{box(1, 1, 3, 3)};
  EXPECT_EQ(exact_signed_area(run(a, b, Op::intersection)), 1);
  EXPECT_EQ(exact_signed_area(run(a, b, Op::union_)), 7);
  EXPECT_EQ(exact_signed_area(run(a, b, Op::difference)), 3);
  EXPECT_EQ(exact_signed_area(run(a, b, Op::xor_)), 6);
  for (Op op : {Op::intersection, Op::union_, Op::difference, Op::xor_}) {
    EXPECT_TRUE(is_valid_ogc(run(a, b, op)));
  }
}

TEST(PolygonBoolean, UnionWithItselfReturnsTheInputBitForBit) {
  std::mt19937_64 rng(7);
  const Ring shell = star(rng, 200, 0.3, -0.7, 1.0, 2.0);
  Ring hole = star(rng, 50, 0.3, -0.7, 0.3, 0.6);
  std::reverse(hole.begin(), hole.end());
  const MultiPolygon a = region({shell, hole});
  EXPECT_EQ(polygon_boolean(a, a, {.op = Op::union_}), a);
  EXPECT_EQ(polygon_boolean(a, a, {.op = Op::intersection}), a);
  EXPECT_TRUE(polygon_boolean(a, a, {.op = Op::difference}).empty());
  EXPECT_TRUE(polygon_boolean(a, a, {.op = Op::xor_}).empty());
}

TEST(PolygonBoolean, IntersectionWithAContainingBoxReturnsTheInputBitForBit) {
  std::mt19937_64 rng(8);
  const MultiPolygon a = region({star(rng, 300, 0.1, 0.2, 1.0, 3.0)});
  const MultiPolygon b = region({box(-5, -5, 5, 5)});
  EXPECT_EQ(polygon_boolean(a, b, {.op = Op::intersection}), a);
  EXPECT_EQ(polygon_boolean(b, a, {.op = Op::intersection}), a);
}

TEST(PolygonBoolean, OneInsideTheOtherGivesAHoleOrTheInnerOne) {
  const std::vector<Ring> outer{box(0, 0, 10, 10)}, inner{box(2, 2, 4, 4)};
  const MultiPolygon d = run(outer, inner, Op::difference);
  ASSERT_EQ(d.polygons.size(), 1u);
  EXPECT_EQ(d.polygons[0].rings.size(), 2u);
  EXPECT_EQ(exact_signed_area(d), 96);
  EXPECT_TRUE(is_valid_ogc(d));
  EXPECT_EQ(exact_signed_area(run(outer, inner, Op::intersection)), 4);
  EXPECT_EQ(exact_signed_area(run(outer, inner, Op::union_)), 100);
  EXPECT_TRUE(run(inner, outer, Op::difference).empty());
}

TEST(PolygonBoolean, SharedEdgeMergesInUnionAndLeavesNothingInIntersection) {
  const std::vector<Ring> a{box(0, 0, 1, 1)}, b{box(1, 0, 2, 1)};
  const MultiPolygon u = run(a, b, Op::union_);
  ASSERT_EQ(u.polygons.size(), 1u);
  EXPECT_EQ(u.polygons[0].rings.size(), 1u);
  EXPECT_EQ(exact_signed_area(u), 2);
  EXPECT_TRUE(is_valid_ogc(u));
  EXPECT_TRUE(run(a, b, Op::intersection).empty());
  EXPECT_EQ(exact_signed_area(run(a, b, Op::difference)), 1);
}

TEST(PolygonBoolean, CollinearPartialOverlapAndVertexOnEdgeAreNoded) {
  // b's edge overlaps part of a's top edge, and b's vertex (1, 1) touches a's right edge.
  const std::vector<Ring> a{box(0, 0, 1, 1)};
  const std::vector<Ring> b{{{0.25, 1}, {0.75, 1}, {1, 1.5}, {0.5, 2}}};
  const std::vector<Ring> c{{{1, 0.5}, {2, 0}, {2, 1}}};
  for (const auto& other : {b, c}) {
    for (Op op : {Op::intersection, Op::union_, Op::difference, Op::xor_}) {
      const MultiPolygon r = run(a, other, op);
      EXPECT_TRUE(is_valid_ogc(r));
    }
    EXPECT_TRUE(run(a, other, Op::intersection).empty());
    EXPECT_EQ(exact_signed_area(run(a, other, Op::union_)),
              exact_signed_area(region(a)) + exact_signed_area(region(other)));
  }
}

TEST(PolygonBoolean, SquaresTouchingAtACornerStaySeparatePolygons) {
  const std::vector<Ring> a{box(0, 0, 1, 1)}, b{box(1, 1, 2, 2)};
  const MultiPolygon u = run(a, b, Op::union_);
  EXPECT_EQ(u.polygons.size(), 2u);
  EXPECT_TRUE(is_valid_ogc(u));
  EXPECT_TRUE(run(a, b, Op::intersection).empty());
}

TEST(PolygonBoolean, HoleTouchingTheShellAtAPointBecomesAHoleNotASelfTouchingShell) {
  // The triangle's apex touches the square's bottom edge from inside.
  const std::vector<Ring> a{box(0, 0, 4, 4)};
  const std::vector<Ring> b{{{2, 0}, {3, 2}, {1, 2}}};
  const MultiPolygon d = run(a, b, Op::difference);
  ASSERT_EQ(d.polygons.size(), 1u);
  EXPECT_EQ(d.polygons[0].rings.size(), 2u);
  EXPECT_TRUE(is_valid_ogc(d));
  EXPECT_EQ(exact_signed_area(d), 14);
}

TEST(PolygonBoolean, FillRulesReadOverlappingAndRepeatedRings) {
  // Two counter-clockwise squares overlapping in a unit square, and one clockwise square.
  Ring cw = box(10, 0, 11, 1);
  std::reverse(cw.begin(), cw.end());
  const std::vector<Ring> a{box(0, 0, 2, 2), box(1, 1, 3, 3), cw};
  const std::vector<Ring> none;
  EXPECT_EQ(exact_signed_area(run(a, none, Op::union_, Fill::even_odd)), 7);
  EXPECT_EQ(exact_signed_area(run(a, none, Op::union_, Fill::nonzero)), 8);
  EXPECT_EQ(exact_signed_area(run(a, none, Op::union_, Fill::positive)), 7);
  EXPECT_EQ(exact_signed_area(run(a, none, Op::union_, Fill::negative)), 1);
  // A ring traversed twice winds twice: not filled under even-odd.
  const std::vector<Ring> twice{box(0, 0, 1, 1), box(0, 0, 1, 1)};
  EXPECT_TRUE(run(twice, none, Op::union_, Fill::even_odd).empty());
  EXPECT_EQ(exact_signed_area(run(twice, none, Op::union_, Fill::nonzero)), 1);
}

TEST(PolygonBoolean, BowTieIsSplitIntoTwoValidTriangles) {
  const std::vector<Ring> bow{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}};
  const std::vector<Ring> none;
  for (Fill fill : {Fill::even_odd, Fill::nonzero}) {
    const MultiPolygon r = run(bow, none, Op::union_, fill);
    EXPECT_EQ(r.polygons.size(), 2u);
    EXPECT_EQ(exact_signed_area(r), 2);
    EXPECT_TRUE(is_valid_ogc(r));
  }
  // One lobe winds +1, the other -1.
  EXPECT_EQ(exact_signed_area(run(bow, none, Op::union_, Fill::positive)), 1);
  EXPECT_EQ(exact_signed_area(run(bow, none, Op::union_, Fill::negative)), 1);
}

TEST(PolygonBoolean, RandomSelfIntersectingPairsGiveValidOutputAndConsistentAreas) {
  std::mt19937_64 rng(2024);
  for (int trial = 0; trial < 60; ++trial) {
    const std::vector<Ring> a{scribble(rng, 12), scribble(rng, 5)};
    const std::vector<Ring> b{scribble(rng, 10)};
    const std::vector<Ring> none;
    for (Fill fill : {Fill::even_odd, Fill::nonzero, Fill::positive, Fill::negative}) {
      const double area_a = area(run(a, none, Op::union_, fill));
      const double area_b = area(run(b, none, Op::union_, fill));
      const MultiPolygon i = run(a, b, Op::intersection, fill);
      const MultiPolygon u = run(a, b, Op::union_, fill);
      const MultiPolygon d = run(a, b, Op::difference, fill);
      const MultiPolygon x = run(a, b, Op::xor_, fill);
      for (const MultiPolygon* r : {&i, &u, &d, &x}) {
        ASSERT_TRUE(is_valid_ogc(*r)) << trial << " " << static_cast<int>(fill) << " " << (r - &i);
      }
      constexpr double kTol = 1e-12;  // relative to the extent squared (1 here)
      EXPECT_NEAR(area(u) + area(i), area_a + area_b, kTol);
      EXPECT_NEAR(area(d), area_a - area(i), kTol);
      EXPECT_NEAR(area(x), area(u) - area(i), kTol);
    }
  }
}

// Intersection and difference leave out the edges of the larger operand far from the other
// (rule clip-far-edges): the results must still agree with the union, which uses every edge, for
// regions that wind several times, have far islands and rings around the small operand.
TEST(PolygonBoolean, SmallOperandsAgainstALargeWindingRegionAgreeWithTheUnion) {
  std::mt19937_64 rng(77);
  Ring twice = star(rng, 120, 0.5, 0.5, 0.3, 0.45);
  const Ring once(twice);
  twice.insert(twice.end(), once.begin(), once.end());  // winding 2 inside
  Ring clockwise = star(rng, 80, 0.5, 0.5, 0.1, 0.25);  // a hole, or winding 1 again
  std::reverse(clockwise.begin(), clockwise.end());
  const std::vector<Ring> big{twice, clockwise, star(rng, 50, 1.5, 1.5, 0.05, 0.1),
                              box(-1, -1, 2, 2), scribble(rng, 20)};
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  const std::vector<Ring> none;
  for (int trial = 0; trial < 24; ++trial) {
    const double x = u(rng), y = u(rng), s = trial % 2 == 0 ? 0.03 : 0.2;
    const std::vector<Ring> small{trial % 3 == 0 ? star(rng, 7, x, y, s / 2, s)
                                                 : box(x, y, x + s, y + s)};
    for (Fill fill : {Fill::even_odd, Fill::nonzero, Fill::positive, Fill::negative}) {
      const double area_big = area(run(big, none, Op::union_, fill));
      const double area_small = area(run(small, none, Op::union_, fill));
      const MultiPolygon i1 = run(big, small, Op::intersection, fill);
      const MultiPolygon i2 = run(small, big, Op::intersection, fill);
      const MultiPolygon d = run(small, big, Op::difference, fill);
      const MultiPolygon un = run(big, small, Op::union_, fill);
      for (const MultiPolygon* r : {&i1, &i2, &d, &un}) {
        ASSERT_TRUE(is_valid_ogc(*r)) << trial << " " << static_cast<int>(fill);
      }
      constexpr double kTol = 1e-12;  // relative to the extent squared (9 here)
      EXPECT_NEAR(area(i1) + area(un), area_big + area_small, kTol) << trial;
      EXPECT_NEAR(area(i2), area(i1), kTol) << trial;
      EXPECT_NEAR(area(d), area(un) - area_big, kTol) << trial;
    }
  }
}

TEST(PolygonBoolean, NearlyCoincidentEdgesStillGiveValidOutput) {
  // b is a copy of a turned by a few ulps about a vertex: edges cross at tiny angles.
  std::mt19937_64 rng(5);
  const Ring a = star(rng, 100, 0, 0, 1, 2);
  for (const double angle : {1e-15, 1e-13, 1e-10}) {
    Ring b;
    for (const Vec2 p : a) {
      b.push_back({p.x * std::cos(angle) - p.y * std::sin(angle) + 1e-16,
                   p.x * std::sin(angle) + p.y * std::cos(angle)});
    }
    for (Op op : {Op::intersection, Op::union_, Op::difference, Op::xor_}) {
      const MultiPolygon r = run({a}, {b}, op);
      EXPECT_TRUE(is_valid_ogc(r)) << angle;
    }
    EXPECT_NEAR(area(run({a}, {b}, Op::intersection)) + area(run({a}, {b}, Op::union_)),
                2 * area(region({a})), 1e-12 * 16);
  }
}

// Two generic regions (no vertex on an edge of the other) have interiors that meet exactly when
// an edge crosses an edge or a vertex lies inside the other; the intersection must agree.
TEST(PolygonBoolean, IntersectionIsNonEmptyExactlyWhenTheRegionsOverlap) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> shift(-3, 3);
  int overlapping = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Ring a = star(rng, 9, 0, 0, 0.5, 1.5);
    const Ring b = star(rng, 7, shift(rng), shift(rng), 0.2, 1.0);
    bool meet = false;
    for (std::size_t i = 0; i < a.size() && !meet; ++i) {
      for (std::size_t j = 0; j < b.size() && !meet; ++j) {
        const Vec2 p0 = a[i], p1 = a[(i + 1) % a.size()], q0 = b[j], q1 = b[(j + 1) % b.size()];
        meet = predicates::orient2d(p0, p1, q0) != predicates::orient2d(p0, p1, q1) &&
               predicates::orient2d(q0, q1, p0) != predicates::orient2d(q0, q1, p1);
      }
    }
    const std::vector<Ring> ra{a}, rb{b};
    meet = meet || inside::point_in_polygon(ra, b[0]) == Location::inside ||
           inside::point_in_polygon(rb, a[0]) == Location::inside;
    const MultiPolygon i = run(ra, rb, Op::intersection);
    EXPECT_EQ(!i.empty(), meet) << trial;
    EXPECT_EQ(!i.empty(), exact_signed_area(i) > 0) << trial;
    overlapping += meet ? 1 : 0;
  }
  EXPECT_GT(overlapping, 20);
  EXPECT_LT(overlapping, 180);
}

TEST(PolygonBoolean, EmptyAndDegenerateInputsGiveEmptyOrTheOtherRegion) {
  const std::vector<Ring> none;
  const std::vector<Ring> a{box(0, 0, 1, 1)};
  const std::vector<Ring> flat{{{0, 0}, {1, 1}, {2, 2}}};  // zero area
  EXPECT_TRUE(run(none, none, Op::union_).empty());
  EXPECT_TRUE(run(a, none, Op::intersection).empty());
  EXPECT_EQ(run(a, none, Op::union_), region(a));
  EXPECT_EQ(run(a, flat, Op::union_), region(a));
  EXPECT_TRUE(run(flat, flat, Op::union_).empty());
}

TEST(PolygonBoolean, SmoothRingsGiveValidOutputConsistentAreasAndFewGraphEdges) {
  std::mt19937_64 rng(31);
  const std::vector<Ring> none;
  for (int trial = 0; trial < 12; ++trial) {
    std::uniform_real_distribution<double> shift(-0.6, 0.6);
    const std::vector<Ring> a{blob(rng, 400, 0, 0, 1)};
    std::vector<Ring> b{blob(rng, 300, shift(rng), shift(rng), 0.9)};
    if (trial % 2 == 1) std::reverse(b[0].begin(), b[0].end());
    for (Fill fill : {Fill::even_odd, Fill::nonzero, Fill::positive}) {
      const double area_a = area(run(a, none, Op::union_, fill));
      const double area_b = area(run(b, none, Op::union_, fill));
      const auto [i, stats] =
          polygon_boolean_with_stats(a, b, {.op = Op::intersection, .fill = fill});
      const MultiPolygon u = run(a, b, Op::union_, fill);
      const MultiPolygon d = run(a, b, Op::difference, fill);
      const MultiPolygon x = run(a, b, Op::xor_, fill);
      for (const MultiPolygon* r : {&i, &u, &d, &x}) {
        ASSERT_TRUE(is_valid_ogc(*r)) << trial << " " << static_cast<int>(fill) << " " << (r - &i);
      }
      constexpr double kTol = 1e-12 * 9;  // relative to the extent squared
      EXPECT_NEAR(area(u) + area(i), area_a + area_b, kTol) << trial;
      EXPECT_NEAR(area(d), area_a - area(i), kTol) << trial;
      EXPECT_NEAR(area(x), area(u) - area(i), kTol) << trial;
      // Runs through vertices that nothing else meets are single edges: a few per crossing.
      EXPECT_LT(stats.graph_edges, 4 * stats.crossings + 8) << trial;
    }
  }
}

TEST(PolygonBoolean, UnionOfASmoothRegionWithItselfReturnsTheInputBitForBit) {
  std::mt19937_64 rng(32);
  Ring hole = blob(rng, 500, 0.1, 0.2, 0.4);
  std::reverse(hole.begin(), hole.end());
  const MultiPolygon a = region({blob(rng, 2000, 0, 0, 2), hole});
  EXPECT_EQ(polygon_boolean(a, a, {.op = Op::union_}), a);
  EXPECT_EQ(polygon_boolean(a, a, {.op = Op::intersection}), a);
  EXPECT_TRUE(polygon_boolean(a, a, {.op = Op::difference}).empty());
  const MultiPolygon big = region({box(-5, -5, 5, 5)});
  EXPECT_EQ(polygon_boolean(a, big, {.op = Op::intersection}), a);
}

// A vertex that another ring passes through or shares is a vertex of the arrangement even when
// it lies inside a long run of untouched vertices: the noding reports it (Noded::event).
TEST(PolygonBoolean, SmoothRingsSharingVerticesAndEdgesWithoutCrossingStayApart) {
  std::mt19937_64 rng(33);
  const Ring a = blob(rng, 600, 0, 0, 1);
  // b shares the vertices 100 .. 250 of a (and the edges between them, in the opposite
  // direction) and closes with an arc outside a: the regions touch along that chain only.
  Ring b;
  for (int k = 250; k >= 100; --k)
    b.push_back(a[k]);
  for (int k = 100; k <= 250; k += 10) {
    const Vec2 p = a[k];
    b.push_back({p.x * 2.5, p.y * 2.5});
  }
  // c touches a at vertex 400 from outside with one corner (a thin counter-clockwise triangle
  // along the ray from the centre, which meets a only there: a is star-shaped).
  const Vec2 q = a[400], side{-0.02 * q.y, 0.02 * q.x};
  const Ring c{q, {3 * q.x - side.x, 3 * q.y - side.y}, {3 * q.x + side.x, 3 * q.y + side.y}};
  const mpq_class area_a = exact_signed_area(region({a}));
  for (const Ring& other : {b, c}) {
    const mpq_class area_o = exact_signed_area(region({other}));
    ASSERT_GT(area_o, 0);
    const MultiPolygon u = run({a}, {other}, Op::union_);
    const MultiPolygon i = run({a}, {other}, Op::intersection);
    const MultiPolygon d = run({a}, {other}, Op::difference);
    EXPECT_TRUE(is_valid_ogc(u));
    EXPECT_TRUE(is_valid_ogc(d));
    EXPECT_TRUE(i.empty());
    EXPECT_EQ(exact_signed_area(u), area_a + area_o);
    EXPECT_EQ(exact_signed_area(d), area_a);
  }
}

// Components without crossings get their winding numbers from a ray from their lowest point,
// which is usually inside a run.
TEST(PolygonBoolean, NestedSmoothRingsGetTheirWindingNumbersRight) {
  std::mt19937_64 rng(34);
  const Ring outer = blob(rng, 700, 0, 0, 3);
  const Ring inner = blob(rng, 300, 0.2, -0.1, 1);
  Ring inner_cw(inner);
  std::reverse(inner_cw.begin(), inner_cw.end());
  const mpq_class area_outer = exact_signed_area(region({outer}));
  const mpq_class area_inner = exact_signed_area(region({inner}));
  const MultiPolygon d = run({outer}, {inner}, Op::difference);
  ASSERT_EQ(d.polygons.size(), 1u);
  EXPECT_EQ(d.polygons[0].rings.size(), 2u);
  EXPECT_TRUE(is_valid_ogc(d));
  EXPECT_EQ(exact_signed_area(d), area_outer - area_inner);
  EXPECT_EQ(exact_signed_area(run({outer}, {inner}, Op::intersection)), area_inner);
  EXPECT_EQ(exact_signed_area(run({inner}, {outer}, Op::union_)), area_outer);
  // One operand of two nested rings: even-odd makes a hole, nonzero with a counter-clockwise
  // inner ring a region of winding 2, with a clockwise one a hole again.
  const std::vector<Ring> none;
  EXPECT_EQ(exact_signed_area(run({outer, inner}, none, Op::union_)), area_outer - area_inner);
  EXPECT_EQ(exact_signed_area(run({outer, inner}, none, Op::union_, Fill::nonzero)), area_outer);
  EXPECT_EQ(exact_signed_area(run({outer, inner_cw}, none, Op::union_, Fill::nonzero)),
            area_outer - area_inner);
  // Far apart: each its own component.
  Ring away = inner;
  for (Vec2& p : away)
    p.x += 10;
  EXPECT_EQ(exact_signed_area(run({outer}, {away}, Op::union_)),
            area_outer + exact_signed_area(region({away})));
  EXPECT_TRUE(run({outer}, {away}, Op::intersection).empty());
}

// Rings of one operand written one after another, the next starting where the one before ends:
// the paths are kept apart, and the shared start is a vertex.
TEST(PolygonBoolean, RingsStartingWhereThePreviousEndsAreSeparatePaths) {
  const std::vector<Ring> a{box(0, 0, 1, 1), {{0, 0}, {-1, 0}, {-1, -1}, {0, -1}}};
  const MultiPolygon u = run(a, {}, Op::union_);
  EXPECT_TRUE(is_valid_ogc(u));
  EXPECT_EQ(u.polygons.size(), 2u);
  EXPECT_EQ(exact_signed_area(u), 2);
  const MultiPolygon i = run(a, {box(-0.5, -0.5, 0.5, 0.5)}, Op::intersection);
  EXPECT_TRUE(is_valid_ogc(i));
  EXPECT_EQ(exact_signed_area(i), 0.5);
}

}  // namespace
}  // namespace contain::clip
