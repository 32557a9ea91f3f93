#pragma once
/// \file
/// The same-side test for convex polygons.

#include "contain/core/location.h"
#include "contain/inside/point_in_polygon.h"
#include "contain/shapes/polygon.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// The same-side test ("Algorithms of Informatics" vol. 2, § 22.4: "for convex polygons, we can
/// also test whether the point is on the same side of the edges as the polygon itself"), exact:
/// `point` is inside iff orient2d(a, b, point) has the ring's orientation for every edge a->b, on
/// the boundary iff it is zero for some edges and never of the opposite sign, and outside
/// otherwise.
///
/// - `ring`: a convex ring, counter-clockwise or clockwise, which turns once (collinear and
///   repeated vertices are allowed; repeated ones are skipped). For a non-convex ring the answer is
///   unspecified: use `point_in_polygon`. The orientation is the sign of the first non-collinear
///   vertex triple, exactly; a ring with no such triple (zero area) encloses nothing, so every
///   point is `outside`.
/// - `options.fill`: the ring's winding number is +1 (counter-clockwise) or -1 inside; if the rule
///   does not fill it (a clockwise ring under `Fill::positive`, a counter-clockwise one under
///   `Fill::negative`) the region is empty and every point is `outside`.
///
/// Agrees with `point_in_polygon(Polygon{{ring}}, point, options)` on convex rings.
/// Complexity: O(n), stops at the first edge that separates the point.
[[nodiscard]] Location point_in_convex_polygon(const Ring& ring, Vec2 point,
                                               const PointInPolygonOptions& options = {});

}  // namespace contain::inside
