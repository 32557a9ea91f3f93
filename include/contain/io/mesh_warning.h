#pragma once
/// \file
/// The words for a prepared mesh's regime and report: the one wording of the command's and the
/// Python module's mesh warnings and of the CSG reader's open-mesh error. The library itself
/// keeps the facts as data (`inside::MeshIndex::regime()`, `MeshReport`).

#include <string>
#include <string_view>

#include "contain/inside/mesh_index.h"
#include "contain/shapes/mesh_closure.h"
#include "contain/shapes/mesh_validation.h"

namespace contain::io {

/// One line for a user about a mesh answered in `regime`, from its validation `report`; empty
/// when there is nothing to say (a plain closed 2-manifold).
///
/// - `winding_number`: "mesh is not closed (223 border edges, ...): answers come from the
///   generalized winding number (...)", naming every fact that keeps the mesh from being a plain
///   solid: no triangles, border edges, edges of three or more triangles, duplicated triangles,
///   pinch vertices (the first one 1-based, as files count), inconsistent orientation,
///   degenerate triangles.
/// - `closed_exact`: empty, or "mesh has 1 pinch vertex (...); every edge has exactly two
///   triangles, so the answers (closed-exact ray parity) are still exact" for pinch vertices,
///   inconsistent orientation, degenerate or duplicated triangles.
///
/// Counts are written "1 border edge", "2 border edges". O(1).
[[nodiscard]] std::string mesh_warning(inside::MeshRegime regime, const MeshReport& report);

/// How a pair or scene query reads a mesh that is not closed: the second half of its warning.
enum class OpenMeshReading {
  /// "read as a surface, which meets the other shape only where they share a point" (a pair).
  surface_contact,
  /// "read as a surface, which meets another shape only where they share a point" (a scene).
  surface_contact_in_scene,
  /// "read as a surface, whose distance is to its triangles only".
  surface_distance,
  /// "signs come from the generalized winding number (inside where >= 0.5)".
  winding_number_sign,
};

/// One line for a user about the mesh `name` that is not closed and is answered as `reading`
/// says: "NAME: not closed (B border edges, N non-manifold edges): READING" with the counts of
/// `report` (written as numbers, "1 border edges" too: the command's words since the pair
/// queries came). O(1).
[[nodiscard]] std::string open_mesh_warning(std::string_view name, const MeshReport& report,
                                            OpenMeshReading reading);

/// The same line without the counts, where a query knows only that the mesh is open (a scene's
/// objects): "NAME: not closed: READING". O(1).
[[nodiscard]] std::string open_mesh_warning(std::string_view name, OpenMeshReading reading);

/// One line for a user about the mesh `name` that is not a solid's boundary (the solids of the
/// mesh booleans, `shapes::unmatched_edge`): "NAME: not closed: the directed edge (x y z) -> (x y
/// z) of triangle T (counted from 0 in file order, polygons split into fans) occurs N times, its
/// reverse M times; a solid's mesh has every directed edge as often as its reverse". Coordinates
/// are the shortest decimals that read back as the same doubles. O(1).
[[nodiscard]] std::string open_solid_message(std::string_view name, const UnmatchedEdge& edge);

}  // namespace contain::io
