#pragma once
/// \file
/// Exact booleans of solids given as triangle meshes (union, intersection, difference, xor of
/// two or of many), and the repair of one solid (its self-intersections and overlaps resolved):
/// issue 25, ../shared/spec/cli.md "Solids: booleans of meshes".

#include <cstddef>
#include <span>

#include "contain/clip/polygon_boolean.h"
#include "contain/core/result.h"
#include "contain/shapes/mesh.h"

namespace contain::clip {

/// What is computed.
struct MeshBooleanOptions {
  Op op = Op::union_;
  /// Where the engine's large arrays live: in the call's own pool (the default: the pages one
  /// stage wrote and freed are the next stage's, whatever the process's malloc settings), or in
  /// the process's heap, for a caller whose malloc already keeps freed memory for reuse (the
  /// contain CLI's `mallopt`): there a pool only walls its pages off from the allocations
  /// outside it (the CLI's union of two 131k-triangle spheres: 16,954 page faults with the
  /// pool, 14,867 without). The result is the same either way.
  bool scratch_pool = true;
};

/// The written result and what it took.
struct MeshBooleanResult {
  /// The regularised result (no dangling faces, no zero-volume parts) on doubles: closed (each
  /// directed edge matched by exactly one opposite directed edge), outward oriented, no
  /// zero-area triangle, no two triangles meeting other than at shared vertices or a shared
  /// edge, all of it true of the written doubles exactly. Where the exact result touches itself
  /// along an edge or at a point, each sheet has its own vertices there (same positions).
  /// An empty result is a mesh with no triangles.
  Mesh mesh;
  std::size_t shells = 0;  ///< connected sheets of `mesh` (by shared vertex indices)
  double volume = 0.0;     ///< volume of the written mesh, the double nearest to the exact one
  /// Written positions that are not the nearest doubles of an exact point of the result (made
  /// by the snap-rounding repair), 0 when every vertex is the double nearest to its exact point.
  std::size_t moved = 0;
};

/// The solid `inputs[0] op inputs[1] op ...`: `union_` and `intersection` of all inputs,
/// `difference` = inputs[0] minus the union of the rest, `xor_` = the points in an odd number
/// of inputs. One input with `Op::union_`: that solid repaired. No input: the empty solid.
///
/// - `inputs`: closed meshes (each directed edge occurs as often as its reverse, so that the
///   winding number is defined off the surface; non-manifold edges are fine). Each is the
///   solid where its winding number is positive: self-intersecting meshes, nested shells and
///   several shells per mesh are accepted, and a shell turned inside out subtracts. Zero-area
///   triangles are allowed (they bound nothing). An empty mesh is the empty solid.
///
/// Method (engine in src/clip/solid/, one file per stage): candidate triangle pairs from a
/// BVH over all triangles; each pair intersected exactly (the segment's ends are implicit
/// points: an edge of one triangle through the other's plane, or three planes), coplanar pairs
/// overlaid in their common plane; every input triangle refined by a constrained triangulation
/// of its intersection segments with exact predicates on the implicit points; refined faces
/// grouped by position and labelled with every input's winding number on both sides (one exact
/// ray per connected patch group, then the jumps across faces); a face is kept where
/// `op(filled)` differs on its two sides, oriented with the in-side behind; where the result
/// touches itself the sheets get their own vertices (before that, adjacent output faces of one
/// plane are merged and triangulated again without the points inside them that no other face
/// holds; every point on their outlines stays, so the mesh stays closed); vertices rounded to the
/// nearest doubles and the written mesh checked exactly (pairs of triangles whose corners were
/// all written exactly are faces of the exact arrangement and are not tested again); when the
/// check fails, iterated snap rounding: the written mesh's own arrangement computed exactly
/// again (as a union; only the pairs of the triangles that failed intersected) and rounded,
/// after three rounds also with points closer than 2^2, 2^5, ... 2^20 ulps of the largest input
/// coordinate merged, at most 10 rounds (rules solid-* in docs/robustness.md).
///
/// Complexity: O(n log n) for the hierarchy and the candidate pairs, then work per intersecting
/// pair and per refined triangle (quadratic in the constraints of one triangle), one ray pair
/// per patch. Predicates on implicit points are decided by an interval filter first, by
/// big-number arithmetic only when it cannot (rule solid-exact-points); the constructions of new
/// points and their rounding to doubles are big-number arithmetic. Single-threaded,
/// deterministic.
///
/// Errors: `ErrorKind::invalid_value` for an input that is not closed (the message names the
/// input index and one unmatched directed edge by its two vertex coordinates) or whose
/// coordinates are not finite or whose indices are out of range; `ErrorKind::degenerate` when
/// rounding the exact result to doubles made it invalid and 10 rounds of the repair could not
/// restore validity (not seen in the tests): never an invalid mesh.
[[nodiscard]] Result<MeshBooleanResult> mesh_boolean(std::span<const Mesh> inputs,
                                                     const MeshBooleanOptions& options = {});

}  // namespace contain::clip
