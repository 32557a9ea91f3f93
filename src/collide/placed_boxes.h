#pragma once
// Boxes of a mesh's own frame mapped into world coordinates by a transform, enlarged so that
// they hold every transformed point as the doubles Transform::apply computes them.

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "contain/values/box.h"
#include "contain/values/transform.h"

namespace contain::collide::detail {

// Rounding bound. For v in a local box with centre c and half extents h (computed in floating
// point), the exact image R v + t lies within |R| h of R c + t; the computed centre, the
// computed extents and apply(v) itself each differ from their exact values by a few units in
// the last place of |R| max|v| + |t| (at most ~10 roundings of terms bounded by that sum).
// The margin 2^-40 of that sum exceeds those ~10 * 2^-53 by a factor of about 800, and the
// absolute term covers underflow. Conservative boxes only cost time, never answers.
class PlacedBoxes {
 public:
  PlacedBoxes(const Transform& transform, double max_abs_coordinate) : t_(transform) {
    double norm = 0.0;
    for (int i = 0; i < 3; ++i) {
      double row = 0.0;
      for (int j = 0; j < 3; ++j) {
        abs_[i][j] = std::fabs(t_.r[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]);
        row += abs_[i][j];
      }
      norm = std::max(norm, row);
    }
    const double shift = std::max({std::fabs(t_.t.x), std::fabs(t_.t.y), std::fabs(t_.t.z)});
    tol_ = 0x1p-40 * (norm * max_abs_coordinate + shift) + 0x1p-1000;
  }

  // A closed world box holding apply(v) for every v in `local`.
  [[nodiscard]] Box3 operator()(const Box3& local) const {
    const Vec3 c{0.5 * local.min.x + 0.5 * local.max.x, 0.5 * local.min.y + 0.5 * local.max.y,
                 0.5 * local.min.z + 0.5 * local.max.z};
    const Vec3 h{0.5 * local.max.x - 0.5 * local.min.x, 0.5 * local.max.y - 0.5 * local.min.y,
                 0.5 * local.max.z - 0.5 * local.min.z};
    const Vec3 w = t_.apply(c);
    const Vec3 e{abs_[0][0] * h.x + abs_[0][1] * h.y + abs_[0][2] * h.z + tol_,
                 abs_[1][0] * h.x + abs_[1][1] * h.y + abs_[1][2] * h.z + tol_,
                 abs_[2][0] * h.x + abs_[2][1] * h.y + abs_[2][2] * h.z + tol_};
    return Box3{w - e, w + e};
  }

  [[nodiscard]] const Transform& transform() const { return t_; }
  /// The rounding bound added to every side of a placed box.
  [[nodiscard]] double tolerance() const { return tol_; }

 private:
  Transform t_;
  double abs_[3][3]{};
  double tol_ = 0.0;
};

// Closed box of three points (exact).
[[nodiscard]] inline Box3 box_of(Vec3 a, Vec3 b, Vec3 c) {
  return Box3{{std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z})},
              {std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})}};
}

}  // namespace contain::collide::detail
