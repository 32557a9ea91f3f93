#include "contain/bvh/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include "contain/bvh/triangle_boxes.h"
#include "scenes/scenes.h"

namespace contain::bvh {
namespace {

std::vector<Box3> random_boxes(std::size_t n, unsigned seed, double size = 0.05) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(0.0, size);
  std::vector<Box3> boxes(n);
  for (Box3& b : boxes) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    b.min = p;
    b.max = p + Vec3{s(rng), s(rng), s(rng)};
  }
  return boxes;
}

Box3 translated(const Box3& b, Vec3 t) {
  return {b.min + t, b.max + t};
}

// Every pair i < j of overlapping boxes, by brute force.
std::set<std::pair<std::int32_t, std::int32_t>> overlapping_pairs(const std::vector<Box3>& boxes) {
  std::set<std::pair<std::int32_t, std::int32_t>> pairs;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j]))
        pairs.insert({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
  return pairs;
}

// The self traversal's pairs of overlapping boxes (i < j), each expected once.
TraversalStats self_pairs(const Bvh& tree, const std::vector<Box3>& boxes,
                          std::set<std::pair<std::int32_t, std::int32_t>>& found) {
  return traverse_self(
      tree, [](const Node& x, const Node& y) { return x.box.overlaps(y.box); },
      [&](std::int32_t i, std::int32_t j) {
        EXPECT_NE(i, j);
        if (boxes[static_cast<std::size_t>(i)].overlaps(boxes[static_cast<std::size_t>(j)])) {
          EXPECT_TRUE(found.insert({std::min(i, j), std::max(i, j)}).second) << "each pair once";
        }
        return Visit::proceed;
      });
}

// How often each item is in a leaf (of at most 4 items), every node box checked to hold its
// children and items.
std::vector<int> leaf_counts(const Bvh& bvh, const std::vector<Box3>& boxes) {
  std::vector<int> seen(boxes.size(), 0);
  const auto nodes = bvh.nodes();
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    if (!nodes[n].is_leaf()) {
      const Box3& l = nodes[n + 1].box;
      const Box3& r = nodes[static_cast<std::size_t>(nodes[n].first)].box;
      EXPECT_TRUE(l.empty() || (nodes[n].box.contains(l.min) && nodes[n].box.contains(l.max)));
      EXPECT_TRUE(r.empty() || (nodes[n].box.contains(r.min) && nodes[n].box.contains(r.max)));
      continue;
    }
    EXPECT_LE(nodes[n].count, 4);
    for (std::int32_t k = nodes[n].first; k < nodes[n].first + nodes[n].count; ++k) {
      const std::int32_t item = bvh.items()[static_cast<std::size_t>(k)];
      ++seen[static_cast<std::size_t>(item)];
      const Box3& b = boxes[static_cast<std::size_t>(item)];
      EXPECT_TRUE(b.empty() || (nodes[n].box.contains(b.min) && nodes[n].box.contains(b.max)));
    }
  }
  return seen;
}

// 300 point boxes at +-scale times 0..1: centroid spans beyond DBL_MAX or subnormal.
std::vector<Box3> extreme_boxes(double scale) {
  std::vector<Box3> boxes;
  for (int i = 0; i < 300; ++i) {
    const double c = scale * ((i % 2) ? 1.0 : -1.0) * ((i % 7) / 6.0);
    boxes.push_back(Box3{{c, -c, c}, {c, -c, c}});
  }
  return boxes;
}

TEST(Bvh, EveryItemIsInExactlyOneLeafAndEveryNodeBoxContainsItsItems) {
  const std::vector<Box3> boxes = random_boxes(5000, 1);
  const Bvh bvh(boxes);
  const std::vector<int> seen = leaf_counts(bvh, boxes);
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
  EXPECT_LE(bvh.nodes().size(), 2 * boxes.size() - 1);
}

