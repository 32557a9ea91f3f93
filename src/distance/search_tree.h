#pragma once
// Private to contain::distance: the nearest-item search shared by triangles (3D) and segments
// (2D, on the plane z = 0), over a BVH of the items' boxes.
//
// The tree has four children a node (the binary BVH collapsed: a node takes its grandchildren in
// place of its children), so that a step of the descent bounds four boxes at once and a search
// takes half the steps, each one a cache line and a half.
//
// Search: depth first, the nearer children first, pruning a node whose box is farther (squared
// distance, a lower bound rounded down) than the best upper bound found so far. Each item is
// bounded by the caller's `bound(position, lo, hi)`: proven lo <= dist^2 <= hi (see
// triangle_search.h for triangles, segment_search.h for segments). An item whose lo exceeds the
// final best hi cannot be closest; the others are the contenders, decided exactly by the caller.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/values/box.h"
#include "contain/values/vec.h"

namespace contain::distance::detail {

/// An item that may be the closest, with bounds on its squared distance.
struct Contender {
  std::int32_t item;  // index given to the search
  double lo;
  double hi;
};

/// Counts of a search, for benchmarks.
struct SearchStats {
  std::size_t nodes = 0;
  std::size_t items = 0;
  std::size_t cheap = 0;  // items put out by a first, cheap bound (counted in items too)
};

/// Lower bound of the squared distance from p to the closed box (rounded down; +inf beyond the
/// double range). Each difference is rounded (eps), the squares and sums add 3 eps: 8 eps covers
/// them and the final factor. A square that underflows only lowers the bound; an overflow means
/// the exact value exceeds DBL_MAX.
[[nodiscard]] inline double box_lower_bound(Vec3 p, const float lo[3], const float hi[3]) {
  constexpr double kEps = 0x1p-53;
  const double dx =
      std::max(std::max(static_cast<double>(lo[0]) - p.x, p.x - static_cast<double>(hi[0])), 0.0);
  const double dy =
      std::max(std::max(static_cast<double>(lo[1]) - p.y, p.y - static_cast<double>(hi[1])), 0.0);
  const double dz =
      std::max(std::max(static_cast<double>(lo[2]) - p.z, p.z - static_cast<double>(hi[2])), 0.0);
  return ((dx * dx + dy * dy) + dz * dz) * (1 - 8 * kEps);
}

// Four boxes' lower bounds at once, lane by lane the same operations as box_lower_bound (so the
// same proof), two lanes a vector of the compiler (SSE2 on x86-64, NEON on arm64, plain code
// elsewhere). Empty lanes hold lo = +inf, hi = -inf: their bound is +inf (the callers still test
// for them, as the bound they compare with may be +inf too).
using Double2 = double __attribute__((vector_size(16)));

[[nodiscard]] inline Double2 max2(Double2 a, Double2 b) {
  return a > b ? a : b;
}

inline void box_lower_bound4(Vec3 p, const float lo[3][4], const float hi[3][4], double out[4]) {
  constexpr double kEps = 0x1p-53;
  const double pc[3] = {p.x, p.y, p.z};
#pragma GCC unroll 2
  for (int half = 0; half < 4; half += 2) {
    Double2 sum{};
#pragma GCC unroll 3
    for (int a = 0; a < 3; ++a) {
      const Double2 l{static_cast<double>(lo[a][half]), static_cast<double>(lo[a][half + 1])};
      const Double2 h{static_cast<double>(hi[a][half]), static_cast<double>(hi[a][half + 1])};
      const Double2 pa{pc[a], pc[a]};
      const Double2 d = max2(max2(l - pa, pa - h), Double2{});
      // The sum in the order of box_lower_bound: (dx^2 + dy^2) + dz^2.
      sum = a == 0 ? d * d : sum + d * d;
    }
    const Double2 lb = sum * (1 - 8 * kEps);
    out[half] = lb[0];
    out[half + 1] = lb[1];
  }
}

class SearchTree {
 public:
  SearchTree() = default;
  /// Items numbered 0..n-1 with the boxes given (no NaN).
  SearchTree(std::span<const Box3> boxes, const bvh::BuildOptions& options);

  [[nodiscard]] bool empty() const { return items_.empty(); }
  /// Item numbers in leaf order: the callers store their items' data in this order and are
  /// called back with positions into it.
  [[nodiscard]] std::span<const std::int32_t> items() const { return items_; }
  [[nodiscard]] std::int32_t position(std::int32_t item) const {
    return position_[static_cast<std::size_t>(item)];
  }

  /// The contenders for the closest item of p, into `out` (cleared first; never empty for a
  /// non-empty tree). `hint` (an item or -1) is bounded first, so that a near item prunes the
  /// search from the start; it never changes which items are contenders' decisions.
  template <class Bound>
  void contenders(Vec3 p, Bound&& bound, std::vector<Contender>& out, SearchStats* stats,
                  std::int32_t hint) const;

  /// Three-valued "some item within squared distance d2" from the bounds: +1 proven (some hi <=
  /// d2_lo), -1 disproven (every lo > d2_hi), 0 undecided; the undecided items go to `out`.
  template <class Bound>
  [[nodiscard]] int within(Vec3 p, double d2_lo, double d2_hi, Bound&& bound,
                           std::vector<Contender>& out) const;

