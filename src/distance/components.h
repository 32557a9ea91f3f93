#pragma once
// Private to contain::distance: one vertex per connected component of a mesh's surface (the
// nesting test locates one point of each component in the other solid).

#include <cstdint>
#include <vector>

#include "contain/geometry/mesh.h"

namespace contain::distance::detail {

/// The smallest vertex index of each component (triangles joined through shared vertices),
/// ascending; vertices of no triangle are ignored. O(n alpha(n)).
[[nodiscard]] std::vector<std::int32_t> component_vertices(const Mesh& mesh);

}  // namespace contain::distance::detail
