#pragma once
/// \file
/// What is left of a segment after clipping: the answer of every segment clipper in `clip::`.

#include "contain/values/segment.h"

namespace contain::clip {

/// The part of the closed segment p(t) = a + t (b - a), 0 <= t <= 1, inside a closed region.
///
/// - `kept == false`: nothing is left (the segment misses the region); `segment`, `t0` and `t1`
///   are then unspecified.
/// - otherwise `segment` runs from p(t0) to p(t1), 0 <= t0 <= t1 <= 1, in the input's direction.
///   An endpoint that was inside is returned bit for bit (t = 0 or 1 exactly). `t0 == t1` and
///   `segment.a == segment.b` when the segment only touches the region (at one point): a
///   zero-length segment, not `kept == false`.
///
/// Which of the three happens (missed, touched, crossed) is decided exactly on the given doubles.
/// Computed crossing points are floating point; each clipper documents its accuracy.
struct ClippedSegment2 {
  bool kept = false;
  Segment2 segment;
  double t0 = 0.0;
  double t1 = 0.0;

  explicit operator bool() const { return kept; }
};

/// The 3D form of `ClippedSegment2`.
struct ClippedSegment3 {
  bool kept = false;
  Segment3 segment;
  double t0 = 0.0;
  double t1 = 0.0;

  explicit operator bool() const { return kept; }
};

}  // namespace contain::clip
