#pragma once
/// \file
/// Exact side of a half-space or half-plane given by its coefficients.

#include "contain/predicates/sign.h"
#include "contain/values/plane.h"

namespace contain::predicates {

/// Sign of a p.x + b p.y + c p.z + d, exactly on the given doubles: positive inside the closed
/// half-space, zero on its plane. The coefficients need not be normalised.
/// Valid for every finite double (NaN or infinity is a precondition violation): a filter with a
/// proven error bound answers most calls, then exact expansion arithmetic, then big numbers
/// for exponents outside the expansion range. Bounds and regimes: docs/robustness.md.
[[nodiscard]] Sign side_of_plane(const Plane& plane, Vec3 p);

/// Sign of a p.x + b p.y + c, exactly: positive inside the closed half-plane, zero on its line.
/// Same stages as `side_of_plane`.
[[nodiscard]] Sign side_of_line(const HalfPlane& half_plane, Vec2 p);

}  // namespace contain::predicates
