#pragma once
/// \file
/// The boxes of a mesh's triangles, the items of a triangle `Bvh`.

#include <vector>

#include "contain/shapes/mesh.h"
#include "contain/values/box.h"

namespace contain::bvh {

/// boxes[t] is the closed axis-aligned box of triangle t's three vertices (exact: only
/// comparisons). Precondition: a validated mesh (indices in range). O(triangles).
[[nodiscard]] std::vector<Box3> triangle_boxes(const Mesh& mesh);

}  // namespace contain::bvh
