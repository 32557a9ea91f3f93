#pragma once
/// \file
/// A bounding volume hierarchy over axis-aligned boxes: flat nodes in one vector with int32
/// indices, built once with the binned surface area heuristic, queried with visitors that can
/// stop early. Items are any boxed things (triangles of a mesh, whole objects of a scene); the
/// hierarchy knows only their boxes, so exact tests stay with the caller (broad phase apart from
/// narrow phase).

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contain/core/huge_pages.h"
#include "contain/values/box.h"

namespace contain::bvh {

/// One node of a `Bvh`. Nodes are stored depth first: the first child of an inner node is the
/// node right after it, the second child is `nodes()[first]`.
struct Node {
  Box3 box;                ///< closed box of every item below
  std::int32_t first = 0;  ///< leaf: first position in `items()`; inner: index of the 2nd child
  std::int32_t count = 0;  ///< leaf: number of items (> 0); inner: 0
  [[nodiscard]] constexpr bool is_leaf() const { return count > 0; }
};

/// How a `Bvh` splits its nodes.
enum class BuildMethod : std::uint8_t {
  /// Binned surface area heuristic (Wald 2007): the best trees for queries, O(n log n) with a
  /// sweep of every item per level.
  sah,
  /// Linear BVH (Lauterbach et al. 2009, Karras 2012): items sorted by the Morton code of their
  /// box centroids (21 bits per axis in the centroids' bounds), each node split where the
  /// codes' highest differing bit changes (at the middle when all are equal), leaves of at
  /// most `max_leaf_items`. A radix sort and one pass per node boundary: several times faster
  /// to build than `sah`, for somewhat slower queries; for hierarchies built once per query
  /// batch of a few queries per item (the self-intersection of a large mesh).
  morton,
};

/// How a `Bvh` is built (binned SAH, Wald 2007, unless `method` says otherwise).
struct BuildOptions {
  BuildMethod method = BuildMethod::sah;
  /// Bins per axis of the centroid bounds in the SAH sweep.
  int bins = 16;
  /// A node with at most this many items may become a leaf ...
  int max_leaf_items = 4;
  /// ... and becomes one when splitting is not cheaper under the cost model
  /// node_cost + (area(L) n(L) + area(R) n(R)) / area(parent) * item_cost against n * item_cost.
  double node_cost = 1.0;
  double item_cost = 1.0;
};

/// What a visitor tells a traversal.
enum class Visit : std::uint8_t { proceed, stop };

/// Counts of a traversal, for benchmarks and `--json`.
struct TraversalStats {
  std::size_t nodes = 0;  ///< nodes whose box was tested (entered or not)
  std::size_t items = 0;  ///< items handed to the visitor
  bool stopped = false;   ///< a visitor returned Visit::stop
};

/// A bounding volume hierarchy over n boxes, items numbered 0..n-1 in the order given.
///
/// Build: top down; at each node the items' box centroids are binned along each axis and the
/// split plane with the least surface area heuristic cost is taken (Wald, "On fast Construction
/// of SAH-based Bounding Volume Hierarchies", 2007; MacDonald and Booth 1990). Items whose
/// centroids coincide are split by count; the tree depth stays O(log n) in that case.
/// O(n log n) time (n * bins per level), O(n) memory (at most 2n - 1 nodes). Deterministic.
/// Empty boxes (min > max) are allowed and never overlap anything.
///
/// Queries are templates over the visitors so that they inline; every decision about a box is
/// the caller's (`enter`), so a query under a transform, a ray or a distance bound is a lambda.
/// Thread safety: const; queries may run concurrently.
class Bvh {
 public:
  /// An empty hierarchy: every traversal visits nothing.
  Bvh() = default;
  /// Builds over `boxes` (item i has box boxes[i]); no box may hold NaN.
  explicit Bvh(std::span<const Box3> boxes, const BuildOptions& options = {});

