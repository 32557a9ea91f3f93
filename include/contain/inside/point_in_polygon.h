#pragma once
/// \file
/// Exact point-in-polygon by ray crossing: even-odd, nonzero, positive and negative fill.

#include <span>

#include "contain/core/location.h"
#include "contain/shapes/polygon.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// How a set of rings is read: which winding numbers are filled (see `contain::Fill`).
struct PointInPolygonOptions {
  Fill fill = Fill::even_odd;
};

/// Where `point` lies relative to the region enclosed by `rings` under `options.fill`, exactly
/// on the given doubles ("Algorithms of Informatics" vol. 2, § 22.4: "a point is in a general
/// polygon if the half line
/// ... intersects the edges of the polygon odd times", generalised to winding numbers).
///
/// - `rings`: closed paths in the direction written (the last point joins the first; a ring of
///   fewer than 3 points or with repeated points is allowed and encloses what its path encloses).
///   Coordinates must be finite (validated types, e.g. `Polygon::from_rings`, guarantee it).
/// - `point`: any finite point.
///
/// Method: a horizontal ray to the right, counted with the **half-open ray rule**: an edge a->b
/// crosses the ray iff exactly one of a.y <= p.y, b.y <= p.y holds (a vertex on the ray counts as
/// lying below it, so a ray through a vertex counts once and horizontal edges never count), and
/// the crossing lies right of p iff orient2d(a, b, p) has the sign of the edge's direction
/// (upward +1, downward -1). The sum is the winding number of p, and for a point on an edge the
/// winding number of the sector just counter-clockwise of the +x direction (**right-up
/// perturbation rule**: every winding number is that of p + delta*(1, eta), delta, eta -> 0+).
///
/// Boundary (**filled-sector boundary rule**): a point on one or more edges or vertices is
/// `boundary` only if it lies on the boundary of the filled region: the incident edge directions
/// are sorted exactly around the point (orient2d and coordinate comparisons), the winding number of
/// every sector between them follows from the right-up sector by +1 across an outgoing and -1
/// across an incoming edge, and the answer is `boundary` iff both filled and unfilled sectors
/// occur; otherwise `inside` or `outside` like its neighbourhood. So an edge buried in the filled
/// region (overlapping rings, an edge traversed twice, a spike into the interior, two rings sharing
/// an edge under nonzero) is `inside`, and a zero-area spike or ring outside it is `outside`.
/// Zero-length edges are ignored.
///
/// Complexity: O(n) for n edges, no allocation unless the point lies on an edge (then
/// O(n + k log k) for k incident edges). For many queries build an `inside::PolygonIndex`.
[[nodiscard]] Location point_in_polygon(std::span<const Ring> rings, Vec2 point,
                                        const PointInPolygonOptions& options = {});

/// The same for the rings of a polygon (shell and holes alike are closed paths).
[[nodiscard]] Location point_in_polygon(const Polygon& polygon, Vec2 point,
                                        const PointInPolygonOptions& options = {});

/// The same for every ring of every polygon of `polygons`, read together as one set of paths.
[[nodiscard]] Location point_in_polygon(const MultiPolygon& polygons, Vec2 point,
                                        const PointInPolygonOptions& options = {});

}  // namespace contain::inside
