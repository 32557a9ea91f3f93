#pragma once
/// \file
/// Is a mesh a solid's boundary? The rule of the solids in ../shared/spec/cli.md: a mesh is
/// closed when each directed edge occurs as often as its reverse, so that its winding number is
/// defined everywhere off its surface. Non-manifold edges (four triangles on one edge, two shells
/// touching along an edge) are fine; a hole, a flipped triangle or a dangling face are not.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "contain/shapes/mesh.h"
#include "contain/shapes/mesh_validation.h"
#include "contain/values/vec.h"

namespace contain::shapes {

/// A directed edge that occurs more often than its reverse. Vertices are judged by position
/// (as `weld_vertices` does), so an unwelded STL is judged as its welded twin.
struct UnmatchedEdge {
  Vec3 from;
  Vec3 to;
  std::int32_t triangle = 0;  ///< the first triangle (in file order) that has the edge from -> to
  std::int64_t count = 0;     ///< occurrences of from -> to
  std::int64_t reverse = 0;   ///< occurrences of to -> from (fewer than `count`)
};

/// One directed edge that breaks closedness, or nothing when every directed edge occurs as often
/// as its reverse (an empty mesh is closed: the empty solid). Deterministic: of the unbalanced
/// edges, the one whose first triangle comes first in the file, then by its corners' order.
/// Triangles with a repeated corner add an edge and its reverse, so they never unbalance one.
/// O(n log n) for n triangles.
[[nodiscard]] std::optional<UnmatchedEdge> unmatched_edge(const Mesh& mesh);

/// The same answer from the mesh already welded (`weld_vertices(mesh)`), for callers that go on
/// to use the welded mesh (slicing): the mesh is welded once, not once per question.
[[nodiscard]] std::optional<UnmatchedEdge> unmatched_edge(const WeldResult& weld);
/// The same from vertices already welded by position (distinct positions, distinct numbers) and
/// triangles on them, held in other structures (the mesh booleans' soup of several inputs);
/// `triangle` counts from the first of `triangles`.
[[nodiscard]] std::optional<UnmatchedEdge> unmatched_edge(
    std::span<const Vec3> vertices, std::span<const TriangleIndices> triangles);

/// For a welded mesh (`weld_vertices(mesh).mesh`): nothing when some directed edge occurs more
/// often than its reverse (`unmatched_edge` names one), else per half-edge 3t + i (triangle t from
/// corner i to corner i + 1) the half-edge running the other way along the same edge when these
/// two are its only uses and lie in two triangles (a manifold edge), else -1. The pairing that
/// walks a surface from triangle to triangle (slicing), at about the cost of the closedness test
/// alone: O(n) plus a sort of each vertex's few edges. Also nothing for a mesh of 2^31 / 3
/// triangles or more, closed or not.
[[nodiscard]] std::optional<std::vector<std::int32_t>> paired_half_edges(const Mesh& welded);
/// The same for triangles on `vertices` welded vertices (numbers below it), held elsewhere (a
/// mesh whose vertices `vertices_distinct` found welded already, not copied).
[[nodiscard]] std::optional<std::vector<std::int32_t>> paired_half_edges(
    std::span<const TriangleIndices> triangles, std::size_t vertices);

}  // namespace contain::shapes

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using shapes::paired_half_edges;
using shapes::unmatched_edge;
using shapes::UnmatchedEdge;
}  // namespace contain
