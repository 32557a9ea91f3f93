#pragma once
/// \file
/// Indexed triangle meshes: a vertex array and a triangle index array (flat data). Readers
/// triangulate polygonal faces as fans and keep the count of the faces they read.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "contain/core/result.h"
#include "contain/values/transform.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::shapes {

/// Indices of a triangle's three vertices; counter-clockwise seen from outside for an outward
/// oriented closed mesh.
using TriangleIndices = std::array<std::int32_t, 3>;

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;

  /// Validates: rejects NaN/Inf coordinates and indices out of range (ErrorKind::invalid_value).
  /// Triangles may be degenerate and the mesh may be open: `validate_mesh` reports those.
  [[nodiscard]] static Result<Mesh> from_arrays(std::vector<Vec3> vertices,
                                                std::vector<TriangleIndices> triangles);

  /// The vertex that a triangle's index `i` names (`i` in [0, vertices.size())).
  [[nodiscard]] const Vec3& vertex(std::int32_t i) const {
    return vertices[static_cast<std::size_t>(i)];
  }
  /// Triangle `t` (in [0, triangles.size())) with its corners in index order, so its normal
  /// points outward on an outward oriented closed mesh.
  [[nodiscard]] Triangle3 triangle(std::size_t t) const {
    const TriangleIndices& v = triangles[t];
    return {vertex(v[0]), vertex(v[1]), vertex(v[2])};
  }

  friend bool operator==(const Mesh&, const Mesh&) = default;
};

/// `mesh` with every vertex replaced by `transform.apply(v)`, the triangles unchanged: the
/// doubles every exact decision on a placed mesh is made on (a pair query's A, the brute-force
/// reference). The result is finite where the placed coordinates do not overflow. O(n).
[[nodiscard]] Mesh placed(const Mesh& mesh, const Transform& transform);

}  // namespace contain::shapes

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using shapes::Mesh;
using shapes::placed;
using shapes::TriangleIndices;
}  // namespace contain
