#pragma once
/// \file
/// Batch segment clipping against a region chosen at run time (a box, half-spaces, a convex
/// region or a ball) with a choice of clipper: the one call behind `contain clip --segments`.

#include <cstdint>
#include <span>
#include <variant>
#include <vector>

#include "contain/core/parallel.h"
#include "contain/core/result.h"
#include "contain/shapes/convex_polyhedron.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"
#include "contain/values/plane.h"
#include "contain/values/segment.h"
#include "contain/values/sphere.h"

namespace contain::clip {

/// A closed region of the plane for 2D segments: a box, the intersection of half-planes
/// (a x + b y + c >= 0), a convex ring (either orientation) or a disc.
using SegmentRegion2 = std::variant<Box2, std::vector<HalfPlane>, Ring, Circle>;

/// A closed region of space for 3D segments: a box, the intersection of half-spaces
/// (a x + b y + c z + d >= 0), a convex polyhedron or a ball.
using SegmentRegion3 = std::variant<Box3, std::vector<Plane>, ConvexPolyhedron, Sphere>;

/// Which clipper runs.
enum class SegmentClipper : std::uint8_t {
  /// The region's own batch call of clip_segments.h: for a box the branch-free kernel with
  /// exact decisions, for one half-space `clip_segment(segment, half_space)`, for several
  /// `cyrus_beck`, for a
  /// convex polyhedron or ring `cyrus_beck` on its faces or edges, for a ball
  /// `clip_segment(segment, ball)`.
  automatic,
  /// `cohen_sutherland` (outcodes; a box only).
  cohen_sutherland,
  /// `liang_barsky` (a box only).
  liang_barsky,
  /// `cyrus_beck`: a box is clipped by its half-spaces (`box_halfspaces`); every other region as
  /// with `automatic` (their clippers are Cyrus-Beck already, or exact tests of their own).
  cyrus_beck,
};

/// Which clipper `clip_segments` runs (its threads: `BatchOptions`).
struct SegmentClipOptions {
  SegmentClipper clipper = SegmentClipper::automatic;
};

/// Clips every segment by `region` with `options.clipper`: `kept[i]` is 1 when something of
/// `segments[i]` is left and `out[i]` is then that part (zero-length when it only touches, an
/// endpoint that was inside returned bit for bit), 0 when nothing is left (`out[i]` unspecified).
/// Whether a segment misses, touches or crosses is decided exactly; points are as the chosen
/// clipper documents them (cohen_sutherland.h, liang_barsky.h, cyrus_beck.h, clip_segments.h).
///
/// Validated before any work (nothing is written on error):
/// - ErrorKind::usage: `out` or `kept` not of the size of `segments`; `cohen_sutherland` or
///   `liang_barsky` for a region that is not a box;
/// - ErrorKind::invalid_value: a coordinate of a segment or a number of the region that is NaN or
///   infinite (the message names the segment, 0-based).
///
/// Runs on `batch.threads` threads; the answer of each segment does not depend on the thread
/// count. O(n) work for n segments (O(n k) for k half-spaces, faces or ring edges), O(n / threads)
/// time. Reference: Algorithms of Informatics, vol. 2, § 22.4 (Cohen-Sutherland; exercise 22.4-6:
/// convex regions), Liang and Barsky 1984, Cyrus and Beck 1978.
[[nodiscard]] Status clip_segments(std::span<const Segment2> segments, const SegmentRegion2& region,
                                   std::span<Segment2> out, std::span<std::uint8_t> kept,
                                   const SegmentClipOptions& options = {},
                                   const BatchOptions& batch = {});

/// The 3D form: the same rules, with `SegmentRegion3`.
[[nodiscard]] Status clip_segments(std::span<const Segment3> segments, const SegmentRegion3& region,
                                   std::span<Segment3> out, std::span<std::uint8_t> kept,
                                   const SegmentClipOptions& options = {},
                                   const BatchOptions& batch = {});

}  // namespace contain::clip
