#pragma once
/// \file
/// Containment in solids defined by a function, f(p) >= 0 ("Algorithms of Informatics" vol. 2,
/// § 22.4, equation 22.1): balls, half-spaces, axis-aligned boxes and user-supplied functions.

#include "contain/core/location.h"
#include "contain/shapes/implicit_function.h"
#include "contain/values/box.h"
#include "contain/values/plane.h"
#include "contain/values/sphere.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// Where `p` lies relative to the closed ball. Exact: predicates::side_of_sphere decides the sign
/// of r^2 - |p - c|^2 on the given doubles, so (3, 4, 0) is `boundary` of the ball of radius 5
/// about the origin. A negative radius is taken as its absolute value (validated inputs never
/// hold one); a zero radius gives `boundary` at the centre and `outside` elsewhere. O(1).
[[nodiscard]] Location point_in_sphere(const Sphere& sphere, Vec3 p);

/// Where `p` lies relative to the closed half-space a x + b y + c z + d >= 0 (the normal points
/// inward). Exact (predicates::side_of_plane). A zero normal gives the sign of d everywhere:
/// all of space (`inside`), nothing (`outside`), or, for d = 0, `boundary` everywhere. O(1).
[[nodiscard]] Location point_in_halfspace(const Plane& plane, Vec3 p);

/// Where `p` lies relative to the closed box: `boundary` on a face, edge or corner. Exact (only
/// comparisons of the given doubles). An empty box (min > max on some axis) contains nothing; a
/// flat box (min == max on some axis) has no interior, so its points are all `boundary`. O(1).
[[nodiscard]] Location point_in_box(const Box3& box, Vec3 p);

/// Where `p` lies relative to { q : f(q) >= 0 }: `boundary` when f(p) == 0 exactly as evaluated,
/// `inside` when f(p) > 0, `outside` when f(p) < 0 or f(p) is NaN. Only as exact as the
/// evaluation of `f`: a floating-point formula may round a true zero away or a nonzero value to
/// zero (f = x*x - 2 is never 0 at a double, though the solid has a boundary there). O(cost of f).
[[nodiscard]] Location point_in_implicit(const ImplicitFunction& f, Vec3 p);

}  // namespace contain::inside
