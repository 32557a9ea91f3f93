#pragma once
// Private to contain::distance: an order of query points along a Morton (Z-order) curve, so that
// consecutive queries of a batch lie near each other and can start from each other's answers.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "contain/values/vec.h"

namespace contain::distance::detail {

/// Indices 0..n-1 sorted by the Morton code of each point quantised to 2^10 cells per axis of
/// the points' bounding box (non-finite points last). Deterministic; O(n log n).
[[nodiscard]] std::vector<std::uint32_t> morton_order(std::span<const Vec3> points);
[[nodiscard]] std::vector<std::uint32_t> morton_order(std::span<const Vec2> points);

/// Asks for the point and the answer of the query a few places after k in `order` (before
/// `end`) to be fetched: a batch in Morton order visits its arrays at random, and without this
/// each query first waits on memory for both (5% of a signed distance query on the armadillo).
template <class Point, class Answer>
inline void prefetch_ahead(std::span<const std::uint32_t> order, std::size_t k, std::size_t end,
                           const Point* points, Answer* out) {
  constexpr std::size_t kAhead = 8;
  if (k + kAhead < end) {
    const std::size_t i = order[k + kAhead];
    __builtin_prefetch(points + i);
    __builtin_prefetch(out + i, 1);
  }
}

}  // namespace contain::distance::detail
