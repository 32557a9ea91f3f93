#pragma once
/// \file
/// 2D regions (polygons with holes, multipolygons) clipped by half-planes, a box or a convex
/// polygon: Sutherland-Hodgman ring by ring (the section: "executed separately for each closed
/// polyline of the boundary"), with the result either as the section gives it or split into its
/// separate valid pieces.

#include <cstdint>
#include <span>

#include "contain/shapes/polygon.h"
#include "contain/values/box.h"
#include "contain/values/plane.h"

namespace contain::clip {

/// What `clip_polygon` returns.
enum class PolygonClipOutput : std::uint8_t {
  /// The region split into its pieces: an OGC-valid MultiPolygon for OGC-valid input (closed
  /// simple rings, shells counter-clockwise, holes clockwise, every hole in its piece).
  pieces,
  /// The section's result: one ring per input ring (rings that vanish are left out; a polygon
  /// whose shell vanishes is left out), with the degenerate bridging edges along the clip lines;
  /// read under the even-odd rule it covers the same area. Ring directions as in the input.
  bridged,
};

struct PolygonClipOptions {
  PolygonClipOutput output = PolygonClipOutput::pieces;
};

/// Clips a region by the intersection of closed half-planes (a convex region, possibly
/// unbounded), one half-plane after the other.
///
/// Pieces: for each half-plane, each polygon's rings are walked once (shells turned
/// counter-clockwise and holes clockwise first, orientation decided exactly at the lowest
/// vertex); the runs of the rings inside the half-plane become chains from an entry point on the
/// line to an exit point on it (a vertex on the line is taken as an entry or exit according to
/// the next vertex off the line, so parts lying in the line with nothing inside beside them give
/// no area); the chain ends are sorted along the line exactly (big-number comparisons of
/// the exact crossing points' positions, ties: exit first) and each exit joins the next entry
/// along the line's direction (inside on the left). The closed cycles are the pieces' shells;
/// rings entirely inside stay as they are, and each hole not cut goes to the piece that contains
/// it (inside::point_in_polygon). Rings entirely outside, and pieces of zero area, are dropped.
/// Decisions are exact on the doubles each step sees; crossing points are rounded as in
/// `sutherland_hodgman`. For input that is not OGC-valid (self-intersecting rings) the pieces
/// cover the clipped area but are not guaranteed valid.
///
/// Half-planes x >= k, x <= k, y >= k, y <= k (coefficients 0 and +-1, so k is exact) are taken
/// together as a box by the one-pass box cut below; the others then cut its pieces one after
/// the other. Each cut reads every ring once; a run of points strictly outside costs one
/// floating-point filter a point and is kept as its two ends (the chord lies outside too).
///
/// Complexity: O(n) per half-plane for n vertices (the box part: one pass with outcodes), plus
/// O(c log c) for c chain ends and O(h s) for h uncut holes and s pieces.
[[nodiscard]] MultiPolygon clip_polygon(const MultiPolygon& region,
                                        std::span<const HalfPlane> half_planes,
                                        const PolygonClipOptions& options = {});

/// By a closed box, in one pass over each ring with Cohen-Sutherland outcodes, all four sides at
/// once (docs/clipping.md): runs of points beyond one side cost a comparison a point; the edges
/// that can reach the box are cut with exact decisions (outcodes, orient2d with the corners);
/// the pieces are linked into chains from entry to exit on the boundary, and each exit joins the
/// next entry counter-clockwise through the corners between them. An edge lying on a side stays
/// when the region is on the box's side of it, so a hole whose edge lies on a side becomes a
/// notch of the shell. Crossing points lie on their side exactly (the other coordinate rounded,
/// with a proven error bound); where rounding or a degeneracy could change the topology (see
/// src/clip/box_cut.h) the region goes to `polygon_boolean` with the box, exact and valid in
/// every case. O(n) for n vertices. For many boxes against one region, `BoxClipper`.
[[nodiscard]] MultiPolygon clip_polygon(const MultiPolygon& region, const Box2& box,
                                        const PolygonClipOptions& options = {});

/// By a convex ring (either direction, see `sutherland_hodgman`): the box cut by the ring's
/// bounding box first, then the ring's edges (exact orient2d sides) cut its pieces.
[[nodiscard]] MultiPolygon clip_polygon(const MultiPolygon& region, const Ring& convex_ring,
                                        const PolygonClipOptions& options = {});

}  // namespace contain::clip
