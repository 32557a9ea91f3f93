#include "contain/bvh/bvh.h"

#include <algorithm>
#include <array>
#include <bit>
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
  HugePageVector<std::int32_t>& items;
  HugePageVector<Node>& nodes;
  const BuildOptions& options;
  int bins = 16;
  int depth = 0;
  // Scratch of the SAH sweep, allocated once: the three axes' bins side by side (two sets of
  // them, see fill_bins), empty between nodes (a node resets only the bins it filled: a small node
  // fills few, and resetting all of them at every node cost more than the sweep itself); the bin of
  // each item on each axis at the current node (the partition reads it instead of binning again);
  // the non-empty bins of each axis in ascending order and the sweep's costs of the sides right of
  // them.
  std::vector<Box3> bin_box;
  std::vector<std::int32_t> bin_count;
  std::vector<std::uint8_t> item_bin;
  std::array<std::vector<int>, 3> filled;
  std::vector<double> right_cost;

  Builder(std::span<const Box3> boxes_in, std::vector<Vec3> centroids_in,
          HugePageVector<std::int32_t>& items_out, HugePageVector<Node>& nodes_out,
          const BuildOptions& options_in)
      : boxes(boxes_in),
        centroids(std::move(centroids_in)),
        items(items_out),
        nodes(nodes_out),
        options(options_in),
        bins(std::clamp(options_in.bins, 2, 256)),
        bin_box(6 * static_cast<std::size_t>(bins)),
        bin_count(6 * static_cast<std::size_t>(bins), 0),
        item_bin(3 * boxes_in.size(), 0) {
    for (std::vector<int>& f : filled)
      f.reserve(static_cast<std::size_t>(bins));
    right_cost.reserve(static_cast<std::size_t>(bins));
  }

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
  // centroid instead of three); each axis's bins are what a pass of their own would give. Each
  // item's bins are kept for the partition. Neighbours in `items` mostly fall in one bin, and
  // a bin's box updated by every item was a chain of loads and stores through memory (most of
  // the build's time): items alternate between two sets of bins, merged at the end (min and
  // max are exact, so a bin's box is the same union in another order, up to a zero's sign,
  // and the bins' boxes feed only surface areas). Gathering runs of one bin in a local box
  // was slower: the branch on the bin waits for the division. The filled bins are marked in
  // bit masks rather than found by a scan of every bin.
  void fill_bins(const std::array<Binning, 3>& binning, std::size_t begin, std::size_t end) {
    const std::array<bool, 3> usable = {binning[0].usable(), binning[1].usable(),
                                        binning[2].usable()};
    const auto per_axis = static_cast<std::size_t>(bins);
    const std::size_t spare = 3 * per_axis;  // the second set of bins
    std::array<std::array<std::uint64_t, 4>, 3> mask{};
    // Plain pointers and a copy of the binning: a store of a byte (item_bin) may alias
    // anything, so members read through `this` were loaded again after each one.
    const std::array<Binning, 3> axes = binning;
    const std::int32_t* const order = items.data();
    const Vec3* const centre = centroids.data();
    const Box3* const box_of = boxes.data();
    std::uint8_t* const bin_of_item = item_bin.data();
    std::int32_t* const count = bin_count.data();
    Box3* const bin_boxes = bin_box.data();
    for (std::size_t k = begin; k < end; ++k) {
      const auto item = static_cast<std::size_t>(order[k]);
      const Vec3 c = centre[item];
      const Box3& b = box_of[item];
      const std::size_t set = (k & 1U) != 0 ? spare : 0;
      for (std::size_t axis = 0; axis < 3; ++axis) {
        if (!usable[axis]) continue;
        const auto at =
            static_cast<std::size_t>(axes[axis].bin_of(axis_of(c, static_cast<int>(axis))));
        bin_of_item[3 * item + axis] = static_cast<std::uint8_t>(at);
        mask[axis][at >> 6U] |= std::uint64_t{1} << (at & 63U);
        const std::size_t slot = set + axis * per_axis + at;
        count[slot]++;
        bin_boxes[slot].expand(b);
      }
    }
    for (std::size_t axis = 0; axis < 3; ++axis) {
      filled[axis].clear();
      for (std::size_t word = 0; word < 4; ++word) {
        for (std::uint64_t bits = mask[axis][word]; bits != 0; bits &= bits - 1) {
          const std::size_t bin = 64 * word + static_cast<std::size_t>(std::countr_zero(bits));
          const std::size_t slot = axis * per_axis + bin;
          filled[axis].push_back(static_cast<int>(bin));
          bin_box[slot].expand(bin_box[spare + slot]);
          bin_count[slot] += bin_count[spare + slot];
          bin_box[spare + slot] = Box3{};
          bin_count[spare + slot] = 0;
        }
      }
    }
  }

  // Empties the bins `fill_bins` filled, so that the next node finds them empty.
  void clear_bins() {
    for (std::size_t axis = 0; axis < 3; ++axis) {
      for (const int b : filled[axis]) {
        const std::size_t slot =
            axis * static_cast<std::size_t>(bins) + static_cast<std::size_t>(b);
        bin_box[slot] = Box3{};
        bin_count[slot] = 0;
      }
    }
  }

  // The SAH costs of the bin boundaries of one axis; a cheaper one than `best_cost` replaces it.
  // An empty bin changes neither side's box nor count, so a boundary next to it costs what the
  // boundary at the next non-empty bin costs, which a strict `<` never prefers: only the
  // boundaries between consecutive non-empty bins are costed, in ascending order, and the
  // split is the one a sweep over every bin boundary takes (sah_build_test keeps that sweep and
  // compares the trees).
  void sweep(int axis, double& best_cost, int& best_axis, int& best_split) {
    const std::vector<int>& used = filled[static_cast<std::size_t>(axis)];
    if (used.size() < 2) return;
    const std::size_t base = static_cast<std::size_t>(axis) * static_cast<std::size_t>(bins);
    const auto slot = [&](std::size_t g) { return base + static_cast<std::size_t>(used[g]); };
    right_cost.resize(used.size());
    Box3 acc;
    std::size_t acc_n = 0;
    for (std::size_t g = used.size() - 1; g > 0; --g) {
      acc.expand(bin_box[slot(g)]);
      acc_n += static_cast<std::size_t>(bin_count[slot(g)]);
      right_cost[g] = surface_area(acc) * static_cast<double>(acc_n);
    }
    acc = Box3{};
    acc_n = 0;
    for (std::size_t g = 0; g + 1 < used.size(); ++g) {
      acc.expand(bin_box[slot(g)]);
      acc_n += static_cast<std::size_t>(bin_count[slot(g)]);
      const double cost = surface_area(acc) * static_cast<double>(acc_n) + right_cost[g + 1];
      if (cost < best_cost) {
        best_cost = cost;
        best_axis = axis;
        best_split = used[g] + 1;
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
    double best_cost = std::numeric_limits<double>::infinity();
    int best_axis = -1, best_split = 0;
    const double parent_area = surface_area(box);
    const std::array<Binning, 3> binning = {Binning(cbox.min.x, cbox.max.x, bins),
                                            Binning(cbox.min.y, cbox.max.y, bins),
                                            Binning(cbox.min.z, cbox.max.z, bins)};
    fill_bins(binning, begin, end);
    for (int axis = 0; axis < 3; ++axis)
      sweep(axis, best_cost, best_axis, best_split);
    clear_bins();
    std::size_t mid = begin;
    if (best_axis >= 0) {
      const double split_cost = options.node_cost + (parent_area > 0.0 ? best_cost / parent_area
                                                                       : static_cast<double>(n)) *
                                                        options.item_cost;
      if (n <= max_leaf && split_cost >= static_cast<double>(n) * options.item_cost) {
        make_leaf(node, begin, end);
        return;
      }
      const auto axis = static_cast<std::size_t>(best_axis);
      const auto it =
          std::partition(items.begin() + static_cast<std::ptrdiff_t>(begin),
                         items.begin() + static_cast<std::ptrdiff_t>(end), [&](std::int32_t i) {
                           return item_bin[3 * static_cast<std::size_t>(i) + axis] < best_split;
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
    build_morton(
        boxes.size(),
        [](const void* context, std::size_t i) { return static_cast<const Box3*>(context)[i]; },
        boxes.data(), options.max_leaf_items);
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
  Builder builder(boxes, std::move(centroids), items_, nodes_, options);
  builder.build(0, 0, items_.size(), 1);
  depth_ = builder.depth;
}

}  // namespace contain::bvh
