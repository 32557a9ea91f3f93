#pragma once
/// \file
/// Exact orientation of a closed ring, and of closed cycles of directed edges: the sign of
/// their signed area, decided exactly.

#include <optional>
#include <span>

#include "contain/predicates/sign.h"
#include "contain/values/segment.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// The orientation of the closed ring p_0, ..., p_{n-1} (the edge p_{n-1} -> p_0 implied; do not
/// repeat the first point at the end, though a repeat only adds an edge of length zero): the
/// exact sign of the shoelace sum
///     A = sum over i of (x_i y_{i+1} - x_{i+1} y_i)   (indices mod n),
/// twice the ring's signed area, evaluated in real arithmetic on the given doubles.
/// Positive: counter-clockwise (the region on the left of every edge), negative: clockwise.
///
/// Degenerate rings, all by the same formula (no vertex is special):
/// - fewer than three vertices, all vertices collinear, repeated vertices only: zero;
/// - repeated vertices add zero-length edges, which add nothing: the orientation of the ring
///   with the repeats removed; a spike (a vertex with zero turn) likewise adds no area;
/// - a self-intersecting ring: the sign of the area weighted by the winding number, the integral
///   of wind(p) over the plane; a figure eight with equal lobes is zero, with unequal lobes it
///   takes the larger lobe's orientation. (For a simple ring this is the orientation at its
///   lowest vertex, the usual one-vertex rule; for other rings the one-vertex rule is not
///   defined or depends on the vertex.)
/// Translation does not change A, so it is the sign of sum_i det[p_i - p_0, p_{i+1} - p_0].
///
/// Exact for every finite double (NaN or infinite input is a precondition violation): a
/// floating-point filter on the fan sum about p_0 with a proven bound (docs/robustness.md,
/// "Predicates"), then exact expansion arithmetic on the shoelace sum (Shewchuk 1997) when the
/// coordinates lie in 2^-480..2^500 and n <= 2^20, else `BigFloat`. O(n) for the filter; the
/// exact stages are O(n k) for k <= 2n expansion components (a few in practice).
[[nodiscard]] Sign ring_orientation(std::span<const Vec2> ring);

/// The orientation of directed edges that form closed cycles (each vertex has as many edges in
/// as out: the border of a region before it is chained into rings): the exact sign of
///     A = sum over edges (a, b) of (a.x b.y - a.y b.x),
/// twice the total signed area of the cycles (each weighted by its winding number), as
/// `ring_orientation`. For cycles that close, A is the same about every origin; edges that do
/// not close are summed about the origin (0, 0) as written. No edges, or only degenerate ones:
/// zero. Exact as `ring_orientation` (its filter sums about the origin); O(m) for m edges.
[[nodiscard]] Sign edges_orientation(std::span<const Segment2> edges);

namespace detail {
/// The stages of `ring_orientation`, each callable alone for the tests: the filter (no answer
/// when the rounded sum lies within its bound), the expansion stage (precondition: every
/// coordinate 0 or of magnitude in [2^-480, 2^500), n <= 2^20) and the big-number stage.
[[nodiscard]] std::optional<Sign> ring_orientation_filter(std::span<const Vec2> ring);
[[nodiscard]] Sign ring_orientation_expansion(std::span<const Vec2> ring);
[[nodiscard]] Sign ring_orientation_big(std::span<const Vec2> ring);
}  // namespace detail

}  // namespace contain::predicates
