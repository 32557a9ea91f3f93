#pragma once
/// \file
/// The connected components of a mesh's surface, one vertex each: what the nesting tests of
/// collide::MeshPair and distance::MeshPairDistance locate in the other solid (two surfaces that
/// do not cross each other have each component wholly inside or outside the other solid).

#include <cstdint>
#include <vector>

#include "contain/shapes/mesh.h"

namespace contain::shapes {

/// The smallest vertex index of each connected component of the surface (triangles joined
/// through shared vertex indices), ascending; vertices of no triangle are left out.
/// Precondition: the indices are in range (as `Mesh::from_arrays` checks). O(n log n) at worst.
[[nodiscard]] std::vector<std::int32_t> component_vertices(const Mesh& mesh);

}  // namespace contain::shapes

namespace contain {
using shapes::component_vertices;
}  // namespace contain
