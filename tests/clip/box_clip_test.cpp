// Regions clipped by a box in one pass (clip_polygon by a Box2): valid pieces (exact OGC check)
// whose area is the boolean engine's, on random and on degenerate classes: hole edges on every
// box side, vertices and edges on the sides (lattice coordinates), holes touching their shell.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "clip/boolean_checks.h"
#include "contain/clip/box_clipper.h"
#include "contain/clip/clip_polygon.h"
#include "contain/clip/polygon_boolean.h"
#include "scenes/scenes.h"

namespace contain::test {
namespace {

MultiPolygon as_multi(Polygon p) {
  return MultiPolygon{{std::move(p)}};
}

MultiPolygon by_engine(const MultiPolygon& region, const Box2& box) {
  const std::vector<Ring> rings = region.all_rings();
  const Ring frame{box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
  return clip::polygon_boolean(rings, std::span<const Ring>(&frame, 1),
                               {.op = clip::Op::intersection, .fill = Fill::even_odd});
}

// Valid, and the same exact area as the engine's result up to the rounding of crossing points
// (both round them; `exact` when no crossing needs rounding).
::testing::AssertionResult same_region(const MultiPolygon& region, const Box2& box, bool exact) {
  const MultiPolygon cut = clip::clip_polygon(region, box);
  if (auto valid = is_valid_ogc(cut); !valid) return valid;
  const mpq_class a = exact_signed_area(cut), b = exact_signed_area(by_engine(region, box));
  const double diff = std::fabs(mpq_class(a - b).get_d());
  const double scale = std::max(1.0, std::fabs(b.get_d()));
  if (exact ? a != b : diff > 1e-13 * scale) {
    return ::testing::AssertionFailure()
           << "area " << a.get_d() << " vs the engine's " << b.get_d();
  }
  return ::testing::AssertionSuccess();
}

TEST(BoxClip, RandomStarsByRandomBoxesAreValidWithTheEnginesArea) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.2, 1.2), s(0.01, 1.5);
  for (int t = 0; t < 600; ++t) {
    const Ring star = scenes::star_ring(5 + t % 120, {0, 0}, 0.2, 1.0, static_cast<unsigned>(t));
    const double x = u(rng), y = u(rng), w = s(rng), h = s(rng);
    ASSERT_TRUE(same_region(as_multi(Polygon{{star}}), Box2{{x, y}, {x + w, y + h}}, false)) << t;
  }
}

TEST(BoxClip, PolygonWithHolesByRandomBoxes) {
  const Polygon demo = scenes::demo_polygon();
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-3, 3), s(0.02, 3);
  for (int t = 0; t < 600; ++t) {
    const double x = u(rng), y = u(rng), w = s(rng), h = s(rng);
    ASSERT_TRUE(same_region(as_multi(demo), Box2{{x, y}, {x + w, y + h}}, false)) << t;
  }
}

// The class of issue 13's instance: a hole whose edge lies on a side of the box. Inside the box
// it becomes a notch of the shell; outside, the shell runs along it.
TEST(BoxClip, HoleEdgeOnEveryBoxSideBecomesANotchOfTheShell) {
  const Polygon frame{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 3}, {2, 6}, {4, 6}, {4, 3}}}};
  const Box2 inside_boxes[] = {{{-1, -1}, {4, 11}},   // right side on the hole's right edge
                               {{2, -1}, {11, 11}},   // left side on its left edge
                               {{-1, 3}, {11, 11}},   // bottom on its bottom edge
                               {{-1, -1}, {11, 6}}};  // top on its top edge
  for (const Box2& box : inside_boxes) {
    const MultiPolygon r = clip::clip_polygon(as_multi(frame), box);
    ASSERT_TRUE(is_valid_ogc(r)) << box.min.x << " " << box.min.y;
    ASSERT_EQ(r.polygons.size(), 1u);
    EXPECT_EQ(r.polygons[0].rings.size(), 1u) << "the hole is a notch, not a hole";
    EXPECT_TRUE(same_region(as_multi(frame), box, true));
  }
  const Box2 outside_boxes[] = {{{4, 0}, {10, 10}}, {{0, 0}, {2, 10}}, {{0, 6}, {10, 10}},
                                {{0, 0}, {10, 3}},  {{4, 3}, {8, 6}},  {{2, 6}, {4, 8}}};
  for (const Box2& box : outside_boxes) {
    const MultiPolygon r = clip::clip_polygon(as_multi(frame), box);
    ASSERT_TRUE(is_valid_ogc(r)) << box.min.x << " " << box.min.y;
    EXPECT_TRUE(same_region(as_multi(frame), box, true));
  }
  // The hole's box itself: nothing is left.
  EXPECT_TRUE(clip::clip_polygon(as_multi(frame), Box2{{2, 3}, {4, 6}}).polygons.empty());
}

