#include "contain/bvh/bvh.h"

#include <algorithm>
#include <array>
#include <limits>

// Outline: top-down build over index ranges of `items_`. For each range: the bounds and the
// centroid bounds; a leaf if small and the SAH says so; else, per axis, the centroids are put in
// `bins` equal bins, prefix and suffix boxes give the cost of every bin boundary, and the range
// is partitioned at the cheapest one. Coinciding centroids (or a split that leaves one side
// empty) fall back to a split by count at the median, so the depth stays logarithmic.

namespace contain::bvh {

namespace {

struct Builder {
  std::span<const Box3> boxes;
  std::vector<Vec3> centroids;
  std::vector<std::int32_t>& items;
  std::vector<Node>& nodes;
  const BuildOptions& options;
  int depth = 0;
  // Scratch of the SAH sweep, sized by the bins in use (three axes' bins side by side) and reset
  // per node: arrays of the largest bin count (256 boxes, counts and costs, 16 KiB) constructed
  // afresh at every node and axis cost more than the sweep itself (half of a self-intersection
  // check's time).
  std::vector<Box3> bin_box;
  std::vector<std::size_t> bin_count;
  std::vector<double> right_cost;

  Vec3 centroid(std::int32_t i) const { return centroids[static_cast<std::size_t>(i)]; }

  static double axis_of(Vec3 v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }

  // Equal bins over [lo, hi] on halved values: hi - lo overflows for coordinates near DBL_MAX
  // and bins / (hi - lo) for a subnormal span, and either made an infinite or NaN bin index
  // (undefined behaviour in the conversion to int; found by fuzz_point_in_mesh). The bins only
  // steer the SAH, so halving's rounding among subnormals does no harm.
  struct Binning {
    double lo_half, span_half, bins;
    Binning(double lo, double hi, int n)
        : lo_half(lo * 0.5), span_half(hi * 0.5 - lo * 0.5), bins(n) {}
    [[nodiscard]] bool usable() const { return span_half > 0.0 && span_half < kInfinity; }
    [[nodiscard]] int bin_of(double c) const {
      const double f = (c * 0.5 - lo_half) / span_half * bins;
      return f >= 0.0 ? static_cast<int>(std::min(f, bins - 1.0)) : 0;  // NaN -> 0
    }
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
  };

  void make_leaf(std::size_t node, std::size_t begin, std::size_t end) {
    nodes[node].first = static_cast<std::int32_t>(begin);
    nodes[node].count = static_cast<std::int32_t>(end - begin);
  }

  // The bins of every usable axis in one pass over the range (one load of each item's box and
  // centroid instead of three); each axis's bins are what a pass of their own would give.
  void fill_bins(const std::array<Binning, 3>& binning, std::size_t begin, std::size_t end,
                 int bins) {
    const auto total = static_cast<std::size_t>(3 * bins);
    bin_box.assign(total, Box3{});
    bin_count.assign(total, 0);
    const std::array<bool, 3> usable = {binning[0].usable(), binning[1].usable(),
                                        binning[2].usable()};
    for (std::size_t k = begin; k < end; ++k) {
      const Vec3 c = centroid(items[k]);
      const Box3& b = boxes[static_cast<std::size_t>(items[k])];
      for (std::size_t axis = 0; axis < 3; ++axis) {
        if (!usable[axis]) continue;
        const auto slot =
            axis * static_cast<std::size_t>(bins) +
            static_cast<std::size_t>(binning[axis].bin_of(axis_of(c, static_cast<int>(axis))));
        bin_count[slot]++;
        bin_box[slot].expand(b);
      }
    }
  }

