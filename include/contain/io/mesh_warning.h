#pragma once
/// \file
/// The words for a prepared mesh's regime and report: the one wording of the command's and the
/// Python module's mesh warnings and of the CSG reader's open-mesh error. The library itself
/// keeps the facts as data (`inside::MeshIndex::regime()`, `MeshReport`).

#include <string>

#include "contain/collide/self_intersections.h"
#include "contain/inside/mesh_index.h"
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

/// One line for a user about a closed mesh that crosses itself (`collide::self_intersections`),
/// empty when it does not: "mesh crosses itself (triangles 3 and 17 meet away from the corners
/// they share, counted from 0 in file order): answers come from closed-exact ray parity, which
/// reads a point inside two overlapping parts as outside". Names the first pair found and
/// the count when more than one was counted ("... and 5 more pairs"; "at least" when the search
/// stopped at its limit). O(1).
[[nodiscard]] std::string mesh_warning(const collide::SelfIntersections& found);

}  // namespace contain::io