// Every box on a lattice against polygons whose vertices lie on it: vertices on the sides, edges
// along them, crossings at corners, shells and holes touching the boundary at a vertex.
TEST(BoxClip, LatticeBoxesAgainstLatticePolygonsWithHoles) {
  const Polygon frame{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                       {{2, 3}, {2, 6}, {4, 6}, {4, 3}},
                       {{6, 2}, {5, 4}, {7, 5}, {8, 3}}}};
  for (int x0 = -1; x0 <= 10; ++x0) {
    for (int y0 = -1; y0 <= 10; ++y0) {
      for (int w = 1; w <= 11 - x0; w += 2) {
        for (int h = 1; h <= 11 - y0; h += 3) {
          const Box2 box{{double(x0), double(y0)}, {double(x0 + w), double(y0 + h)}};
          ASSERT_TRUE(same_region(as_multi(frame), box, false))
              << x0 << " " << y0 << " " << w << " " << h;
        }
      }
    }
  }
}

TEST(BoxClip, GridUnionsOfSquaresByBoxesOnTheGridAndBetween) {
  for (int t = 0; t < 40; ++t) {
    std::mt19937_64 g(static_cast<unsigned>(t));
    std::uniform_int_distribution<int> c(0, 9);
    std::vector<Ring> squares;
    for (int k = 0; k < 30; ++k) {
      const double x = c(g), y = c(g);
      squares.push_back({{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}});
    }
    const MultiPolygon region = clip::polygon_boolean(
        squares, std::vector<Ring>{}, {.op = clip::Op::union_, .fill = Fill::nonzero});
    for (int k = 0; k < 20; ++k) {
      const double x0 = c(g) - 0.5 * (k % 2), y0 = c(g), x1 = x0 + 1 + c(g) / 2,
                   y1 = y0 + 1 + c(g) / 3;
      ASSERT_TRUE(same_region(region, Box2{{x0, y0}, {x1, y1}}, true)) << t << " " << k;
    }
  }
}

// OGC lets a hole touch its shell at a point; a box can cut the region so that the point
// pinches it into two polygons.
TEST(BoxClip, HolesTouchingTheirShellAtAVertexOrInsideAnEdge) {
  const Polygon touch{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                       {{5, 0}, {4, 2}, {6, 2}},
                       {{0, 5}, {2, 6}, {2, 4}},
                       {{7, 7}, {10, 10}, {9, 7}}}};
  // OGC-valid (GEOS agrees); the strict checker here also wants the shell split at (5, 0).
  for (int x0 = -1; x0 <= 10; ++x0) {
    for (int y0 = -1; y0 <= 10; ++y0) {
      for (int w = 1; w <= 6; ++w) {
        const Box2 on{{double(x0), double(y0)}, {double(x0 + w), double(y0 + 2)}};
        ASSERT_TRUE(same_region(as_multi(touch), on, false)) << x0 << " " << y0 << " " << w;
        const Box2 off{{x0 + 0.5, y0 + 0.25}, {x0 + w + 0.5, y0 + 3.25}};
        ASSERT_TRUE(same_region(as_multi(touch), off, false)) << x0 << " " << y0 << " " << w;
      }
    }
  }
  // The instance: the box cuts the hole below y = 1 and the shell's bottom edge runs through
  // the box, so the hole's tip at (5, 0) splits the part into two polygons touching there.
  const MultiPolygon r = clip::clip_polygon(as_multi(touch), Box2{{3, -1}, {7, 1}});
  ASSERT_TRUE(is_valid_ogc(r));
  EXPECT_EQ(r.polygons.size(), 2u);
}

TEST(BoxClip, BoxesThatChangeNothingOrLeaveNothing) {
  const Polygon demo = scenes::demo_polygon();
  const MultiPolygon all = clip::clip_polygon(as_multi(demo), Box2{{-100, -100}, {100, 100}});
  ASSERT_TRUE(is_valid_ogc(all));
  EXPECT_EQ(exact_signed_area(all),
            exact_signed_area(by_engine(as_multi(demo), {{-100, -100}, {100, 100}})));
  const double inf = std::numeric_limits<double>::infinity();
  const MultiPolygon unbounded = clip::clip_polygon(as_multi(demo), Box2{{-inf, -inf}, {inf, inf}});
  EXPECT_EQ(exact_signed_area(unbounded), exact_signed_area(all));
  const MultiPolygon half = clip::clip_polygon(as_multi(demo), Box2{{0, -inf}, {inf, inf}});
  ASSERT_TRUE(is_valid_ogc(half));
  EXPECT_GT(exact_signed_area(half), 0);
  EXPECT_TRUE(clip::clip_polygon(as_multi(demo), Box2{{50, 50}, {60, 60}}).polygons.empty());
  EXPECT_TRUE(
      clip::clip_polygon(as_multi(demo), Box2{{0, 0}, {0, 1}}).polygons.empty());  // no area
  EXPECT_TRUE(clip::clip_polygon(as_multi(demo), Box2{}).polygons.empty());
}

