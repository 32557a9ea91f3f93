#include "contain/bvh/nearest_pairs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace contain::bvh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Points on an integer lattice (as point boxes), so that every squared distance and box gap
// below is exact in doubles and the bounds are tight without rounding arguments.
std::vector<Vec3> lattice_points(std::size_t n, unsigned seed, int offset) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> u(0, 200);
  std::vector<Vec3> points(n);
  for (Vec3& p : points)
    p = {double(u(rng) + offset), double(u(rng)), double(u(rng))};
  return points;
}

std::vector<Box3> point_boxes(const std::vector<Vec3>& points) {
  std::vector<Box3> boxes(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    boxes[i] = {points[i], points[i]};
  return boxes;
}

double squared_gap(const Box3& a, const Box3& b) {
  const double dx = std::max({a.min.x - b.max.x, b.min.x - a.max.x, 0.0});
  const double dy = std::max({a.min.y - b.max.y, b.min.y - a.max.y, 0.0});
  const double dz = std::max({a.min.z - b.max.z, b.min.z - a.max.z, 0.0});
  return dx * dx + dy * dy + dz * dz;
}

// The closest pair of points of two sets, with a log of the bounds of the pairs opened.
struct ClosestPoints {
  const Bvh& ta;
  const Bvh& tb;
  const std::vector<Vec3>& pa;
  const std::vector<Vec3>& pb;
  double best = kInf;
  std::pair<std::int32_t, std::int32_t> found{-1, -1};
  std::vector<std::pair<double, double>> opened;  // (bound, best when opened)
  std::size_t leaf_pairs = 0;

  double lower(std::int32_t x, std::int32_t y) const {
    return squared_gap(ta.nodes()[static_cast<std::size_t>(x)].box,
                       tb.nodes()[static_cast<std::size_t>(y)].box);
  }
  bool worth(const NodePair& e) const { return !(e.lower > best); }
  bool split_a(std::int32_t x, std::int32_t y) const {
    return surface_area(ta.nodes()[static_cast<std::size_t>(x)].box) >=
           surface_area(tb.nodes()[static_cast<std::size_t>(y)].box);
  }
  Visit leaves(std::int32_t x, std::int32_t y) {
    opened.emplace_back(lower(x, y), best);
    ++leaf_pairs;
    const Node& p = ta.nodes()[static_cast<std::size_t>(x)];
    const Node& q = tb.nodes()[static_cast<std::size_t>(y)];
    for (std::int32_t s = p.first; s < p.first + p.count; ++s) {
      for (std::int32_t t = q.first; t < q.first + q.count; ++t) {
        const std::int32_t i = ta.items()[static_cast<std::size_t>(s)];
        const std::int32_t j = tb.items()[static_cast<std::size_t>(t)];
        const Vec3 d = pa[static_cast<std::size_t>(i)] - pb[static_cast<std::size_t>(j)];
        const double dd = dot(d, d);
        if (dd < best || (dd == best && std::make_pair(i, j) < found)) {
          best = dd;
          found = {i, j};
        }
      }
    }
    return Visit::proceed;
  }
};

std::pair<double, std::pair<std::int32_t, std::int32_t>> brute_force(const std::vector<Vec3>& a,
                                                                     const std::vector<Vec3>& b) {
  double best = kInf;
  std::pair<std::int32_t, std::int32_t> found{-1, -1};
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec3 d = a[i] - b[j];
      if (dot(d, d) < best) {
        best = dot(d, d);
        found = {static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)};
      }
    }
  }
  return {best, found};
}

TEST(NearestPairs, BothOrdersFindTheClosestPairAndItsLowestIndicesAsBruteForce) {
  for (unsigned seed = 0; seed < 20; ++seed) {
    const std::vector<Vec3> a = lattice_points(300, seed, 0);
    const std::vector<Vec3> b = lattice_points(250, seed + 100, 150 + int(seed) * 10);
    const Bvh ta(point_boxes(a)), tb(point_boxes(b));
    const auto expected = brute_force(a, b);
    for (const PairOrder order : {PairOrder::depth_first, PairOrder::best_first}) {
      ClosestPoints v{ta, tb, a, b};
      (void)nearest_pairs(ta, tb, v, order);
      EXPECT_EQ(v.best, expected.first) << "seed " << seed;
      EXPECT_EQ(v.found, expected.second) << "seed " << seed;
    }
  }
}

