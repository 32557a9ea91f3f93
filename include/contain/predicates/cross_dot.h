#pragma once
/// \file
/// Exact sign of a dot product of two cross products, the same-side test of the seed section.

#include "contain/geometry/vec.h"
#include "contain/predicates/sign.h"

namespace contain::predicates {

/// Sign of ((b - a) x (p - a)) . ((b - a) x (c - a)), exactly on the given doubles: positive when
/// p and c lie on the same side of the line a->b as seen across the plane of a, b, c (the
/// seed's point-in-triangle test, valid for p anywhere in the perpendicular prism), zero when p
/// lies in the plane through a->b perpendicular to the triangle, or the triangle is degenerate.
[[nodiscard]] Sign cross_dot(Vec3 a, Vec3 b, Vec3 p, Vec3 c);

}  // namespace contain::predicates
