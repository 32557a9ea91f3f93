// Polygons clipped into valid pieces: validity, conserved area, holes, the section's form.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "clip/boolean_checks.h"
#include "clip/polygon_checks.h"
#include "contain/clip/clip_polygon.h"
#include "contain/clip/polygon_boolean.h"
#include "contain/clip/sutherland_hodgman.h"
#include "scenes/scenes.h"

namespace contain::test {
namespace {

MultiPolygon of(Polygon p) {
  return MultiPolygon{{std::move(p)}};
}

TEST(ClipPolygon, ConcaveShapeFallsApartIntoValidPieces) {
  const Polygon u{{{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}}};
  const std::vector<HalfPlane> y_ge_2 = {{0, 1, -2}};
  const MultiPolygon pieces = clip::clip_polygon(of(u), y_ge_2);
  ASSERT_EQ(pieces.polygons.size(), 2u);
  EXPECT_EQ(ogc_problem(pieces), "");
  EXPECT_DOUBLE_EQ(area(pieces), 2.0);
  const MultiPolygon bridged =
      clip::clip_polygon(of(u), y_ge_2, {.output = clip::PolygonClipOutput::bridged});
  ASSERT_EQ(bridged.polygons.size(), 1u);
  EXPECT_EQ(bridged.polygons[0].rings.size(), 1u);
  EXPECT_DOUBLE_EQ(area(bridged), 2.0);
}

TEST(ClipPolygon, HoleCutByTheBoxBecomesPartOfTheShell) {
  const Polygon frame{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 2}, {2, 8}, {8, 8}, {8, 2}}}};
  const MultiPolygon a = clip::clip_polygon(of(frame), Box2{{0, 0}, {5, 5}});
  EXPECT_EQ(ogc_problem(a), "");
  ASSERT_EQ(a.polygons.size(), 1u);
  EXPECT_EQ(a.polygons[0].rings.size(), 1u);
  EXPECT_DOUBLE_EQ(area(a), 25.0 - 9.0);
  const MultiPolygon b = clip::clip_polygon(of(frame), Box2{{1, 1}, {9, 9}});
  ASSERT_EQ(b.polygons.size(), 1u);
  EXPECT_EQ(b.polygons[0].rings.size(), 2u);  // the hole is uncut and stays a hole
  EXPECT_DOUBLE_EQ(area(b), 64.0 - 36.0);
  EXPECT_TRUE(clip::clip_polygon(of(frame), Box2{{3, 3}, {4, 4}}).polygons.empty());
  // A box cutting the frame into a C: one piece, no hole.
  const MultiPolygon c = clip::clip_polygon(of(frame), Box2{{0, 0}, {5, 10}});
  EXPECT_EQ(ogc_problem(c), "");
  ASSERT_EQ(c.polygons.size(), 1u);
  EXPECT_DOUBLE_EQ(area(c), 50.0 - 18.0);
}

TEST(ClipPolygon, ClockwiseInputComesOutCounterClockwise) {
  const Polygon cw{{{{0, 0}, {0, 2}, {2, 2}, {2, 0}}}};
  const MultiPolygon r = clip::clip_polygon(of(cw), Box2{{1, -1}, {3, 3}});
  EXPECT_EQ(ogc_problem(r), "");
  EXPECT_DOUBLE_EQ(area(r), 2.0);
}

TEST(ClipPolygon, VertexTouchingTheLineFromInsideKeepsOnePiece) {
  const Polygon diamond{{{{0, 1}, {1, 0}, {2, 1}, {1, 2}}}};
  const std::vector<HalfPlane> y_le_2 = {{0, -1, 2}};
  const MultiPolygon r = clip::clip_polygon(of(diamond), y_le_2);
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].rings[0].size(), 4u);
  const std::vector<HalfPlane> y_ge_2 = {{0, 1, -2}};
  EXPECT_TRUE(clip::clip_polygon(of(diamond), y_ge_2).polygons.empty());  // zero area: gone
}

