#include "contain/bound/bounding_sphere.h"

#include <vector>

#include "bound/enclose.h"
#include "contain/predicates/compare_distance.h"

namespace contain::bound {

Result<Sphere> bounding_sphere(std::span<const Vec3> points, const BoundingSphereOptions& options) {
  auto ball = detail::enclose(points, options.method, [](Vec3 center, double radius, Vec3 p) {
    return predicates::side_of_sphere(Sphere{center, radius}, p);
  });
  if (!ball.ok()) return ball.error();
  return Sphere{ball->center, ball->radius};
}

Result<Sphere> bounding_sphere(const Mesh& mesh, const BoundingSphereOptions& options) {
  if (options.vertices == MeshVertices::all) return bounding_sphere(mesh.vertices, options);
  const std::vector<Vec3> vertices = referenced_vertices(mesh);
  if (vertices.empty() && !mesh.vertices.empty()) {
    return Error{ErrorKind::degenerate, "the mesh has no triangles, so no vertex to enclose"};
  }
  return bounding_sphere(vertices, options);
}

}  // namespace contain::bound
