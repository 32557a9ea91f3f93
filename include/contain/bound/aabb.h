#pragma once
/// \file
/// Axis-aligned bounding boxes of point sets, polygons and meshes (exercise 22.4-4).

#include <span>

#include "contain/bound/mesh_vertices.h"
#include "contain/shapes/mesh.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"
#include "contain/values/vec.h"

namespace contain::bound {

/// Options of the mesh overload of `aabb`.
struct AabbOptions {
  /// Which vertices the box encloses (default: those used by a triangle).
  MeshVertices vertices = MeshVertices::referenced;
};

/// The smallest closed box holding every point: per axis the minimum and maximum coordinate,
/// exactly (comparisons only, no arithmetic). A `Ring` converts to the span.
/// Empty input gives the empty `Box2{}` (min = +inf, max = -inf), the identity of `Box2::expand`.
/// A NaN coordinate is skipped on its axis (validated types never hold one). O(n).
[[nodiscard]] Box2 aabb(std::span<const Vec2> points);

/// 3D form of `aabb(std::span<const Vec2>)`; empty input gives the empty `Box3{}`.
[[nodiscard]] Box3 aabb(std::span<const Vec3> points);

/// The box of every ring of the polygon (shell and holes: the holes lie inside the shell for
/// valid input, but any ring counts under a fill rule). Empty polygon: empty box. O(points).
[[nodiscard]] Box2 aabb(const Polygon& polygon);

/// The box of every ring of every polygon; empty box when there are none. O(points).
[[nodiscard]] Box2 aabb(const MultiPolygon& multi_polygon);

/// The box of the mesh's vertices, by default only those a triangle refers to (the surface; this
/// is the answer of `contain bound` and of the shared corpus). A mesh without triangles has the
/// empty box under `MeshVertices::referenced`. O(V + T).
[[nodiscard]] Box3 aabb(const Mesh& mesh, const AabbOptions& options = {});

}  // namespace contain::bound
