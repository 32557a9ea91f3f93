// The few-query PolygonIndex (one cell holding every edge: the crossing test over all of them,
// chosen by the cost model when `queries` is small) answers as the gridded index, on random
// stars and on the degenerate cases: points on vertices and edges, touching and nested rings,
// collinear spikes of zero area, every fill rule; and its batches, run on several threads,
// answer as its single queries.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include "contain/inside/polygon_index.h"
#include "inside/polygon_random.h"

namespace contain::inside {
namespace {

constexpr std::array<Fill, 4> kDirectFills{Fill::even_odd, Fill::nonzero, Fill::positive,
                                           Fill::negative};

void expect_one_cell_as_grid(const std::vector<Ring>& rings, const std::vector<Vec2>& points,
                             Fill fill) {
  const PolygonIndex grid(std::span<const Ring>(rings), {.fill = fill});
  const PolygonIndex direct(std::span<const Ring>(rings), {.fill = fill, .queries = 1});
  ASSERT_EQ(direct.stats().cells, 1u);
  EXPECT_TRUE(direct.bounds() == grid.bounds());
  for (const Vec2& p : points)
    ASSERT_EQ(direct.locate(p), grid.locate(p)) << p.x << " " << p.y;
}

// The rings' vertices, their edges' midpoints, and a lattice over the box and beyond it.
std::vector<Vec2> ring_points_and_lattice(const std::vector<Ring>& rings) {
  std::vector<Vec2> points;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      points.push_back(ring[i]);
      points.push_back(0.5 * (ring[i] + ring[(i + 1) % ring.size()]));
    }
  }
  for (double x = -1; x <= 5; x += 0.25)
    for (double y = -1; y <= 5; y += 0.25)
      points.push_back({x, y});
  return points;
}

TEST(PolygonIndexDirect, AnswersAsTheGridOnTouchingNestedAndZeroAreaRings) {
  const std::vector<std::vector<Ring>> cases{
      {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}},
      {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{2, 0}, {4, 0}, {4, 2}, {2, 2}}},  // sharing an edge
      {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{2, 2}, {4, 2}, {4, 4}, {2, 4}}},  // sharing a vertex
      {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {1, 3}, {3, 3}, {3, 1}}},  // a hole
      {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}},  // nested, same way
      {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{0, 0}, {4, 0}, {4, 4}, {0, 4}}},  // one ring twice
      {{{0, 0}, {4, 0}, {0, 0}, {0, 4}}},                                    // zero-area spikes
      {{{0, 0}, {0, 4}, {0, 2}}},                                            // a vertical line
      {{{0, 0}, {4, 4}, {4, 0}, {0, 4}}},                                    // a bow tie
  };
  for (const auto& rings : cases)
    for (const Fill fill : kDirectFills)
      expect_one_cell_as_grid(rings, ring_points_and_lattice(rings), fill);
}

TEST(PolygonIndexDirect, AnswersAsTheGridOnRandomStarsAndPointsOnTheirEdges) {
  std::mt19937_64 rng(27);
  for (int round = 0; round < 8; ++round) {
    std::vector<Ring> rings{test::random_star(rng, 50 + 20 * round, 0.1, 0.2, 1.0),
                            test::random_star(rng, 30, 0.4, 0.3, 0.5)};
    if (round % 2 == 1) std::reverse(rings[1].begin(), rings[1].end());
    std::vector<Vec2> points = test::points_near_rings(rng, rings, 2);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    for (int i = 0; i < 500; ++i)
      points.push_back({u(rng), u(rng)});
    for (const Fill fill : kDirectFills)
      expect_one_cell_as_grid(rings, points, fill);
  }
}

TEST(PolygonIndexDirect, ConcurrentBatchesAnswerAsSingleQueries) {
  std::mt19937_64 rng(5);
  const std::vector<Ring> rings{test::random_star(rng, 400, 0.1, 0.2, 1.0)};
  const PolygonIndex direct(std::span<const Ring>(rings), {.queries = 1});
  ASSERT_EQ(direct.stats().cells, 1u);
  std::vector<Vec2> points = test::points_near_rings(rng, rings, 4);
  std::vector<Location> serial(points.size()), parallel(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    serial[i] = direct.locate(points[i]);
  direct.locate(points, parallel, {.threads = 4});
  EXPECT_EQ(serial, parallel);
}

TEST(PolygonIndexDirect, ManyQueriesOrAnUnknownCountBuildTheGrid) {
  std::mt19937_64 rng(9);
  const std::vector<Ring> rings{test::random_star(rng, 1000, 0.1, 0.2, 1.0)};
  EXPECT_GT(PolygonIndex(std::span<const Ring>(rings)).stats().cells, 1u);
  EXPECT_GT(PolygonIndex(std::span<const Ring>(rings), {.queries = 1000}).stats().cells, 1u);
  EXPECT_EQ(PolygonIndex(std::span<const Ring>(rings), {.queries = 2}).stats().cells, 1u);
}

}  // namespace
}  // namespace contain::inside
