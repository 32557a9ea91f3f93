#pragma once
/// \file
/// Branch and bound over pairs of nodes of two hierarchies: the one descent under every "least
/// over all pairs of items" query (closest triangles of two meshes, closest edges of two
/// regions, earliest contact of two moving meshes), as `traverse_pairs` is the one descent under
/// every "any overlapping pair" query.

#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contain/bvh/bvh.h"

namespace contain::bvh {

/// A pair of nodes (indices into the two hierarchies' `nodes()`) and a lower bound, under the
/// query's measure (a squared distance, a time ...), of every pair of items below them.
struct NodePair {
  std::int32_t a = 0;
  std::int32_t b = 0;
  double lower = 0;
};

/// In which order `nearest_pairs` opens the waiting node pairs.
enum class PairOrder : std::uint8_t {
  /// The two children of the last opened pair, the nearer first (a stack of depth
  /// O(depth_a + depth_b)): the first leaf pairs reached are near, and the upkeep is least.
  depth_first,
  /// The waiting pair of least bound over all (a heap): no pair is opened whose bound exceeds the
  /// final answer, at the cost of the heap.
  best_first,
};

/// The pair of nodes opened first among two of equal bounds when the visitor names no order:
/// the lower node of A, then of B (children are stored after their parent, the first child
/// right after it).
[[nodiscard]] constexpr bool lower_nodes_first(const NodePair& x, const NodePair& y) {
  return x.a != y.a ? x.a < y.a : x.b < y.b;
}

/// Descends hierarchies `a` and `b` together from their roots, opening pairs of nodes in
/// `order` (nearer bounds first; equal bounds by `visitor.before`, else `lower_nodes_first`) and
/// leaving out every pair the visitor no longer wants. The visitor is asked:
/// - `double lower(std::int32_t node_a, std::int32_t node_b)`: a lower bound of every item pair
///   below the two nodes (called once per pair made);
/// - `bool worth(const NodePair&)`: can the pair still hold an answer (its bound against the best
///   found so far)? Asked when the pair is made and again when it is opened, since the best may
///   have improved in between. Under `best_first` it must hold for no bound once it fails for a
///   smaller one: the descent ends at the first opened pair not worth it;
/// - `bool split_a(std::int32_t node_a, std::int32_t node_b)`: for two inner nodes, whether to
///   open A's node (else B's); a leaf is never split while the other node is inner;
/// - `Visit leaves(std::int32_t node_a, std::int32_t node_b)`: a pair of leaves (the visitor
///   tests their items, lowers its best, and may stop the descent);
/// - optionally `bool before(const NodePair& x, const NodePair& y)`: of two pairs of equal
///   bound, x is opened first.
/// Stats: `nodes` counts the pairs opened (worth it when opened), `items` the leaf pairs.
/// O(pairs opened) visitor calls, times log(waiting pairs) under `best_first`. Deterministic:
/// the order depends only on the bounds and the tie order.
template <class Visitor>
TraversalStats nearest_pairs(const Bvh& a, const Bvh& b, Visitor&& visitor,
                             PairOrder order = PairOrder::depth_first) {
  TraversalStats stats;
  if (a.empty() || b.empty()) return stats;
  const auto first = [&](const NodePair& x, const NodePair& y) {
    if (x.lower != y.lower) return x.lower < y.lower;
    if constexpr (requires { visitor.before(x, y); }) {
      return visitor.before(x, y);
    } else {
      return lower_nodes_first(x, y);
    }
  };
  // The heap's top is the pair opened first; the stack's back is.
  const auto later = [&](const NodePair& x, const NodePair& y) { return first(y, x); };
  const bool heap = order == PairOrder::best_first;
  std::vector<NodePair> waiting;
  waiting.reserve(static_cast<std::size_t>(2 * (a.depth() + b.depth()) + 4));
  const auto wait = [&](const NodePair& pair) {
    if (!visitor.worth(pair)) return;
    waiting.push_back(pair);
    if (heap) std::push_heap(waiting.begin(), waiting.end(), later);
  };
  wait({0, 0, visitor.lower(0, 0)});
  const std::span<const Node> na = a.nodes(), nb = b.nodes();
  while (!waiting.empty()) {
    if (heap) std::pop_heap(waiting.begin(), waiting.end(), later);
    const NodePair e = waiting.back();
    waiting.pop_back();
    if (!visitor.worth(e)) {
      if (heap) break;
      continue;
    }
    ++stats.nodes;
    const Node& p = na[static_cast<std::size_t>(e.a)];
    const Node& q = nb[static_cast<std::size_t>(e.b)];
    if (p.is_leaf() && q.is_leaf()) {
      ++stats.items;
      if (visitor.leaves(e.a, e.b) == Visit::stop) {
        stats.stopped = true;
        return stats;
      }
      continue;
    }
    const bool split_a = q.is_leaf() || (!p.is_leaf() && visitor.split_a(e.a, e.b));
    NodePair c1 = e, c2 = e;
    if (split_a) {
      c1.a = e.a + 1;
      c2.a = p.first;
    } else {
      c1.b = e.b + 1;
      c2.b = q.first;
    }
    c1.lower = visitor.lower(c1.a, c1.b);
    c2.lower = visitor.lower(c2.a, c2.b);
    if (first(c2, c1)) std::swap(c1, c2);
    wait(c2);  // on a stack the one opened first goes last
    wait(c1);
  }
  return stats;
}

}  // namespace contain::bvh
