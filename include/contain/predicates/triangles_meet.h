#pragma once
/// \file
/// Do two closed triangles in space share a point, and do two of one mesh meet beyond what they
/// share? The exact tests of collide (tri_tri, self_intersections) and of clip's mesh check.

#include <array>

#include "contain/values/segment.h"
#include "contain/values/triangle.h"

namespace contain::predicates {

/// True when the closed triangles `a` and `b` share at least one point: crossing, touching at a
/// vertex or along an edge, a vertex on the other's face, and coplanar overlap or touch all
/// count. Exact on the given doubles (checked against a GMP oracle): every decision is a
/// predicates::orient3d or orient2d sign.
///
/// Outline (Guigue and Devillers, "Fast and robust triangle-triangle overlap test using
/// orientation predicates", JGT 8(1), 2003): the signs of each triangle's vertices against the
/// other's plane reject most pairs (6 orient3d); otherwise both triangles meet the line L of the
/// two planes in an interval, and after a cyclic relabelling that leaves one vertex of each
/// triangle alone on its side, the intervals overlap iff two more orient3d signs allow it.
/// Special cases are decided exactly: coplanar triangles by the 2D test (`triangles_meet_2d.h`) in
/// a coordinate projection along which their projected area is exactly non-zero (an affine
/// bijection of their plane); a degenerate triangle (collinear or coincident vertices) as the
/// segment or point it spans (segment against triangle: the section's edge-face test with
/// orient3d; segment against segment; point on a triangle or segment).
/// O(1): about 6-8 orient3d calls.
[[nodiscard]] bool triangles_meet(const Triangle3& a, const Triangle3& b);

/// True when the closed segment `s` and the closed triangle `t` share a point (the section's
/// edge-face test made exact: endpoints on opposite sides or on the plane by orient3d, then the
/// crossing point in the face by the signs of the three tetrahedra (s, edge), never by computing
/// the point). Coplanar: the 2D test in an exact projection. Degenerate `t` or zero-length `s`
/// included. O(1).
[[nodiscard]] bool segment_meets_triangle(const Segment3& s, const Triangle3& t);

/// Which corners `a` and `b` share, by coordinates: corner m of `b` is corner result[m] of `a`,
/// or -1. For triangles whose corners are pairwise distinct within each.
[[nodiscard]] std::array<int, 3> shared_corners(const Triangle3& a, const Triangle3& b);

/// True when the non-degenerate triangles `a` and `b` (corners pairwise distinct within each)
/// share a point besides the corners and the edge they share (corner m of `b` is corner
/// b_in_a[m] of `a`, or -1: `shared_corners`), exactly: the decision of two triangles of one
/// mesh. None shared: `triangles_meet`. One shared: the edge of either opposite it meets the
/// other (a common point beyond the corner makes a segment from it, which leaves one of the
/// triangles through that edge or ends inside both). An edge shared: both in one plane
/// (orient3d) with the third corners on one side of the edge (orient2d in a projection that is
/// one to one on the plane). Three shared (the same triangle twice): false, left to the caller
/// (a mesh check reports it in its own way). O(1): at most about 10 orient3d.
[[nodiscard]] bool triangles_meet_beyond_shared(const Triangle3& a, const Triangle3& b,
                                                const std::array<int, 3>& b_in_a);
[[nodiscard]] inline bool triangles_meet_beyond_shared(const Triangle3& a, const Triangle3& b) {
  return triangles_meet_beyond_shared(a, b, shared_corners(a, b));
}

}  // namespace contain::predicates
