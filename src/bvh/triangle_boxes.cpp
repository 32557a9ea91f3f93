#include "contain/bvh/triangle_boxes.h"

namespace contain::bvh {

std::vector<Box3> triangle_boxes(const Mesh& mesh) {
  std::vector<Box3> boxes(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    boxes[t] = bounding_box(mesh.triangle(t));
  return boxes;
}

}  // namespace contain::bvh
