#pragma once
/// \file
/// Continuous collision of two meshes whose vertices move on straight lines from t = 0 to
/// t = 1: the earliest time at which the solids (or surfaces) touch, exactly, with the witness
/// pair of primitives.

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/collide/contact.h"
#include "contain/collide/mesh_mesh.h"
#include "contain/core/parallel.h"
#include "contain/shapes/mesh.h"
#include "contain/values/transform.h"

namespace contain::collide {

/// A mesh's placement at t = 0 (`from`) and at t = 1 (`to`). Each vertex v moves on the straight
/// line from from.apply(v) to to.apply(v) (the doubles `Transform::apply` computes); for a
/// rotation the shape is not rigid in between (the contract's meaning, as in the CCD benchmark).
struct Motion {
  Transform from{};
  Transform to{};
};

/// What proves the first contact.
enum class MeshImpactWitness : std::uint8_t {
  none,     ///< no contact in [0, 1]
  initial,  ///< the shapes already touch or nest at t = 0 (`initial` holds the discrete witness)
  vertex_a_face_b,  ///< vertex `vertex` of A meets triangle `triangle` of B
  vertex_b_face_a,  ///< vertex `vertex` of B meets triangle `triangle` of A
  edges,            ///< edge `edge_a` of A (two vertex indices) meets edge `edge_b` of B
};

/// "none", "initial", "vertex_a_face_b", "vertex_b_face_a", "edges".
[[nodiscard]] constexpr const char* to_string(MeshImpactWitness w) {
  switch (w) {
    case MeshImpactWitness::initial:
      return "initial";
    case MeshImpactWitness::vertex_a_face_b:
      return "vertex_a_face_b";
    case MeshImpactWitness::vertex_b_face_a:
      return "vertex_b_face_a";
    case MeshImpactWitness::edges:
      return "edges";
    case MeshImpactWitness::none:
      break;
  }
  return "none";
}

/// The answer of a moving mesh query.
struct MeshImpact {
  /// The shapes touch at some time in [0, 1].
  bool hit = false;
  /// hit: the largest double <= the earliest time of contact (0 when they touch or nest at
  /// t = 0); miss: +infinity.
  double time = std::numeric_limits<double>::infinity();
  MeshImpactWitness witness = MeshImpactWitness::none;
  std::int32_t vertex = -1;    ///< vertex-face witnesses: the vertex in its own mesh
  std::int32_t triangle = -1;  ///< vertex-face witnesses: the triangle of the other
  std::array<std::int32_t, 2> edge_a{-1, -1};  ///< edges: the vertex indices of A's edge
  std::array<std::int32_t, 2> edge_b{-1, -1};  ///< edges: the vertex indices of B's edge
  Contact initial;                             ///< the discrete test at t = 0 (witness `initial`)
  std::size_t node_pairs = 0;                  ///< pairs of swept bounding boxes tested
  std::size_t primitive_tests = 0;             ///< vertex-face and edge-edge queries run
};

/// How a `MovingMeshPair` is prepared.
struct MovingMeshPairOptions {
  /// A's motion (identity: A stays where its vertices are).
  Motion motion_a{};
  /// A deforming mesh instead: A's vertices at t = 1 (as many as A has; A's own vertices are its
  /// positions at t = 0). When not empty, `motion_a` is ignored.
  std::vector<Vec3> a_at1;
  /// The hierarchies over the triangles' swept boxes.
  bvh::BuildOptions bvh{};
};

/// Two meshes prepared for continuous collision queries: A with a fixed motion, B moved per
/// query.
///
/// Semantics: at t = 0 the shapes are tested as `MeshPair` does (closed meshes are solids,
/// nesting counts); if they touch there the answer is 0. Otherwise two solids that start apart
/// first touch where their surfaces first meet, and two triangles moving continuously first
/// meet at a vertex-face or an edge-edge contact (docs/robustness.md, rule ccd-mesh-rule),
/// so the answer is the least, over all vertex-face (both ways) and edge-edge pairs, of the
/// exact primitive answers (`vertex_face_ccd`, `edge_edge_ccd`): the largest double <= the
/// earliest contact time. The witness is the first primitive pair in the order (time, vertex of
/// A on a face of B, vertex of B on a face of A, edges; then indices) among those with that time.
///
/// Algorithm: A's triangles in a hierarchy over their swept boxes (the boxes of their corners at
/// t = 0 and t = 1); B's hierarchy in its own frame, its boxes mapped by both placements
/// (enclosing, with a rounding margin) or, for a deforming B, built per query. A box whose
/// corners move linearly holds its points at time t in (1 - t) b0 + t b1, so two moving boxes
/// can first overlap at a time found from six linear inequalities; node pairs are opened best
/// first in the order of that time, and none that can only meet after the best contact found so
/// far is opened. At leaf pairs, each vertex-face and edge-edge primitive whose own boxes can meet
/// in time is decided exactly, once per query (a vertex or an edge is shared by several
/// triangles).
/// Complexity: build O(n log n); a query O(node pairs entered + primitives tested).
/// Thread safety: const; queries may run concurrently.
class MovingMeshPair {
 public:
  /// Prepares validated meshes (any topology; an empty mesh never touches anything).
  /// Precondition: `options.a_at1` is empty or has one position per vertex of A (finite).
  MovingMeshPair(const Mesh& a, const Mesh& b, const MovingMeshPairOptions& options = {});

