// The SAH build's sweep over the non-empty bins only (src/bvh/bvh.cpp) builds the tree the
// sweep over every bin boundary built before it: same nodes, same boxes, same item order. The
// older build is kept here as the reference; the mesh boolean's written meshes depend on the
// tree's item order (it numbers the crossing points), so "as good a tree" would not do.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/bvh/triangle_boxes.h"
#include "scenes/scenes.h"

namespace contain::bvh {
namespace {

// The SAH build as it was before the sweep over the non-empty bins only (commit ec8459d),
// verbatim but for names: every bin reset at every node, every bin scanned by the sweep, the
// partition binning each centroid again.
struct ReferenceSahBuild {
  std::span<const Box3> boxes;
  std::vector<Vec3> centroids;
  const BuildOptions& options;
  std::vector<std::int32_t> items;
  std::vector<Node> nodes;
  std::vector<Box3> bin_box;
  std::vector<std::size_t> bin_count;
  std::vector<double> right_cost;

  static double axis_of(Vec3 v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }

  struct Binning {
    double lo_half, span_half, bins;
    Binning(double lo, double hi, int n)
        : lo_half(lo * 0.5), span_half(hi * 0.5 - lo * 0.5), bins(n) {}
    [[nodiscard]] bool usable() const {
      return span_half > 0.0 && span_half < std::numeric_limits<double>::infinity();
    }
    [[nodiscard]] int bin_of(double c) const {
      const double f = (c * 0.5 - lo_half) / span_half * bins;
      return f >= 0.0 ? static_cast<int>(std::min(f, bins - 1.0)) : 0;
    }
  };

  ReferenceSahBuild(std::span<const Box3> boxes_in, const BuildOptions& options_in)
      : boxes(boxes_in), options(options_in) {
    if (boxes.empty()) return;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      items.push_back(static_cast<std::int32_t>(i));
      centroids.push_back(boxes[i].empty() ? Vec3{} : 0.5 * boxes[i].min + 0.5 * boxes[i].max);
    }
    nodes.emplace_back();
    build(0, 0, items.size());
  }

  void make_leaf(std::size_t node, std::size_t begin, std::size_t end) {
    nodes[node].first = static_cast<std::int32_t>(begin);
    nodes[node].count = static_cast<std::int32_t>(end - begin);
  }

  void fill_bins(const std::array<Binning, 3>& binning, std::size_t begin, std::size_t end,
                 int bins) {
    const auto total = static_cast<std::size_t>(3 * bins);
    bin_box.assign(total, Box3{});
    bin_count.assign(total, 0);
    for (std::size_t k = begin; k < end; ++k) {
      const Vec3 c = centroids[static_cast<std::size_t>(items[k])];
      const Box3& b = boxes[static_cast<std::size_t>(items[k])];
      for (std::size_t axis = 0; axis < 3; ++axis) {
        if (!binning[axis].usable()) continue;
        const auto slot =
            axis * static_cast<std::size_t>(bins) +
            static_cast<std::size_t>(binning[axis].bin_of(axis_of(c, static_cast<int>(axis))));
        bin_count[slot]++;
        bin_box[slot].expand(b);
      }
    }
  }

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