TEST(NearestPairs, PrunesEveryPairWhoseBoundExceedsTheBestAndOpensFarFewerThanAllPairs) {
  const std::vector<Vec3> a = lattice_points(2000, 7, 0), b = lattice_points(2000, 8, 230);
  const Bvh ta(point_boxes(a)), tb(point_boxes(b));
  for (const PairOrder order : {PairOrder::depth_first, PairOrder::best_first}) {
    ClosestPoints v{ta, tb, a, b};
    const TraversalStats stats = nearest_pairs(ta, tb, v, order);
    for (const auto& [bound, best] : v.opened)
      EXPECT_LE(bound, best);
    EXPECT_EQ(stats.items, v.leaf_pairs);
    EXPECT_LT(v.leaf_pairs * 100, ta.nodes().size() * tb.nodes().size() / 4);
  }
}

TEST(NearestPairs, BestFirstOpensLeafPairsInTheOrderOfTheirBoundsAndNoneBeyondTheAnswer) {
  const std::vector<Vec3> a = lattice_points(1500, 9, 0), b = lattice_points(1500, 10, 210);
  const Bvh ta(point_boxes(a)), tb(point_boxes(b));
  ClosestPoints v{ta, tb, a, b};
  (void)nearest_pairs(ta, tb, v, PairOrder::best_first);
  ASSERT_FALSE(v.opened.empty());
  for (std::size_t k = 1; k < v.opened.size(); ++k)
    EXPECT_LE(v.opened[k - 1].first, v.opened[k].first);
  for (const auto& opened : v.opened)
    EXPECT_LE(opened.first, v.best);
}

// Every bound 0: the visitor's tie order alone decides, here the highest node pairs first.
struct TieOrder {
  std::vector<std::pair<std::int32_t, std::int32_t>> leaves_seen;
  int stop_after = -1;
  double lower(std::int32_t, std::int32_t) const { return 0; }
  bool worth(const NodePair&) const { return true; }
  bool split_a(std::int32_t, std::int32_t) const { return true; }
  bool before(const NodePair& x, const NodePair& y) const { return lower_nodes_first(y, x); }
  Visit leaves(std::int32_t x, std::int32_t y) {
    leaves_seen.emplace_back(x, y);
    return static_cast<int>(leaves_seen.size()) == stop_after ? Visit::stop : Visit::proceed;
  }
};

TEST(NearestPairs, EqualBoundsOpenInTheVisitorsTieOrderUnderBothOrders) {
  const std::vector<Vec3> a = lattice_points(64, 11, 0), b = lattice_points(64, 12, 0);
  const Bvh ta(point_boxes(a)), tb(point_boxes(b));
  for (const PairOrder order : {PairOrder::depth_first, PairOrder::best_first}) {
    TieOrder v;
    (void)nearest_pairs(ta, tb, v, order);
    ASSERT_FALSE(v.leaves_seen.empty());
    // The last node of each tree (a leaf: children come after their parent) is opened first.
    const auto last = [](const Bvh& t) { return static_cast<std::int32_t>(t.nodes().size()) - 1; };
    EXPECT_EQ(v.leaves_seen.front(), std::make_pair(last(ta), last(tb)));
    const std::size_t leaves_a = (ta.nodes().size() + 1) / 2,
                      leaves_b = (tb.nodes().size() + 1) / 2;
    EXPECT_EQ(v.leaves_seen.size(), leaves_a * leaves_b) << "nothing is pruned";
  }
}

TEST(NearestPairs, VisitorThatStopsEndsTheDescentAtOnceAndEmptyTreesVisitNothing) {
  const std::vector<Vec3> a = lattice_points(64, 13, 0);
  const Bvh ta(point_boxes(a)), empty;
  TieOrder v;
  v.stop_after = 3;
  const TraversalStats stats = nearest_pairs(ta, ta, v);
  EXPECT_TRUE(stats.stopped);
  EXPECT_EQ(v.leaves_seen.size(), 3u);
  TieOrder none;
  EXPECT_EQ(nearest_pairs(ta, empty, none).nodes, 0u);
  EXPECT_EQ(nearest_pairs(empty, ta, none, PairOrder::best_first).nodes, 0u);
  EXPECT_TRUE(none.leaves_seen.empty());
}

}  // namespace
}  // namespace contain::bvh