 private:
  // A node holding its (up to) four children's boxes, rounded outward to float, axis by axis.
  struct QuadNode {
    float lo[3][4];
    float hi[3][4];
    std::int32_t child[4];  // inner: QuadNode index; leaf: first position
    std::int32_t count[4];  // leaf: number of items; inner: 0; empty lane: -1
  };

  template <class Bound>
  void bound_leaf(std::int32_t first, std::int32_t count, std::int32_t skip, Bound& bound,
                  double& best, std::vector<Contender>& out, std::size_t& bounded) const {
    for (std::int32_t k = first; k < first + count; ++k) {
      if (k == skip) continue;
      ++bounded;
      double lo = 0.0, hi = 0.0;
      bound(k, lo, hi);
      if (lo > best) continue;
      out.push_back({items_[static_cast<std::size_t>(k)], lo, hi});
      if (hi < best) best = hi;
    }
  }

  std::vector<std::int32_t> items_;     // leaf order
  std::vector<std::int32_t> position_;  // item -> position in leaf order
  std::vector<QuadNode> quads_;         // empty when the root is a leaf
  float root_lo_[3]{}, root_hi_[3]{};
  std::int32_t root_count_ = 0;  // items when the root is a leaf
  int depth_ = 0;
};

// ---- templates ----------------------------------------------------------------------------

template <class Bound>
void SearchTree::contenders(Vec3 p, Bound&& bound, std::vector<Contender>& out, SearchStats* stats,
                            std::int32_t hint) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  out.clear();
  if (items_.empty()) return;
  double best = kInf;
  std::int32_t skip = -1;
  std::size_t bounded = 0, nodes = 0;
  if (hint >= 0 && static_cast<std::size_t>(hint) < position_.size()) {
    skip = position(hint);
    bound_leaf(skip, 1, -1, bound, best, out, bounded);
  }
  if (quads_.empty()) {
    bound_leaf(0, root_count_, skip, bound, best, out, bounded);
  } else {
    // An entry is a node to descend (count 0) or a leaf to bound (count > 0), with its box's
    // lower bound; the nearest children are pushed last, so popped first.
    struct Entry {
      std::int32_t node;
      std::int32_t count;
      double lb;
    };
    Entry local[128];
    std::vector<Entry> heap;
    Entry* stack = local;
    if (3 * depth_ + 8 > 128) {
      heap.resize(3 * static_cast<std::size_t>(depth_) + 8);
      stack = heap.data();
    }
    int top = 0;
    stack[top++] = {0, 0, box_lower_bound(p, root_lo_, root_hi_)};
    while (top > 0) {
      const Entry e = stack[--top];
      if (e.lb > best) continue;
      if (e.count > 0) {
        bound_leaf(e.node, e.count, skip, bound, best, out, bounded);
        continue;
      }
      const QuadNode& node = quads_[static_cast<std::size_t>(e.node)];
      ++nodes;
      double lb[4];
      box_lower_bound4(p, node.lo, node.hi, lb);
      // The children within the bound, farthest first (insertion sort of at most four).
      Entry near[4]{};
      int n = 0;
#pragma GCC unroll 4
      for (int c = 0; c < 4; ++c) {
        if (node.count[c] < 0 || !(lb[c] <= best)) continue;  // an empty lane, or too far
        const Entry x{node.child[c], node.count[c], lb[c]};
        int k = n++;
        while (k > 0 && near[k - 1].lb < x.lb) {
          near[k] = near[k - 1];
          --k;
        }
        near[k] = x;
      }
      // All four slots copied (a fixed size copies inline; the stack has room for them), the
      // first n kept.
      std::copy(near, near + 4, stack + top);
      top += n;
    }
  }
  std::erase_if(out, [best](const Contender& c) { return c.lo > best; });
  if (stats) {
    stats->nodes += nodes;
    stats->items += bounded;
  }
}

template <class Bound>
int SearchTree::within(Vec3 p, double d2_lo, double d2_hi, Bound&& bound,
                       std::vector<Contender>& out) const {
  out.clear();
  if (items_.empty()) return -1;
  auto leaf = [&](std::int32_t first, std::int32_t count) {
    for (std::int32_t k = first; k < first + count; ++k) {
      double lo = 0.0, hi = 0.0;
      bound(k, lo, hi);
      if (hi <= d2_lo) return true;
      if (lo <= d2_hi) out.push_back({items_[static_cast<std::size_t>(k)], lo, hi});
    }
    return false;
  };
  if (quads_.empty()) {
    if (leaf(0, root_count_)) {
      out.clear();
      return 1;
    }
    return out.empty() ? -1 : 0;
  }
  if (box_lower_bound(p, root_lo_, root_hi_) > d2_hi) return -1;
  std::vector<std::int32_t> stack;
  stack.reserve(3 * static_cast<std::size_t>(depth_) + 8);
  stack.push_back(0);
  while (!stack.empty()) {
    const QuadNode& node = quads_[static_cast<std::size_t>(stack.back())];
    stack.pop_back();
    double lb[4];
    box_lower_bound4(p, node.lo, node.hi, lb);
    for (int c = 0; c < 4; ++c) {
      if (node.count[c] < 0 || !(lb[c] <= d2_hi)) continue;  // an empty lane, or too far
      if (node.count[c] == 0) {
        stack.push_back(node.child[c]);
      } else if (leaf(node.child[c], node.count[c])) {
        out.clear();
        return 1;
      }
    }
  }
  return out.empty() ? -1 : 0;
}

}  // namespace contain::distance::detail
