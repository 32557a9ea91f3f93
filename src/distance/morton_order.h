#pragma once
// Private to contain::distance: an order of query points along a Morton (Z-order) curve, so that
// consecutive queries of a batch lie near each other and can start from each other's answers.

#include <cstdint>
#include <span>
#include <vector>

#include "contain/values/vec.h"

namespace contain::distance::detail {

/// Indices 0..n-1 sorted by the Morton code of each point quantised to 2^10 cells per axis of
/// the points' bounding box (non-finite points last). Deterministic; O(n log n).
[[nodiscard]] std::vector<std::uint32_t> morton_order(std::span<const Vec3> points);
[[nodiscard]] std::vector<std::uint32_t> morton_order(std::span<const Vec2> points);

}  // namespace contain::distance::detail