TEST(BoxClip, ClockwiseShellsAndCounterClockwiseHolesAreReadAsOgc) {
  Polygon p{{{{0, 0}, {0, 4}, {4, 4}, {4, 0}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}}};
  const MultiPolygon r = clip::clip_polygon(as_multi(p), Box2{{2, -1}, {5, 5}});
  ASSERT_TRUE(is_valid_ogc(r));
  EXPECT_EQ(exact_signed_area(r), 8 - 2);
}

TEST(BoxClip, TouchingPolygonsOfAMultiPolygon) {
  const MultiPolygon checker{{Polygon{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}},
                              Polygon{{{{1, 1}, {2, 1}, {2, 2}, {1, 2}}}},
                              Polygon{{{{2, 0}, {3, 0}, {3, 1}, {2, 1}}}}}};
  for (const Box2& box : {Box2{{0.5, 0.5}, {2.5, 1.5}}, Box2{{1, 0}, {2, 2}}, Box2{{0, 1}, {3, 2}},
                          Box2{{0.25, -1}, {1, 1}}}) {
    ASSERT_TRUE(same_region(checker, box, true)) << box.min.x << " " << box.min.y;
  }
}

}  // namespace
}  // namespace contain::test

namespace contain::test {
namespace {

TEST(BoxClipper, PreparedRegionGivesClipPolygonsResultBitForBit) {
  const Polygon demo = scenes::demo_polygon();
  const MultiPolygon region{{demo, Polygon{{scenes::star_ring(300, {5, 5}, 0.5, 2.0, 3)}}}};
  const clip::BoxClipper prepared(region);
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-3, 8), s(0.01, 4);
  for (int t = 0; t < 800; ++t) {
    const double x = u(rng), y = u(rng), w = s(rng), h = s(rng);
    const Box2 box{{x, y}, {x + w, y + h}};
    ASSERT_EQ(prepared.clip(box), clip::clip_polygon(region, box)) << t;
  }
  // Lattice boxes: vertices on the sides, fallbacks to the engine.
  const Polygon frame{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{5, 0}, {4, 2}, {6, 2}}}};
  const clip::BoxClipper lattice(MultiPolygon{{frame}});
  for (int x0 = -1; x0 <= 10; ++x0) {
    for (int y0 = -1; y0 <= 10; ++y0) {
      const Box2 box{{double(x0), double(y0)}, {x0 + 3.0, y0 + 2.0}};
      ASSERT_EQ(lattice.clip(box), clip::clip_polygon(MultiPolygon{{frame}}, box));
    }
  }
}

TEST(BoxClipper, BoxesInsideOrOutsideWithoutAnyEdgeUseTheRayParity) {
  // A ring with a hole: boxes wholly in the hole, in the material, outside.
  const Polygon ring{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{3, 3}, {3, 7}, {7, 7}, {7, 3}}}};
  const clip::BoxClipper prepared(MultiPolygon{{ring}});
  EXPECT_TRUE(prepared.clip(Box2{{4, 4}, {6, 6}}).polygons.empty());
  EXPECT_TRUE(prepared.clip(Box2{{11, 4}, {12, 6}}).polygons.empty());
  const MultiPolygon solid = prepared.clip(Box2{{1, 1}, {2, 9}});
  ASSERT_EQ(solid.polygons.size(), 1u);
  EXPECT_EQ(exact_signed_area(solid), 8);
}

TEST(Tile, GridTilesCoverTheRegionAndEqualClipPolygonPerTile) {
  const MultiPolygon region{{scenes::demo_polygon()}};
  const Box2 bounds = bounding_box(region.all_rings());
  const clip::TileGrid grid{.bounds = bounds, .columns = 7, .rows = 5};
  const std::vector<MultiPolygon> tiles = clip::tile(region, grid, {.threads = 3});
  ASSERT_EQ(tiles.size(), 35u);
  mpq_class sum = 0;
  for (int row = 0; row < 5; ++row) {
    for (int column = 0; column < 7; ++column) {
      const MultiPolygon& t = tiles[static_cast<std::size_t>(row * 7 + column)];
      ASSERT_TRUE(is_valid_ogc(t));
      EXPECT_EQ(t, clip::clip_polygon(region, grid.tile(column, row)));
      sum += exact_signed_area(t);
    }
  }
  // The tiles partition the region up to the rounding of crossing points.
  EXPECT_NEAR(sum.get_d(), exact_signed_area(region).get_d(), 1e-12);
  EXPECT_EQ(clip::tile(region, grid, {.threads = 1}), tiles);
  // Neighbours share their sides exactly; the last side is the bounds' side.
  EXPECT_EQ(grid.tile(2, 1).max.x, grid.tile(3, 1).min.x);
  EXPECT_EQ(grid.tile(6, 4).max, bounds.max);
  EXPECT_TRUE(clip::tile(region, {.bounds = bounds, .columns = 0, .rows = 3}).empty());
}

}  // namespace
}  // namespace contain::test
