#pragma once
/// \file
/// Batch segment clipping: spans in, spans out, spread over threads (core/parallel.h).

#include <cstdint>
#include <span>

#include "contain/core/parallel.h"
#include "contain/shapes/convex_polyhedron.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"
#include "contain/values/plane.h"
#include "contain/values/segment.h"
#include "contain/values/sphere.h"

namespace contain::clip {

/// Clips every segment: `kept[i]` is 1 when something of `segments[i]` is left and `out[i]` is
/// then that part (zero-length when it only touches), 0 when nothing is left (`out[i]` is then
/// unspecified). Results per index do not depend on the thread count.
/// `out` and `kept` have the size of `segments` (asserted: a different size is a programming
/// error; a build without assertions clips the common prefix). Finite coordinates.
///
/// The box forms run a branch-free kernel (no data-dependent branch; GCC/Clang vector
/// extensions: four segments per step in AVX2 where the CPU has it, chosen at run time, else
/// two in SSE2, which every x86-64 has; no -march needed, and the same bits either way)
/// computing Liang-Barsky in floating point together with a certificate: every decision whose
/// margin exceeds the kernel's proven rounding error bound (8.01 eps of the parameters involved) is
/// final; the rest (touching, nearly touching, parallel on a face, huge or tiny coordinates) are
/// redone by the exact `liang_barsky`. So decisions equal `liang_barsky`'s exactly; points agree
/// with it to rounding (the kernel may pick the other face at a corner tie) and lie in the
/// closed box. The other regions call `clip_segment` (half-space, ball, disc) and `cyrus_beck`.
/// O(n) work; O(n / threads) time.
void clip_segments(std::span<const Segment3> segments, const Box3& box, std::span<Segment3> out,
                   std::span<std::uint8_t> kept, const BatchOptions& options = {});
void clip_segments(std::span<const Segment2> segments, const Box2& box, std::span<Segment2> out,
                   std::span<std::uint8_t> kept, const BatchOptions& options = {});
void clip_segments(std::span<const Segment3> segments, const Plane& half_space,
                   std::span<Segment3> out, std::span<std::uint8_t> kept,
                   const BatchOptions& options = {});
void clip_segments(std::span<const Segment2> segments, const HalfPlane& half_plane,
                   std::span<Segment2> out, std::span<std::uint8_t> kept,
                   const BatchOptions& options = {});
void clip_segments(std::span<const Segment3> segments, const Sphere& ball, std::span<Segment3> out,
                   std::span<std::uint8_t> kept, const BatchOptions& options = {});
void clip_segments(std::span<const Segment2> segments, const Circle& disc, std::span<Segment2> out,
                   std::span<std::uint8_t> kept, const BatchOptions& options = {});
void clip_segments(std::span<const Segment3> segments, const ConvexPolyhedron& polyhedron,
                   std::span<Segment3> out, std::span<std::uint8_t> kept,
                   const BatchOptions& options = {});
void clip_segments(std::span<const Segment2> segments, const Ring& convex_ring,
                   std::span<Segment2> out, std::span<std::uint8_t> kept,
                   const BatchOptions& options = {});

}  // namespace contain::clip