  /// The linear build (BuildMethod::morton, leaves of at most `max_leaf_items`) over n items
  /// whose boxes `box_of(std::size_t i) -> Box3` gives where they are not kept in an array (a
  /// triangle's box from its corners: an array of them is 48 bytes an item, each page of it a
  /// fault). The same tree as `Bvh(boxes, {.method = BuildMethod::morton})` over those boxes;
  /// `box_of` is called a few times per item and must give the same box each time.
  template <class BoxOf>
  [[nodiscard]] static Bvh morton(std::size_t n, const BoxOf& box_of, int max_leaf_items = 4) {
    Bvh tree;
    if (n == 0) return tree;
    tree.build_morton(
        n,
        [](const void* context, std::size_t i) { return (*static_cast<const BoxOf*>(context))(i); },
        &box_of, max_leaf_items);
    return tree;
  }

  /// The nodes, root first (none for an empty hierarchy).
  [[nodiscard]] std::span<const Node> nodes() const { return nodes_; }
  /// Item numbers in leaf order: a leaf holds items()[first .. first + count).
  [[nodiscard]] std::span<const std::int32_t> items() const { return items_; }
  [[nodiscard]] bool empty() const { return nodes_.empty(); }
  /// The box of every item (empty for an empty hierarchy).
  [[nodiscard]] Box3 bounds() const { return nodes_.empty() ? Box3{} : nodes_.front().box; }
  /// Depth of the deepest leaf (root: 1; 0 when empty).
  [[nodiscard]] int depth() const { return depth_; }

  /// Depth-first traversal: `enter(const Node&, std::int32_t index) -> bool` decides whether to
  /// descend into a node (called on the root too); `visit(std::int32_t item) -> Visit` sees the
  /// items of every entered leaf and may stop the traversal. Children are visited first then
  /// second. O(nodes entered + items visited).
  template <class Enter, class VisitItem>
  TraversalStats traverse(Enter&& enter, VisitItem&& visit) const;

 private:
  using BoxSource = Box3 (*)(const void* context, std::size_t item);
  void build_morton(std::size_t n, BoxSource box_of, const void* context, int max_leaf_items);