  // The SAH costs of the bin boundaries of one axis; a cheaper one than `best_cost` replaces it.
  // An empty bin changes neither side's box nor count, so its costs are those of the bin before
  // it (right: after it), which a strict `<` never prefers: empty bins are skipped (small ranges
  // fill few of them), and the tree is the one the full sweep builds.
  void sweep(int axis, int bins, std::size_t n, double& best_cost, int& best_axis,
             int& best_split) {
    const std::size_t base = static_cast<std::size_t>(axis) * static_cast<std::size_t>(bins);
    right_cost.assign(static_cast<std::size_t>(bins), 0.0);
    Box3 acc;
    std::size_t acc_n = 0;
    for (int b = bins - 1; b > 0; --b) {
      if (bin_count[base + static_cast<std::size_t>(b)] == 0 && b + 1 < bins) {
        right_cost[static_cast<std::size_t>(b)] = right_cost[static_cast<std::size_t>(b) + 1];
        continue;
      }
      acc.expand(bin_box[base + static_cast<std::size_t>(b)]);
      acc_n += bin_count[base + static_cast<std::size_t>(b)];
      right_cost[static_cast<std::size_t>(b)] = surface_area(acc) * static_cast<double>(acc_n);
    }
    acc = Box3{};
    acc_n = 0;
    for (int b = 0; b + 1 < bins; ++b) {
      if (bin_count[base + static_cast<std::size_t>(b)] == 0) continue;
      acc.expand(bin_box[base + static_cast<std::size_t>(b)]);
      acc_n += bin_count[base + static_cast<std::size_t>(b)];
      if (acc_n == 0 || acc_n == n) continue;
      const double cost = surface_area(acc) * static_cast<double>(acc_n) +
                          right_cost[static_cast<std::size_t>(b) + 1];
      if (cost < best_cost) {
        best_cost = cost;
        best_axis = axis;
        best_split = b + 1;
      }
    }
  }

  void build(std::size_t node, std::size_t begin, std::size_t end, int level) {
    depth = std::max(depth, level);
    Box3 box, cbox;
    for (std::size_t k = begin; k < end; ++k) {
      box.expand(boxes[static_cast<std::size_t>(items[k])]);
      cbox.expand(centroid(items[k]));
    }
    nodes[node].box = box;
    const std::size_t n = end - begin;
    const auto max_leaf = static_cast<std::size_t>(std::max(options.max_leaf_items, 1));
    if (n <= 1) {
      make_leaf(node, begin, end);
      return;
    }
    const int bins = std::clamp(options.bins, 2, 256);
    double best_cost = std::numeric_limits<double>::infinity();
    int best_axis = -1, best_split = 0;
    const double parent_area = surface_area(box);
    const std::array<Binning, 3> binning = {Binning(cbox.min.x, cbox.max.x, bins),
                                            Binning(cbox.min.y, cbox.max.y, bins),
                                            Binning(cbox.min.z, cbox.max.z, bins)};
    fill_bins(binning, begin, end, bins);
    for (int axis = 0; axis < 3; ++axis) {
      if (!binning[static_cast<std::size_t>(axis)].usable()) continue;
      sweep(axis, bins, n, best_cost, best_axis, best_split);
    }
    std::size_t mid = begin;
    if (best_axis >= 0) {
      const double split_cost = options.node_cost + (parent_area > 0.0 ? best_cost / parent_area
                                                                       : static_cast<double>(n)) *
                                                        options.item_cost;
      if (n <= max_leaf && split_cost >= static_cast<double>(n) * options.item_cost) {
        make_leaf(node, begin, end);
        return;
      }
      const Binning& split = binning[static_cast<std::size_t>(best_axis)];
      const auto it =
          std::partition(items.begin() + static_cast<std::ptrdiff_t>(begin),
                         items.begin() + static_cast<std::ptrdiff_t>(end), [&](std::int32_t i) {
                           return split.bin_of(axis_of(centroid(i), best_axis)) < best_split;
                         });
      mid = static_cast<std::size_t>(it - items.begin());
    }
    if (mid == begin || mid == end) {
      if (n <= max_leaf) {
        make_leaf(node, begin, end);
        return;
      }
      mid = begin + n / 2;  // coinciding centroids: split by count (order is deterministic)
    }
    const std::size_t left = node + 1;
    nodes.emplace_back();
    build(left, begin, mid, level + 1);
    const std::size_t right = nodes.size();
    nodes.emplace_back();
    nodes[node].first = static_cast<std::int32_t>(right);
    nodes[node].count = 0;
    build(right, mid, end, level + 1);
  }
};

}  // namespace

Bvh::Bvh(std::span<const Box3> boxes, const BuildOptions& options) {
  if (boxes.empty()) return;
  if (options.method == BuildMethod::morton) {
    build_morton(boxes, options);
    return;
  }
  items_.resize(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i)
    items_[i] = static_cast<std::int32_t>(i);
  std::vector<Vec3> centroids(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Box3& b = boxes[i];
    // An empty box has no centroid; any finite point keeps the binning finite.
    centroids[i] = b.empty() ? Vec3{} : 0.5 * b.min + 0.5 * b.max;
  }
  nodes_.reserve(2 * boxes.size());
  nodes_.emplace_back();
  Builder builder{boxes, std::move(centroids), items_, nodes_, options};
  builder.build(0, 0, items_.size(), 1);
  depth_ = builder.depth;
}

}  // namespace contain::bvh
