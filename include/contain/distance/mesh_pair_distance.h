#pragma once
/// \file
/// Distance between two triangle meshes as solids (0 where they touch, overlap or nest), under
/// rigid transforms and for batches of poses, with the closest pair of points and triangles; and
/// the exact clearance test `within d`.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/core/parallel.h"
#include "contain/inside/pair_witness.h"
#include "contain/inside/placed_mesh.h"
#include "contain/shapes/mesh.h"
#include "contain/values/transform.h"
#include "contain/values/vec.h"

namespace contain::distance {

/// How two meshes relate at the answer of a `MeshPairDistance` query (and of the convex and
/// region pairs), as an `inside::PairWitness` (collide's witness type too): `none` (distance >
/// 0), `triangles` (the surfaces share a point, distance 0: `triangle_a`, `triangle_b` meet;
/// `edges` for regions), `vertex_of_a_in_b` / `vertex_of_b_in_a` (`vertex` inside the other
/// solid: they overlap or nest, distance 0).
///
/// The words of a distance answer: "separate" (`none`), "touching" (`triangles`, `edges`),
/// "vertex_of_a_in_b", "vertex_of_b_in_a".
[[nodiscard]] const char* to_string(inside::PairWitness contact);

/// The answer of a mesh pair distance query.
struct PairDistance3 {
  /// The double nearest to the exact distance between the two shapes (solids where closed,
  /// surfaces where open); 0 exactly where they touch, overlap or nest; +infinity when either is
  /// empty.
  double distance = 0.0;
  /// The closest pair of points, on A and on B (world coordinates), each coordinate the double
  /// nearest to the exact one. Touching: a common point (both the same). Nested: the contained
  /// vertex (both the same).
  Vec3 point_a{};
  Vec3 point_b{};
  /// The closest triangles (index in each mesh; ties to the lowest triangle of A, then of B);
  /// -1 for nested answers.
  std::int32_t triangle_a = -1;
  std::int32_t triangle_b = -1;
  inside::PairWitness contact = inside::PairWitness::none;
  std::int32_t vertex = -1;    ///< nested answers: the contained vertex (in its own mesh)
  std::size_t node_pairs = 0;  ///< bounding volume pairs tested
  std::size_t contenders = 0;  ///< triangle pairs passed to the exact stage
};

/// How a `MeshPairDistance` is prepared: the fixed placement of A (`transform_a`, evaluated
/// once), the hierarchies' build options (`bvh`) and A's point-location index (`index`, where
/// vertices of B are located for nesting). The same options as `collide::MeshPair`'s.
using MeshPairDistanceOptions = inside::MeshPairOptions;

/// Two meshes prepared for distance queries, B placed by a transform per query.
///
/// Semantics: as `collide::MeshPair` (the CLI contract): a closed mesh bounds a solid (a closed
/// set), an open mesh is a surface. The distance is 0 where the shapes share a point, including
/// one solid inside the other; otherwise it is the least distance between the two surfaces. All
/// coordinates are the doubles `transform.apply(v)`, and every decision is exact on them: the
/// closest triangle pair is the one of least exact distance (ties to the lowest triangle of A,
/// then of B: **distance-tie rule**), the distance is rounded once to the nearest double, and
/// the closest points per coordinate.
///
/// Algorithm per query: first one vertex per component of B is located in A (exact,
/// inside::MeshIndex) and one vertex per component of A in B as placed (the exact signed
/// crossings of the perturbed +x ray, read by B's inside::SolidRule): a vertex strictly inside
/// makes the distance 0 (overlapping or nested solids). A closed mesh's solid is `contain
/// inside`'s: where its winding number is positive (overlapping parts of a self-intersecting mesh
/// count once, a shell turned inside out is a cavity), ray parity for inconsistent orientation;
/// a pose that reflects a mesh places the image of its solid. Then a
/// simultaneous descent of both hierarchies (A's built in world coordinates; B's in its own
/// frame), nearer pairs first, pruned against the best upper bound so far by a lower bound
/// between the nodes' oriented boxes (principal axes of the node's vertices, proven to hold
/// them; separation along the line between the centres, B's box placed by the pose, minus a
/// proven rounding margin); each triangle pair is bounded in floating point (approximate closest
/// points, an upper bound, and a lower bound from the separation along their difference, proven
/// for any direction); a pair whose lower bound is 0 is tested exactly for meeting, and once
/// one meets the distance is 0 and the descent only looks for lower meeting pairs (tie rule);
/// otherwise the exact stage decides among the triangle pairs that can be closest
/// (predicates::closest_flats: crossing edges, six vertex-triangle and nine edge-edge pairs).
/// If no vertex lies inside and no surfaces meet, the solids are apart (the boundary of their
/// intersection would consist of whole components).
///
/// Complexity: build O(n log n); a query O(node pairs + triangle pairs near the closest
/// distance) + a ray per component for separated solids; B's vertices are placed where the
/// descent meets them.
/// Thread safety: const; queries may run concurrently; batch answers do not depend on the thread
/// count. Reference: Larsen, Gottschalk, Lin, Manocha, "Fast proximity queries with swept sphere
/// volumes" (1999) for the hierarchy descent; Ericson, "Real-Time Collision Detection" (2005) 5.1.
class MeshPairDistance {
 public:
  /// Prepares `a` and `b` (validated meshes; any topology).
  MeshPairDistance(const Mesh& a, const Mesh& b, const MeshPairDistanceOptions& options = {});

