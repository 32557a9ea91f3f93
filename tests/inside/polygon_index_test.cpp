#include "contain/inside/polygon_index.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "contain/inside/point_in_polygon.h"
#include "inside/polygon_oracle.h"
#include "inside/polygon_random.h"

namespace contain::inside {
namespace {

constexpr std::array<Fill, 4> kIndexFills{Fill::even_odd, Fill::nonzero, Fill::positive,
                                          Fill::negative};

// Points that stress the grid: its lines, its corners, cell centres, and the box's sides.
std::vector<Vec2> points_on_grid(std::mt19937_64& rng, const PolygonIndex& index, int count) {
  std::vector<Vec2> points;
  const auto xs = index.grid_x();
  const auto ys = index.grid_y();
  if (xs.empty()) return points;
  std::uniform_int_distribution<std::size_t> ix(0, xs.size() - 1), iy(0, ys.size() - 1);
  std::uniform_real_distribution<double> ux(xs.front(), xs.back()), uy(ys.front(), ys.back());
  for (int k = 0; k < count; ++k) {
    points.push_back({xs[ix(rng)], ys[iy(rng)]});
    points.push_back({xs[ix(rng)], uy(rng)});
    points.push_back({ux(rng), ys[iy(rng)]});
    points.push_back({ux(rng), uy(rng)});
  }
  return points;
}

void expect_index_matches_one_shot(const std::vector<Ring>& rings, const std::vector<Vec2>& points,
                                   const PolygonIndexOptions& options) {
  const PolygonIndex index(std::span<const Ring>(rings), options);
  for (const Vec2& p : points) {
    ASSERT_EQ(index.locate(p),
              point_in_polygon(std::span<const Ring>(rings), p, {.fill = options.fill}))
        << "point (" << p.x << ", " << p.y << ") fill " << static_cast<int>(options.fill)
        << " cells " << index.stats().cells;
  }
}

TEST(PolygonIndex, EmptyRegionIsOutsideEverywhere) {
  const PolygonIndex empty;
  EXPECT_EQ(empty.locate({0, 0}), Location::outside);
  const std::vector<Ring> degenerate{{{1, 1}, {1, 1}, {1, 1}}};
  const PolygonIndex point(std::span<const Ring>(degenerate), {});
  EXPECT_EQ(point.locate({1, 1}), Location::outside);
  EXPECT_EQ(point.stats().edges, 0u);
}

TEST(PolygonIndex, AnswersLikeTheOneShotTestOnHandCases) {
  const std::vector<std::vector<Ring>> cases{
      {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}},
      {{{0, 0}, {6, 0}, {6, 4}, {4, 4}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}},
      {{{0, 0}, {2, 0}, {2, 1}, {3, 1}, {2, 1}, {2, 2}, {0, 2}}},
      {{{0, 0}, {2, 2}, {2, 0}, {0, 2}}},
      {{{0, 10}, {6, -8}, {-10, 3}, {10, 3}, {-6, -8}}},
      {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{1, 0}, {2, 0}, {2, 1}, {1, 1}}},
      {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}},
      {{{0, 0}, {4, 0}, {0, 0}, {0, 4}}},  // zero area, a horizontal and a vertical spike
      {{{0, 0}, {0, 4}, {0, 2}}},          // zero width: a vertical line
      {{{0, 0}, {4, 0}, {2, 0}}},          // zero height
  };
  for (const auto& rings : cases) {
    std::vector<Vec2> points;
    for (double x = -11; x <= 11; x += 0.25) {
      for (double y = -9; y <= 11; y += 0.25)
        points.push_back({x, y});
    }
    for (Fill fill : kIndexFills) {
      for (std::size_t cells : {1u, 16u, 4096u}) {
        expect_index_matches_one_shot(rings, points,
                                      {.fill = fill, .min_cells = cells, .max_cells = cells});
      }
    }
  }
}

