#pragma once
/// \file
/// Affine maps x' = R x + t with a 3x3 matrix R (rotation for rigid motions) and a translation t,
/// in the contract's row order r00 r01 r02 t0 r10 r11 r12 t1 r20 r21 r22 t2.

#include <array>
#include <span>

#include "contain/core/result.h"
#include "contain/values/vec.h"

namespace contain::values {

struct Transform {
  std::array<std::array<double, 3>, 3> r{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  Vec3 t;

  /// Applies the map in the contract's evaluation order ((r0 x + r1 y) + r2 z) + t, so that
  /// results are reproducible bit for bit.
  [[nodiscard]] constexpr Vec3 apply(Vec3 p) const {
    return {((r[0][0] * p.x + r[0][1] * p.y) + r[0][2] * p.z) + t.x,
            ((r[1][0] * p.x + r[1][1] * p.y) + r[1][2] * p.z) + t.y,
            ((r[2][0] * p.x + r[2][1] * p.y) + r[2][2] * p.z) + t.z};
  }

  /// From 12 numbers in the contract's order; rejects NaN/Inf and a count other than 12.
  [[nodiscard]] static Result<Transform> from_row_major(std::span<const double> numbers);

  friend constexpr bool operator==(const Transform&, const Transform&) = default;
};

}  // namespace contain::values

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using values::Transform;
}  // namespace contain
