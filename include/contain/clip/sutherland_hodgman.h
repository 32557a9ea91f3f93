#pragma once
/// \file
/// The Sutherland-Hodgman polygon clipping algorithm of "Algorithms of Informatics" vol. 2 (§ 22.4,
/// "Sutherland- Hodgeman-Polygon-Clipping"): one ring against a half-plane or half-space, and
/// against a convex polygon or polyhedron as a sequence of them (figure 22.22: "the result of one
/// clipping step on a half plane is the input of clipping on the next").

#include <span>
#include <vector>

#include "contain/shapes/polygon.h"
#include "contain/values/plane.h"
#include "contain/values/vec.h"

namespace contain::clip {

/// Clips a closed ring by the closed half-plane, vertex by vertex as the section does: an inside
/// vertex is kept; where an edge crosses the line its crossing point is added. In/out of every
/// vertex is exact (predicates::side_of_line; a vertex on the line is in); a crossing point is
/// computed only for an edge with one endpoint strictly in and one strictly out, as
/// p + t (q - p), t = s(p) / (s(p) - s(q)), in floating point (a few ulps), and for an
/// axis-parallel line x = v or y = v with a unit coefficient its coordinate is v exactly.
///
/// A concave ring that falls apart gives the section's single ring whose pieces are joined by an
/// even number of degenerate bridging edges along the line (figure 22.27): under the even-odd rule
/// it covers the clipped area; `clip_polygon` splits it into valid pieces. The result keeps the
/// input's direction and may hold repeated points; it is empty when fewer than 3 points remain.
/// O(n) for n vertices.
[[nodiscard]] Ring sutherland_hodgman(const Ring& ring, const HalfPlane& half_plane);

/// Against the intersection of half-planes, one after the other. O(n m) for m half-planes (the
/// ring grows by at most one vertex per crossing pair).
[[nodiscard]] Ring sutherland_hodgman(const Ring& ring, std::span<const HalfPlane> half_planes);

/// Against a convex ring (either direction; side tests are predicates::orient2d on its edges,
/// no rounded line). A ring with no three non-collinear vertices encloses nothing: empty result.
[[nodiscard]] Ring sutherland_hodgman(const Ring& ring, const Ring& convex_ring);

/// A planar polygon in 3D (its vertices in order; planarity is not checked) against a closed
/// half-space (predicates::side_of_plane), as in 2D; a plane with one nonzero coefficient of
/// magnitude 1 (a box face) gives crossing coordinates equal to its offset exactly. O(n).
[[nodiscard]] std::vector<Vec3> sutherland_hodgman(std::span<const Vec3> polygon,
                                                   const Plane& half_space);

/// A planar polygon in 3D against the intersection of half-spaces, one after the other.
[[nodiscard]] std::vector<Vec3> sutherland_hodgman(std::span<const Vec3> polygon,
                                                   std::span<const Plane> half_spaces);

}  // namespace contain::clip