TEST(Bvh, OverlapQueryFindsExactlyTheOverlappingBoxes) {
  const std::vector<Box3> boxes = random_boxes(3000, 2);
  const Bvh bvh(boxes);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int q = 0; q < 50; ++q) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const Box3 query{p, p + Vec3{0.1, 0.1, 0.1}};
    std::set<std::int32_t> found;
    const TraversalStats stats =
        bvh.traverse([&](const Node& node, std::int32_t) { return node.box.overlaps(query); },
                     [&](std::int32_t item) {
                       if (boxes[static_cast<std::size_t>(item)].overlaps(query))
                         found.insert(item);
                       return Visit::proceed;
                     });
    std::set<std::int32_t> expected;
    for (std::size_t i = 0; i < boxes.size(); ++i)
      if (boxes[i].overlaps(query)) expected.insert(static_cast<std::int32_t>(i));
    EXPECT_EQ(found, expected);
    EXPECT_FALSE(stats.stopped);
    EXPECT_LT(stats.items, boxes.size() / 4) << "the hierarchy prunes";
  }
}

TEST(Bvh, VisitorThatStopsEndsTheTraversalAtOnce) {
  const std::vector<Box3> boxes = random_boxes(1000, 4);
  const Bvh bvh(boxes);
  int visited = 0;
  const TraversalStats stats = bvh.traverse([](const Node&, std::int32_t) { return true; },
                                            [&](std::int32_t) {
                                              ++visited;
                                              return visited == 3 ? Visit::stop : Visit::proceed;
                                            });
  EXPECT_TRUE(stats.stopped);
  EXPECT_EQ(visited, 3);
  EXPECT_EQ(stats.items, 3u);
}

