#pragma once
/// \file
/// A mesh prepared as one side of pair queries (collision, distance, a scene's pair tests): its
/// hierarchy, components and solidity, built once in its own frame and placed by a transform per
/// query; and two meshes prepared together, A placed once with its point-location index.

#include <cstdint>
#include <memory>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/inside/mesh_index.h"
#include "contain/inside/solid_rule.h"
#include "contain/shapes/mesh.h"
#include "contain/values/transform.h"

namespace contain::inside {

/// `mesh` placed by `transform` as a solid's boundary: the vertices transform.apply(v), and each
/// triangle's corners reversed where the transform reflects (transform_orientation negative), so
/// that the placed mesh's solid (MeshIndex) is the image of the mesh's solid. O(n).
[[nodiscard]] Mesh placed_solid(const Mesh& mesh, const Transform& transform);

/// A mesh prepared for pair queries, in the frame of its vertices.
struct PlacedMesh {
  Mesh mesh;                             ///< the triangles, in this side's frame
  bvh::Bvh bvh;                          ///< over the triangles' boxes, in the same frame
  std::vector<std::int32_t> components;  ///< one vertex of each connected component
  /// How its crossing counts read (solid_rule.h): the solid of its winding number, ray parity
  /// for a closed mesh of inconsistent orientation, or `none`: not closed, a surface.
  SolidRule rule = SolidRule::none;
  double max_abs = 0.0;  ///< the largest |coordinate|: the scale of placement bounds

  /// An empty side: it meets nothing.
  PlacedMesh() = default;
  /// Prepares a validated `mesh`: its hierarchy, one vertex per connected component, its solid
  /// rule (`solid_rule`, as `MeshIndex` chooses its regime), its largest coordinate. An empty mesh
  /// gets no hierarchy and is no solid. O(n log n).
  explicit PlacedMesh(Mesh mesh, const bvh::BuildOptions& options = {});

  /// Closed: a solid (`MeshIndex` regime `closed_exact`), not a surface.
  [[nodiscard]] bool solid() const { return rule != SolidRule::none; }
};

/// How a `PlacedMeshPair` is prepared (collide::MeshPairOptions and
/// distance::MeshPairDistanceOptions are this).
struct MeshPairOptions {
  /// The fixed placement of A (world = transform_a.apply(local), evaluated once).
  Transform transform_a{};
  /// The hierarchies over the triangles of A and B.
  bvh::BuildOptions bvh{};
  /// The point-location index of A (vertices of B are located in it for nesting).
  MeshIndexOptions index{};
};

/// Two meshes prepared for queries that place B by a transform each: A placed once in world
/// coordinates (the doubles `transform_a.apply(v)`) with its exact point location, B in its
/// own frame. The prepared pair of `collide::MeshPair` and `distance::MeshPairDistance`.
///
/// A's point location is prepared in proportion to the work: A's `MeshIndex` is not built with
/// the pair. `a_holds` casts the perturbed ray through A's hierarchy (which the pair has anyway)
/// until the rays have cost about as much as building the index (a measured cost model,
/// placed_mesh.cpp: one pose of a nested pair casts a ray per component, where the index of a
/// 100k-triangle mesh costs as much as tens of thousands of rays), then builds the index once
/// (thread-safe) and asks it. Both are exact and give the same answers.
struct PlacedMeshPair {
  PlacedMesh a;  ///< A in world coordinates; its rule `MeshIndex`'s for it (`solid_rule`)
  PlacedMesh b;  ///< B in its own frame

  PlacedMeshPair() = default;
  /// Prepares validated meshes `a` and `b` (any topology). O(n log n).
  PlacedMeshPair(const Mesh& a, const Mesh& b, const MeshPairOptions& options = {});

  /// Is the world point `q` inside A's solid: exactly `index_a().locate(q) == Location::inside`?
  /// A must be a solid (`a.solid()`). A point off A's surface is located by the signed crossings
  /// of the perturbed +x ray through A's hierarchy (`locate_by_ray`) until A's index is built; a
  /// point on it (where `MeshIndex` tells a buried face from the solid's boundary) by the index.
  /// O(nodes the ray meets + their triangles), or O(1) once the index is built. Thread safety:
  /// const; calls may run concurrently (the index is built once, by the call that finds it due).
  [[nodiscard]] bool a_holds(Vec3 q) const;

  /// A's point-location index (`MeshIndex` of A as placed, its triangles reversed where
  /// `transform_a` reflects, so that its solid is the image of A's), built on the first call
  /// that needs it; empty for an empty A. Thread-safe as `a_holds`.
  [[nodiscard]] const MeshIndex& index_a() const;

  /// Whether A's index has been built (by `index_a`, or by `a_holds` once its rays cost as much).
  [[nodiscard]] bool index_a_built() const;

 private:
  struct LazyIndex;  // placed_mesh.cpp: the index, its once_flag and the rays' cost so far
  std::shared_ptr<LazyIndex> lazy_a_;
};

}  // namespace contain::inside
