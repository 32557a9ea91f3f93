#pragma once
/// \file
/// Exact comparison of a squared distance with a squared radius (containment in balls and discs).

#include "contain/predicates/sign.h"
#include "contain/values/sphere.h"

namespace contain::predicates {

/// Sign of r^2 - |p - center|^2, exactly on the given doubles: positive strictly inside the
/// ball, zero on its sphere, negative outside. A negative radius is treated as its absolute value.
/// p - center need not be exact in double: it is formed exactly (Two-Diff) when the filter fails.
/// Valid for every finite double (NaN or infinity is a precondition violation): a filter with a
/// proven error bound answers most calls, then exact expansion arithmetic, then big numbers
/// for exponents outside the expansion range. Bounds and regimes: docs/robustness.md.
[[nodiscard]] Sign side_of_sphere(const Sphere& sphere, Vec3 p);

/// Sign of r^2 - |p - center|^2 in the plane, exactly; same stages as `side_of_sphere`.
[[nodiscard]] Sign side_of_circle(const Circle& circle, Vec2 p);

}  // namespace contain::predicates
