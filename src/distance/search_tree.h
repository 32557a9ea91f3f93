#pragma once
// Private to contain::distance: the nearest-item search shared by triangles (3D) and segments
// (2D, on the plane z = 0), over a BVH of the items' boxes.
//
// The tree has four children a node (the binary BVH collapsed: a node takes its grandchildren in
// place of its children), so that a step of the descent bounds four boxes at once and a search
// takes half the steps.
//
// Each child is bounded by an oriented box in floats: the principal axes of its items' corners
// and the corners' extent along them. Around a curved surface patch it is as thin as the patch
// is curved, where an axis-aligned box is as thick as the patch is wide: a point's ball meets far
// fewer of them (on a 100k-triangle torus, 15 triangles bounded a query instead of 130). The
// four children's bounds are computed together in float lanes, with a margin that covers every
// rounding (oriented_lower_bound4).
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
#include "contain/predicates/unit_roundoff.h"
#include "contain/values/box.h"
#include "contain/values/max_abs.h"
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
  constexpr double kEps = predicates::unit_roundoff<double>;
  const double dx =
      std::max(std::max(static_cast<double>(lo[0]) - p.x, p.x - static_cast<double>(hi[0])), 0.0);
  const double dy =
      std::max(std::max(static_cast<double>(lo[1]) - p.y, p.y - static_cast<double>(hi[1])), 0.0);
  const double dz =
      std::max(std::max(static_cast<double>(lo[2]) - p.z, p.z - static_cast<double>(hi[2])), 0.0);
  return ((dx * dx + dy * dy) + dz * dz) * (1 - 8 * kEps);
}

/// Four float lanes, one per child of a node (SSE on x86-64, NEON on arm64, plain code
/// elsewhere).
using Float4 = float __attribute__((vector_size(16)));

/// Four oriented boxes, lane c the set of points x with
///   lo[a][c] <= u_a . (x - o) <= hi[a][c]   for the axes a = 0, 1, 2,
/// u_a = (axis[a][0][c], axis[a][1][c], axis[a][2][c]) exact floats with |u_a|_1 <= 1.75 and o the
/// tree's origin (doubles); k[c] <= 1 / lambda_max(U U^T), U the matrix with rows u_a. The build
/// proves that every item below the lane lies in it.
struct OrientedLanes {
  float axis[3][3][4];
  float lo[3][4];
  float hi[3][4];
  float k[4];
};

/// A query point in a tree's frame: p - o rounded to floats, and the margin m that covers its
/// rounding and that of each lane's dot product (oriented_lower_bound4).
struct LanePoint {
  Float4 x, y, z, m;
};

/// The LanePoint of p for a tree of origin o. With d = p - o in doubles (within eps |d_i| of the
/// exact difference) and P = max |d_i|, the floats f_i = fl(d_i) are within
/// (2^-24 + 2^-52) P + 2^-150 of the exact p_i - o_i; a lane's dot product of f with u (floats,
/// |u|_1 <= 1.75) is within gamma_3 |u|_1 max |f_i| <= 5.3 2^-24 P (plus 3 2^-150 for products that
/// underflow) of u . f, and u . f within 1.75 ((2^-24 + 2^-52) P + 2^-150) of u . (p - o): in all
/// below m = 16 2^-24 P + 2^-140, with room for the roundings of the bound itself. Beyond 2^100
/// (or for infinite d) m is +inf and every lane's bound 0.
[[nodiscard]] inline LanePoint lane_point(Vec3 p, Vec3 o) {
  const Vec3 d = p - o;
  const double big = max_abs(d);
  constexpr float kInf = std::numeric_limits<float>::infinity();
  if (!(big <= 0x1p100)) return {Float4{}, Float4{}, Float4{}, Float4{kInf, kInf, kInf, kInf}};
  // m in floats, rounded up: the product by a power of two is exact, the sum and the conversion
  // round once each, by less than the factor.
  const auto m =
      static_cast<float>((16 * predicates::unit_roundoff<float> * big + 0x1p-140) * (1 + 0x1p-20));
  const auto x = static_cast<float>(d.x), y = static_cast<float>(d.y), z = static_cast<float>(d.z);
  return {Float4{x, x, x, x}, Float4{y, y, y, y}, Float4{z, z, z, z}, Float4{m, m, m, m}};
}

