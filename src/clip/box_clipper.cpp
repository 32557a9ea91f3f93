// A region prepared for many boxes: per ring, a balanced tree of the boxes of its edge ranges
// (leaves of 16 edges, heap order). A box reads the leaves it overlaps (every edge that is not
// strictly outside one side is in such a leaf, so the cut sees the same edges in the same order
// as clip_polygon's scan), and the parity of the ray from its centre reads only the nodes that
// straddle the ray's line right of the centre.

#include "contain/clip/box_clipper.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <thread>
#include <vector>

#include "clip/box_cut.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/ring_orientation.h"

namespace contain::clip {
namespace {

constexpr std::size_t kLeaf = 16;  // edges per leaf

BoxClipper::RingIndex build_index(const Ring& ring) {
  BoxClipper::RingIndex index;
  const std::size_t n = ring.size();
  if (n < 3) return index;
  index.leaves = (n + kLeaf - 1) / kLeaf;
  std::size_t first = 1;
  while (first < index.leaves)
    first *= 2;
  index.first_leaf = first;
  index.nodes.assign(2 * first, Box2{});
  for (std::size_t k = 0; k < index.leaves; ++k) {
    Box2& b = index.nodes[first + k];
    const std::size_t end = std::min(n, (k + 1) * kLeaf);
    for (std::size_t i = k * kLeaf; i <= end; ++i)
      b.expand(ring[i < n ? i : 0]);
  }
  for (std::size_t v = first; v-- > 1;) {
    index.nodes[v] = index.nodes[2 * v];
    index.nodes[v].expand(index.nodes[2 * v + 1]);
  }
  index.orientation = predicates::ring_orientation(ring);
  return index;
}

// The edges of the leaves that overlap the box and are not strictly outside one side, in ring
// order (a depth-first walk from the left).
// Calls leaf(first, end) for the edge ranges of the leaves whose box `wanted` accepts (any node
// whose box it rejects is skipped with its subtree), from the left: in ring order.
template <class Wanted, class Leaf>
void visit_leaves(std::size_t n, const BoxClipper::RingIndex& index,
                  std::vector<std::size_t>& stack, Wanted wanted, Leaf leaf) {
  if (index.leaves == 0) return;
  stack.assign(1, 1);
  while (!stack.empty()) {
    const std::size_t v = stack.back();
    stack.pop_back();
    if (!wanted(index.nodes[v])) continue;
    if (v < index.first_leaf) {
      stack.push_back(2 * v + 1);
      stack.push_back(2 * v);
      continue;
    }
    const std::size_t k = v - index.first_leaf;
    leaf(k * kLeaf, std::min(n, (k + 1) * kLeaf));
  }
}

// The edges of the leaves that overlap the box and are not strictly outside one side, in ring
// order.
void active_edges(const Ring& ring, const BoxClipper::RingIndex& index, const Box2& box,
                  const detail::BoxCut& cut, std::vector<std::uint32_t>& active,
                  std::vector<std::size_t>& stack) {
  active.clear();
  const std::size_t n = ring.size();
  visit_leaves(
      n, index, stack, [&](const Box2& b) { return b.overlaps(box); },
      [&](std::size_t first, std::size_t end) {
        unsigned cp = cut.code(ring[first]);
        for (std::size_t i = first; i < end; ++i) {
          const unsigned cq = cut.code(ring[i + 1 < n ? i + 1 : 0]);
          if ((cp & cq & 15u) == 0) active.push_back(static_cast<std::uint32_t>(i));
          cp = cq;
        }
      });
}

// Whether the +x ray from c crosses the ring an odd number of times (half-open in y: a point
// counts as above when y > c.y), c on none of its edges. Only nodes reaching right of c and
// straddling its line can hold a crossing.
bool ray_parity(const Ring& ring, const BoxClipper::RingIndex& index, Vec2 c,
                std::vector<std::size_t>& stack) {
  const std::size_t n = ring.size();
  bool odd = false;
  visit_leaves(
      n, index, stack,
      [&](const Box2& b) { return !b.empty() && b.max.x > c.x && b.max.y > c.y && b.min.y <= c.y; },
      [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) {
          const Vec2 p = ring[i], q = ring[i + 1 < n ? i + 1 : 0];
          if ((p.y > c.y) == (q.y > c.y)) continue;
          if (std::min(p.x, q.x) > c.x) {
            odd = !odd;
            continue;
          }
          if (std::max(p.x, q.x) <= c.x) continue;
          const Vec2 lo = p.y < q.y ? p : q, hi = p.y < q.y ? q : p;
          if (predicates::orient2d(lo, hi, c) == Sign::positive) odd = !odd;
        }
      });
  return odd;
}

}  // namespace

