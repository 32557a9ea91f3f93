#include "contain/inside/point_in_mesh.h"

namespace contain::inside {

Location point_in_mesh(const Mesh& mesh, Vec3 p, const MeshIndexOptions& options) {
  MeshIndexOptions one = options;
  one.queries = 1;  // no grid: one pass over the triangles
  return MeshIndex(mesh, one).locate(p);
}

}  // namespace contain::inside
