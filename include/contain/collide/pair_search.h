#pragma once
/// \file
/// Broad phase for scenes of many objects: which bounding boxes overlap?

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contain/values/box.h"

namespace contain::collide {

/// Every pair (i, j), i < j, of closed boxes that share a point: touching boxes (a shared face,
/// edge or corner) are candidates. Empty boxes (min > max on some axis, e.g. a default Box3)
/// pair with nothing. Exact: only comparisons of the given doubles. Pairs come sorted
/// (lexicographically), so the output does not depend on the algorithm's internal order.
///
/// Sweep and prune (Baraff 1992; Cohen et al., I-COLLIDE 1995) along the axis on which the
/// boxes' centres spread most: sorted by their low end on that axis, each box meets only the
/// boxes that start before its high end, tested on the other two axes.
/// O(n log n + k_axis) time for k_axis pairs overlapping on the sweep axis (k_axis is close to
/// the output size for scattered scenes; n^2 in the worst case of boxes all stacked over one
/// interval), O(n + output) memory.
[[nodiscard]] std::vector<std::pair<std::int32_t, std::int32_t>> pair_search(
    std::span<const Box3> boxes);

}  // namespace contain::collide
