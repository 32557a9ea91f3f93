#pragma once
// Exact triangle-triangle intersection in GMP rationals, by a different route from the library:
// closed triangles share a point iff an edge of one meets the other (the boundary of their
// convex intersection lies on their edges); an edge meets a triangle where the exactly computed
// crossing point lies in it, or, coplanar, where it crosses an edge or has an endpoint inside.

#include "contain/values/triangle.h"

namespace contain::test {

[[nodiscard]] bool exact_tri_tri_3d(const Triangle3& a, const Triangle3& b);
[[nodiscard]] bool exact_tri_tri_2d(const Triangle2& a, const Triangle2& b);

}  // namespace contain::test