TEST(PolygonIndex, MatchesExactOracleOnRandomIntegerRings) {
  std::mt19937_64 rng(99);
  for (int round = 0; round < 60; ++round) {
    const std::vector<Ring> rings = test::random_integer_rings(rng, 3, 7, 4);
    for (Fill fill : kIndexFills) {
      // A grid whose lines fall on and between the integer coordinates.
      const std::size_t cells = round % 3 == 0 ? 16 : (round % 3 == 1 ? 64 : 7);
      const PolygonIndex index(std::span<const Ring>(rings),
                               {.fill = fill, .min_cells = cells, .max_cells = cells});
      for (double x = -0.5; x <= 4.5; x += 0.5) {
        for (double y = -0.5; y <= 4.5; y += 0.5) {
          ASSERT_EQ(index.locate({x, y}), test::oracle_point_in_polygon(rings, {x, y}, fill))
              << "round " << round << " point (" << x << ", " << y << ")";
        }
      }
    }
  }
}

TEST(PolygonIndex, MatchesOneShotOnRandomPointsSnappedToEdgesVerticesAndGridLines) {
  std::mt19937_64 rng(2024);
  for (int round = 0; round < 12; ++round) {
    std::vector<Ring> rings{test::random_star(rng, 40 + 10 * round, 0.1, 0.2, 1.0),
                            test::random_star(rng, 25, 0.4, 0.3, 0.5)};
    if (round % 2 == 1) std::reverse(rings[1].begin(), rings[1].end());
    for (Fill fill : kIndexFills) {
      for (std::size_t cells : {64u, 4096u, 65536u}) {
        const PolygonIndexOptions options{.fill = fill, .min_cells = cells, .max_cells = cells};
        const PolygonIndex index(std::span<const Ring>(rings), options);
        std::vector<Vec2> points = test::points_near_rings(rng, rings, 2);
        const std::vector<Vec2> grid = points_on_grid(rng, index, 300);
        points.insert(points.end(), grid.begin(), grid.end());
        expect_index_matches_one_shot(rings, points, options);
      }
    }
  }
}

TEST(PolygonIndex, MatchesExactOracleNearEdgesOfRandomStars) {
  std::mt19937_64 rng(31337);
  for (int round = 0; round < 6; ++round) {
    const std::vector<Ring> rings{test::random_star(rng, 30, 0, 0, 1.0)};
    const PolygonIndex index(std::span<const Ring>(rings), {.min_cells = 256, .max_cells = 256});
    std::vector<Vec2> points = test::points_near_rings(rng, rings, 1);
    const std::vector<Vec2> grid = points_on_grid(rng, index, 30);
    points.insert(points.end(), grid.begin(), grid.end());
    for (const Vec2& p : points) {
      ASSERT_EQ(index.locate(p), test::oracle_point_in_polygon(rings, p, Fill::even_odd));
    }
  }
}

TEST(PolygonIndex, LongEdgesAcrossManyCellsAreExact) {
  // A thin sliver and a long diagonal: edges cross hundreds of cells, close to their corners.
  const std::vector<Ring> rings{{{0, 0}, {1000, 1}, {1000, 1.0000001}, {3, 997}, {0, 1000}},
                                {{1, 1}, {999, 998}, {999, 999}}};
  std::mt19937_64 rng(8);
  for (Fill fill : kIndexFills) {
    const PolygonIndexOptions options{.fill = fill, .min_cells = 40000};
    const PolygonIndex index(std::span<const Ring>(rings), options);
    std::vector<Vec2> points = test::points_near_rings(rng, rings, 200);
    const std::vector<Vec2> grid = points_on_grid(rng, index, 2000);
    points.insert(points.end(), grid.begin(), grid.end());
    expect_index_matches_one_shot(rings, points, options);
  }
}

TEST(PolygonIndex, HugeAndTinyCoordinatesAreExact) {
  std::mt19937_64 rng(4);
  for (double scale : {1e300, 1e-300, 1e-315, 1.0}) {
    std::vector<Ring> rings{test::random_star(rng, 50, 0, 0, 1.0)};
    for (Vec2& p : rings[0])
      p = {p.x * scale, p.y * scale};
    const PolygonIndexOptions options{.min_cells = 1024};
    const PolygonIndex index(std::span<const Ring>(rings), options);
    std::vector<Vec2> points = test::points_near_rings(rng, rings, 3);
    const std::vector<Vec2> grid = points_on_grid(rng, index, 300);
    points.insert(points.end(), grid.begin(), grid.end());
    expect_index_matches_one_shot(rings, points, options);
  }
}

