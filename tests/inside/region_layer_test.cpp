#include "contain/inside/region_layer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "contain/inside/point_in_polygon.h"
#include "inside/polygon_random.h"

namespace contain::inside {
namespace {

constexpr std::array<Fill, 4> kLayerFills{Fill::even_odd, Fill::nonzero, Fill::positive,
                                          Fill::negative};

MultiPolygon square(double x0, double y0, double x1, double y1) {
  return MultiPolygon{{Polygon{{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}}}};
}

// n x n unit squares [i, i+1] x [j, j+1], numbered row by row: they share edges and corners.
std::vector<MultiPolygon> square_grid(int n) {
  std::vector<MultiPolygon> regions;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i)
      regions.push_back(square(i, j, i + 1, j + 1));
  }
  return regions;
}

std::vector<Holder> brute_force(const std::vector<MultiPolygon>& regions, Vec2 p, Fill fill) {
  std::vector<Holder> out;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const Location where = point_in_polygon(regions[r], p, {.fill = fill});
    if (where != Location::outside) out.push_back({static_cast<std::int32_t>(r), where});
  }
  return out;
}

constexpr Holder in(std::int32_t r) {
  return {r, Location::inside};
}
constexpr Holder on(std::int32_t r) {
  return {r, Location::boundary};
}

TEST(RegionLayer, EmptyLayerAndEmptyRegionsHoldNoPoint) {
  const RegionLayer empty;
  EXPECT_TRUE(empty.locate(Vec2{0, 0}).empty());
  EXPECT_EQ(empty.locate(std::vector<Vec2>{{0, 0}, {1, 1}}).holders.size(), 0u);
  const std::vector<MultiPolygon> regions{MultiPolygon{}, square(0, 0, 1, 1), MultiPolygon{}};
  const RegionLayer layer(regions);
  EXPECT_EQ(layer.size(), 3u);
  EXPECT_EQ(layer.locate(Vec2{0.5, 0.5}), std::vector<Holder>{in(1)});
  EXPECT_EQ(layer.locate(Vec2{1, 1}), std::vector<Holder>{on(1)});
  EXPECT_TRUE(layer.locate(Vec2{2, 2}).empty());
}

TEST(RegionLayer, PointOnAnEdgeSharedByTwoSquaresIsOnForBoth) {
  const RegionLayer layer(square_grid(3));
  // Square (i, j) is number 3 j + i; the centre square is 4.
  EXPECT_EQ(layer.locate(Vec2{1.5, 1.5}), std::vector<Holder>{in(4)});
  EXPECT_EQ(layer.locate(Vec2{1, 1.5}), (std::vector<Holder>{on(3), on(4)}));
  EXPECT_EQ(layer.locate(Vec2{1.5, 2}), (std::vector<Holder>{on(4), on(7)}));
  EXPECT_EQ(layer.locate(Vec2{0, 0.25}), std::vector<Holder>{on(0)});
  EXPECT_TRUE(layer.locate(Vec2{-0.5, 0.25}).empty());
  EXPECT_TRUE(layer.locate(Vec2{3, std::nextafter(3.0, 4.0)}).empty());
}

TEST(RegionLayer, SharedCornerIsOnForEverySquareMeetingThere) {
  const RegionLayer layer(square_grid(3));
  EXPECT_EQ(layer.locate(Vec2{1, 1}), (std::vector<Holder>{on(0), on(1), on(3), on(4)}));
  EXPECT_EQ(layer.locate(Vec2{2, 3}), (std::vector<Holder>{on(7), on(8)}));
  EXPECT_EQ(layer.locate(Vec2{3, 3}), std::vector<Holder>{on(8)});
  // One ulp off the corner: inside exactly one square.
  EXPECT_EQ(layer.locate(Vec2{std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0)}),
            std::vector<Holder>{in(1)});
}

TEST(RegionLayer, PointInsideOverlappingRegionsGetsEveryOne) {
  const std::vector<MultiPolygon> regions{square(0, 0, 4, 4), square(2, 2, 6, 6),
                                          square(3, 3, 5, 5), square(10, 10, 11, 11)};
  const RegionLayer layer(regions);
  EXPECT_EQ(layer.locate(Vec2{3.5, 3.5}), (std::vector<Holder>{in(0), in(1), in(2)}));
  EXPECT_EQ(layer.locate(Vec2{4, 3.5}), (std::vector<Holder>{on(0), in(1), in(2)}));
  EXPECT_EQ(layer.locate(Vec2{3, 3}), (std::vector<Holder>{in(0), in(1), on(2)}));
  EXPECT_EQ(layer.locate(Vec2{1, 1}), std::vector<Holder>{in(0)});
}

