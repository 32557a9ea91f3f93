#pragma once
// The stages of slice_mesh and shadow (include/contain/clip/slice_mesh.h), one file each:
// prepare.cpp (weld, sort triangles along the axis), crossings.cpp (a plane's directed crossing
// segments, for the plane just above and just below), rings.cpp (chaining them into closed
// paths through shared keys), provenance.cpp (the triangle under each output edge), sweep.cpp
// (planes in sorted order, the active triangles, one section each), shadow.cpp.

#include <cstdint>
#include <span>
#include <vector>

#include "contain/clip/slice_mesh.h"
#include "contain/core/result.h"
#include "contain/shapes/mesh.h"
#include "contain/shapes/polygon.h"
#include "contain/values/vec.h"

namespace contain::clip::slice {

/// The axis k of the planes and the section's coordinates (u, v), cyclic so that (u, v, k) is
/// right-handed.
struct Frame {
  int k = 2;
  int u = 0;
  int v = 1;
};
[[nodiscard]] Frame frame_of(Axis axis);
[[nodiscard]] inline double coord(Vec3 p, int i) {
  return i == 0 ? p.x : (i == 1 ? p.y : p.z);
}
[[nodiscard]] inline Vec2 project(Vec3 p, const Frame& f) {
  return {coord(p, f.u), coord(p, f.v)};
}

/// Ok, or `ErrorKind::degenerate` naming one directed edge (by position) that occurs more often
/// than its reverse: an open mesh has no winding number off its surface.
[[nodiscard]] Status require_closed(const Mesh& mesh);

/// The mesh as the sweep reads it: vertices welded by position (closedness and chaining judge
/// vertices by position), triangles in file order, and the triangles that are not flat along
/// the axis sorted by their lowest coordinate (then index).
struct SweepMesh {
  Frame frame;
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  std::vector<double> low, high;     // per triangle, along the axis
  std::vector<std::int32_t> by_low;  // non-flat triangles, by low
};
[[nodiscard]] SweepMesh prepare(const Mesh& mesh, const Frame& frame);

/// One triangle's directed piece of a plane's curve: from the crossing of its edge going down
/// to the crossing of its edge going up (so that the curve runs counter-clockwise around the
/// solid, seen from +axis). A crossing is keyed by the mesh edge (its welded vertex pair) or by
/// the vertex on the plane, so that the triangles of an edge meet at one key.
struct CrossingSegment {
  std::uint64_t from_key = 0;
  std::uint64_t to_key = 0;
  Vec2 from;
  Vec2 to;
  std::int32_t triangle = 0;
};

/// The curves of a plane: `above` for the plane just above c (a vertex on the plane counts
/// below it), `below` for the plane just below (a vertex on it counts above). `touches` is
/// false when no vertex of the active triangles lies on the plane; `below` is then left empty,
/// being equal to `above`. `active`: triangle indices in increasing order.
struct PlaneCurves {
  std::vector<CrossingSegment> above;
  std::vector<CrossingSegment> below;
  bool touches = false;
};
[[nodiscard]] PlaneCurves crossing_segments(const SweepMesh& mesh,
                                            std::span<const std::int32_t> active, double c);

/// Closed paths through the segments, joined where one's to_key is another's from_key. The
/// segments of a closed mesh balance at every key, so every walk closes; zero-length pieces
/// (from_key == to_key) are left out, and so are paths of fewer than 3 points. Deterministic for
/// a given segment order. `triangles`, when given, receives per ring the triangle of the segment
/// each edge (point k to k + 1) comes from.
[[nodiscard]] std::vector<Ring> chain_rings(
    std::span<const CrossingSegment> segments,
    std::vector<std::vector<std::int32_t>>* triangles = nullptr);

/// The section of a plane through no vertex when the chained rings are already the answer:
/// every ring proven simple and counter-clockwise (star-shaped about the mean of its vertices,
/// or strictly convex: exact orient2d at every vertex, one turn), their boxes pairwise disjoint,
/// and every segment used by a ring. Then the rings are simple, disjoint and not nested, so
/// `polygon_boolean` (union, positive) would return each ring as a polygon, in order, from its
/// first point, and each edge's provenance is its own segment. False (out untouched) when that
/// is not proven: the caller runs the 2D engine.
[[nodiscard]] bool simple_section(std::vector<Ring>& rings,
                                  std::vector<std::vector<std::int32_t>>& triangles,
                                  std::size_t segments, Section& out);

/// For each ring of `region` (in `all_rings` order) and each of its edges, the triangle of a
/// segment that the edge lies on: exactly (both ends on the segment, exact orient2d), else the
/// nearest candidate (an end that the 2D engine rounded or snapped), preferring the segment's
/// direction and then the lowest triangle index.
[[nodiscard]] std::vector<std::vector<std::int32_t>> edge_triangles(
    const MultiPolygon& region, std::span<const CrossingSegment> segments);

/// The section at c from the active triangles (increasing indices).
[[nodiscard]] Section section_at(const SweepMesh& mesh, std::span<const std::int32_t> active,
                                 double c);

/// Sections of the planes values[order[i]] for i in [begin, end), `order` sorting the values
/// increasingly: one sweep with an active set, each answer written to out[order[i]].
void sweep(const SweepMesh& mesh, std::span<const double> values,
           std::span<const std::size_t> order, std::size_t begin, std::size_t end,
           std::span<Section> out);

}  // namespace contain::clip::slice
