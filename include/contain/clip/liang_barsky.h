#pragma once
/// \file
/// Liang-Barsky parametric line clipping against an axis-aligned box (Y.-D. Liang, B. A. Barsky,
/// "A new concept and method for line clipping", ACM TOG 3(1), 1984).

#include "contain/clip/clipped_segment.h"
#include "contain/values/box.h"
#include "contain/values/segment.h"

namespace contain::clip {

/// Clips with the parametric form: for every axis with b_k != a_k the slab min_k <= x_k <= max_k
/// bounds t by an entering and an exiting face parameter; t0 = max(0, entering), t1 = min(1,
/// exiting); kept iff t0 <= t1. An axis with b_k == a_k keeps all or nothing (a_k in the slab).
///
/// Exactness: parameters are never compared as rounded quotients: two face parameters of axes k
/// and j compare by the sign of an orient2d in the (k, j) coordinate plane on the original
/// endpoints and the face corner, and a parameter compares with 0 and 1 by coordinate
/// comparisons. So missed / touched (t0 == t1, a zero-length segment) / crossed is exact and
/// agrees with `cohen_sutherland` and `cyrus_beck`. Accuracy as `cohen_sutherland`: the coordinate
/// on the face is the face value, the others are clamped into the box. O(D).
[[nodiscard]] ClippedSegment2 liang_barsky(const Segment2& segment, const Box2& box);
[[nodiscard]] ClippedSegment3 liang_barsky(const Segment3& segment, const Box3& box);

}  // namespace contain::clip
