#pragma once
/// \file
/// An axis-aligned box as the intersection of its face half-spaces.

#include <vector>

#include "contain/values/box.h"
#include "contain/values/plane.h"

namespace contain::clip {

/// The 2 D half-spaces x_k - min_k >= 0 and max_k - x_k >= 0, in the order x min, x max, y min,
/// y max(, z min, z max) of the Cohen-Sutherland code bits. Every coefficient is 0, 1, -1 or a
/// box coordinate, so the half-spaces are the box's faces exactly. O(1).
[[nodiscard]] std::vector<Plane> box_halfspaces(const Box3& box);
[[nodiscard]] std::vector<HalfPlane> box_halfspaces(const Box2& box);

}  // namespace contain::clip