  /// The distance between A and B placed by `transform_b`.
  [[nodiscard]] PairDistance3 distance(const Transform& transform_b) const;
  /// out[i] = distance(poses[i]) for every i (`out` has the inputs' size: `batch_size`), in
  /// parallel on `options.threads` threads.
  void distance(std::span<const Transform> poses, std::span<PairDistance3> out,
                const BatchOptions& options = {}) const;

  /// Is the distance between A and B placed by `transform_b` at most `d`? Exact (squared
  /// distances against d^2, no rounding); d < 0 or NaN: false.
  [[nodiscard]] bool within(const Transform& transform_b, double d) const;
  void within(std::span<const Transform> poses, double d, std::span<std::uint8_t> out,
              const BatchOptions& options = {}) const;

  [[nodiscard]] bool a_is_solid() const { return pair_.a.solid(); }
  [[nodiscard]] bool b_is_solid() const { return pair_.b.solid(); }

 private:
  // The stages of a query (src/distance/mesh_pair_distance.cpp): B placed by the pose, a vertex
  // of one inside the other, the descent over node pairs, the exact closest contender.
  struct Volumes;  // oriented boxes of both hierarchies' nodes (src/distance/oriented_box.h)
  struct Placed;   // B's vertices and nodes as placed by one pose (thread-local, on first use)
  struct Descent;  // the branch and bound over node pairs
  struct Nested {  // a component's vertex strictly inside the other solid, if any
    inside::PairWitness contact = inside::PairWitness::none;
    std::int32_t vertex = -1;
    Vec3 point{};
  };
  struct Closest;  // the exact winner among the descent's contenders
  [[nodiscard]] Placed& place(const Transform& tb) const;
  [[nodiscard]] Nested nested(Placed& placed) const;
  [[nodiscard]] Closest closest(Descent& descent) const;

  inside::PlacedMeshPair pair_;  // A in world coordinates with its index, B in its own frame
  std::shared_ptr<const Volumes> volumes_;
};

/// One query: exactly `MeshPairDistance(a, b, {.transform_a = transform_a}).distance(transform_b)`.
[[nodiscard]] PairDistance3 mesh_mesh(const Mesh& a, const Mesh& b,
                                      const Transform& transform_a = {},
                                      const Transform& transform_b = {});

}  // namespace contain::distance
