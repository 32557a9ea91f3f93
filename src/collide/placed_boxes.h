#pragma once
// A mesh's own frame placed into world coordinates by a transform: its boxes and points as
// bvh/placed_box.h bounds them (proven to hold every point as Transform::apply computes it).

#include <algorithm>

#include "contain/bvh/placed_box.h"
#include "contain/values/box.h"
#include "contain/values/transform.h"

namespace contain::collide::detail {

// The placement of a mesh whose local coordinates are at most `max_abs_coordinate` in magnitude.
class PlacedBoxes {
 public:
  PlacedBoxes(const Transform& transform, double max_abs_coordinate)
      : t_(transform), tol_(bvh::placement_error(transform, max_abs_coordinate)) {}

  // A closed world box holding apply(v) for every v in `local`.
  [[nodiscard]] Box3 operator()(const Box3& local) const { return bvh::placed_box(local, t_); }

  [[nodiscard]] const Transform& transform() const { return t_; }
  /// How far a placed vertex lies from its exact image, per coordinate (the proven bound).
  [[nodiscard]] double tolerance() const { return tol_; }

 private:
  Transform t_;
  double tol_ = 0.0;
};

// Closed box of three points (exact).
[[nodiscard]] inline Box3 box_of(Vec3 a, Vec3 b, Vec3 c) {
  return Box3{{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z})},
              {std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})}};
}

}  // namespace contain::collide::detail
