#include "contain/inside/point_in_mesh.h"

namespace contain::inside {

Location point_in_mesh(const Mesh& mesh, Vec3 p, const MeshIndexOptions& options) {
  return MeshIndex(mesh, options).locate(p);
}

}  // namespace contain::inside
