#pragma once
/// \file
/// Collision of two triangle meshes under rigid (or affine) transforms: the fast path of
/// exercise 22.4-1, a bounding volume hierarchy against another, exact triangle tests, and a
/// containment check for nested solids.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/collide/contact.h"
#include "contain/core/parallel.h"
#include "contain/inside/placed_mesh.h"
#include "contain/shapes/mesh.h"
#include "contain/values/transform.h"

namespace contain::collide {

/// How a `MeshPair` is prepared: the fixed placement of A (`transform_a`, evaluated once), the
/// hierarchies' build options (`bvh`) and A's point-location index (`index`, where vertices of
/// B are located). The same options as `distance::MeshPairDistance`'s.
using MeshPairOptions = inside::MeshPairOptions;

/// Two meshes prepared for many collision queries, B placed by a transform per query.
///
/// Semantics (the CLI contract): a closed mesh bounds a solid, a closed set: touching counts, and
/// one inside the other counts. The solid is `inside::MeshIndex`'s (`contain inside`'s; rule in
/// inside/solid_rule.h): for a mesh whose directed edges all match, where its winding number is
/// positive (the parts of a self-intersecting mesh or of nested shells count once, a shell turned
/// inside out is a cavity); for a mesh of two triangles on every edge but inconsistent
/// orientation, ray parity. A pose that reflects a mesh places the image of its solid. Touching
/// is decided on the triangles: a triangle that bounds no part of the solid (a shell turned inside
/// out standing alone, whose points `inside` calls `out`) still counts where it touches. A mesh
/// that is not closed is a surface: it meets the other shape where the surfaces share a point,
/// or where it lies inside the other if that one is a solid. Coordinates are the doubles
/// `transform.apply(v)` (the contract's evaluation order), and every answer is exact on them.
///
/// Algorithm per query: a simultaneous descent of both hierarchies (A's built in world
/// coordinates; B's in its own frame, its boxes mapped by the transform to enclosing world
/// boxes widened by a bound on the rounding, so no pair is ever missed); at leaf pairs B's
/// triangle is transformed, its box compared exactly and `tri_tri` decides. If no
/// surfaces meet, solids can still be nested: the boundary of A ∩ B then consists of whole
/// connected components of the two surfaces, so one vertex per component of A is located in B
/// (the exact signed crossings of the perturbed +x ray against B's transformed triangles, read
/// by B's solid rule: `inside::locate_by_ray`, docs/robustness.md) and one vertex per component
/// of B in A (the same ray through A's hierarchy, or A's `inside::MeshIndex` once the rays have
/// cost as much as building it: `inside::PlacedMeshPair::a_holds`); the winding number is
/// constant on a connected set off the surface, so one vertex decides for its component.
///
/// Complexity: build O(n log n); a query O(node pairs entered + leaf pairs) plus a ray per
/// component reaching the containment check. Thread safety: const; queries may run
/// concurrently. Reference: "Algorithms of Informatics" vol. 2, § 22.4 (polyhedron collision,
/// bounding volumes), exercise 22.4-1; Gottschalk, Lin, Manocha, "OBBTree", SIGGRAPH 1996
/// (hierarchy pairs).
class MeshPair {
 public:
  /// Prepares `a` and `b` (validated meshes; any topology; empty meshes never intersect).
  MeshPair(const Mesh& a, const Mesh& b, const MeshPairOptions& options = {});

  /// Does A meet B placed by `transform_b`?
  [[nodiscard]] Contact collide(const Transform& transform_b) const;

  /// out[i] = collide(poses[i]) for every i (`out` has the inputs' size: `batch_size`), in parallel
  /// on `options.threads` threads.
  void collide(std::span<const Transform> poses, std::span<Contact> out,
               const BatchOptions& options = {}) const;

  /// True when A (resp. B) is closed, so a solid; false: a surface.
  [[nodiscard]] bool a_is_solid() const { return pair_.a.solid(); }
  [[nodiscard]] bool b_is_solid() const { return pair_.b.solid(); }
  /// A's vertices in world coordinates (transform_a applied).
  [[nodiscard]] std::span<const Vec3> a_vertices() const { return pair_.a.mesh.vertices; }
  /// The prepared pair: A in world coordinates with its index, B in its own frame, each with
  /// its hierarchy, components and solidity (shared with `MovingMeshPair`).
  [[nodiscard]] const inside::PlacedMeshPair& prepared() const { return pair_; }

 private:
  inside::PlacedMeshPair pair_;  // A in world coordinates with its index, B in its own frame
};

/// One query: does `a` placed by `transform_a` meet `b` placed by `transform_b`? Exactly
/// `MeshPair(a, b, {.transform_a = transform_a}).collide(transform_b)`.
[[nodiscard]] Contact mesh_mesh(const Mesh& a, const Mesh& b, const Transform& transform_a = {},
                                const Transform& transform_b = {});

}  // namespace contain::collide
