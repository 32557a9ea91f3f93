#pragma once
// Monotone chains for the first noding round (rule clip-noding-chains in docs/robustness.md).
// Private to the polygon booleans.

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "clip/boolean/noding.h"

namespace contain::clip::detail {

// Maximal runs of linked segments monotone in x and in y (each coordinate never decreases, or
// never increases, along the run; Guibas and Stolfi's monotone chains as GEOS uses them). A
// segment lies in the box of its endpoints, and those boxes follow each other along a chain
// meeting only at the joints, so two segments of one chain meet at most at the joint of
// consecutive ones: the first round tests only pairs from different chains (rule
// clip-noding-chains in docs/robustness.md). The box of the points i .. j of a chain is the box
// of points i and j, which prunes a pair of chains by bisection.
struct Chain {
  std::uint32_t first, last;  // segments first .. last - 1; points 0 .. last - first
  double xmin, xmax, ymin, ymax;
};

[[nodiscard]] std::vector<Chain> monotone_chains(std::span<const NodingInput> segments,
                                                 std::span<const char> links);

// Calls test(segment i, segment j) for every pair of segments of different chains whose boxes
// overlap: chains by a sweep over their x intervals, segments of a chain pair by bisection of
// both chains while the boxes of their parts overlap.
template <class Test>
void chain_pairs(std::span<const NodingInput> segments, const std::vector<Chain>& chains,
                 Test&& test) {
  // Point i of the chain starting at segment f.
  auto point = [&](std::uint32_t f, std::uint32_t i) {
    return i == 0 ? segments[f].a : segments[f + i - 1].b;
  };
  auto disjoint = [](Vec2 a0, Vec2 a1, Vec2 b0, Vec2 b1) {
    return std::max(a0.x, a1.x) < std::min(b0.x, b1.x) ||
           std::max(b0.x, b1.x) < std::min(a0.x, a1.x) ||
           std::max(a0.y, a1.y) < std::min(b0.y, b1.y) ||
           std::max(b0.y, b1.y) < std::min(a0.y, a1.y);
  };
  struct Task {
    std::uint32_t i0, i1, j0, j1;  // point ranges of the two chains
  };
  std::vector<Task> stack;
  auto overlap = [&](const Chain& c, const Chain& d) {
    stack.clear();
    stack.push_back({0, c.last - c.first, 0, d.last - d.first});
    while (!stack.empty()) {
      const Task t = stack.back();
      stack.pop_back();
      if (disjoint(point(c.first, t.i0), point(c.first, t.i1), point(d.first, t.j0),
                   point(d.first, t.j1)))
        continue;
      const std::uint32_t ni = t.i1 - t.i0, nj = t.j1 - t.j0;
      if (ni == 1 && nj == 1) {
        test(c.first + t.i0, d.first + t.j0);
        continue;
      }
      if (ni >= nj) {
        const std::uint32_t m = t.i0 + ni / 2;
        stack.push_back({m, t.i1, t.j0, t.j1});
        stack.push_back({t.i0, m, t.j0, t.j1});
      } else {
        const std::uint32_t m = t.j0 + nj / 2;
        stack.push_back({t.i0, t.i1, m, t.j1});
        stack.push_back({t.i0, t.i1, t.j0, m});
      }
    }
  };
  std::vector<std::uint32_t> order(chains.size());
  for (std::uint32_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t l, std::uint32_t r) {
    return chains[l].xmin < chains[r].xmin || (chains[l].xmin == chains[r].xmin && l < r);
  });
  std::vector<std::uint32_t> active;
  for (const std::uint32_t ci : order) {
    const Chain& c = chains[ci];
    std::size_t m = 0;
    for (const std::uint32_t di : active) {
      const Chain& d = chains[di];
      if (d.xmax < c.xmin) continue;
      active[m++] = di;
      if (d.ymax < c.ymin || c.ymax < d.ymin) continue;
      overlap(c, d);
    }
    active.resize(m);
    active.push_back(ci);
  }
}

}  // namespace contain::clip::detail
