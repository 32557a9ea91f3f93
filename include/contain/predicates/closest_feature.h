#pragma once
/// \file
/// Which vertex, edge or face of a triangle or segment holds the point closest to a query point,
/// decided exactly: the step that turns "the distance to a triangle" into the distance between
/// two flats (`squared_distance.h`), whose value is then a known quotient.

#include <cstdint>

#include "contain/predicates/sign.h"
#include "contain/predicates/squared_distance.h"
#include "contain/values/segment.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// The part of a triangle that holds its point closest to a query point.
enum class TriangleFeature : std::uint8_t {
  vertex_a,
  vertex_b,
  vertex_c,
  edge_ab,
  edge_bc,
  edge_ca,
  face
};

/// The part of a segment that holds its point closest to a query point.
enum class SegmentFeature : std::uint8_t { vertex_a, vertex_b, interior };

/// Sign of (b - a) . (p - a), exactly (degree 2): positive when p lies beyond the plane through
/// a perpendicular to a b, on b's side.
[[nodiscard]] Sign dot_sign(Vec3 a, Vec3 b, Vec3 p);
[[nodiscard]] Sign dot_sign(Vec2 a, Vec2 b, Vec2 p);

/// True when a, b, c are collinear (or coincide), exactly: the triangle has no face.
[[nodiscard]] bool collinear(Vec3 a, Vec3 b, Vec3 c);

/// The feature of `t` that holds the point of `t` closest to `p` (the closed triangle is convex,
/// so that point is unique), exactly:
/// - `face` when the triangle is not degenerate and p projects into the closed triangle
///   (cross_dot >= 0 across all three edges); the distance is then p's distance to the plane;
/// - otherwise the closest of the three closed edges, each reduced to a vertex where p projects
///   onto or beyond an end (dot_sign <= 0), by exact comparisons. Where the point is a vertex
///   shared by several of these, the vertex is named; coincident vertices resolve to the first of
///   a, b, c; an edge of zero length is its vertex.
/// A degenerate triangle (collinear corners) is its segment hull and never answers `face`.
/// O(1); exact for every finite double.
[[nodiscard]] TriangleFeature closest_feature(const Triangle3& t, Vec3 p);

/// The feature of the closed segment `s` closest to `p`: `vertex_a` where dot_sign(a, b, p) <= 0
/// (also for a segment of zero length), `vertex_b` where dot_sign(b, a, p) <= 0, else `interior`.
[[nodiscard]] SegmentFeature closest_feature(const Segment3& s, Vec3 p);
[[nodiscard]] SegmentFeature closest_feature(const Segment2& s, Vec2 p);

/// The flat carrying a feature: a vertex, the line of an edge, the plane of the face.
[[nodiscard]] Flat3 feature_flat(const Triangle3& t, TriangleFeature f);
[[nodiscard]] Flat3 feature_flat(const Segment3& s, SegmentFeature f);
[[nodiscard]] Flat2 feature_flat(const Segment2& s, SegmentFeature f);

/// The flats carrying the closest points of two closed segments (the first flat on s, the
/// second on t), exactly: the least of the four end-to-segment distances and, when the lines
/// are not parallel and the feet of their common perpendicular lie strictly inside both
/// segments, the line-line distance; equal distances keep the first in that order (s.a, s.b,
/// t.a, t.b, interior). In the plane, segments that cross properly (each end strictly on either
/// side of the other's line) give their crossing (a pair of crossing lines, distance 0).
/// Segments of zero length are points.
[[nodiscard]] FlatPair3 closest_flats(const Segment3& s, const Segment3& t);
[[nodiscard]] FlatPair2 closest_flats(const Segment2& s, const Segment2& t);

/// The flats carrying the closest points of two closed triangles (first on s, second on t),
/// exactly. Where an edge of one passes through the interior of the other (both ends strictly on
/// either side of its plane, the line strictly inside its three edges), that edge's line and the
/// other's plane (distance 0, their crossing). Otherwise the least of the six vertex-triangle and
/// nine edge-edge distances (the triangles are convex, so the closest points lie on a vertex and
/// a triangle or on two edges); equal distances keep the first in the order: s's vertices against
/// t, t's vertices against s, then edge pairs (ab, bc, ca of s against ab, bc, ca of t).
/// Degenerate triangles are their segment hulls. O(1); exact for every finite double.
[[nodiscard]] FlatPair3 closest_flats(const Triangle3& s, const Triangle3& t);

/// True when the closed segment p q crosses the interior of triangle t: p and q strictly on
/// either side of its plane and the line p q strictly inside its three edges (exact orient3d).
[[nodiscard]] bool segment_crosses_triangle(const Triangle3& t, Vec3 p, Vec3 q);

}  // namespace contain::predicates
