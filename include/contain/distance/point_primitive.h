#pragma once
/// \file
/// Distance from a point to one primitive: a triangle, a segment, a box.

#include "contain/distance/closest.h"
#include "contain/distance/point_query.h"
#include "contain/values/box.h"
#include "contain/values/segment.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::distance {

/// Distance from `p` to the closed triangle `t` (its points, not only its edges), the double
/// nearest to the exact value, and the closest point (each coordinate the nearest double).
/// Method: the closest feature (vertex, edge or face) is decided exactly
/// (predicates::closest_feature), then the distance to that feature's flat is rounded once
/// (predicates::rounded_distance). Degenerate triangles are their segment hull (or point).
/// `feature` is -1. O(1); exact for every finite double.
[[nodiscard]] Closest3 point_triangle(const Triangle3& t, Vec3 p);

/// Distance from `p` to the closed segment `s` (a point where s.a == s.b); as `point_triangle`.
[[nodiscard]] Closest3 point_segment(const Segment3& s, Vec3 p);
[[nodiscard]] Closest2 point_segment(const Segment2& s, Vec2 p);

/// Distance from `p` to the surface of the closed box `box` (non-empty: min <= max; flat boxes
/// are allowed and are all surface). Unsigned: outside, the distance to the box (the closest point
/// is p clamped to the box, exact); inside, the distance to the nearest face. Signed
/// (`query.signed_distance`): negative inside, 0 on the surface. Inside, `feature` names the
/// nearest face (0..5: -x, +x, -y, +y, -z, +z; ties to the lowest) and the closest point is p
/// moved onto it (exact); outside `feature` is -1. O(1); exact.
[[nodiscard]] Closest3 point_box(const Box3& box, Vec3 p, const PointQuery& query = {});

}  // namespace contain::distance