TEST(ClipPolygon, RandomStarsByRandomHalfPlanesGiveValidPiecesOfTheBridgedArea) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int multi = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const Ring star = scenes::star_ring(40, {0, 0}, 0.2, 1.0, static_cast<std::uint64_t>(trial));
    std::vector<HalfPlane> planes;
    for (int i = 0; i < 1 + trial % 4; ++i) {
      const double a = u(rng) * M_PI;
      planes.push_back({std::cos(a), std::sin(a), 0.5 * u(rng)});
    }
    const MultiPolygon pieces = clip::clip_polygon(of(Polygon{{star}}), planes);
    ASSERT_EQ(ogc_problem(pieces), "") << trial;
    multi += pieces.polygons.size() > 1;
    const Ring bridged = clip::sutherland_hodgman(star, planes);
    EXPECT_NEAR(area(pieces), 0.5 * signed_area2(bridged), 1e-12) << trial;
  }
  EXPECT_GT(multi, 10);
}

TEST(ClipPolygon, DemoPolygonWithHolesByAConvexRing) {
  const Polygon demo = scenes::demo_polygon();
  const Ring window = {{-0.3, -2}, {2, -0.5}, {1.5, 2}, {-0.5, 1}};
  const MultiPolygon r = clip::clip_polygon(of(demo), window);
  EXPECT_EQ(ogc_problem(r), "");
  MultiPolygon bridged =
      clip::clip_polygon(of(demo), window, {.output = clip::PolygonClipOutput::bridged});
  EXPECT_NEAR(area(r), area(bridged), 1e-12);
}

// The class of issue 13's instance on half-planes and convex rings: a hole edge on the line.
// Inside the half-plane it becomes a notch of the shell; outside, the shell runs along it.
// Every result is valid (exact check) with the area the boolean engine gives for the same
// region written as a polygon whose edge lies on the line.
TEST(ClipPolygon, HoleEdgeOnAHalfPlaneLineOrConvexEdgeBecomesANotch) {
  const Polygon frame{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                       {{2, 3}, {2, 6}, {4, 6}, {4, 3}},
                       {{7, 9}, {9, 7}, {7, 7}}}};  // the triangle's long edge lies on x + y = 16
  struct Case {
    HalfPlane h;
    Ring as_polygon;  // the half-plane within [-100, 120]^2, corners exactly on its line
  };
  const Case cases[] = {
      {{-1, 0, 4}, {{-100, -100}, {4, -100}, {4, 110}, {-100, 110}}},  // x <= 4
      {{1, 0, -4}, {{4, -100}, {110, -100}, {110, 110}, {4, 110}}},    // x >= 4
      {{1, 0, -2}, {{2, -100}, {110, -100}, {110, 110}, {2, 110}}},    // x >= 2
      {{0, 1, -3}, {{-100, 3}, {110, 3}, {110, 110}, {-100, 110}}},    // y >= 3
      {{0, -1, 6}, {{-100, -100}, {110, -100}, {110, 6}, {-100, 6}}},  // y <= 6
      {{0, -1, 3}, {{-100, -100}, {110, -100}, {110, 3}, {-100, 3}}},  // y <= 3
      {{-1, -1, 8}, {{-100, -100}, {108, -100}, {-100, 108}}},         // x + y <= 8
      {{1, 1, -8}, {{108, -100}, {110, -100}, {110, 110}, {-100, 110}, {-100, 108}}}};
  for (const Case& c : cases) {
    const std::vector<HalfPlane> planes{c.h};
    const MultiPolygon r = clip::clip_polygon(of(frame), planes);
    ASSERT_TRUE(is_valid_ogc(r)) << c.h.a << " " << c.h.b << " " << c.h.c;
    const MultiPolygon engine = clip::polygon_boolean(frame.rings, std::vector<Ring>{c.as_polygon},
                                                      {.op = clip::Op::intersection});
    EXPECT_EQ(exact_signed_area(r), exact_signed_area(engine)) << c.h.a << " " << c.h.c;
    // The convex ring of the same region gives the same pieces' area and validity.
    const MultiPolygon by_ring = clip::clip_polygon(of(frame), c.as_polygon);
    ASSERT_TRUE(is_valid_ogc(by_ring)) << c.h.a << " " << c.h.c;
    EXPECT_EQ(exact_signed_area(by_ring), exact_signed_area(engine));
  }
  // The instance: x <= 4 keeps the square hole as a notch, no hole touching the shell.
  const MultiPolygon notch = clip::clip_polygon(of(frame), std::vector<HalfPlane>{{-1, 0, 4}});
  ASSERT_EQ(notch.polygons.size(), 1u);
  EXPECT_EQ(notch.polygons[0].rings.size(), 1u);  // the shell with the notch
}

