#include "contain/bvh/triangle_boxes.h"

namespace contain::bvh {

std::vector<Box3> triangle_boxes(const Mesh& mesh) {
  std::vector<Box3> boxes(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::int32_t v : mesh.triangles[t])
      boxes[t].expand(mesh.vertices[static_cast<std::size_t>(v)]);
  }
  return boxes;
}

}  // namespace contain::bvh