TEST(Bvh, PairTraversalUnderATranslationFindsExactlyTheOverlappingPairs) {
  const std::vector<Box3> a = random_boxes(800, 5), b = random_boxes(600, 6);
  const Bvh ba(a), bb(b);
  const Vec3 shift{0.3, -0.2, 0.1};  // b is moved: its boxes are tested translated
  std::set<std::pair<std::int32_t, std::int32_t>> found;
  (void)traverse_pairs(
      ba, bb,
      [&](const Node& na, const Node& nb) { return na.box.overlaps(translated(nb.box, shift)); },
      [&](std::int32_t i, std::int32_t j) {
        if (a[static_cast<std::size_t>(i)].overlaps(
                translated(b[static_cast<std::size_t>(j)], shift))) {
          EXPECT_TRUE(found.insert({i, j}).second) << "each pair once";
        }
        return Visit::proceed;
      });
  std::set<std::pair<std::int32_t, std::int32_t>> expected;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      if (a[i].overlaps(translated(b[j], shift)))
        expected.insert({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
  EXPECT_EQ(found, expected);
  EXPECT_FALSE(expected.empty());
}

TEST(Bvh, SelfTraversalFindsEachOverlappingPairOfDistinctItemsOnce) {
  const std::vector<Box3> boxes = random_boxes(900, 11);
  const Bvh tree(boxes);
  std::set<std::pair<std::int32_t, std::int32_t>> found;
  const TraversalStats stats = self_pairs(tree, boxes, found);
  const std::set<std::pair<std::int32_t, std::int32_t>> expected = overlapping_pairs(boxes);
  EXPECT_EQ(found, expected);
  EXPECT_FALSE(expected.empty());
  // About half the work of the pair traversal of the tree with itself.
  const TraversalStats both = traverse_pairs(
      tree, tree, [](const Node& x, const Node& y) { return x.box.overlaps(y.box); },
      [](std::int32_t, std::int32_t) { return Visit::proceed; });
  EXPECT_LT(stats.items, both.items);
  EXPECT_FALSE(stats.stopped);
}

// The self traversal as first written (every pair of nodes pushed, then popped), to check
// that the walk by leaves keeps its order: the mesh booleans number their crossing points in it.
std::vector<std::pair<std::int32_t, std::int32_t>> stack_walk_pairs(const Bvh& tree,
                                                                    std::size_t& nodes) {
  std::vector<std::pair<std::int32_t, std::int32_t>> out;
  nodes = 0;
  if (tree.empty()) return out;
  const auto n = tree.nodes();
  const auto items = tree.items();
  std::vector<std::pair<std::int32_t, std::int32_t>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [x, y] = stack.back();
    stack.pop_back();
    ++nodes;
    const Node& p = n[static_cast<std::size_t>(x)];
    const Node& q = n[static_cast<std::size_t>(y)];
    if (x == y) {
      if (!p.is_leaf()) {
        stack.emplace_back(p.first, p.first);
        stack.emplace_back(x + 1, p.first);
        stack.emplace_back(x + 1, x + 1);
        continue;
      }
      for (std::int32_t s = p.first; s < p.first + p.count; ++s)
        for (std::int32_t t = s + 1; t < p.first + p.count; ++t)
          out.emplace_back(items[static_cast<std::size_t>(s)], items[static_cast<std::size_t>(t)]);
      continue;
    }
    if (!p.box.overlaps(q.box)) continue;
    if (p.is_leaf() && q.is_leaf()) {
      for (std::int32_t s = p.first; s < p.first + p.count; ++s)
        for (std::int32_t t = q.first; t < q.first + q.count; ++t)
          out.emplace_back(items[static_cast<std::size_t>(s)], items[static_cast<std::size_t>(t)]);
      continue;
    }
    if (q.is_leaf() || (!p.is_leaf() && surface_area(p.box) >= surface_area(q.box))) {
      stack.emplace_back(p.first, y);
      stack.emplace_back(x + 1, y);
    } else {
      stack.emplace_back(x, q.first);
      stack.emplace_back(x, y + 1);
    }
  }
  return out;
}

// The walk by leaves asked `within` at each inner node: the pairs it skips are exactly those
// with both items under a refused node, the others come in the order of the full walk.
TEST(Bvh, SelfWalkByLeavesSkipsExactlyThePairsWithinRefusedNodesKeepingTheOrder) {
  for (const unsigned seed : {41U, 42U}) {
    const std::vector<Box3> boxes = random_boxes(600, seed, 0.25);
    const Bvh tree(boxes, {.method = BuildMethod::morton});
    const auto enter = [](const Node& x, const Node& y) { return x.box.overlaps(y.box); };
    std::vector<std::pair<std::int32_t, std::int32_t>> all, kept;
    const auto collect = [](std::vector<std::pair<std::int32_t, std::int32_t>>& out) {
      return [&out](std::span<const std::int32_t> a, std::span<const std::int32_t> b) {
        const bool same = a.data() == b.data();
        for (std::size_t i = 0; i < a.size(); ++i)
          for (std::size_t j = same ? i + 1 : 0; j < b.size(); ++j)
            out.emplace_back(a[i], b[j]);
        return Visit::proceed;
      };
    };
    (void)traverse_self_leaves(tree, enter, collect(all));
    // Refuse every inner node whose index is 3 modulo 7 (not the root); record their items.
    const std::span<const Node> nodes = tree.nodes();
    std::vector<std::int32_t> refused;
    std::size_t asked = 0;
    (void)traverse_self_leaves(tree, enter, collect(kept), [&](std::int32_t node) {
      ++asked;
      EXPECT_FALSE(nodes[static_cast<std::size_t>(node)].is_leaf());
      if (node % 7 != 3) return true;
      refused.push_back(node);
      return false;
    });
    EXPECT_GT(refused.size(), 3U);
    EXPECT_GT(asked, refused.size());
    const auto items_below = [&](std::int32_t node) {
      std::vector<bool> below(boxes.size(), false);
      std::vector<std::int32_t> stack{node};
      while (!stack.empty()) {
        const std::int32_t x = stack.back();
        stack.pop_back();
        const Node& n = nodes[static_cast<std::size_t>(x)];
        if (n.is_leaf()) {
          for (std::int32_t k = n.first; k < n.first + n.count; ++k)
            below[static_cast<std::size_t>(tree.items()[static_cast<std::size_t>(k)])] = true;
        } else {
          stack.push_back(x + 1);
          stack.push_back(n.first);
        }
      }
      return below;
    };
    std::vector<std::vector<bool>> refused_items;
    for (const std::int32_t node : refused)
      refused_items.push_back(items_below(node));
    std::vector<std::pair<std::int32_t, std::int32_t>> expected;
    for (const auto& [i, j] : all) {
      bool skipped = false;
      for (const std::vector<bool>& below : refused_items) {
        skipped =
            skipped || (below[static_cast<std::size_t>(i)] && below[static_cast<std::size_t>(j)]);
      }
      if (!skipped) expected.emplace_back(i, j);
    }
    EXPECT_EQ(kept, expected);
    EXPECT_LT(kept.size(), all.size());
  }
}

TEST(Bvh, SelfTraversalAndItsWalkByLeavesVisitThePairsOfTheStackWalkInItsOrder) {
  const BuildOptions wide_leaves{.max_leaf_items = 8, .item_cost = 4.0};
  for (const unsigned seed : {31U, 32U, 33U}) {
    const std::vector<Box3> boxes = random_boxes(700, seed, 0.25);
    for (const BuildOptions& options :
         {BuildOptions{}, BuildOptions{.method = BuildMethod::morton}, wide_leaves}) {
      const Bvh tree(boxes, options);
      std::size_t nodes = 0;
      const auto expected = stack_walk_pairs(tree, nodes);
      const auto enter = [](const Node& x, const Node& y) { return x.box.overlaps(y.box); };
      std::vector<std::pair<std::int32_t, std::int32_t>> by_pairs, by_leaves;
      const TraversalStats stats = traverse_self(tree, enter, [&](std::int32_t i, std::int32_t j) {
        by_pairs.emplace_back(i, j);
        return Visit::proceed;
      });
      const TraversalStats leaf_stats = traverse_self_leaves(
          tree, enter, [&](std::span<const std::int32_t> a, std::span<const std::int32_t> b) {
            const bool same = a.data() == b.data();
            if (same) {
              EXPECT_EQ(a.size(), b.size());
            }
            for (std::size_t i = 0; i < a.size(); ++i)
              for (std::size_t j = same ? i + 1 : 0; j < b.size(); ++j)
                by_leaves.emplace_back(a[i], b[j]);
            return Visit::proceed;
          });
      EXPECT_EQ(by_pairs, expected);
      EXPECT_EQ(by_leaves, expected);
      EXPECT_EQ(stats.nodes, nodes);
      EXPECT_EQ(leaf_stats.nodes, nodes);
      EXPECT_EQ(stats.items, expected.size());
      EXPECT_GT(expected.size(), 1000U);
    }
  }
  // A walk by leaves that stops ends at once.
  const std::vector<Box3> same(10, Box3{{0, 0, 0}, {1, 1, 1}});
  int leaves = 0;
  const TraversalStats stopped = traverse_self_leaves(
      Bvh(same), [](const Node&, const Node&) { return true; },
      [&](std::span<const std::int32_t>, std::span<const std::int32_t>) {
        return ++leaves == 2 ? Visit::stop : Visit::proceed;
      });
  EXPECT_TRUE(stopped.stopped);
  EXPECT_EQ(leaves, 2);
}

TEST(Bvh, SelfTraversalOfOneItemOrNoneVisitsNothingAndStopsOnRequest) {
  const std::vector<Box3> one{{{0, 0, 0}, {1, 1, 1}}};
  const auto count = [](const Bvh& tree) {
    std::size_t n = 0;
    (void)traverse_self(
        tree, [](const Node&, const Node&) { return true; },
        [&](std::int32_t, std::int32_t) {
          ++n;
          return Visit::proceed;
        });
    return n;
  };
  EXPECT_EQ(count(Bvh(one)), 0u);
  EXPECT_EQ(count(Bvh()), 0u);
  const std::vector<Box3> same(10, Box3{{0, 0, 0}, {1, 1, 1}});
  EXPECT_EQ(count(Bvh(same)), 45u);
  std::size_t seen = 0;
  const TraversalStats stopped = traverse_self(
      Bvh(same), [](const Node&, const Node&) { return true; },
      [&](std::int32_t, std::int32_t) {
        ++seen;
        return seen == 3 ? Visit::stop : Visit::proceed;
      });
  EXPECT_TRUE(stopped.stopped);
  EXPECT_EQ(seen, 3u);
}

TEST(Bvh, CoincidentBoxesStillGiveALogarithmicDepth) {
  const std::vector<Box3> boxes(4096, Box3{{1, 1, 1}, {2, 2, 2}});
  const Bvh bvh(boxes);
  EXPECT_LE(bvh.depth(), 14);
  std::size_t count = 0;
  (void)bvh.traverse([](const Node&, std::int32_t) { return true; },
                     [&](std::int32_t) {
                       ++count;
                       return Visit::proceed;
                     });
  EXPECT_EQ(count, boxes.size());
}

// Centroid spans that overflow (near +-DBL_MAX) or are subnormal made the SAH bin index infinite
// (undefined behaviour, found by fuzz_point_in_mesh): every item must still land in one leaf.
TEST(Bvh, CentroidSpansBeyondDblMaxOrSubnormalStillPlaceEveryItemOnce) {
  const double big = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  for (const double scale : {big, big / 3, tiny, 1e-310}) {
    const std::vector<Box3> boxes = extreme_boxes(scale);
    const Bvh bvh(boxes);
    std::vector<int> seen(boxes.size(), 0);
    (void)bvh.traverse([](const Node&, std::int32_t) { return true; },
                       [&](std::int32_t item) {
                         ++seen[static_cast<std::size_t>(item)];
                         return Visit::proceed;
                       });
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }))
        << "scale " << scale;
    EXPECT_LE(bvh.depth(), 64) << "scale " << scale;
  }
}

