#include "contain/clip/box_halfspaces.h"

namespace contain::clip {

std::vector<Plane> box_halfspaces(const Box3& box) {
  return {{1, 0, 0, -box.min.x}, {-1, 0, 0, box.max.x}, {0, 1, 0, -box.min.y},
          {0, -1, 0, box.max.y}, {0, 0, 1, -box.min.z}, {0, 0, -1, box.max.z}};
}

std::vector<HalfPlane> box_halfspaces(const Box2& box) {
  return {{1, 0, -box.min.x}, {-1, 0, box.max.x}, {0, 1, -box.min.y}, {0, -1, box.max.y}};
}

}  // namespace contain::clip
