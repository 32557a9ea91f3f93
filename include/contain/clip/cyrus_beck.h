#pragma once
/// \file
/// Cyrus-Beck clipping of a segment by a convex polygon or polyhedron: the generalisation of
/// Cohen-Sutherland to convex clipping regions asked by exercise 22.4-6 of "Algorithms of
/// Informatics" vol. 2 (M. Cyrus, J. Beck, "Generalized two- and three-dimensional clipping",
/// Computers & Graphics 3(1), 1978).

#include <span>

#include "contain/clip/clipped_segment.h"
#include "contain/shapes/convex_polyhedron.h"
#include "contain/shapes/polygon.h"
#include "contain/values/plane.h"
#include "contain/values/segment.h"

namespace contain::clip {

/// Clips a segment by the intersection of closed half-spaces (the region need not be bounded).
///
/// With s_i(p) the value of half-space i (positive inside), each half-space is, like a code bit,
/// decided exactly from the signs at the endpoints: both in: no constraint; both out: trivial
/// reject; otherwise an entering (s(a) < 0 <= s(b)) or exiting (s(a) >= 0 > s(b)) parameter
/// t_i = s_i(a) / (s_i(a) - s_i(b)). t0 = max(0, entering), t1 = min(1, exiting), kept iff
/// t0 <= t1. Two parameters are compared exactly: sign(t_i - t_j) is the sign of
/// s_j(a) s_i(b) - s_i(a) s_j(b) (times the signs of the denominators), decided by a
/// floating-point filter with a proven error bound and, near ties, exact big-number arithmetic.
/// So missed / touched (zero-length result) / crossed is exact, and on a box's six half-spaces
/// it agrees with `liang_barsky` and `cohen_sutherland`.
///
/// Accuracy: crossing points are a + t (b - a) with t from the rounded values, a few ulps from
/// the true point; each is then checked against every half-space exactly and, if rounding put it
/// outside, moved along the kept part toward its other end until it is inside (so returned
/// points lie in the closed region), with two exceptions: a zero-length (touching) result,
/// whose one point may miss the region by rounding; and a kept part shorter than the resolution
/// of t (about 2^-53 of the segment's length, e.g. 9 units of a segment 3.5e282 long), which no
/// double t names a point of, so both returned points can lie outside the region. In both the
/// decision kept / touched / missed stays exact (docs/robustness.md, "Documented, not a bug");
/// `liang_barsky` and `cohen_sutherland` keep their points in the box always.
/// Half-spaces with a zero normal are all or nothing.
/// O(n) for n half-spaces (O(n) more predicate calls if a point is adjusted).
[[nodiscard]] ClippedSegment3 cyrus_beck(const Segment3& segment,
                                         std::span<const Plane> half_spaces);

/// Against a convex polyhedron: its planes, or for one made from a mesh its faces, whose side
/// tests are predicates::orient3d on the three face vertices (exact, no rounded plane).
[[nodiscard]] ClippedSegment3 cyrus_beck(const Segment3& segment,
                                         const ConvexPolyhedron& polyhedron);

/// 2D: against the intersection of closed half-planes.
[[nodiscard]] ClippedSegment2 cyrus_beck(const Segment2& segment,
                                         std::span<const HalfPlane> half_planes);

/// 2D: against a convex ring (counter-clockwise or clockwise; collinear and repeated vertices
/// allowed), each edge's side test being predicates::orient2d on its two vertices. A ring with no
/// three non-collinear vertices encloses nothing: the result is never kept. For a non-convex ring
/// the result is unspecified.
[[nodiscard]] ClippedSegment2 cyrus_beck(const Segment2& segment, const Ring& convex_ring);

}  // namespace contain::clip
