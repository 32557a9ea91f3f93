#pragma once
/// \file
/// Does a mesh cross itself? Pairs of its triangles that meet where they are not joined (a
/// closed mesh that overlaps itself is still one solid for every query: its winding number).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/shapes/mesh.h"

namespace contain::collide {

/// Two triangles of one mesh (numbers into `Mesh::triangles`, first < second) that meet beyond
/// the corners they share.
struct TrianglePair {
  std::int32_t first = 0;
  std::int32_t second = 0;
  friend constexpr bool operator==(const TrianglePair&, const TrianglePair&) = default;
};

/// How `self_intersections` searches.
struct SelfIntersectionsOptions {
  /// At most this many pairs are kept in `SelfIntersections::pairs`.
  std::size_t keep = 8;
  /// The search stops once this many pairs are found (0: counts every pair). 1 answers "does it
  /// cross itself at all" at the cost of the first pair found.
  std::size_t limit = 0;
  /// The hierarchy over the mesh's triangles.
  bvh::BuildOptions bvh{};
};

/// What `self_intersections` found.
struct SelfIntersections {
  /// The first pairs found (at most `keep`), in the traversal's order (deterministic).
  std::vector<TrianglePair> pairs;
  /// Pairs found (all of them unless the search stopped at `limit`).
  std::size_t count = 0;
  /// True when the search stopped at `limit`, so `count` may be short of the total.
  bool stopped = false;
  /// Pairs of hierarchy nodes tested, for benchmarks.
  std::size_t node_pairs = 0;
  [[nodiscard]] bool empty() const { return count == 0; }
};

/// Pairs of triangles of `mesh` that share a point which is not a corner they share.
///
/// Triangles share a corner when they have a vertex at the same coordinates (by value, so an
/// unwelded mesh is judged as its welded twin). Such a pair always meets at the shared corners
/// and counts only when it meets elsewhere too:
/// - no shared corner: any common point counts (crossing or touching, `tri_tri`);
/// - one shared corner P (a = P a1 a2, b = P b1 b2): a and b meet beyond P iff the edge a1 a2
///   meets b or the edge b1 b2 meets a (a triangle crossing its neighbour's interior, a fold
///   onto the neighbour's plane);
/// - a shared edge P Q (a = P Q a2, b = P Q b2): iff both lie in one plane (orient3d) with a2
///   and b2 on the same side of P Q (a folded, overlapping pair; orient2d in a projection one
///   to one on that plane); across the edge, or at any angle, they meet only there;
/// - all three corners shared (a duplicated triangle): not counted here, `validate_mesh`
///   reports duplicates.
/// Why these are exact: a ∩ b is compact and convex; if it holds a point besides the shared
/// corners, it has an extreme point besides them, and an extreme point of a ∩ b lies on an edge
/// of a or of b. An edge through a shared corner P that goes on into the other triangle either
/// ends inside it (its far end is in the other triangle, so the far edge meets it) or leaves it
/// through the other's edge opposite P. The decision is predicates::triangles_meet_beyond_shared
/// (shared with clip's check of a written mesh): orient3d and orient2d signs only.
/// Degenerate triangles (collinear or coincident corners, decided exactly) are skipped: they
/// bound no area, `validate_mesh` counts them, and a shared corner in the middle of one would
/// make every neighbour "meet it beyond the corner".
///
/// Complexity: one hierarchy over the triangles (O(n log n)) and one traversal of it against
/// itself (the pairs of overlapping boxes), an exact test per candidate pair: about the cost of
/// building a `MeshIndex` (`bvh::traverse_self`: each pair of boxes once). Deterministic;
/// single-threaded.
[[nodiscard]] SelfIntersections self_intersections(const Mesh& mesh,
                                                   const SelfIntersectionsOptions& options = {});

}  // namespace contain::collide