TEST(Bvh, EmptyHierarchyVisitsNothingAndEmptyBoxesNeverOverlap) {
  const Bvh empty;
  const TraversalStats stats = empty.traverse([](const Node&, std::int32_t) { return true; },
                                              [](std::int32_t) { return Visit::proceed; });
  EXPECT_EQ(stats.nodes, 0u);
  EXPECT_TRUE(empty.bounds().empty());
  std::vector<Box3> boxes = random_boxes(10, 7);
  boxes.push_back(Box3{});  // empty
  const Bvh bvh(boxes);
  EXPECT_EQ(bvh.items().size(), boxes.size());
}

// The linear (Morton) build: the same contract as the SAH's (every item once, boxes enclose,
// queries exact), a deterministic tree, a bounded depth on coincident or extreme centroids.
constexpr BuildOptions morton{.method = BuildMethod::morton};

TEST(MortonBvh, EveryItemIsInExactlyOneLeafAndEveryNodeBoxContainsItsItems) {
  std::vector<Box3> boxes = random_boxes(5000, 21);
  boxes.push_back(Box3{});  // empty: in a leaf, overlapping nothing
  const Bvh bvh(boxes, morton);
  const std::vector<int> seen = leaf_counts(bvh, boxes);
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
  EXPECT_LE(bvh.nodes().size(), 2 * boxes.size() - 1);
}

