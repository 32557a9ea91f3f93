#pragma once
/// \file
/// Every intersecting pair in a scene of solids (meshes placed by transforms): a broad phase
/// over the objects' boxes, then the exact test of `MeshPair` on each candidate pair.

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/collide/contact.h"
#include "contain/core/parallel.h"
#include "contain/inside/placed_mesh.h"
#include "contain/inside/solid_scene.h"
#include "contain/shapes/mesh.h"
#include "contain/values/box.h"

namespace contain::collide {

/// An intersecting pair of objects (a < b) and the contact that proves it.
struct ScenePair {
  std::int32_t a = 0;
  std::int32_t b = 0;
  Contact contact;
};

/// How a `MeshScene` is prepared.
struct MeshSceneOptions {
  /// The hierarchy over each distinct mesh's triangles (built once per mesh, shared by the
  /// objects placing it).
  bvh::BuildOptions bvh{};
};

/// A scene prepared for collision: which objects touch or overlap.
///
/// Semantics: those of `MeshPair` for every pair (the CLI contract): a closed mesh bounds a
/// solid, a closed set, so touching counts and one solid inside another counts; a mesh that is
/// not closed is a surface. Coordinates are the doubles `transform.apply(v)` of each object, and
/// each pair's answer equals `MeshPair(mesh_a, mesh_b, {.transform_a = ta}).collide(tb)`
/// exactly (the witness may differ: any witness proves the contact).
///
/// Algorithm: each distinct mesh gets its hierarchy, connected components and solidity once,
/// in its own frame (objects sharing a mesh share them: 500 objects of 8 meshes cost 8
/// hierarchies). Each object's world box holds its placed triangles (`bounds`); sweep and
/// prune (`pair_search`) over those boxes gives the candidate pairs; each candidate is tested
/// exactly: both hierarchies under their transforms, node pairs culled by the separating axis
/// test of the two placed boxes (15 axes, Gottschalk et al. 1996; widened by a rounding bound,
/// so no pair is missed), exact triangle tests at the leaves, then one vertex per component
/// located in the other solid by the exact signed crossings of the perturbed ray (the solid of
/// `inside::MeshIndex`: winding number positive, parity for inconsistent orientation).
///
/// Complexity: build O(n log n) for n distinct triangles plus O(1) per object for its box;
/// `pairs` O(m log m + candidates x pair test). Thread safety: const; `pairs` runs candidates
/// on `options.threads` threads and its answer does not depend on the thread count.
class MeshScene {
 public:
  /// An empty scene.
  MeshScene() = default;
  /// Prepares the objects (meshes validated; an object whose mesh number is out of range is
  /// empty and meets nothing).
  MeshScene(std::span<const Mesh> meshes, std::span<const inside::SceneObject> objects,
            const MeshSceneOptions& options = {});

  /// The number of objects.
  [[nodiscard]] std::size_t size() const { return objects_.size(); }
  /// True when object k is a solid (its mesh closed), false for a surface.
  [[nodiscard]] bool is_solid(std::size_t k) const;
  /// A closed world box holding every placed triangle of object k (empty for an empty
  /// object): the union of the placed boxes of its hierarchy's nodes 8 levels down, widened by
  /// the rounding bound, so slightly larger than the exact box.
  [[nodiscard]] const Box3& bounds(std::size_t k) const { return boxes_[k]; }

  /// Every intersecting pair (a < b), sorted by a then b: `pairs(candidates(), options)`.
  [[nodiscard]] std::vector<ScenePair> pairs(const BatchOptions& options = {}) const;
  /// The intersecting pairs among `candidates` (pairs of objects i != j, such as a range of
  /// `candidates()`), in their order. Consecutive ranges of `candidates()` give `pairs()` in
  /// pieces, so a long run can report progress between them (the command's `collide --scene`).
  [[nodiscard]] std::vector<ScenePair> pairs(
      std::span<const std::pair<std::int32_t, std::int32_t>> candidates,
      const BatchOptions& options = {}) const;
  /// The exact test of objects i and j (i != j).
  [[nodiscard]] Contact collide(std::size_t i, std::size_t j) const;

  /// The candidates of the broad phase: pairs of objects whose `bounds` share a point, sorted
  /// (a superset of `pairs`).
  [[nodiscard]] std::vector<std::pair<std::int32_t, std::int32_t>> candidates() const;

 private:
  // One per distinct mesh, in its own frame (empty where no object places the mesh).
  std::vector<inside::PlacedMesh> models_;
  std::vector<inside::SceneObject> objects_;
  std::vector<Box3> boxes_;
};

/// Every intersecting pair of the scene (one call: prefer `MeshScene` to ask several times).
[[nodiscard]] std::vector<ScenePair> scene_pairs(std::span<const Mesh> meshes,
                                                 std::span<const inside::SceneObject> objects,
                                                 const BatchOptions& options = {});

}  // namespace contain::collide
