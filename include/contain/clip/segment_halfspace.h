#pragma once
/// \file
/// A segment against one half-space or half-plane: the three cases of "Algorithms of Informatics"
/// vol. 2, § 22.4, and its intersection parameter (section 22.4, "Clipping").

#include <cstdint>

#include "contain/clip/clipped_segment.h"
#include "contain/values/plane.h"
#include "contain/values/segment.h"

namespace contain::clip {

/// The section's three cases for a segment and a closed half-space, decided exactly by the signs
/// of predicates::side_of_plane (side_of_line in 2D) at the two endpoints (zero counts as in).
enum class SegmentCase : std::uint8_t {
  inside,    ///< both endpoints in: the whole segment is kept
  outside,   ///< both endpoints out: the segment is removed
  crossing,  ///< one endpoint in, one out: the out endpoint is replaced by the crossing point
};

/// Which of the three cases holds. Exact. O(1).
[[nodiscard]] SegmentCase segment_case(const Segment3& segment, const Plane& half_space);
[[nodiscard]] SegmentCase segment_case(const Segment2& segment, const HalfPlane& half_plane);

/// The section's intersection parameter: t = s(a) / (s(a) - s(b)), where s(p) = a p.x + b p.y +
/// c p.z + d, so that a + t (b - a) lies on the plane. Floating point (relative error a few ulps
/// when the endpoints are not nearly on the plane). Precondition: s(a) != s(b) exactly (not
/// parallel); for the `crossing` case t is in [0, 1], and it is 0 or 1 exactly when the in
/// endpoint lies on the plane.
[[nodiscard]] double crossing_parameter(const Segment3& segment, const Plane& half_space);
[[nodiscard]] double crossing_parameter(const Segment2& segment, const HalfPlane& half_plane);

/// Clips a segment by a closed half-space: the three cases, with the crossing point computed
/// from `crossing_parameter`. An in endpoint on the plane with the other out gives the
/// zero-length segment at that endpoint (touching). The computed crossing point is checked with
/// side_of_plane and, if rounding put it outside, moved toward the in endpoint by the smallest
/// tried step that brings it inside, so every returned point lies in the closed half-space
/// (exactly). A zero-length input segment is kept iff its point is in. A plane with a = b = c = 0
/// is all of space (d >= 0) or nothing. O(1) (the adjustment takes at most ~60 predicate calls).
[[nodiscard]] ClippedSegment3 clip_segment(const Segment3& segment, const Plane& half_space);
[[nodiscard]] ClippedSegment2 clip_segment(const Segment2& segment, const HalfPlane& half_plane);

}  // namespace contain::clip
