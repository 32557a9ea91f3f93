#pragma once
/// \file
/// A CSG tree with polyhedral leaves evaluated to one mesh by the exact mesh booleans: issue 25,
/// ../shared/spec/cli.md "Solids: booleans of meshes" (`contain clip --csg FILE`).

#include "contain/clip/mesh_boolean.h"
#include "contain/core/result.h"
#include "contain/shapes/csg.h"

namespace contain::clip {

/// The solid of `tree` as one written mesh, with the guarantees of `mesh_boolean` (closed,
/// outward, no zero-area triangle, no two triangles crossing, checked exactly on the doubles).
///
/// - Leaves: meshes, boxes, half-spaces and convex polyhedra, each made a closed mesh by
///   `csg_leaf_mesh`. A mesh leaf is a solid by its winding number, as every input of
///   `mesh_boolean` (where `inside::CsgSolid` reads a closed mesh by ray parity, the two agree on
///   a closed, outward, self-disjoint mesh; a mesh turned inside out is empty here).
/// - Half-spaces within a box: a leaf that may be unbounded (a half-space, a convex polyhedron
///   given by planes, a complement) is read inside the tree's box: the box of its bounded
///   solids (the union's, the intersection's bounded operands', the difference's first operand's),
///   grown by a quarter of its largest side, so `{"intersection": [{"box": ...}, {"halfspace":
///   ...}]}` is the box cut by the plane and `{"difference": [A, {"halfspace": ...}]}` is A cut
///   by it. A tree whose solid is unbounded (a half-space alone, a union with one) is an error.
/// - Operations: union and intersection of n operands are one n-ary `mesh_boolean` each (nested
///   unions of unions, intersections of intersections, flattened into it); `difference(A, B)` is
///   one call, with B's operands when B is a union (A minus the union of the rest); a complement
///   is the tree's box minus its operand. The root is one call even for a lone leaf, so the
///   result is always a repaired, valid mesh.
///
/// The result's `shells` and `volume` are of the written mesh; `moved` counts the vertices the
/// rounding repair moved in every call of the evaluation.
///
/// Errors, whose messages start with the JSON path of the node (as io::parse_csg_json's,
/// "difference[1].sphere: ..."): `ErrorKind::unsupported` for a leaf that is not polyhedral (a
/// sphere, an implicit function), found before any boolean runs; `ErrorKind::invalid_value` for
/// an unbounded tree, and `mesh_boolean`'s errors (a mesh that is not closed, non-finite
/// coordinates) on the node whose call refused.
/// Complexity: one `mesh_boolean` per operation node.
[[nodiscard]] Result<MeshBooleanResult> csg_to_mesh(const Csg& tree);

}  // namespace contain::clip
