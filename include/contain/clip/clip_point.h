#pragma once
/// \file
/// Point clipping ("Algorithms of Informatics" vol. 2, § 22.4: "If the object to be clipped is a
/// point, then containment can be tested ... the point is either removed or preserved"): a thin
/// wrapper on `inside::`.

#include <optional>

#include "contain/shapes/convex_polyhedron.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"
#include "contain/values/plane.h"
#include "contain/values/sphere.h"
#include "contain/values/vec.h"

namespace contain::clip {

/// `p` if it lies in the closed region (boundary included), nothing otherwise. Exact: box
/// comparisons, predicates::side_of_plane / side_of_line / side_of_sphere / side_of_circle,
/// inside::point_in_convex / point_in_polygon (even-odd) on the given doubles. O(1), or O(n) for
/// n planes, faces or edges.
[[nodiscard]] std::optional<Vec3> clip_point(Vec3 p, const Box3& box);
[[nodiscard]] std::optional<Vec2> clip_point(Vec2 p, const Box2& box);
[[nodiscard]] std::optional<Vec3> clip_point(Vec3 p, const Plane& half_space);
[[nodiscard]] std::optional<Vec2> clip_point(Vec2 p, const HalfPlane& half_plane);
[[nodiscard]] std::optional<Vec3> clip_point(Vec3 p, const Sphere& ball);
[[nodiscard]] std::optional<Vec2> clip_point(Vec2 p, const Circle& disc);
[[nodiscard]] std::optional<Vec3> clip_point(Vec3 p, const ConvexPolyhedron& polyhedron);
/// Against a polygon read under the even-odd rule (any polygon, convex or not).
[[nodiscard]] std::optional<Vec2> clip_point(Vec2 p, const Polygon& polygon);

}  // namespace contain::clip
