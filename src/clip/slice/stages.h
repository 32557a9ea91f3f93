#pragma once
// The stages of slice_mesh and shadow (include/contain/clip/slice_mesh.h), one file each:
// prepare.cpp (weld, sort triangles along the axis), crossings.cpp (a plane's directed crossing
// segments, for the plane just above and just below), rings.cpp (chaining them into closed
// paths through shared keys), simple_section.cpp and nested_section.cpp (sections that need no
// 2D boolean), walk.cpp (both at once along the surface, for a plane through no
// vertex of a manifold stretch), provenance.cpp (the triangle under each output edge), sweep.cpp
// (planes in sorted order, the active triangles, one section each), shadow.cpp.

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "contain/clip/slice_mesh.h"
#include "contain/core/result.h"
#include "contain/shapes/mesh.h"
#include "contain/shapes/mesh_validation.h"
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
/// than its reverse: an open mesh has no winding number off its surface. `weld` is
/// `weld_vertices(mesh)`.
[[nodiscard]] Status require_closed(const WeldResult& weld);

/// The mesh as the sweep reads it: vertices welded by position (closedness and chaining judge
/// vertices by position), each as its coordinates (u, v, axis) in x, y, z, so that the sweep
/// reads heights and section coordinates without the frame; triangles in file order, and the
/// pairing of their half-edges (`shapes::paired_half_edges`: -1 off manifold edges, everywhere
/// when not given). `vertices` and `triangles` are the input mesh's own when it needs no weld
/// (distinct vertices; and for the axis z, where the frame is the identity, no copy of the
/// vertices either), else they view `own_vertices` and `own_triangles`: the prepared mesh refers
/// to the input, which must outlive it, and is moved, never copied (a copy would view the
/// original's vectors).
struct SweepMesh {
  Frame frame;
  std::span<const Vec3> vertices;
  std::span<const TriangleIndices> triangles;
  std::vector<std::int32_t> twin;  // per half-edge 3t + i
  std::vector<Vec3> own_vertices;
  std::vector<TriangleIndices> own_triangles;

  SweepMesh() = default;
  SweepMesh(SweepMesh&&) = default;
  SweepMesh& operator=(SweepMesh&&) = default;
  SweepMesh(const SweepMesh&) = delete;
  SweepMesh& operator=(const SweepMesh&) = delete;
  ~SweepMesh() = default;

  /// Triangle t's extent along the axis (computed, not stored: the sweep asks for few).
  [[nodiscard]] double low(std::size_t t) const {
    const TriangleIndices& v = triangles[t];
    return std::min({height(v[0]), height(v[1]), height(v[2])});
  }
  [[nodiscard]] double high(std::size_t t) const {
    const TriangleIndices& v = triangles[t];
    return std::max({height(v[0]), height(v[1]), height(v[2])});
  }
  /// Both, from one read of the corners.
  [[nodiscard]] std::pair<double, double> extent(std::size_t t) const {
    const TriangleIndices& v = triangles[t];
    const double a = height(v[0]), b = height(v[1]), c = height(v[2]);
    return {std::min({a, b, c}), std::max({a, b, c})};
  }

 private:
  [[nodiscard]] double height(std::int32_t v) const {
    return vertices[static_cast<std::size_t>(v)].z;
  }
};
/// The mesh welded and in the frame, its half-edges paired, whether or not it is closed (-1
/// everywhere when it is not).
[[nodiscard]] SweepMesh prepare(const Mesh& mesh, const Frame& frame);
/// The same for a closed mesh, in `out`; else `require_closed`'s error.
[[nodiscard]] Status prepare_closed(const Mesh& mesh, const Frame& frame, SweepMesh& out);

/// The triangles that cross some plane of the sweep (not flat along the axis, and a plane value
/// in [low, high]), grouped by the first plane they reach: `triangles[start[i]]` to
/// `triangles[start[i + 1] - 1]` for plane `sorted[i]`, in index order. Triangles between two
/// planes never enter the sweep. `sorted`: the plane values in increasing order.
struct SweepStarts {
  std::vector<std::size_t> start;
  std::vector<std::int32_t> triangles;
};
[[nodiscard]] SweepStarts sweep_starts(const SweepMesh& mesh, std::span<const double> sorted);

