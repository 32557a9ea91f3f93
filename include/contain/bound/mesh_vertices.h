#pragma once
/// \file
/// Which vertices of a mesh a bounding volume encloses, and the selection itself.

#include <cstdint>
#include <vector>

#include "contain/shapes/mesh.h"
#include "contain/values/vec.h"

namespace contain::bound {

/// The vertices a mesh bound encloses. A vertex that no triangle uses is not part of the surface,
/// so `referenced` (the default, and the meaning of the shared corpus and of `contain bound`)
/// leaves it out; `all` takes the vertex array as it is.
enum class MeshVertices : std::uint8_t {
  referenced,  ///< only vertices used by at least one triangle
  all,         ///< every entry of `Mesh::vertices`
};

/// The vertices of `mesh` that at least one triangle refers to, each once, in vertex-array order.
/// Empty for a mesh without triangles. O(V + T) time, O(V) extra memory.
[[nodiscard]] std::vector<Vec3> referenced_vertices(const Mesh& mesh);

}  // namespace contain::bound
