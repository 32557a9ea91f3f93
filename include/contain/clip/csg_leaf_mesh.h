#pragma once
/// \file
/// The polyhedral leaves of a CSG tree (shapes/csg.h) as closed, outward triangle meshes: the
/// inputs of the mesh booleans (clip/mesh_boolean.h) when a tree is evaluated to one mesh
/// (clip/csg_to_mesh.h).

#include <optional>

#include "contain/core/result.h"
#include "contain/shapes/csg.h"
#include "contain/shapes/mesh.h"
#include "contain/values/box.h"

namespace contain::clip {

/// The closed, outward oriented mesh (counter-clockwise seen from outside; every directed edge
/// matched by its reverse, shapes/mesh_closure.h) of a polyhedral leaf:
/// - a box: its 8 corners and 12 triangles, exact (a flat box gives zero-volume triangles, an
///   empty box no triangles);
/// - a mesh: the mesh itself, as given (a solid by its winding number, clip/mesh_boolean.h);
/// - a convex polyhedron made from a mesh or a box: its corners and faces, exact;
/// - a half-space, or a convex polyhedron given by planes (which may be unbounded): its part
///   inside `bounds`, the box's mesh cut by the planes and capped (clip/mesh_clip.h's `cap`):
///   the side of every box corner is exact, the corners where a plane crosses a box edge are
///   rounded (a few ulps; exact on the box's own faces where they lie on a box plane). An empty
///   `bounds` gives no triangles.
///
/// Errors: `ErrorKind::unsupported` for a leaf that is not polyhedral (a sphere, an implicit
/// function); the message names its kind ("a sphere is not polyhedral ..."). O(n) for a mesh of
/// n triangles, O(k) for k planes.
[[nodiscard]] Result<Mesh> csg_leaf_mesh(const CsgLeaf& leaf, const Box3& bounds);

/// A box that holds the leaf's solid, or nothing when the leaf may be unbounded (a half-space, a
/// convex polyhedron given by planes) or is not polyhedral (a sphere, an implicit function). A
/// mesh's box is its vertices' box (empty for an empty mesh). O(n) for n vertices.
[[nodiscard]] std::optional<Box3> csg_leaf_box(const CsgLeaf& leaf);

}  // namespace contain::clip
