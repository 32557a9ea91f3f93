#include "contain/shapes/mesh.h"

#include <string>

namespace contain::shapes {

Result<Mesh> Mesh::from_arrays(std::vector<Vec3> vertices, std::vector<TriangleIndices> triangles) {
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!is_finite(vertices[i])) {
      return Error{ErrorKind::invalid_value,
                   "vertex " + std::to_string(i) + " has a NaN or infinite coordinate"};
    }
  }
  const auto count = static_cast<std::int64_t>(vertices.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::int32_t index : triangles[t]) {
      if (index < 0 || index >= count) {
        return Error{ErrorKind::invalid_value, "triangle " + std::to_string(t) +
                                                   " refers to vertex " + std::to_string(index) +
                                                   ", but there are " + std::to_string(count)};
      }
    }
  }
  return Mesh{std::move(vertices), std::move(triangles)};
}

Mesh placed(const Mesh& mesh, const Transform& transform) {
  Mesh out = mesh;
  for (Vec3& v : out.vertices)
    v = transform.apply(v);
  return out;
}

}  // namespace contain::shapes
