#pragma once
// One vertex per connected component of a mesh's surface.

#include <cstdint>
#include <vector>

#include "contain/shapes/mesh.h"

namespace contain::collide::detail {

// The smallest vertex index of each component (triangles joined through shared vertices),
// ascending; vertices of no triangle are ignored. O(n alpha(n)).
[[nodiscard]] std::vector<std::int32_t> component_vertices(const Mesh& mesh);

}  // namespace contain::collide::detail