TEST(MortonBvh, SelfTraversalFindsEachOverlappingPairOnceAndTheTreeIsDeterministic) {
  const std::vector<Box3> boxes = random_boxes(900, 22);
  const Bvh tree(boxes, morton);
  std::set<std::pair<std::int32_t, std::int32_t>> found;
  (void)self_pairs(tree, boxes, found);
  const std::set<std::pair<std::int32_t, std::int32_t>> expected = overlapping_pairs(boxes);
  EXPECT_EQ(found, expected);
  EXPECT_FALSE(expected.empty());
  const Bvh again(boxes, morton);
  EXPECT_TRUE(std::equal(tree.items().begin(), tree.items().end(), again.items().begin(),
                         again.items().end()));
  ASSERT_EQ(tree.nodes().size(), again.nodes().size());
  for (std::size_t n = 0; n < tree.nodes().size(); ++n) {
    EXPECT_EQ(tree.nodes()[n].first, again.nodes()[n].first);
    EXPECT_EQ(tree.nodes()[n].count, again.nodes()[n].count);
    EXPECT_EQ(tree.nodes()[n].box, again.nodes()[n].box);
  }
}

// Bvh::morton over boxes given by a callable (the mesh boolean computes a triangle's box from its
// corners instead of keeping an array) is the tree of those boxes: the same items in the same
// leaf order, the same nodes and depth, empty boxes and other leaf sizes included.
TEST(MortonBvh, BoxesGivenByACallableBuildTheTreeOfThoseBoxes) {
  std::vector<Box3> boxes = random_boxes(3000, 23);
  boxes[17] = Box3{};
  boxes[2999] = Box3{};
  for (const int leaf : {1, 4, 7}) {
    const Bvh stored(boxes, {.method = BuildMethod::morton, .max_leaf_items = leaf});
    std::size_t calls = 0;
    const Bvh computed = Bvh::morton(
        boxes.size(),
        [&](std::size_t i) {
          ++calls;
          return boxes[i];
        },
        leaf);
    EXPECT_GT(calls, 0U);
    EXPECT_EQ(computed.depth(), stored.depth()) << leaf;
    EXPECT_TRUE(std::ranges::equal(computed.items(), stored.items())) << leaf;
    ASSERT_EQ(computed.nodes().size(), stored.nodes().size()) << leaf;
    for (std::size_t n = 0; n < stored.nodes().size(); ++n) {
      EXPECT_EQ(computed.nodes()[n].first, stored.nodes()[n].first) << leaf;
      EXPECT_EQ(computed.nodes()[n].count, stored.nodes()[n].count) << leaf;
      EXPECT_EQ(computed.nodes()[n].box, stored.nodes()[n].box) << leaf;
    }
  }
  EXPECT_TRUE(Bvh::morton(0, [](std::size_t) { return Box3{}; }).empty());
}

