#pragma once
/// \file
/// Do two closed triangles in the plane share a point? ("Algorithms of Informatics" vol. 2, § 22.4,
/// exercise 22.4-5) Collide's names for the exact tests of `predicates/triangles_meet_2d.h`.

#include "contain/predicates/triangles_meet_2d.h"
#include "contain/values/segment.h"
#include "contain/values/triangle.h"

namespace contain::collide {

/// True when the closed triangles `a` and `b` (either winding) share at least one point,
/// touching included, exactly: predicates::triangles_meet. O(1).
[[nodiscard]] inline bool tri_tri(const Triangle2& a, const Triangle2& b) {
  return predicates::triangles_meet(a, b);
}

/// True when the closed segments `a` and `b` share a point (collinear overlap and zero-length
/// segments included), exactly: predicates::segments_meet. O(1).
[[nodiscard]] inline bool segment_segment(const Segment2& a, const Segment2& b) {
  return predicates::segments_meet(a, b);
}

}  // namespace contain::collide
