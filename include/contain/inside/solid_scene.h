#pragma once
/// \file
/// A scene of solids (meshes placed by transforms) prepared once: which solids hold each point.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/core/parallel.h"
#include "contain/inside/holders.h"
#include "contain/inside/mesh_index.h"
#include "contain/inside/placed_mesh.h"
#include "contain/shapes/mesh.h"
#include "contain/values/box.h"
#include "contain/values/transform.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// One object of a scene: mesh number `mesh` of the scene's meshes, placed by `transform`
/// (world = transform.apply(local)). Several objects may share a mesh.
struct SceneObject {
  std::int32_t mesh = 0;
  Transform transform{};
};

/// How a `SolidScene` is built.
struct SolidSceneOptions {
  /// The index of each object; a coarser grid than a single `MeshIndex`'s default, since a
  /// scene holds many (memory per object: 5 bytes a cell, 28 a triangle-cell pair, about 100 a
  /// triangle).
  MeshIndexOptions index{.cells_per_triangle = 4.0, .min_cells = 512};
};

/// Many solids prepared for exact point location: for a point, the objects that hold it.
///
/// Object k holds p with `MeshIndex(placed mesh).locate(p)`: its mesh's vertices placed by its
/// transform (the doubles `Transform::apply` gives, as `contain inside --mesh` of that placed
/// mesh; `placed_solid`: a reflecting transform also reverses the triangles, so the object is the
/// image of the mesh's solid, as collide::MeshScene reads it), exact for closed meshes
/// (**perturbed +x ray rule**, the solid of the winding number), the generalized winding number
/// for a mesh that is not closed (`object(k).regime()` says so). A point on the surface of a
/// solid is `boundary` for it; nested solids both hold a point inside the inner one.
///
/// Structure: one `MeshIndex` per object in world coordinates, and a bounding volume hierarchy
/// over the objects' boxes, so a point meets only the objects whose boxes hold it.
/// Complexity: build O(n log n) for n triangles in all (each object's triangles are indexed once
/// per object, shared meshes included); a query O(log m + sum over candidate objects of a
/// `MeshIndex` query). Thread safety: const queries may run concurrently; batch tables do not
/// depend on the thread count.
class SolidScene {
 public:
  /// An empty scene: no point is held.
  SolidScene() = default;
  /// Prepares every object (meshes validated; `objects[k].mesh` must index `meshes`, else the
  /// object is empty and holds nothing).
  SolidScene(std::span<const Mesh> meshes, std::span<const SceneObject> objects,
             const SolidSceneOptions& options = {});

  /// The number of objects.
  [[nodiscard]] std::size_t size() const { return indexes_.size(); }
  /// The prepared index of object k (in world coordinates).
  [[nodiscard]] const MeshIndex& object(std::size_t k) const { return indexes_[k]; }

  /// The objects holding `point`, numbers ascending.
  [[nodiscard]] std::vector<Holder> locate(Vec3 point) const;
  /// Appends the objects holding `point` to `out`, numbers ascending.
  void locate(Vec3 point, std::vector<Holder>& out) const;
  /// The holders of every point, in parallel (0 threads: all); the same for every thread count.
  [[nodiscard]] HolderTable locate(std::span<const Vec3> points,
                                   const BatchOptions& options = {}) const;

 private:
  std::vector<MeshIndex> indexes_;
  bvh::Bvh tree_;
};

/// The objects holding `point` (one query: prefer `SolidScene` for many).
[[nodiscard]] std::vector<Holder> point_in_solids(std::span<const Mesh> meshes,
                                                  std::span<const SceneObject> objects, Vec3 point,
                                                  const SolidSceneOptions& options = {});

}  // namespace contain::inside
