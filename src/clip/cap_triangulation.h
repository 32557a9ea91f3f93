#pragma once
// Triangulation of the planar region bounded by closed loops (the cap of a cut mesh): nesting by
// the even-odd rule, holes bridged to their outer loop, ear clipping, all with exact orient2d.

#include <array>
#include <cstdint>
#include <vector>

#include "contain/values/vec.h"

namespace contain::clip::detail {

/// `loops` hold indices into `points`. Returns triangles (indices) counter-clockwise in the
/// plane when `counter_clockwise`, clockwise otherwise. Loops that are open or of zero area
/// (exactly: `predicates::ring_orientation`, which also orients the loops) are ignored. O(k^2)
/// bridging and O(k^3) worst-case ear clipping for k loop vertices.
[[nodiscard]] std::vector<std::array<std::int32_t, 3>> triangulate_loops(
    const std::vector<std::vector<std::int32_t>>& loops, const std::vector<Vec2>& points,
    bool counter_clockwise);

}  // namespace contain::clip::detail