BoxClipper::BoxClipper(MultiPolygon region) : region_(std::move(region)) {
  polygon_bounds_.reserve(region_.polygons.size());
  index_.reserve(region_.polygons.size());
  for (const Polygon& p : region_.polygons) {
    Box2 b;
    std::vector<RingIndex> rings;
    rings.reserve(p.rings.size());
    for (const Ring& r : p.rings) {
      for (const Vec2 v : r)
        b.expand(v);
      rings.push_back(build_index(r));
    }
    polygon_bounds_.push_back(b);
    bounds_.expand(b);
    index_.push_back(std::move(rings));
  }
}

MultiPolygon BoxClipper::clip(const Box2& given) const {
  const Box2 box = detail::finite_box(given);
  if (box.empty()) return {};
  detail::BoxCut cut(box);
  std::vector<std::uint32_t> active;
  std::vector<std::size_t> stack;
  for (std::size_t pi = 0; pi < region_.polygons.size() && cut.ok(); ++pi) {
    if (!polygon_bounds_[pi].overlaps(box)) continue;
    const Polygon& polygon = region_.polygons[pi];
    cut.begin_polygon();
    for (std::size_t r = 0; r < polygon.rings.size() && cut.ok(); ++r) {
      const Ring& ring = polygon.rings[r];
      const RingIndex& index = index_[pi][r];
      active_edges(ring, index, box, cut, active, stack);
      if (!cut.add_ring(ring, active, r > 0, index.orientation)) {
        cut.add_parity(ray_parity(ring, index, cut.centre(), stack));
      }
    }
    cut.end_polygon();
  }
  MultiPolygon out = cut.take();
  if (cut.ok()) return out;
  return detail::clip_by_box_exactly(region_, box);
}

Box2 TileGrid::tile(int column, int row) const {
  auto at = [](double lo, double hi, int i, int count) {
    if (i >= count) return hi;
    if (i <= 0) return lo;
    const double width = hi - lo;
    if (std::isfinite(width * static_cast<double>(count))) {
      return lo + width * static_cast<double>(i) / static_cast<double>(count);
    }
    // Bounds so wide that width * count overflows (-9e307 to 9e307): the lines in halves, which
    // cannot overflow, for every line of the grid alike (monotone in i, as rounding is).
    const double share = static_cast<double>(i) / static_cast<double>(count);
    return std::min(hi, 2.0 * (0.5 * lo + (0.5 * hi - 0.5 * lo) * share));
  };
  return Box2{
      {at(bounds.min.x, bounds.max.x, column, columns), at(bounds.min.y, bounds.max.y, row, rows)},
      {at(bounds.min.x, bounds.max.x, column + 1, columns),
       at(bounds.min.y, bounds.max.y, row + 1, rows)}};
}

std::vector<MultiPolygon> tile(const BoxClipper& region, const TileGrid& grid,
                               const BatchOptions& options) {
  return tile_range(region, grid, 0, std::numeric_limits<std::size_t>::max(), options);
}

std::vector<MultiPolygon> tile_range(const BoxClipper& region, const TileGrid& grid,
                                     std::size_t first_tile, std::size_t wanted,
                                     const BatchOptions& options) {
  if (grid.columns <= 0 || grid.rows <= 0 || grid.bounds.empty()) return {};
  const std::size_t total =
      static_cast<std::size_t>(grid.columns) * static_cast<std::size_t>(grid.rows);
  if (first_tile >= total) return {};
  const std::size_t count = std::min(wanted, total - first_tile);
  std::vector<MultiPolygon> out(count);
  // Tiles differ in cost (empty ones are cheap): threads take the next tile as they finish.
  // Each tile's result depends only on the tile, so the order of work changes nothing.
  // Runs of 16 tiles a grab keep the counter and the neighbouring results off each other's
  // cache lines.
  constexpr std::size_t kRun = 16;
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t first = next.fetch_add(kRun); first < count; first = next.fetch_add(kRun)) {
      for (std::size_t t = first; t < std::min(count, first + kRun); ++t) {
        const std::size_t index = first_tile + t;
        const int column = static_cast<int>(index % static_cast<std::size_t>(grid.columns));
        const int row = static_cast<int>(index / static_cast<std::size_t>(grid.columns));
        out[t] = region.clip(grid.tile(column, row));
      }
    }
  };
  const int threads = thread_count(options, count, kRun);
  std::vector<std::thread> workers;
  for (int i = 1; i < threads; ++i)
    workers.emplace_back(work);
  work();
  for (std::thread& w : workers)
    w.join();
  return out;
}

std::vector<MultiPolygon> tile(const MultiPolygon& region, const TileGrid& grid,
                               const BatchOptions& options) {
  return tile(BoxClipper(region), grid, options);
}

}  // namespace contain::clip