TEST(RegionLayer, LakeHoleIsHeldByTheIslandInItOnly) {
  // 0: land with a lake (hole), 1: an island in the lake, 2: the lake itself as a region.
  const MultiPolygon land{
      {Polygon{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{2, 2}, {2, 8}, {8, 8}, {8, 2}}}}}};
  const std::vector<MultiPolygon> regions{land, square(4, 4, 6, 6), square(2, 2, 8, 8)};
  const RegionLayer layer(regions);
  EXPECT_EQ(layer.locate(Vec2{1, 1}), std::vector<Holder>{in(0)});
  EXPECT_EQ(layer.locate(Vec2{3, 3}), std::vector<Holder>{in(2)});           // water
  EXPECT_EQ(layer.locate(Vec2{5, 5}), (std::vector<Holder>{in(1), in(2)}));  // island
  EXPECT_EQ(layer.locate(Vec2{2, 5}), (std::vector<Holder>{on(0), on(2)}));  // shore
  EXPECT_EQ(layer.locate(Vec2{4, 5}), (std::vector<Holder>{on(1), in(2)}));  // island shore
  // Under every fill rule the same answers as each region alone.
  for (const Fill fill : kLayerFills) {
    const RegionLayer filled(regions, {.fill = fill});
    for (const Vec2 p : {Vec2{1, 1}, Vec2{3, 3}, Vec2{5, 5}, Vec2{2, 5}, Vec2{4, 5}}) {
      EXPECT_EQ(filled.locate(p), brute_force(regions, p, fill));
    }
  }
}

TEST(RegionLayer, MatchesEachRegionAloneOnRandomDegenerateLayers) {
  std::mt19937_64 rng(14);
  for (int round = 0; round < 20; ++round) {
    std::vector<MultiPolygon> regions;
    std::vector<Vec2> points;
    const int count = 1 + round * 2;
    for (int r = 0; r < count; ++r) {
      // Small integer coordinates: shared vertices, collinear and overlapping edges.
      std::vector<Ring> rings = test::random_integer_rings(rng, 3, 9, 12);
      const auto more = test::points_near_rings(rng, rings, 1);
      points.insert(points.end(), more.begin(), more.end());
      regions.push_back(MultiPolygon{{Polygon{std::move(rings)}}});
    }
    // A sample of them (the brute force is regions x points) and half-integer points.
    std::shuffle(points.begin(), points.end(), rng);
    points.resize(std::min<std::size_t>(points.size(), 800));
    std::uniform_int_distribution<int> c(-1, 13);
    for (int k = 0; k < 200; ++k)
      points.push_back({c(rng) * 0.5, c(rng) * 0.5});
    const Fill fill = kLayerFills[static_cast<std::size_t>(round) % kLayerFills.size()];
    const RegionLayer layer(regions, {.fill = fill});
    for (const Vec2& p : points) {
      ASSERT_EQ(layer.locate(p), brute_force(regions, p, fill))
          << "round " << round << " point (" << p.x << ", " << p.y << ")";
    }
  }
}

TEST(RegionLayer, GridCellsOfLargeRegionsGiveTheSameAnswersAsSingleCells) {
  std::mt19937_64 rng(3);
  std::vector<MultiPolygon> regions;
  for (int r = 0; r < 12; ++r) {
    regions.push_back(MultiPolygon{
        {Polygon{{test::random_star(rng, 50 + 40 * r, 0.3 * r, 0.2 * r, 1.0 + 0.1 * r)}}}});
  }
  const RegionLayer gridded(regions);
  const RegionLayer flat(regions, {.single_cell_edges = 1u << 30});
  EXPECT_GT(gridded.stats().cells, 10 * flat.stats().cells);
  std::uniform_real_distribution<double> x(-1.5, 5.5), y(-1.5, 4.5);
  std::vector<Vec2> points(4000);
  for (Vec2& p : points)
    p = {x(rng), y(rng)};
  for (const MultiPolygon& region : regions) {
    const auto near = test::points_near_rings(rng, region.polygons[0].rings, 1);
    points.insert(points.end(), near.begin(), near.end());
  }
  EXPECT_EQ(gridded.locate(points, {.threads = 1}), flat.locate(points, {.threads = 1}));
  for (std::size_t k = 0; k < points.size(); k += 13)
    ASSERT_EQ(gridded.locate(points[k]), brute_force(regions, points[k], Fill::even_odd));
}

TEST(RegionLayer, BatchTableIsTheSameForEveryThreadCountAndEqualsSingleQueries) {
  const std::vector<MultiPolygon> regions = square_grid(40);
  const RegionLayer layer(regions);
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> q(-4, 4 * 40 + 4);  // quarter steps: many on the edges
  std::vector<Vec2> points(40000);
  for (Vec2& p : points)
    p = {q(rng) * 0.25, q(rng) * 0.25};
  const HolderTable one = layer.locate(points, {.threads = 1});
  EXPECT_EQ(one, layer.locate(points, {.threads = 2}));
  EXPECT_EQ(one, layer.locate(points, {.threads = 7}));
  EXPECT_EQ(one, layer.locate(points));
  ASSERT_EQ(one.points(), points.size());
  std::size_t shared = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const auto row = one.of(k);
    ASSERT_EQ(std::vector<Holder>(row.begin(), row.end()), layer.locate(points[k]));
    shared += row.size() >= 2;
  }
  EXPECT_GT(shared, 4000u);  // the points on shared edges and corners were there
}