/// The key of a plane's crossing on the mesh edge a-b (welded vertex numbers, either order).
[[nodiscard]] inline std::uint64_t edge_key(std::int32_t a, std::int32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

/// Open addressing from 64-bit keys to values, reused from plane to plane: `reset` empties it
/// by a new stamp (no clearing, no allocation once grown) with room for `entries` keys at most
/// half full.
template <class V>
class KeyTable {
 public:
  void reset(std::size_t entries) {
    const std::size_t size = std::bit_ceil(std::max<std::size_t>(16, 2 * entries));
    if (size > slots_.size() || stamp_ == std::numeric_limits<std::uint32_t>::max()) {
      slots_.assign(std::max(size, slots_.size()), Slot{});
      stamp_ = 0;
    }
    ++stamp_;
  }
  /// The value of key, or nullptr.
  [[nodiscard]] V* find(std::uint64_t key) {
    Slot& slot = slots_[probe(key)];
    return slot.stamp == stamp_ ? &slot.value : nullptr;
  }
  /// The value of key and true when the key was absent (its value then default).
  std::pair<V*, bool> insert(std::uint64_t key) {
    Slot& slot = slots_[probe(key)];
    if (slot.stamp == stamp_) return {&slot.value, false};
    slot = {key, stamp_, V{}};
    return {&slot.value, true};
  }

 private:
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t stamp = 0;
    V value{};
  };
  // The slot holding key, or the empty one where it would go.
  [[nodiscard]] std::size_t probe(std::uint64_t key) const {
    const std::size_t mask = slots_.size() - 1;
    std::uint64_t h = key * 0x9E3779B97F4A7C15ULL;
    h ^= h >> 32;
    for (std::size_t i = h & mask;; i = (i + 1) & mask) {
      if (slots_[i].stamp != stamp_ || slots_[i].key == key) return i;
    }
  }
  std::vector<Slot> slots_;
  std::uint32_t stamp_ = 0;
};

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
/// being equal to `above`. The segments come in the order of `active`.
struct PlaneCurves {
  std::vector<CrossingSegment> above;
  std::vector<CrossingSegment> below;
  bool touches = false;
};
[[nodiscard]] PlaneCurves crossing_segments(const SweepMesh& mesh,
                                            std::span<const std::int32_t> active, double c);
/// The same into `out` (its vectors reused), each crossing computed once through `memo`.
void crossing_segments(const SweepMesh& mesh, std::span<const std::int32_t> active, double c,
                       KeyTable<Vec2>& memo, PlaneCurves& out);

/// One closed walk of chain_rings: `size` segments from `begin` in ChainScratch::walk, `first`
/// the position of its least from_key, `least`.
struct ChainCycle {
  std::uint64_t least = 0;
  std::size_t begin = 0;
  std::size_t size = 0;
  std::size_t first = 0;
};

/// The buffers of chain_rings, reused from plane to plane.
struct ChainScratch {
  KeyTable<std::int32_t> leaving;  // from_key -> the one segment leaving it
  std::vector<char> used;
  std::vector<std::int32_t> walk;  // the segments of the closed walks, one after another
  std::vector<ChainCycle> cycles;
  std::vector<std::int32_t> rotated;  // one walk from its least key
  std::vector<std::int32_t> by_from;  // the general case: segments by (from_key, triangle)
  std::vector<std::size_t> cursor;
};

/// The rings of closed walks over the segments: cycle k is `walk[begin, begin + size)` (segment
/// numbers), written from position `first`, the cycles in increasing order of `least`: how
/// chain_rings writes the cycles of segments that leave every key once. Paths of fewer than 3
/// points are left out; `triangles` as for chain_rings. `cycles` is sorted in place.
void write_cycles(std::span<const CrossingSegment> segments, std::span<const std::int32_t> walk,
                  std::vector<ChainCycle>& cycles, std::vector<Ring>& rings,
                  std::vector<std::vector<std::int32_t>>* triangles,
                  std::vector<std::int32_t>& rotated);

/// Closed paths through the segments, joined where one's to_key is another's from_key. The
/// segments of a closed mesh balance at every key, so every walk closes; zero-length pieces
/// (from_key == to_key) are left out, and so are paths of fewer than 3 points. The walks are
/// those of the segments in order of (from_key, triangle), taking at each key the first unused
/// segment leaving it in that order (input order among equal pairs): so the answer does not
/// depend on the order of segments of distinct triangles. `triangles`, when given, receives per
/// ring the triangle of the segment each edge (point k to k + 1) comes from.
[[nodiscard]] std::vector<Ring> chain_rings(
    std::span<const CrossingSegment> segments,
    std::vector<std::vector<std::int32_t>>* triangles = nullptr);
