// The linear build of `Bvh` (BuildMethod::morton): items sorted by the Morton codes of their
// box centroids, nodes split where the codes' highest differing bit changes (Lauterbach et al.
// 2009, "Fast BVH Construction on GPUs"; Karras 2012). A node costs a binary search, not a
// sweep of its items, so the build is a radix sort and a pass to gather the boxes: a few
// times faster than the SAH's, the tree somewhat looser. Deterministic: ties of codes keep the
// items' order (the sort is stable) and are split at the middle.

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/core/huge_pages.h"
#include "contain/core/radix_sort.h"

namespace contain::bvh {
namespace {

constexpr int kBitsPerAxis = 21;

// The low 21 bits of x spread to every third bit.
std::uint64_t spread(std::uint64_t x) {
  x &= 0x1fffffU;
  x = (x | x << 32U) & 0x1f00000000ffffULL;
  x = (x | x << 16U) & 0x1f0000ff0000ffULL;
  x = (x | x << 8U) & 0x100f00f00f00f00fULL;
  x = (x | x << 4U) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2U) & 0x1249249249249249ULL;
  return x;
}

// 2^21 cells over [lo, hi], on halved values as the SAH's bins (a span beyond DBL_MAX does not
// overflow; a subnormal one gives an infinite scale, whose NaN and infinite products are
// clamped: the cells only steer the tree).
struct Grid {
  double lo_half = 0.0, scale = 0.0;
  Grid(double lo, double hi) : lo_half(lo * 0.5) {
    const double span_half = hi * 0.5 - lo * 0.5;
    if (span_half > 0.0 && span_half < std::numeric_limits<double>::infinity())
      scale = static_cast<double>(1U << kBitsPerAxis) / span_half;
  }
  [[nodiscard]] std::uint64_t cell(double c) const {
    constexpr double last = static_cast<double>((1U << kBitsPerAxis) - 1);
    const double f = (c * 0.5 - lo_half) * scale;
    return f >= 0.0 ? static_cast<std::uint64_t>(std::min(f, last)) : 0;  // NaN -> 0
  }
};

// An empty box has no centroid; any finite point keeps the codes finite.
Vec3 centroid_of(const Box3& b) {
  return b.empty() ? Vec3{} : 0.5 * b.min + 0.5 * b.max;
}

struct MortonBuilder {
  Box3 (*box_of)(const void*, std::size_t);
  const void* context;
  const HugePageVector<std::uint64_t>& codes;
  const HugePageVector<std::int32_t>& items;
  HugePageVector<Node>& nodes;
  std::size_t max_leaf = 4;
  int depth = 0;

  // Builds node `node` over sorted positions [begin, end); returns its box.
  Box3 build(std::size_t node, std::size_t begin, std::size_t end, int level) {
    depth = std::max(depth, level);
    Box3 box;
    if (end - begin <= max_leaf) {
      for (std::size_t k = begin; k < end; ++k)
        box.expand(box_of(context, static_cast<std::size_t>(items[k])));
      nodes[node].box = box;
      nodes[node].first = static_cast<std::int32_t>(begin);
      nodes[node].count = static_cast<std::int32_t>(end - begin);
      return box;
    }
    std::size_t mid = begin + (end - begin) / 2;
    const std::uint64_t differ = codes[begin] ^ codes[end - 1];
    if (differ != 0) {
      // Every code of the range has the bits above `bit` in common: those with `bit` clear
      // come first.
      const std::uint64_t bit = std::uint64_t{1} << (63 - std::countl_zero(differ));
      mid = static_cast<std::size_t>(
          std::partition_point(codes.begin() + static_cast<std::ptrdiff_t>(begin),
                               codes.begin() + static_cast<std::ptrdiff_t>(end),
                               [&](std::uint64_t c) { return (c & bit) == 0; }) -
          codes.begin());
    }
    nodes.emplace_back();
    box = build(node + 1, begin, mid, level + 1);
    const std::size_t right = nodes.size();
    nodes.emplace_back();
    box.expand(build(right, mid, end, level + 1));
    nodes[node].box = box;
    nodes[node].first = static_cast<std::int32_t>(right);
    nodes[node].count = 0;
    return box;
  }
};

}  // namespace

void Bvh::build_morton(std::size_t n, BoxSource box_of, const void* context, int max_leaf_items) {
  // The centroids are computed twice (for their bounds, then for the codes) rather than kept:
  // an array of 24 bytes an item, written once and read once, was a third of the build's fresh
  // pages, and a page fault costs more than the few additions.
  Box3 cbox;
  for (std::size_t i = 0; i < n; ++i)
    cbox.expand(centroid_of(box_of(context, i)));
  const Grid gx(cbox.min.x, cbox.max.x), gy(cbox.min.y, cbox.max.y), gz(cbox.min.z, cbox.max.z);
  // Huge pages where granted, for these and the sort's scratch arrays (which take these
  // allocators, default-initialized: every element is written before it is read).
  HugePageVector<std::uint64_t> codes(n);
  items_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 c = centroid_of(box_of(context, i));
    codes[i] = spread(gx.cell(c.x)) << 2U | spread(gy.cell(c.y)) << 1U | spread(gz.cell(c.z));
    items_[i] = static_cast<std::int32_t>(i);
  }
  stable_radix_sort(codes, items_, 3 * kBitsPerAxis);
  nodes_.reserve(2 * n);
  nodes_.emplace_back();
  MortonBuilder builder{box_of, context, codes,
                        items_, nodes_,  static_cast<std::size_t>(std::max(max_leaf_items, 1))};
  (void)builder.build(0, 0, n, 1);
  depth_ = builder.depth;
}

}  // namespace contain::bvh
