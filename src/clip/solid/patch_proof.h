#pragma once
// Pairs within a patch of the soup settled per subtree of its hierarchy instead of per pair: the
// pair stage walks one tree over both inputs, and most of its walk (18% of a union of two
// 131k-triangle spheres) pairs triangles of one smooth surface with their neighbours, which
// meet nothing but each other's shared corners.
//
// A set S of the soup's triangles is an embedded patch when, exactly, in the projection dropping
// one coordinate axis:
//   1. every triangle of S turns the same strict way (orient2d all > 0, say), and
//   2. the boundary chain of S (its directed edges, a -> b cancelling b -> a) is one closed
//      cycle through distinct vertices whose projection is a simple polygon (no two of its
//      edges meet but consecutive ones at their common corner, decided by orient2d and
//      comparisons of doubles).
// Why then no two triangles of S meet beyond their shared corners or edge. For a point p of the
// plane on no projected edge, the number of triangles of S covering p is, by 1, the sum of their
// boundaries' winding numbers around p, which is the boundary chain's winding number (the
// cancelled edges cancel in the sum too): at most 1 around a simple polygon. So the open
// projected triangles are disjoint. A vertex v of S off the boundary chain has its star's link
// winding k >= 1 times around v (the sectors all turn one way and cancel v's edges), so every
// point near v is covered; a boundary vertex lies on no other edge and at no other vertex
// (simple polygon). Two closed projected triangles that touch other than in shared corners or a
// shared edge then either overlap near the touching point (a vertex on the other's edge or
// vertex, two edges along one line: the neighbour across an inner edge, or the covered
// neighbourhood of an inner vertex, lies on both sides) or put two boundary edges on one
// another (not a simple polygon). Disjoint projections are disjoint in space, and shared
// projected corners or edges are shared in space only as the shared corners or edge.
//
// The pair stage skips the pairs within a subtree whose triangles form an embedded patch and
// whose every corner is proven by star_proof.h: pairs sharing a corner are skipped by the star
// proofs anyway, and the others meet nowhere, so `intersect_pair` gives them no constraint (it
// could still make a crossing point that nothing uses, or pair two disjoint coplanar triangles
// as partners, neither of which changes the result). The proofs are asked lazily where the
// walk would descend, from a bottom-up mask of the directions in which all of a subtree's
// triangles turn strictly.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "clip/solid/engine.h"

namespace contain::clip::solid {

/// Whether the triangles `patch` of the soup form an embedded patch (see above) in the
/// projection dropping some axis. O(n log n) in the patch's triangles.
[[nodiscard]] bool embedded_patch(const Soup& soup, std::span<const std::int32_t> patch);

/// An edge of a patch's boundary chain (vertex numbers of the soup).
struct BoundaryEdge {
  std::int32_t from, to;
};

/// The buffers of a proof, kept from one to the next.
struct PatchScratch {
  std::vector<BoundaryEdge> boundary;
  std::vector<Vec2> from, to;
  std::vector<std::uint32_t> order, active, by_to, parent;
};

/// The proofs of the pair stage, per node of `soup.tree`.
class PatchProofs {
 public:
  /// `corners` and `across` as from `proven_stars`: bit k of triangle t set when its corner k
  /// is proven, and the neighbours across the edges at proven corners.
  PatchProofs(const Soup& soup, std::span<const std::uint8_t> corners,
              std::span<const std::array<std::int32_t, 3>> across);

  /// Whether the triangles under inner node `node` of `soup.tree` form an embedded patch whose
  /// corners are all proven: then no pair of them gives the pair stage anything. Leaves are
  /// never settled (their few pairs cost less than a proof).
  [[nodiscard]] bool settled(std::int32_t node) const;

  /// How many nodes were settled and how many tried in vain (for benchmarks and tests).
  [[nodiscard]] std::size_t settled_count() const { return settled_; }
  [[nodiscard]] std::size_t failed_count() const { return failed_; }

 private:
  const Soup& soup_;
  std::span<const std::array<std::int32_t, 3>> across_;
  // Per node: its items' range in leaf order; per triangle: its position there.
  std::vector<std::array<std::int32_t, 2>> ranges_;
  std::vector<std::int32_t> position_;
  // Per node: bit 2k (2k + 1) when every triangle below turns strictly positively (negatively)
  // in the projection dropping axis k and every corner below is proven; 0 otherwise.
  std::vector<std::uint8_t> directions_;
  mutable PatchScratch scratch_;
  mutable std::size_t settled_ = 0, failed_ = 0;
};

}  // namespace contain::clip::solid
