#pragma once
/// \file
/// Exact 3D orientation.

#include "contain/geometry/vec.h"
#include "contain/predicates/sign.h"

namespace contain::predicates {

/// Sign of det[b - a, c - a, d - a] = ((b - a) x (c - a)) . (d - a), exactly on the given doubles:
/// positive when d lies on the side of the plane through a, b, c that the normal
/// (b - a) x (c - a) points to (where a, b, c look counter-clockwise); zero when coplanar.
/// Note: this is the opposite sign convention from Shewchuk's orient3d. Filter + exact expansion
/// fallback + big-integer fallback for extreme exponents, as `orient2d`.
[[nodiscard]] Sign orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

}  // namespace contain::predicates
