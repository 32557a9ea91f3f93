#pragma once
/// \file
/// Exact comparison of a squared distance with a squared radius (containment in balls and discs).

#include "contain/geometry/sphere.h"
#include "contain/predicates/sign.h"

namespace contain::predicates {

/// Sign of r^2 - |p - center|^2, exactly on the given doubles: positive strictly inside the
/// ball, zero on its sphere, negative outside. A negative radius is treated as its absolute value.
[[nodiscard]] Sign side_of_sphere(const Sphere& sphere, Vec3 p);

/// Sign of r^2 - |p - center|^2 in the plane, exactly.
[[nodiscard]] Sign side_of_circle(const Circle& circle, Vec2 p);

}  // namespace contain::predicates
