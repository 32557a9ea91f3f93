#pragma once
/// \file
/// A segment clipped by a ball or a disc (exercise 22.4-7 of "Algorithms of Informatics" vol. 2).

#include "contain/clip/clipped_segment.h"
#include "contain/values/segment.h"
#include "contain/values/sphere.h"

namespace contain::clip {

/// Clips a segment by the closed ball |p - c| <= r: the part where the quadratic
/// |a + t (b - a) - c|^2 - r^2 is <= 0.
///
/// Exact decisions: each endpoint by predicates::side_of_sphere; if both are in, all is kept
/// (the ball is convex); if both are out, the segment meets the ball iff the nearest point of
/// its line lies strictly between them (signs of w.d and d.d - w.d, w = c - a, d = b - a) and
/// (r^2 - w.w) d.d + (w.d)^2 >= 0, decided in exact big-number arithmetic; equality is tangency
/// and gives a zero-length segment at the tangent point. Accuracy: roots of the quadratic in
/// floating point (the cancellation-free form), then checked with side_of_sphere and moved
/// inward along the kept part if rounding put them outside (not possible for a tangent point).
/// A zero radius is a single point. O(1).
[[nodiscard]] ClippedSegment3 clip_segment(const Segment3& segment, const Sphere& ball);

/// The 2D form: a segment by the closed disc (side_of_circle).
[[nodiscard]] ClippedSegment2 clip_segment(const Segment2& segment, const Circle& disc);

}  // namespace contain::clip