  /// B moves by `motion_b` (its vertices are in its own frame).
  [[nodiscard]] MeshImpact first_contact(const Motion& motion_b) const;

  /// B deforms from its own vertices (t = 0, world coordinates) to `b_at1` (t = 1), one finite
  /// position per vertex of B (precondition). Builds B's swept hierarchy for this query.
  [[nodiscard]] MeshImpact first_contact(std::span<const Vec3> b_at1) const;

  /// out[i] = first_contact(motions_b[i]) for every i (`out` has the inputs' size: `batch_size`),
  /// in parallel on `options.threads` threads (answers independent of the thread count).
  void first_contact(std::span<const Motion> motions_b, std::span<MeshImpact> out,
                     const BatchOptions& options = {}) const;

  /// True when A (B) is closed, so a solid.
  [[nodiscard]] bool a_is_solid() const { return discrete_a_.a_is_solid(); }
  [[nodiscard]] bool b_is_solid() const { return discrete_a_.b_is_solid(); }
  /// The number of vertices of A and B (the length of `a_at1` and `b_at1`).
  [[nodiscard]] std::size_t a_vertex_count() const { return a_.vertices.size(); }
  [[nodiscard]] std::size_t b_vertex_count() const { return b().mesh.vertices.size(); }

 private:
  struct Side;
  [[nodiscard]] MeshImpact surfaces(const Side& b_side, MeshImpact result) const;
  struct Tested;
  void leaf_pair(const Side& b_side, std::int32_t ta, std::int32_t tb, double& limit,
                 MeshImpact& best, Tested& tested) const;

  // B in its own frame with its hierarchy: the discrete test's, shared.
  [[nodiscard]] const inside::PlacedMesh& b() const { return discrete_a_.prepared().b; }

  Mesh a_;
  std::vector<Vec3> a0_, a1_;          // A's vertices at t = 0 and t = 1, world
  bvh::Bvh bvh_a_;                     // over A's swept triangle boxes
  std::vector<Box3> a_box0_, a_box1_;  // per node of bvh_a_: boxes at t = 0 and t = 1
  std::vector<std::array<std::int32_t, 3>> a_edges_, b_edges_;  // per triangle: its edges' ids
  MeshPair discrete_a_;  // the test at t = 0: A placed at t = 0, B by the query's t = 0 pose
  bvh::BuildOptions bvh_options_;
};

/// One query: A moving by `motion_a`, B by `motion_b`. Exactly
/// `MovingMeshPair(a, b, {.motion_a = motion_a}).first_contact(motion_b)`.
[[nodiscard]] MeshImpact mesh_mesh_ccd(const Mesh& a, const Mesh& b, const Motion& motion_a,
                                       const Motion& motion_b);

/// One query for deforming meshes: A from its vertices to `a_at1`, B from its vertices to `b_at1`.
[[nodiscard]] MeshImpact mesh_mesh_ccd(const Mesh& a, std::span<const Vec3> a_at1, const Mesh& b,
                                       std::span<const Vec3> b_at1);

}  // namespace contain::collide
