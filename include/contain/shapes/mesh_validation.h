#pragma once
/// \file
/// What a triangle mesh is, as a surface: closed, 2-manifold, consistently oriented, outward,
/// with degenerate or duplicated faces; a report a user can read; welding of duplicate vertices.
///
/// Layering note: the exact parts of the report (zero-area faces) need contain::predicates, which
/// sit above geometry; the implementation is therefore built into the first layer above them
/// (contain_bvh). Link contain::contain.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "contain/shapes/mesh.h"

namespace contain::shapes {

/// The facts `validate_mesh` finds. Edges are unordered pairs of vertex indices (by index, not
/// by position: weld first if a file repeats positions); a triangle with a repeated index has
/// fewer than three edges and counts as degenerate.
struct MeshReport {
  std::size_t vertices = 0;             ///< in the vertex array
  std::size_t referenced_vertices = 0;  ///< used by some triangle
  std::size_t triangles = 0;
  std::size_t edges = 0;                 ///< distinct edges
  std::size_t border_edges = 0;          ///< edges of exactly one triangle
  std::size_t nonmanifold_edges = 0;     ///< edges of three or more triangles
  std::size_t inconsistent_edges = 0;    ///< two-triangle edges used in the same direction by both
  std::size_t degenerate_triangles = 0;  ///< zero area, exactly (collinear or repeated vertices)
  std::size_t duplicated_triangles = 0;  ///< same three vertices as an earlier triangle (any order)
  /// Vertices where the surface is not a disc or half-disc: their triangles form several fans
  /// joined only at the vertex (0-based indices, ascending).
  std::vector<std::int32_t> pinch_vertices;
  std::size_t components = 0;  ///< connected through shared vertices
  /// V - E + F over referenced vertices, distinct edges and triangles.
  std::int64_t euler_characteristic = 0;
  /// Total genus (sum over components) for a closed, 2-manifold, consistently oriented mesh:
  /// (2 components - euler_characteristic) / 2; nothing otherwise.
  std::optional<std::int64_t> genus;
  /// Signed volume (divergence theorem: (1/6) sum of a . (b x c) over the triangles), the double
  /// nearest to the exact value, so its sign is exact: positive when the triangles face outward.
  /// Meaningful for a closed, consistently oriented mesh (then independent of the origin).
  double signed_volume = 0.0;

  /// Every edge shared by exactly two triangles.
  [[nodiscard]] bool closed() const {
    return triangles > 0 && border_edges == 0 && nonmanifold_edges == 0;
  }
  /// Every edge of one or two triangles and every vertex a single fan.
  [[nodiscard]] bool manifold() const { return nonmanifold_edges == 0 && pinch_vertices.empty(); }
  /// Every two-triangle edge used in opposite directions (and no edge of three or more).
  [[nodiscard]] bool consistently_oriented() const {
    return inconsistent_edges == 0 && nonmanifold_edges == 0;
  }
  /// Closed, consistently oriented and the signed volume positive.
  [[nodiscard]] bool outward() const {
    return closed() && consistently_oriented() && signed_volume > 0.0;
  }
  /// A closed, 2-manifold, consistently oriented surface with no duplicated triangles: a solid.
  [[nodiscard]] bool watertight() const {
    return closed() && manifold() && consistently_oriented() && duplicated_triangles == 0;
  }
  /// A few lines a user can read: counts, the properties, what is wrong and how much.
  [[nodiscard]] std::string summary() const;
};

/// Checks a mesh. Topology vertex by vertex over the triangle corners grouped by vertex (O(n)
/// for n triangles, plus sorting each vertex's few edges): first a quick proof of the common
/// case (one walk around each vertex's fan shows a closed, oriented 2-manifold without
/// duplicates), the full analysis below only where it fails (the same report); degenerate triangles
/// exactly with predicates::orient2d on the three coordinate projections (a triangle has zero
/// area iff all three projected areas are zero); pinch vertices by joining, at each vertex, the
/// triangles that share an edge there (union-find over triangle corners). Precondition: indices
/// in range (a `Mesh` from `Mesh::from_arrays` or a reader).
[[nodiscard]] MeshReport validate_mesh(const Mesh& mesh);

namespace detail {
/// `validate_mesh` without its quick proof of the common case (a closed, oriented 2-manifold
/// without duplicates): the full analysis always. The same report; for tests.
[[nodiscard]] MeshReport validate_mesh_in_full(const Mesh& mesh);
/// Whether `validate_mesh`'s quick proof holds (a closed, oriented 2-manifold without pinches
/// or duplicates, proven by one walk around each vertex's fan); for tests.
[[nodiscard]] bool topology_proven_quickly(const Mesh& mesh);
}  // namespace detail

/// The result of `weld_vertices`.
struct WeldResult {
  Mesh mesh;                        ///< vertices in order of first occurrence
  std::vector<std::int32_t> remap;  ///< old vertex index -> new vertex index
  std::size_t merged = 0;           ///< vertices removed (old count - new count)
};

/// Merges vertices whose coordinates are equal as doubles (exact equality: +0 == -0, no
/// tolerance), keeping the first of each group, and renumbers the triangles. Unreferenced
/// vertices are kept (welded like the others). O(n log n).
[[nodiscard]] WeldResult weld_vertices(const Mesh& mesh);

/// True when no two vertices have equal coordinates (as `weld_vertices` compares them), that is
/// when `weld_vertices` would merge none and return the mesh unchanged. O(n).
[[nodiscard]] bool vertices_distinct(std::span<const Vec3> vertices);

}  // namespace contain::shapes

// Users and every layer above spell these names contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using shapes::MeshReport;
using shapes::validate_mesh;
using shapes::vertices_distinct;
using shapes::weld_vertices;
using shapes::WeldResult;
}  // namespace contain
