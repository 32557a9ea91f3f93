#pragma once
// Pairs within a patch of the soup settled per subtree of its hierarchy instead of per pair: the
// pair stage walks one tree over both inputs, and most of its walk (18% of a union of two
// 131k-triangle spheres) pairs triangles of one smooth surface with their neighbours, which
// meet nothing but each other's shared corners.
//
// A set S of the soup's triangles is an embedded patch when, exactly, in the projection dropping
// one coordinate axis:
//   1. every triangle of S turns the same strict way (orient2d all > 0, say), and
//   2. the boundary chain of S (its directed edges, a -> b cancelling b -> a) holds each edge
//      once, is connected, and its projected edges meet only at the ends they share by number
//      (orient2d and comparisons of doubles); and around a vertex it passes twice (a pinch)
//      its edges alternate in, out, in, out (orient2d; a vertex passed more often fails).
// Why then no two triangles of S meet beyond their shared corners or edge. For a point p of the
// plane on no projected edge, the number of triangles of S covering p is, by 1, the sum of their
// boundaries' winding numbers around p, which is the boundary chain's winding number w(p) (the
// cancelled edges cancel in the sum too). The projected chain is a plane graph (2), connected,
// so each of its faces has one boundary walk; walked with the face on its left, it follows
// either every edge the chain's way or every edge against it, since at each vertex the next
// edge of the walk is a neighbour in angle and in and out alternate. So each face lies left of
// all its edges or right of all, w is one higher on the left of an edge than on its right, and
// along any path of faces w alternates between two values, c on right faces and c + 1 on left
// ones. The unbounded face has w = 0 and w >= 0 everywhere (it counts triangles): it is a right
// face, and w is 0 or 1. So the open projected triangles are disjoint. A vertex v of S off the
// boundary chain has its star's link winding k >= 1 times around it (the sectors all turn one
// way and cancel v's edges), so every point near v is covered, while points just right of a
// boundary edge, or near a boundary vertex in some direction, have w = 0; and a boundary vertex
// lies on no other boundary edge and at no other boundary vertex (2). Two closed projected
// triangles that touch other than in shared corners or a shared edge then either overlap near
// the touching point (a vertex on the other's edge or vertex, or two edges along one line: the
// neighbour across an inner edge, or the covered neighbourhood of an inner vertex, lies on both
// sides) or cover a point where w = 0, or put two boundary edges on one another (excluded by
// 2). Disjoint projections are disjoint in space, and shared projected corners or edges are
// shared in space only as the shared corners or edge.
//
// The pair stage skips the pairs within a subtree whose triangles form an embedded patch and
// whose every corner is proven by star_proof.h: pairs sharing a corner are skipped by the star
// proofs anyway, and the others meet nowhere, so they change no part of the solid. Tested,
// `intersect_pair` could still make a crossing point on the way (two disjoint triangles each
// crossing the other's plane) or pair two disjoint coplanar triangles as partners, each
// taking the other's edges as constraints that clipping to the triangle then leaves without
// effect: the stored points and the work came out the same with and without the skip on every
// input measured (the sphere rungs' written meshes byte for byte, patch_proof_test's
// self-intersecting inputs constraint for constraint), but a saddle-shaped patch or a patch
// with coplanar triangles could change the work and the points' numbering, not the solid. The
// proofs are asked lazily where the walk would descend, from a bottom-up mask of the
// directions in which all of a subtree's triangles turn strictly; subtrees of two inputs are
// not tried.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/star_proof.h"
#include "contain/core/union_find.h"

namespace contain::clip::solid {

/// The fewest triangles of a soup for which the pair stage tries the proofs: below, they cost
/// more than the walk they save (a union of two 2,048-triangle spheres, 4,096 in the soup, was
/// 2-4% slower with them; from 8k triangles a sphere on they pay).
inline constexpr std::size_t patch_proofs_from = 8192;

/// Whether the triangles `patch` of the soup form an embedded patch (see above) in the
/// projection dropping some axis. O(n log n) in the patch's triangles for the sort, plus the
/// sweep's tests of each boundary edge against the edges active at its x (quadratic at worst,
/// for a long thin strip along the sweep's axis).
[[nodiscard]] bool embedded_patch(const Soup& soup, std::span<const std::int32_t> patch);

/// An edge of a patch's boundary chain (vertex numbers of the soup).
struct BoundaryEdge {
  std::int32_t from, to;
};

/// The buffers of a proof, kept from one to the next.
struct PatchScratch {
  std::vector<BoundaryEdge> boundary;
  std::vector<Vec2> from, to;
  std::vector<std::uint32_t> order, active, by_to;
  UnionFind<std::uint32_t> sets{0};  ///< the boundary's edges, joined at shared ends
};

/// The proofs of the pair stage, per node of `soup.tree`.
class PatchProofs {
 public:
  /// `stars` from `proven_stars` in triangle order: which corners are proven, the neighbours
  /// across the edges at proven corners and the triangles' turns, copied into leaf order (read
  /// during construction only, not kept). `soup` is kept and must outlive the proofs.
  PatchProofs(const Soup& soup, const ProvenStars& stars);
  /// The same from `proven_stars(soup, StarOrder::leaf)`, already in the order the proofs read
  /// them: its `across` is taken over (left empty), nothing copied into leaf order; `corners` and
  /// `turns` are read during construction only. The pair stage's path (intersect.cpp).
  [[nodiscard]] static PatchProofs from_leaf_order(const Soup& soup, ProvenStars& stars);

  /// Whether the triangles under inner node `node` of `soup.tree` form an embedded patch whose
  /// corners are all proven: then no pair of them gives the pair stage anything. Leaves are
  /// never settled (their few pairs cost less than a proof).
  [[nodiscard]] bool settled(std::int32_t node) const;

 private:
  const Soup& soup_;
  // Per node: its items' range in leaf order; per position in leaf order: the positions of the
  // triangles across its triangle's edges (-1 across an edge without a proven end).
  std::vector<std::array<std::int32_t, 2>> ranges_;
  ScratchVector<std::array<std::int32_t, 3>> across_at_;
  // Per node: bit 2k (2k + 1) when every triangle below turns strictly positively (negatively)
  // in the projection dropping axis k and every corner below is proven; 0 otherwise.
  std::vector<std::uint8_t> directions_;
  mutable PatchScratch scratch_;

  explicit PatchProofs(const Soup& soup) : soup_(soup) {}
  // directions_ and ranges_, bottom up, from `across_at_` and each position's turns (as
  // ProvenStars::turns) with `corners` by triangle (turns count only where all three are proven).
  void summarize(std::span<const std::uint8_t> turns_at, std::span<const std::uint8_t> corners);
};

}  // namespace contain::clip::solid