  void build(std::size_t node, std::size_t begin, std::size_t end) {
    Box3 box, cbox;
    for (std::size_t k = begin; k < end; ++k) {
      box.expand(boxes[static_cast<std::size_t>(items[k])]);
      cbox.expand(centroids[static_cast<std::size_t>(items[k])]);
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
      const auto it = std::partition(
          items.begin() + static_cast<std::ptrdiff_t>(begin),
          items.begin() + static_cast<std::ptrdiff_t>(end), [&](std::int32_t i) {
            return split.bin_of(axis_of(centroids[static_cast<std::size_t>(i)], best_axis)) <
                   best_split;
          });
      mid = static_cast<std::size_t>(it - items.begin());
    }
    if (mid == begin || mid == end) {
      if (n <= max_leaf) {
        make_leaf(node, begin, end);
        return;
      }
      mid = begin + n / 2;
    }
    const std::size_t left = node + 1;
    nodes.emplace_back();
    build(left, begin, mid);
    const std::size_t right = nodes.size();
    nodes.emplace_back();
    nodes[node].first = static_cast<std::int32_t>(right);
    nodes[node].count = 0;
    build(right, mid, end);
  }
};

// Bitwise: the boxes' doubles, the nodes' links and counts, the items' order.
void expect_same_tree(std::span<const Box3> boxes, const BuildOptions& options) {
  const Bvh tree(boxes, options);
  const ReferenceSahBuild reference(boxes, options);
  ASSERT_EQ(tree.nodes().size(), reference.nodes.size());
  for (std::size_t i = 0; i < reference.nodes.size(); ++i) {
    const Node& a = tree.nodes()[i];
    const Node& b = reference.nodes[i];
    ASSERT_EQ(a.first, b.first) << "node " << i;
    ASSERT_EQ(a.count, b.count) << "node " << i;
    const std::array<double, 6> ca = {a.box.min.x, a.box.min.y, a.box.min.z,
                                      a.box.max.x, a.box.max.y, a.box.max.z};
    const std::array<double, 6> cb = {b.box.min.x, b.box.min.y, b.box.min.z,
                                      b.box.max.x, b.box.max.y, b.box.max.z};
    ASSERT_EQ(0, std::memcmp(ca.data(), cb.data(), sizeof ca)) << "node " << i;
  }
  ASSERT_TRUE(std::equal(tree.items().begin(), tree.items().end(), reference.items.begin(),
                         reference.items.end()));
}

std::vector<Box3> scattered_boxes(std::size_t n, unsigned seed, double size, int grid) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), s(0.0, size);
  std::uniform_int_distribution<int> g(0, grid);
  std::vector<Box3> boxes(n);
  for (Box3& b : boxes) {
    // On a coarse grid when `grid` > 0: coinciding and flat centroids, empty bins.
    const Vec3 p =
        grid > 0 ? Vec3{g(rng) * 0.25, g(rng) * 0.25, g(rng) * 0.25} : Vec3{u(rng), u(rng), u(rng)};
    b.min = p;
    b.max = p + Vec3{s(rng), s(rng), s(rng)};
  }
  return boxes;
}

TEST(SahBuild, SweepOverNonEmptyBinsBuildsTheTreeOfTheFullSweepOnRandomBoxes) {
  unsigned seed = 1;
  for (const std::size_t n : {2U, 3U, 5U, 17U, 100U, 1000U, 2500U}) {
    for (const int grid : {0, 1, 3, 40}) {
      for (const double size : {0.0, 0.01, 0.5}) {
        const std::vector<Box3> boxes = scattered_boxes(n, seed++, size, grid);
        for (const BuildOptions options :
             {BuildOptions{}, BuildOptions{.bins = 2}, BuildOptions{.bins = 7, .max_leaf_items = 1},
              BuildOptions{.bins = 256, .max_leaf_items = 8},
              BuildOptions{.bins = 32, .max_leaf_items = 2, .node_cost = 0.3, .item_cost = 2.0}})
          expect_same_tree(boxes, options);
      }
    }
  }
}

TEST(SahBuild, SweepOverNonEmptyBinsBuildsTheTreeOfTheFullSweepOnMeshesAndEmptyBoxes) {
  const Mesh sphere = scenes::uv_sphere({0.1, -0.2, 0.3}, 1.0, 48, 96);
  std::vector<Box3> boxes = triangle_boxes(sphere);
  expect_same_tree(boxes, {});
  // Degenerate triangles' empty boxes (the mesh boolean's soup), extreme and tiny spans.
  for (std::size_t i = 0; i < boxes.size(); i += 7)
    boxes[i] = Box3{};
  expect_same_tree(boxes, {});
  const double big = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  std::vector<Box3> extreme = {{{-big, 0, 0}, {-big, 0, 0}}, {{big, 1, 0}, {big, 1, 0}},
                               {{0, 2, 0}, {0, 2, 0}},       {{tiny, 3, 0}, {tiny, 3, 0}},
                               {{0, 0, tiny}, {0, 0, tiny}}, {{-tiny, 0, 0}, {0, 0, 0}}};
  expect_same_tree(extreme, {.max_leaf_items = 1});
}

}  // namespace
}  // namespace contain::bvh
