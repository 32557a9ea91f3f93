#pragma once
// The node test of two hierarchies that are both placed by transforms (a scene's objects):
// whether the images of two local boxes may meet, by the separating axis theorem on the two
// parallelepipeds (Gottschalk, Lin, Manocha, "OBBTree", SIGGRAPH 1996: the 3 face normals of
// each and the 9 cross products of their edge directions). Placing both boxes into world
// axis-aligned boxes (PlacedBoxes) inflates each rotated box, twice over for a pair; on 500
// randomly rotated corpus meshes the pair tests then entered 3-4 times as many node pairs.
//
// Conservative: the test says "separate" only when an axis separates the two parallelepipeds
// widened by each side's PlacedBoxes rounding bound (every world vertex, the rounded
// Transform::apply, lies that close to its exact image) and by a margin of 2^-40 of the
// magnitudes in the projection (far above the few roundings of each term). So a pair of
// triangles that meet is never culled, and answers stay exact.

#include <algorithm>
#include <array>
#include <cmath>

#include "collide/placed_boxes.h"
#include "contain/values/box.h"
#include "contain/values/max_abs.h"
#include "contain/values/transform.h"
#include "contain/values/vec.h"

namespace contain::collide::detail {

class SeparatingAxes {
 public:
  SeparatingAxes(const PlacedBoxes& a, const PlacedBoxes& b)
      : a_(a.transform()), b_(b.transform()) {
    tol_ = a.tolerance() + b.tolerance();
    const std::array<Vec3, 3> ua = columns(a_), ub = columns(b_);
    // Face normals of each parallelepiped (the columns themselves for a rotation), then the
    // edge-edge directions.
    std::array<Vec3, 15> l{};
    l[0] = cross(ua[1], ua[2]);
    l[1] = cross(ua[2], ua[0]);
    l[2] = cross(ua[0], ua[1]);
    l[3] = cross(ub[1], ub[2]);
    l[4] = cross(ub[2], ub[0]);
    l[5] = cross(ub[0], ub[1]);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        l[static_cast<std::size_t>(6 + 3 * i + j)] =
            cross(ua[static_cast<std::size_t>(i)], ub[static_cast<std::size_t>(j)]);
    }
    for (const Vec3& axis : l) {
      const double l1 = std::fabs(axis.x) + std::fabs(axis.y) + std::fabs(axis.z);
      if (!(l1 > 0.0) || !std::isfinite(l1)) continue;  // parallel edges: no axis
      Axis& out = axes_[static_cast<std::size_t>(count_++)];
      out.l = axis;
      out.l1 = l1;
      for (std::size_t i = 0; i < 3; ++i) {
        out.a[i] = std::fabs(dot(axis, ua[i]));
        out.b[i] = std::fabs(dot(axis, ub[i]));
      }
    }
  }

  // False only when the placed images of local boxes `a` (of A) and `b` (of B) are apart.
  [[nodiscard]] bool may_meet(const Box3& a, const Box3& b) const {
    const Vec3 ca{0.5 * a.min.x + 0.5 * a.max.x, 0.5 * a.min.y + 0.5 * a.max.y,
                  0.5 * a.min.z + 0.5 * a.max.z};
    const Vec3 ha{0.5 * a.max.x - 0.5 * a.min.x, 0.5 * a.max.y - 0.5 * a.min.y,
                  0.5 * a.max.z - 0.5 * a.min.z};
    const Vec3 cb{0.5 * b.min.x + 0.5 * b.max.x, 0.5 * b.min.y + 0.5 * b.max.y,
                  0.5 * b.min.z + 0.5 * b.max.z};
    const Vec3 hb{0.5 * b.max.x - 0.5 * b.min.x, 0.5 * b.max.y - 0.5 * b.min.y,
                  0.5 * b.max.z - 0.5 * b.min.z};
    const Vec3 wa = a_.apply(ca), wb = b_.apply(cb);
    const Vec3 d = wa - wb;
    const double size = std::max(max_abs(wa), max_abs(wb));
    for (int k = 0; k < count_; ++k) {
      const Axis& x = axes_[static_cast<std::size_t>(k)];
      const double reach = x.a[0] * ha.x + x.a[1] * ha.y + x.a[2] * ha.z + x.b[0] * hb.x +
                           x.b[1] * hb.y + x.b[2] * hb.z;
      const double margin = tol_ * x.l1 + 0x1p-40 * (x.l1 * size + reach) + 0x1p-1000;
      if (std::fabs(dot(x.l, d)) > reach + margin) return false;
    }
    return true;
  }

 private:
  struct Axis {
    Vec3 l;
    double l1 = 0.0;
    double a[3]{};  // |l . column i of A's matrix|
    double b[3]{};
  };

  static std::array<Vec3, 3> columns(const Transform& t) {
    return {Vec3{t.r[0][0], t.r[1][0], t.r[2][0]}, Vec3{t.r[0][1], t.r[1][1], t.r[2][1]},
            Vec3{t.r[0][2], t.r[1][2], t.r[2][2]}};
  }

  Transform a_, b_;
  double tol_ = 0.0;
  std::array<Axis, 15> axes_{};
  int count_ = 0;
};

}  // namespace contain::collide::detail
