#pragma once
/// \file
/// Do two closed triangles in space share a point? The exact narrow-phase test of mesh collision,
/// under collide's names: the decisions live in predicates (`predicates/triangles_meet.h`), one
/// implementation shared with clip's check of a written mesh.

#include "contain/predicates/triangles_meet.h"
#include "contain/values/segment.h"
#include "contain/values/triangle.h"

namespace contain::collide {

/// True when the closed triangles `a` and `b` share at least one point (crossing, touching and
/// coplanar overlap all count), exactly: predicates::triangles_meet. O(1).
[[nodiscard]] inline bool tri_tri(const Triangle3& a, const Triangle3& b) {
  return predicates::triangles_meet(a, b);
}

/// True when the closed segment `s` and the closed triangle `t` share a point (degenerate `t`
/// or zero-length `s` included), exactly: predicates::segment_meets_triangle. O(1).
[[nodiscard]] inline bool segment_triangle(const Segment3& s, const Triangle3& t) {
  return predicates::segment_meets_triangle(s, t);
}

}  // namespace contain::collide
