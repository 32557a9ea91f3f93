#include "contain/bound/aabb.h"

#include <cstddef>
#include <vector>

namespace contain::bound {

Box2 aabb(std::span<const Vec2> points) {
  Box2 box;
  for (const Vec2& p : points)
    box.expand(p);
  return box;
}

Box3 aabb(std::span<const Vec3> points) {
  Box3 box;
  for (const Vec3& p : points)
    box.expand(p);
  return box;
}

Box2 aabb(const Polygon& polygon) {
  Box2 box;
  for (const Ring& ring : polygon.rings)
    box.expand(aabb(ring));
  return box;
}

Box2 aabb(const MultiPolygon& multi_polygon) {
  Box2 box;
  for (const Polygon& polygon : multi_polygon.polygons)
    box.expand(aabb(polygon));
  return box;
}

Box3 aabb(const Mesh& mesh, const AabbOptions& options) {
  if (options.vertices == MeshVertices::all) return aabb(mesh.vertices);
  // Without gathering the referenced vertices: a vertex shared by several triangles is simply
  // expanded into the box several times.
  Box3 box;
  for (const TriangleIndices& t : mesh.triangles) {
    for (std::int32_t index : t)
      box.expand(mesh.vertex(index));
  }
  return box;
}

}  // namespace contain::bound
