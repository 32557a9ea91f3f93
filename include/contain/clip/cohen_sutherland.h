#pragma once
/// \file
/// Cohen-Sutherland line clipping against an axis-aligned box ("Algorithms of Informatics" vol. 2,
/// § 22.4, Definition 22.11 and the algorithm Cohen-Sutherland-Line-Clipping), in 2D (4-bit codes)
/// and 3D (6-bit).

#include <cstdint>

#include "contain/clip/clipped_segment.h"
#include "contain/values/box.h"
#include "contain/values/segment.h"

namespace contain::clip {

/// Code bits: 1 where the point is outside with respect to the box's plane.
enum OutcodeBit : std::uint8_t {
  outcode_x_min = 1u << 0,  ///< x < min.x
  outcode_x_max = 1u << 1,  ///< x > max.x
  outcode_y_min = 1u << 2,  ///< y < min.y
  outcode_y_max = 1u << 3,  ///< y > max.y
  outcode_z_min = 1u << 4,  ///< z < min.z (3D)
  outcode_z_max = 1u << 5,  ///< z > max.z (3D)
};

/// The code word of a point (0: inside the closed box, faces included). Exact comparisons.
[[nodiscard]] std::uint8_t outcode(Vec2 p, const Box2& box);
[[nodiscard]] std::uint8_t outcode(Vec3 p, const Box3& box);

/// Cohen-Sutherland as the section gives it: code words of both endpoints; trivial accept when
/// both are 0 (`c0 | c1 == 0`), trivial reject when they share a bit (`c0 & c1 != 0`); otherwise
/// clip at the plane of the first (lowest) bit where they differ, replacing the endpoint that is
/// outside it, and repeat.
///
/// Exactness: the code word of a computed intersection point is not taken from its rounded
/// coordinates but decided exactly for the true point on the segment's line (the sign of
/// q_j - w for the crossing q with the face x_k = v is that of an orient2d in the (k, j)
/// coordinate plane on the original endpoints), so accept / reject / touch are exact and agree
/// with `liang_barsky`. A segment touching the box (at a corner, an edge or a face point) gives a
/// zero-length segment. A segment lying in a face is kept whole. An empty box (min > max in some
/// axis) keeps nothing.
///
/// Accuracy: the coordinate on the clipping face is the face's value exactly; the others are
/// a_j + t (b_j - a_j) with t = (v - a_k) / (b_k - a_k), within about 4 ulps of max(|a_j|, |b_j|)
/// of the true point, then clamped into [min_j, max_j] (the true point lies there), so every
/// returned point lies in the closed box. O(1): at most 2 D clipping steps.
[[nodiscard]] ClippedSegment2 cohen_sutherland(const Segment2& segment, const Box2& box);
[[nodiscard]] ClippedSegment3 cohen_sutherland(const Segment3& segment, const Box3& box);

}  // namespace contain::clip
