#pragma once
/// \file
/// The angle-sum containment test of "Algorithms of Informatics" vol. 2, § 22.4, kept as the
/// textbook reference.

#include <span>

#include "contain/core/location.h"
#include "contain/inside/point_in_polygon.h"
#include "contain/shapes/polygon.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// The angle-sum test ("Algorithms of Informatics" vol. 2, § 22.4: "containment ... can be tested
/// by adding the angles subtended by the edges from the point. If the sum is 360 degrees, then the
/// point is inside"), generalised to every fill rule: the winding number is the rounded sum of the
/// signed angles atan2(cross, dot) subtended by the edges, divided by 2 pi.
///
/// NOT EXACT away from the boundary: the angles are floating point, so for a point extremely close
/// to an edge (or with huge/tiny coordinates) the rounded sum can be off by one. It is the
/// textbook reference, not the production method: use `point_in_polygon` or `PolygonIndex`.
/// Boundary points are never misreported: an exact on-edge test (orient2d) runs first, and a point
/// on an edge or vertex is answered by the exact `point_in_polygon`.
///
/// Parameters, boundary rules and fill as `point_in_polygon`. Complexity: O(n) with one atan2 per
/// edge (several times slower than ray crossing).
[[nodiscard]] Location point_in_polygon_angle_sum(std::span<const Ring> rings, Vec2 point,
                                                  const PointInPolygonOptions& options = {});

/// The same for the rings of a polygon.
[[nodiscard]] Location point_in_polygon_angle_sum(const Polygon& polygon, Vec2 point,
                                                  const PointInPolygonOptions& options = {});

}  // namespace contain::inside
