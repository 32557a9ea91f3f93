#pragma once
/// \file
/// General polygon booleans: intersection, union, difference and xor of arbitrary regions
/// (exercise 22.4-3 of "Algorithms of Informatics" vol. 2, "clipping onto a concave polygon", in
/// its general form).

#include <cstdint>
#include <span>

#include "contain/shapes/polygon.h"

namespace contain::clip {

/// The boolean operation. `union_` and `xor_` carry a trailing underscore because `union` and
/// `xor` are C++ keywords.
enum class Op : std::uint8_t {
  intersection,  ///< A and B
  union_,        ///< A or B
  difference,    ///< A and not B
  xor_,          ///< A or B but not both (symmetric difference)
};

/// How the inputs are read and what is computed.
struct PolygonBooleanOptions {
  Op op = Op::intersection;
  /// Fill rule of both inputs: every ring of a region is one closed path in the direction
  /// written (see `contain::Fill`). `Fill::even_odd` gives the OGC meaning for OGC-valid input.
  Fill fill = Fill::even_odd;
};

/// Counters of one run, for benchmarks and `--json`.
struct PolygonBooleanStats {
  /// Edges noded: the non-degenerate ones of A and B, far ones replaced (rule clip-far-edges).
  std::int64_t input_edges = 0;
  std::int64_t crossings = 0;      ///< proper crossings whose point was computed and rounded
  std::int64_t noding_rounds = 0;  ///< passes of the split-until-no-crossing loop
  std::int64_t graph_edges = 0;    ///< edges of the noded arrangement
  /// false if the noding hit its cap of 256 rounds (rule clip-noding): not seen on the corpus or
  /// in fuzzing over the whole double range, where the fuzzer checks it.
  bool converged = true;
};

/// The region `a op b`, each read under `options.fill`, as OGC-valid polygons: closed rings
/// (stored without the closing point), no self-intersections, holes inside their shell and
/// touching it at single points at most, disjoint interiors, connected interiors, shells
/// counter-clockwise, holes clockwise, every ring of at least 3 vertices.
///
/// - `a`, `b`: closed paths (a ring joins its last point to its first) with finite coordinates;
///   any rings: self-intersecting, overlapping, touching, repeated points, zero-area rings, any
///   direction. Under `Fill::even_odd` shells and holes may be written in either direction.
///
/// Method: an exact-decision arrangement. All input edges are noded together (candidate pairs
/// from monotone chains for smooth input, rule clip-noding-chains, else from a uniform grid;
/// every crossing, touching and overlap decided by the exact `orient2d`;
/// for an intersection or difference, the edges of the larger operand far from the other's box
/// are first replaced by a few frame edges with the same winding numbers there, rule
/// clip-far-edges in docs/robustness.md); a proper
/// crossing point is computed in extended precision and rounded to the nearest doubles, and the
/// pieces are checked again until no two pieces meet except at shared endpoints ("split until no
/// new crossing", rule clip-noding in docs/robustness.md). Only points that other pieces meet,
/// split points and path ends become vertices; each run through the other points is one graph
/// edge (rule clip-events). Faces of the noded graph get their
/// winding numbers of A and B from one exact ray per connected component and the edge
/// multiplicities; a face is in the result when `op(filled(w_A), filled(w_B))`. Boundary edges
/// are chained with the tightest turn, chains split where they revisit a vertex, and rings are
/// grouped into polygons by the connectivity of the result faces.
///
/// Exactness and error: every topological decision is exact on the noded doubles, so the
/// output is valid by construction. Vertices of the input are output bit for bit; only crossing
/// points are new: each is the exact crossing rounded to doubles, or, within a pixel of half-side
/// 2 ulps of the largest input coordinate, the nearby endpoint or earlier crossing point that
/// the pieces there are snapped to (docs/robustness.md, clip-noding). The area error is
/// therefore at most the sum over new points of (their displacement, <= 3 ulps of the largest
/// coordinate) x (the length of their incident edges); on the shared corpus of GEOS, Boost and
/// Clipper2 cases it stays below 3e-12 x (largest extent of A u B)^2 and 1e-9 relative
/// (documented bound: 1e-12 x extent^2 x the number of crossings near each other). An operation
/// that changes nothing (union of a region with itself, intersection with a containing box)
/// returns the input vertices bit for bit: rings start at the earliest input vertex they contain
/// and polygons are ordered by that vertex.
///
/// Degenerate cases: an empty input is the empty region; zero-length edges are ignored; edges
/// traversed in both directions cancel; shared and collinear overlapping edges merge; a result
/// of zero area is empty. Two regions that touch at a point or along an edge have an empty
/// intersection (the boolean is regularised, as in OGC).
///
/// Complexity: O((n + k) log n) for n input edges and k crossings in typical input (grid cells
/// shared by pieces: O(n^2) pair tests at worst, when all edges crowd into a few cells; smooth
/// input: O(n + k log n) pair tests by monotone chains, and sorting, labelling and tracing on
/// O(k + rings) graph edges), plus O(n) per connected component of the arrangement for its
/// winding ray. An intersection of a
/// small region with a large one costs O(n) comparisons plus the arrangement of the large one's
/// edges near the small one; boxes whose intersection has no interior give the empty result in
/// O(n).
[[nodiscard]] MultiPolygon polygon_boolean(std::span<const Ring> a, std::span<const Ring> b,
                                           const PolygonBooleanOptions& options = {});

/// The region of `polygon_boolean(a, b, options)` and the counters of the run that made it.
struct PolygonBooleanResult {
  MultiPolygon region;
  PolygonBooleanStats stats;
};

/// `polygon_boolean(a, b, options)` with the counters of its run (for benchmarks, `--json` and
/// the fuzzer's check of `stats.converged`); the same region.
[[nodiscard]] PolygonBooleanResult polygon_boolean_with_stats(
    std::span<const Ring> a, std::span<const Ring> b, const PolygonBooleanOptions& options = {});

/// The same for two multipolygons (all rings of each read together under the fill rule).
[[nodiscard]] MultiPolygon polygon_boolean(const MultiPolygon& a, const MultiPolygon& b,
                                           const PolygonBooleanOptions& options = {});

/// The same for two polygons.
[[nodiscard]] MultiPolygon polygon_boolean(const Polygon& a, const Polygon& b,
                                           const PolygonBooleanOptions& options = {});

}  // namespace contain::clip