[[nodiscard]] std::vector<Ring> chain_rings(std::span<const CrossingSegment> segments,
                                            std::vector<std::vector<std::int32_t>>* triangles,
                                            ChainScratch& scratch);

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

/// The section of a plane through no vertex when the chained rings are simple and pairwise
/// disjoint, nested in any way (holes, islands in holes, rings inside out): proven exactly (no two
/// edges meet but consecutive ones of a ring at their joint: exact orient2d; nesting by exact
/// ray parity). Then `polygon_boolean` (union, positive) would return the rings that bound the
/// filled region as they are, shells in order, each with its holes in order, and each edge's
/// provenance is its own segment. False (out untouched) when that is not proven, or the rings
/// are too many or too deeply nested to be worth it: the caller runs the 2D engine.
[[nodiscard]] bool nested_section(std::vector<Ring>& rings,
                                  std::vector<std::vector<std::int32_t>>& triangles,
                                  std::size_t segments, Section& out);

/// For each ring of `region` (in `all_rings` order) and each of its edges, the triangle of a
/// segment that the edge lies on: exactly (both ends on the segment, exact orient2d), else the
/// nearest candidate (an end that the 2D engine rounded or snapped), preferring the segment's
/// direction and then the lowest triangle index.
[[nodiscard]] std::vector<std::vector<std::int32_t>> edge_triangles(
    const MultiPolygon& region, std::span<const CrossingSegment> segments);

/// The marks of walk_curve: triangle t is on a path of the current plane when mark[t] == stamp.
struct WalkScratch {
  std::vector<std::uint32_t> mark;
  std::uint32_t stamp = 0;
};

/// The curve of the plane at c when no vertex of the active triangles lies on it and every
/// crossing edge has a twin: its segments in `out`, path after path (the order of `active`
/// picks where each path starts), and the paths as `cycles` over them. False when that does
/// not hold (a vertex on the plane, a non-manifold or degenerate stretch): the caller takes the
/// general stages. Each crossing is computed once (`predicates::rounded_axis_crossing`).
[[nodiscard]] bool walk_curve(const SweepMesh& mesh, std::span<const std::int32_t> active, double c,
                              WalkScratch& scratch, std::vector<CrossingSegment>& out,
                              std::vector<ChainCycle>& cycles);

/// What one thread of the sweep reuses from plane to plane.
struct SweepScratch {
  std::vector<std::int32_t> active;
  std::vector<double> active_high;  // per active triangle its greatest height
  KeyTable<Vec2> memo;
  PlaneCurves curves;
  std::vector<CrossingSegment> both;
  ChainScratch chain;
  WalkScratch walk;
};

/// The section at c from the active triangles (in any order: the answer does not depend on it).
[[nodiscard]] Section section_at(const SweepMesh& mesh, std::span<const std::int32_t> active,
                                 double c, SweepScratch& scratch);

/// Sections of the planes sorted[i] = values[order[i]] for i in [begin, end), `order` sorting
/// the values increasingly: one sweep with an active set fed by `starts`, each answer written
/// to out[order[i] - first] when order[i] is in [first, first + out.size()); the other planes
/// of the run only move the active set along (a block of unsorted values).
/// `carried`: the positions in `starts.triangles`, increasing, of the triangles entered before
/// plane `begin` that reach sorted[begin] (`carry_active`), so that a run of planes starts
/// where an earlier one ended instead of rescanning every triangle entered before it.
void sweep(const SweepMesh& mesh, const SweepStarts& starts, std::span<const double> sorted,
           std::span<const std::size_t> order, std::size_t begin, std::size_t end,
           std::size_t first, std::span<const std::size_t> carried, std::span<Section> out);

/// Moves `positions` (increasing positions in `starts.triangles` holding every triangle entered
/// before plane `from` that reaches any plane from `from` on) to plane `to` >= `from`: those
/// entered before `to` that reach sorted[to], still increasing, so in the order a rescan of all
/// triangles entered before `to` gives. `to` may be sorted.size(): then none is left.
void carry_active(const SweepMesh& mesh, const SweepStarts& starts, std::span<const double> sorted,
                  std::size_t from, std::size_t to, std::vector<std::size_t>& positions);

}  // namespace contain::clip::slice