TEST(PolygonIndex, PointsOutsideTheBoxAreOutside) {
  const Polygon square{{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}}};
  const PolygonIndex index(square);
  EXPECT_EQ(index.locate({-1e-300, 1}), Location::outside);
  EXPECT_EQ(index.locate({1, std::nextafter(2.0, 3.0)}), Location::outside);
  EXPECT_EQ(index.locate({1e308, -1e308}), Location::outside);
  EXPECT_EQ(index.locate({2, 2}), Location::boundary);
  EXPECT_EQ(index.locate({1, 1}), Location::inside);
}

TEST(PolygonIndex, BatchAnswersDoNotDependOnTheThreadCount) {
  std::mt19937_64 rng(6);
  // Large enough (spiky, ~10^5 edge-cell pairs) for the batch call's prefetching path.
  const MultiPolygon region{{Polygon{{test::random_star(rng, 3000, 0, 0, 1.0)}},
                             Polygon{{test::random_star(rng, 100, 0.5, 0.5, 0.8)}}}};
  const PolygonIndex index(region, {.fill = Fill::nonzero});
  ASSERT_GT(index.stats().edge_refs, 50000u);
  std::uniform_real_distribution<double> c(-1.1, 1.1);
  std::vector<Vec2> points(50000);
  for (Vec2& p : points)
    p = {c(rng), c(rng)};
  std::vector<Location> one(points.size()), four(points.size()), all(points.size());
  index.locate(points, one, {.threads = 1});
  index.locate(points, four, {.threads = 4});
  index.locate(points, all);
  EXPECT_EQ(one, four);
  EXPECT_EQ(one, all);
  for (std::size_t k = 0; k < points.size(); ++k)
    ASSERT_EQ(one[k], index.locate(points[k]));
  for (std::size_t k = 0; k < points.size(); k += 97) {
    ASSERT_EQ(one[k], point_in_polygon(region, points[k], {.fill = Fill::nonzero}));
  }
}

TEST(PolygonIndex, GridStaysSmallForSmallPolygonsAndBoundedForLargeOnes) {
  std::mt19937_64 rng(1);
  const PolygonIndex small(Polygon{{test::random_star(rng, 100, 0, 0, 1.0)}});
  EXPECT_GE(small.stats().cells, 4096u / 2);
  EXPECT_LE(small.stats().cells, 2u * 4096u);
  const PolygonIndex large(Polygon{{test::random_star(rng, 20000, 0, 0, 1.0)}},
                           {.max_cells = 1 << 16});
  EXPECT_LE(large.stats().cells, 2u * (1u << 16));
  EXPECT_EQ(large.stats().edges, 20000u);
}

// Regression (found by fuzz/fuzz_point_in_polygon): with coordinates near DBL_MAX, b.x - a.x
// overflowed, each edge's x-range fell back to its whole extent in every row of cells, and the
// edge-cell pairs grew as cells x edges instead of (columns + rows) x edges.
TEST(PolygonIndex, EdgesNearDblMaxTouchOnlyTheCellsAlongThem) {
  // The same star at 1.7e308 and scaled down by 2^-8 (exactly): the same grid, the same cells.
  auto star = [](double scale) {
    Ring ring;
    const int n = 64;
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * 3.141592653589793 * i / n;
      const double r = (i % 2 == 0 ? 1.0 : 0.4) * 1.7e308;
      ring.push_back({r * std::cos(angle) * scale, r * std::sin(angle) * scale});
    }
    return std::vector<Ring>{ring};
  };
  const std::vector<Ring> huge = star(1.0), smaller = star(1.0 / 256);
  const PolygonIndex index(huge, {.max_cells = 1 << 12});
  const PolygonIndex reference(smaller, {.max_cells = 1 << 12});
  ASSERT_EQ(index.grid_x().size(), reference.grid_x().size());
  EXPECT_EQ(index.stats().edge_refs, reference.stats().edge_refs);
  for (const Vec2 p : {Vec2{0, 0}, Vec2{1.6e308, 0}, Vec2{1.7e308, 0}, Vec2{-1e308, 1e308}}) {
    EXPECT_EQ(index.locate(p), point_in_polygon(huge, p)) << p.x << " " << p.y;
  }
}

}  // namespace
}  // namespace contain::inside