  // In huge pages where granted: at a boolean of two spheres of 131k triangles the nodes were
  // 2,145 fresh 4 kB pages and the item numbers 256 (docs/benchmarks.md, solid-morton).
  HugePageVector<Node> nodes_;
  HugePageVector<std::int32_t> items_;
  int depth_ = 0;
};

/// Simultaneous traversal of two hierarchies (collision of two meshes, self-tests with a == b):
/// `enter(const Node& na, const Node& nb) -> bool` decides whether a pair of nodes can hold a
/// pair of overlapping items (a transform of b goes into this test); `visit(std::int32_t item_a,
/// std::int32_t item_b) -> Visit` sees each candidate pair of items once and may stop. The
/// larger inner node (by surface area; an inner node before a leaf) is split first.
/// O(pairs of nodes entered + pairs of items visited).
template <class Enter, class VisitPair>
TraversalStats traverse_pairs(const Bvh& a, const Bvh& b, Enter&& enter, VisitPair&& visit);

/// Self traversal of one hierarchy (a mesh against itself): `visit(std::int32_t i, std::int32_t
/// j) -> Visit` sees each unordered pair of distinct items i != j whose nodes `enter(const Node&,
/// const Node&) -> bool` accepts exactly once (in either order), where `traverse_pairs(h, h)`
/// would see it twice and each item with itself. A node is paired with itself without `enter`
/// (its children then as both pairs and selves); two different nodes as in `traverse_pairs`.
/// O(pairs of nodes entered + pairs of items visited), about half of `traverse_pairs(h, h)`.
template <class Enter, class VisitPair>
TraversalStats traverse_self(const Bvh& tree, Enter&& enter, VisitPair&& visit);

/// The walk of `traverse_self` by pairs of leaves: `visit(std::span<const std::int32_t> a,
/// std::span<const std::int32_t> b) -> Visit` sees the items of each pair of leaves whose pairs
/// `traverse_self` would visit, in its order: a leaf with itself (a and b the same span: its
/// pairs are a[i], a[j] with i < j) and two different leaves accepted by `enter` (every a[i]
/// with every b[j], i major). For visitors that test a leaf pair's item pairs together (masks
/// instead of a branch per pair). `items` of the stats is left 0 (the visitor counts).
template <class Enter, class VisitLeaves>
TraversalStats traverse_self_leaves(const Bvh& tree, Enter&& enter, VisitLeaves&& visit);

/// `traverse_self_leaves` that asks `within(std::int32_t node) -> bool` once for each inner node,
/// before the pairs within it: false skips all of them (its children's pairs with each other
/// too), as though the node's subtree held no pair; the remaining pairs come in the same order.
/// For callers that can prove a subtree's items never meet each other (a patch of a surface
/// whose projection is an embedding) at less cost than walking its pairs.
template <class Enter, class VisitLeaves, class Within>
TraversalStats traverse_self_leaves(const Bvh& tree, Enter&& enter, VisitLeaves&& visit,
                                    Within&& within);

/// Surface area of a closed box (0 for an empty or flat one), the SAH's measure.
[[nodiscard]] constexpr double surface_area(const Box3& box) {
  if (box.empty()) return 0.0;
  const double dx = box.max.x - box.min.x, dy = box.max.y - box.min.y, dz = box.max.z - box.min.z;
  return 2.0 * (dx * dy + dy * dz + dz * dx);
}

// ---- templates ----------------------------------------------------------------------------

template <class Enter, class VisitItem>
TraversalStats Bvh::traverse(Enter&& enter, VisitItem&& visit) const {
  TraversalStats stats;
  if (nodes_.empty()) return stats;
  // The depth bounds the stack: each level pushes at most one pending second child.
  std::int32_t local[64];
  std::vector<std::int32_t> heap;
  std::int32_t* stack = local;
  if (depth_ > 62) {
    heap.resize(static_cast<std::size_t>(depth_) + 2);
    stack = heap.data();
  }
  int top = 0;
  std::int32_t index = 0;
  for (;;) {
    const Node& node = nodes_[static_cast<std::size_t>(index)];
    ++stats.nodes;
    if (enter(node, index)) {
      if (node.is_leaf()) {
        for (std::int32_t k = node.first; k < node.first + node.count; ++k) {
          ++stats.items;
          if (visit(items_[static_cast<std::size_t>(k)]) == Visit::stop) {
            stats.stopped = true;
            return stats;
          }
        }
      } else {
        stack[top++] = node.first;
        index = index + 1;
        continue;
      }
    }
    if (top == 0) break;
    index = stack[--top];
  }
  return stats;
}

namespace detail {

// One step of a simultaneous descent: node x of a against node y of b (two different nodes when
// a and b are one tree). Tests the pair with `enter`; at two leaves hands every pair of their
// items to `visit`, otherwise pushes the children of the larger node. Returns false when the
// visitor stopped the traversal.
template <class Enter, class VisitPair>
bool pair_step(const Bvh& a, const Bvh& b, std::int32_t x, std::int32_t y,
               std::vector<std::pair<std::int32_t, std::int32_t>>& stack, TraversalStats& stats,
               Enter& enter, VisitPair& visit) {
  const Node& p = a.nodes()[static_cast<std::size_t>(x)];
  const Node& q = b.nodes()[static_cast<std::size_t>(y)];
  ++stats.nodes;
  if (!enter(p, q)) return true;
  if (p.is_leaf() && q.is_leaf()) {
    const std::span<const std::int32_t> ia = a.items(), ib = b.items();
    for (std::int32_t s = p.first; s < p.first + p.count; ++s) {
      for (std::int32_t t = q.first; t < q.first + q.count; ++t) {
        ++stats.items;
        if (visit(ia[static_cast<std::size_t>(s)], ib[static_cast<std::size_t>(t)]) ==
            Visit::stop) {
          stats.stopped = true;
          return false;
        }
      }
    }
    return true;
  }
  const bool split_a = q.is_leaf() || (!p.is_leaf() && surface_area(p.box) >= surface_area(q.box));
  if (split_a) {
    stack.emplace_back(p.first, y);
    stack.emplace_back(x + 1, y);
  } else {
    stack.emplace_back(x, q.first);
    stack.emplace_back(x, y + 1);
  }
  return true;
}

}  // namespace detail

template <class Enter, class VisitPair>
TraversalStats traverse_pairs(const Bvh& a, const Bvh& b, Enter&& enter, VisitPair&& visit) {
  TraversalStats stats;
  if (a.empty() || b.empty()) return stats;
  std::vector<std::pair<std::int32_t, std::int32_t>> stack;
  stack.reserve(static_cast<std::size_t>(2 * (a.depth() + b.depth()) + 4));
  stack.emplace_back(0, 0);
  while (!stack.empty()) {
    const auto [x, y] = stack.back();
    stack.pop_back();
    if (!detail::pair_step(a, b, x, y, stack, stats, enter, visit)) break;
  }
  return stats;
}

template <class Enter, class VisitLeaves>
TraversalStats traverse_self_leaves(const Bvh& tree, Enter&& enter, VisitLeaves&& visit) {
  return traverse_self_leaves(tree, enter, visit, [](std::int32_t) { return true; });
}

template <class Enter, class VisitLeaves, class Within>
TraversalStats traverse_self_leaves(const Bvh& tree, Enter&& enter, VisitLeaves&& visit,
                                    Within&& within) {
  TraversalStats stats;
  if (tree.empty()) return stats;
  const std::span<const std::int32_t> items = tree.items();
  const std::span<const Node> nodes = tree.nodes();
  const auto leaf = [&](const Node& n) {
    return items.subspan(static_cast<std::size_t>(n.first), static_cast<std::size_t>(n.count));
  };
  // (x, x) is a node against itself: the pairs within it. x != y are two disjoint subtrees
  // (pushed only as siblings' descendants), so no pair of items comes twice. The first of the
  // two (or three) pairs a step makes is walked at once, not pushed and popped: the same order.
  std::vector<std::pair<std::int32_t, std::int32_t>> stack;
  stack.reserve(static_cast<std::size_t>(4 * tree.depth() + 4));
  std::int32_t x = 0, y = 0;
  for (;;) {
    const Node& p = nodes[static_cast<std::size_t>(x)];
    ++stats.nodes;
    if (x == y) {
      if (!p.is_leaf() && within(x)) {
        stack.emplace_back(p.first, p.first);
        stack.emplace_back(x + 1, p.first);
        y = ++x;
        continue;
      }
      if (p.is_leaf() && visit(leaf(p), leaf(p)) == Visit::stop) {
        stats.stopped = true;
        return stats;
      }
    } else {
      const Node& q = nodes[static_cast<std::size_t>(y)];
      if (enter(p, q)) {
        if (p.is_leaf() && q.is_leaf()) {
          if (visit(leaf(p), leaf(q)) == Visit::stop) {
            stats.stopped = true;
            return stats;
          }
        } else {
          // As detail::pair_step: the larger inner node split, its first child first.
          if (q.is_leaf() || (!p.is_leaf() && surface_area(p.box) >= surface_area(q.box))) {
            stack.emplace_back(p.first, y);
            ++x;
          } else {
            stack.emplace_back(x, q.first);
            ++y;
          }
          continue;
        }
      }
    }
    if (stack.empty()) break;
    x = stack.back().first;
    y = stack.back().second;
    stack.pop_back();
  }
  return stats;
}

template <class Enter, class VisitPair>
TraversalStats traverse_self(const Bvh& tree, Enter&& enter, VisitPair&& visit) {
  std::size_t pairs = 0;
  TraversalStats stats = traverse_self_leaves(
      tree, enter, [&](std::span<const std::int32_t> a, std::span<const std::int32_t> b) {
        const bool same = a.data() == b.data();
        for (std::size_t s = 0; s < a.size(); ++s) {
          for (std::size_t t = same ? s + 1 : 0; t < b.size(); ++t) {
            ++pairs;
            if (visit(a[s], b[t]) == Visit::stop) return Visit::stop;
          }
        }
        return Visit::proceed;
      });
  stats.items = pairs;
  return stats;
}

}  // namespace contain::bvh
