#pragma once
/// \file
/// Do two closed triangles in the plane share a point? ("Algorithms of Informatics" vol. 2, § 22.4,
/// exercise 22.4-5)

#include "contain/values/segment.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// True when the closed triangles `a` and `b` (either winding) share at least one point:
/// touching at a vertex or along an edge counts, and so does one inside the other.
///
/// Method: two disjoint convex polygons are strictly separated by the line of an edge of one of
/// them (an edge of their Minkowski difference comes from an edge of one polygon), so the answer
/// is `disjoint` iff for some edge of either triangle, oriented counter-clockwise, the other
/// triangle lies strictly on its right: at most 18 exact predicates::orient2d calls.
/// Degenerate triangles (collinear or coincident vertices, decided exactly) are the segment or
/// point they span, tested as such (closed segment intersection by orient2d and exact
/// coordinate order along the segment). Exact for every finite input; O(1).
[[nodiscard]] bool triangles_meet(const Triangle2& a, const Triangle2& b);

/// True when the closed segments `a` and `b` share a point (exact orient2d, collinear overlap
/// and zero-length segments included). O(1).
[[nodiscard]] bool segments_meet(const Segment2& a, const Segment2& b);

}  // namespace contain::predicates