TEST(RegionLayer, GridInFrontOfTheTreeGivesTheTreesAnswersWithDenseClustersAndHugeBoxes) {
  // A dense city of 60 x 60 tiny parcels in one corner (cells listing more than 32 regions go
  // down the tree), a few regions spanning the whole layer, and scattered squares.
  std::vector<MultiPolygon> regions;
  for (int j = 0; j < 60; ++j) {
    for (int i = 0; i < 60; ++i)
      regions.push_back(square(i * 1e-3, j * 1e-3, (i + 1) * 1e-3, (j + 1) * 1e-3));
  }
  regions.push_back(square(0, 0, 100, 100));
  regions.push_back(square(-1, 40, 101, 60));
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> at(0, 98);
  for (int k = 0; k < 200; ++k) {
    const double x = at(rng), y = at(rng);
    regions.push_back(square(x, y, x + 1, y + 1));
  }
  const RegionLayer gridded(regions);
  const RegionLayer tree_only(regions, {.cells_per_region = 0.0});
  EXPECT_GT(gridded.stats().grid_cells, 100u);
  EXPECT_EQ(tree_only.stats().grid_cells, 0u);
  std::vector<Vec2> points;
  std::uniform_real_distribution<double> u(-2, 102), city(0, 0.06);
  std::uniform_int_distribution<int> grid(0, 60);
  for (int k = 0; k < 20000; ++k) {
    points.push_back({u(rng), u(rng)});
    points.push_back({city(rng), city(rng)});
    points.push_back({grid(rng) * 1e-3, grid(rng) * 1e-3});  // corners of the city's parcels
    points.push_back({static_cast<double>(at(rng)), static_cast<double>(at(rng))});
  }
  EXPECT_EQ(gridded.locate(points, {.threads = 1}), tree_only.locate(points, {.threads = 1}));
  for (std::size_t k = 0; k < points.size(); k += 101)
    ASSERT_EQ(gridded.locate(points[k]), brute_force(regions, points[k], Fill::even_odd));
}

TEST(RegionLayer, OneShotFunctionEqualsThePreparedLayer) {
  const std::vector<MultiPolygon> regions = square_grid(4);
  const RegionLayer layer(regions, {.fill = Fill::nonzero});
  for (const Vec2 p : {Vec2{1, 1}, Vec2{0.5, 0.5}, Vec2{4, 4}, Vec2{5, 5}}) {
    EXPECT_EQ(point_in_regions(regions, p, {.fill = Fill::nonzero}), layer.locate(p));
  }
}

TEST(RegionLayer, MemoryStaysWithinTheStatedBoundPerEdgeAndRegion) {
  // The header's bound: 4 KB an edge plus 1 KB a region, spiky and long thin regions included.
  std::mt19937_64 rng(9);
  std::vector<std::vector<MultiPolygon>> layers;
  layers.push_back(square_grid(30));
  std::vector<MultiPolygon> stars, slivers, spikes;
  for (int r = 0; r < 20; ++r) {
    stars.push_back(
        MultiPolygon{{Polygon{{test::random_star(rng, 10 + 300 * r, 3.0 * r, 0, 1.0)}}}});
    slivers.push_back(MultiPolygon{{Polygon{{{{0, r * 1e-3},
                                              {1e4, r * 1e-3},
                                              {1e4, r * 1e-3 + 1e-9},
                                              {5e3, r * 1e-3 + 2e-9},
                                              {0, r * 1e-3 + 1e-9}}}}}});
  }
  // A hedgehog: long spikes from the centre crossing every row and column of its grid.
  Ring hedgehog;
  for (int i = 0; i < 4000; ++i) {
    const double angle = 2 * 3.141592653589793 * i / 4000;
    const double r = i % 2 == 0 ? 1.0 : 0.01;
    hedgehog.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  spikes.push_back(MultiPolygon{{Polygon{{hedgehog}}}});
  layers.push_back(stars);
  layers.push_back(slivers);
  layers.push_back(spikes);
  for (const auto& regions : layers) {
    const RegionLayer layer(regions);
    const RegionLayer::Stats s = layer.stats();
    EXPECT_LE(s.bytes, 4096 * s.edges + 1024 * s.regions)
        << s.regions << " regions, " << s.edges << " edges, " << s.cells << " cells, "
        << s.edge_refs << " refs";
    EXPECT_LE(s.cells, 16 * s.edges + s.regions);
  }
}

}  // namespace
}  // namespace contain::inside