TEST(MortonBvh, CoincidentOrExtremeCentroidsStillPlaceEveryItemOnceAtABoundedDepth) {
  const std::vector<Box3> same(4096, Box3{{1, 1, 1}, {2, 2, 2}});
  const Bvh coincident(same, morton);
  EXPECT_LE(coincident.depth(), 14);  // equal codes split at the middle
  const std::vector<int> seen_same = leaf_counts(coincident, same);
  EXPECT_TRUE(std::all_of(seen_same.begin(), seen_same.end(), [](int c) { return c == 1; }));
  const double big = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  for (const double scale : {big, big / 3, tiny, 1e-310}) {
    const std::vector<Box3> boxes = extreme_boxes(scale);
    const Bvh bvh(boxes, morton);
    const std::vector<int> seen = leaf_counts(bvh, boxes);
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }))
        << "scale " << scale;
    EXPECT_LE(bvh.depth(), 64 + 10) << "scale " << scale;
  }
}

TEST(Bvh, SahTreeOverAMeshPrunesPointQueries) {
  const Mesh torus = scenes::torus(1.0, 0.4, 100, 40);
  const std::vector<Box3> boxes = triangle_boxes(torus);
  const Bvh bvh(boxes);
  const Vec3 p = torus.vertices[17];
  std::size_t hits = 0;
  const TraversalStats stats =
      bvh.traverse([&](const Node& node, std::int32_t) { return node.box.contains(p); },
                   [&](std::int32_t t) {
                     hits += boxes[static_cast<std::size_t>(t)].contains(p);
                     return Visit::proceed;
                   });
  EXPECT_GE(hits, 3u);  // a vertex's triangles
  EXPECT_LT(stats.nodes, 200u);
}

}  // namespace
}  // namespace contain::bvh