// Convex rings (cut by their box first, then their edges) and half-plane sets with and without
// axis-parallel members (their box first, then the others): valid pieces with the area of the
// section's bridged result, on stars and on the demo polygon with holes.
TEST(ClipPolygon, ConvexRingsAndMixedHalfPlanesGiveValidPiecesOfTheBridgedArea) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const MultiPolygon region =
        trial % 2 ? of(scenes::demo_polygon())
                  : of(Polygon{{scenes::star_ring(60 + trial, {0, 0}, 0.2, 1.0,
                                                  static_cast<std::uint64_t>(trial))}});
    const double s = trial % 2 ? 2.5 : 1.0;
    Ring convex;
    const double cx = 0.5 * s * u(rng), cy = 0.5 * s * u(rng), r = s * (0.2 + std::fabs(u(rng)));
    const int k = 3 + trial % 6;
    for (int i = 0; i < k; ++i) {
      const double a = 2 * M_PI * i / k + trial;
      convex.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    }
    const MultiPolygon by_ring = clip::clip_polygon(region, convex);
    ASSERT_TRUE(is_valid_ogc(by_ring)) << trial;
    const MultiPolygon bridged_ring =
        clip::clip_polygon(region, convex, {.output = clip::PolygonClipOutput::bridged});
    EXPECT_NEAR(area(by_ring), area(bridged_ring), 1e-12 * s * s) << trial;
    std::vector<HalfPlane> planes = {{1, 0, s * 0.3 * u(rng)}, {0, -1, s * 0.5}};
    for (int i = 0; i < trial % 3; ++i) {
      const double a = u(rng) * M_PI;
      planes.push_back({std::cos(a), std::sin(a), 0.4 * s * u(rng)});
    }
    const MultiPolygon by_planes = clip::clip_polygon(region, planes);
    ASSERT_TRUE(is_valid_ogc(by_planes)) << trial;
    const MultiPolygon bridged_planes =
        clip::clip_polygon(region, planes, {.output = clip::PolygonClipOutput::bridged});
    EXPECT_NEAR(area(by_planes), area(bridged_planes), 1e-12 * s * s) << trial;
  }
}

// A self-crossing ring (not OGC-valid; Clipper2's test 5) whose lobes cross at (592, 240): the
// upper one clockwise, of area 12640, the lower one counter-clockwise, of area 2840, holding
// the lowest vertex. The ring is oriented by its exact area, the larger lobe's orientation; by
// the turn at the lowest vertex the upper lobe was taken inside out, and the cut above y = 260
// came back as a shell out to +-DBL_MAX around it.
TEST(ClipPolygon, SelfCrossingRingIsOrientedByItsLargerLobe) {
  const Polygon ring{{{{640, 400}, {750, 240}, {450, 240}, {580, 200}}}};
  const double upper_lobe_above_260 = 12640.0 * 0.875 * 0.875;  // similar, 140 of 160 high
  const std::vector<HalfPlane> y_ge_260 = {{0, 1, -260}};
  for (const MultiPolygon& cut : {clip::clip_polygon(of(ring), y_ge_260),
                                  clip::clip_polygon(of(ring), Box2{{0, 260}, {1000, 1000}})}) {
    EXPECT_EQ(ogc_problem(cut), "");
    EXPECT_DOUBLE_EQ(area(cut), upper_lobe_above_260);
    for (const Polygon& p : cut.polygons) {
      for (const Vec2& v : p.rings.front())
        EXPECT_TRUE(Box2({{592, 260}, {750, 400}}).contains(v)) << v.x << " " << v.y;
    }
  }
}

}  // namespace
}  // namespace contain::test
