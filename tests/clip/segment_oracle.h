#pragma once
// The exact oracle of the segment clippers: the clipped parameter interval in GMP rationals, and
// random segments rich in degenerate positions.

#include <gmpxx.h>

#include <random>
#include <span>
#include <utility>
#include <vector>

#include "contain/shapes/polygon.h"
#include "contain/values/box.h"
#include "contain/values/plane.h"
#include "contain/values/segment.h"
#include "contain/values/triangle.h"

namespace contain::test {

/// The exact part of a segment inside a set of half-spaces: t0 <= t <= t1.
struct OracleClip {
  bool kept = false;
  bool touching = false;  ///< kept, t0 == t1 and the segment has positive length
  mpq_class t0 = 0;
  mpq_class t1 = 1;
};

/// From the exact values (s(a), s(b)) of every half-space function (positive inside).
[[nodiscard]] OracleClip oracle_clip(const std::vector<std::pair<mpq_class, mpq_class>>& values,
                                     bool degenerate_segment);

[[nodiscard]] OracleClip oracle_clip(const Segment3& s, const Box3& box);
[[nodiscard]] OracleClip oracle_clip(const Segment2& s, const Box2& box);
[[nodiscard]] OracleClip oracle_clip(const Segment3& s, std::span<const Plane> planes);
[[nodiscard]] OracleClip oracle_clip(const Segment2& s, std::span<const HalfPlane> planes);
/// Faces counter-clockwise from outside.
[[nodiscard]] OracleClip oracle_clip(const Segment3& s, std::span<const Triangle3> faces);
/// A counter-clockwise convex ring.
[[nodiscard]] OracleClip oracle_clip_ring(const Segment2& s, const Ring& ccw_ring);

/// Coordinates drawn from a small integer grid (half the time) or uniform doubles, so that
/// segments often lie in faces, pass through corners, run parallel to faces or have zero length.
class SegmentGenerator {
 public:
  explicit SegmentGenerator(unsigned seed) : rng_(seed) {}
  [[nodiscard]] double coordinate();
  [[nodiscard]] Segment3 segment3();
  [[nodiscard]] Segment2 segment2();

 private:
  std::mt19937_64 rng_;
};

[[nodiscard]] double to_double(const mpq_class& q);

}  // namespace contain::test