/// Lower bounds of the squared distance from the point to the four lanes' boxes. For x in the
/// box and y = p - x, sum_a (u_a . y)^2 = |U y|^2 <= lambda_max |y|^2, and |u_a . y| >= g_a, the
/// distance of u_a . (p - o) outside [lo_a, hi_a]; so |y|^2 >= k sum_a g_a^2. Each g_a as
/// computed, times (1 - 4 u), less m (lane_point) is below the exact one (u = 2^-24: the two
/// subtractions and the product round once each); it is clamped into [0, 2^60] (NaN: 0), so
/// the squares neither overflow nor, once the sum is at least 2^-100, lose more to underflow than
/// the factor (1 - 8 u) leaves room for after the five roundings of the sum and products.
inline void oriented_lower_bound4(const LanePoint& q, const OrientedLanes& lanes, double out[4]) {
  constexpr float kU = predicates::unit_roundoff<float>;
  auto load = [](const float v[4]) {
    Float4 r;
    __builtin_memcpy(&r, v, sizeof r);
    return r;
  };
  const Float4 zero{};
  const Float4 cap{0x1p60f, 0x1p60f, 0x1p60f, 0x1p60f};
  Float4 sum{};
#pragma GCC unroll 3
  for (int a = 0; a < 3; ++a) {
    const Float4 t = (q.x * load(lanes.axis[a][0]) + q.y * load(lanes.axis[a][1])) +
                     q.z * load(lanes.axis[a][2]);
    const Float4 below = load(lanes.lo[a]) - t, above = t - load(lanes.hi[a]);
    const Float4 g = (below > above ? below : above) * (1 - 4 * kU) - q.m;
    const Float4 clamped = g > zero ? (g < cap ? g : cap) : zero;
    sum = a == 0 ? clamped * clamped : sum + clamped * clamped;
  }
  const Float4 b = sum * load(lanes.k) * (1 - 8 * kU);
  const Float4 lb = sum >= Float4{0x1p-100f, 0x1p-100f, 0x1p-100f, 0x1p-100f} ? b : zero;
#pragma GCC unroll 4
  for (int c = 0; c < 4; ++c)
    out[c] = static_cast<double>(lb[c]);
}

class SearchTree {
 public:
  SearchTree() = default;
  /// Items numbered 0..n-1, item i the convex hull of corners[i * per_item, (i + 1) * per_item)
  /// (finite).
  SearchTree(std::span<const Vec3> corners, int per_item, const bvh::BuildOptions& options);

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

  /// For the tests: every lane of every node, with its bound for p (oriented_lower_bound4) and
  /// the positions [first, end) of the items below it in leaf order.
  struct LaneBound {
    double bound;
    std::int32_t first;
    std::int32_t end;
  };
  [[nodiscard]] std::vector<LaneBound> lane_bounds(Vec3 p) const;

  /// Three-valued "some item within squared distance d2" from the bounds: +1 proven (some hi <=
  /// d2_lo), -1 disproven (every lo > d2_hi), 0 undecided; the undecided items go to `out`.
  template <class Bound>
  [[nodiscard]] int within(Vec3 p, double d2_lo, double d2_hi, Bound&& bound,
                           std::vector<Contender>& out) const;

 private:
  // A node holding its (up to) four children's oriented boxes.
  struct QuadNode {
    OrientedLanes box;
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
  Vec3 origin_{};                       // the oriented boxes' origin: the centre of the root's box
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
    const LanePoint q = lane_point(p, origin_);
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
      oriented_lower_bound4(q, node.box, lb);
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
  const LanePoint q = lane_point(p, origin_);
  std::vector<std::int32_t> stack;
  stack.reserve(3 * static_cast<std::size_t>(depth_) + 8);
  stack.push_back(0);
  while (!stack.empty()) {
    const QuadNode& node = quads_[static_cast<std::size_t>(stack.back())];
    stack.pop_back();
    double lb[4];
    oriented_lower_bound4(q, node.box, lb);
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
