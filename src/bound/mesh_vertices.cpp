#include "contain/bound/mesh_vertices.h"

#include <cstddef>

namespace contain::bound {

std::vector<Vec3> referenced_vertices(const Mesh& mesh) {
  std::vector<unsigned char> used(mesh.vertices.size(), 0);
  std::size_t count = 0;
  for (const TriangleIndices& t : mesh.triangles) {
    for (std::int32_t index : t) {
      unsigned char& flag = used[static_cast<std::size_t>(index)];
      count += flag == 0 ? 1 : 0;
      flag = 1;
    }
  }
  std::vector<Vec3> out;
  out.reserve(count);
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (used[i] != 0) out.push_back(mesh.vertices[i]);
  }
  return out;
}

}  // namespace contain::bound
