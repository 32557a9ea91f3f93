#pragma once
/// \file
/// Point in a CSG tree (exercise 22.4-2): unions, intersections, differences and complements of
/// balls, boxes, half-spaces, convex polyhedra, closed triangle meshes and implicit solids, with
/// the regularised
/// operations of solid modelling.
///
/// Semantics. Every leaf is a closed solid. The operations are regularised (the closure of the
/// interior of the plain set operation), so the answer depends only on what fills space near
/// the point: `inside` when every point near p is in the solid, `outside` when none is,
/// `boundary` otherwise. Hence a point on the surface of A and strictly inside B is `boundary`
/// for A ∩ B and `inside` for A ∪ B; a point on the face shared by two touching boxes is
/// `inside` their union; the part of A's boundary inside B is `boundary` of A − B; complement
/// swaps `inside` and `outside` and keeps `boundary`; solids without interior (a flat box, a
/// ball of radius 0) are empty.
///
/// Algorithm. Each leaf is located exactly (inside/implicit.h, inside/point_in_convex.h). If no
/// leaf that matters (three-valued evaluation of the tree) reports `boundary`, the tree is
/// evaluated on in/out. Otherwise p lies on the boundary of some leaves, and the neighbourhood of
/// p is analysed: each such leaf contributes its local constraints at p, the planes through p
/// that bound it there with their inward normals (active faces of boxes and convex polyhedra,
/// half-space planes, the tangent plane of a ball with inward normal c − p). Directions from p
/// are cut by these planes into open cells; the tree is evaluated on a representative of every
/// cell, and the answer is `inside` if all are in, `outside` if all are out, else `boundary`.
/// The representatives are the symbolic points p + ε v + ε² (w + δ u1 + δ² u2) with 0 < ε ≪ δ ≪ 1,
/// v a ray of the arrangement of the planes (a cross product of two normals) and w a vertex or
/// a point on a line of the second-order arrangement in the plane normal to v, in which a ball's
/// surface is the line 2 (c − p)·w = |v|²: this sees the curvature of balls, so a ball tangent to
/// a half-space from outside leaves an uncovered cusp (`boundary` of their union) and two
/// internally tangent balls are ordered by radius. All signs are evaluated exactly (normals and
/// their products in exact dyadic arithmetic), so the answer is exact for trees of balls, boxes,
/// half-spaces and convex polyhedra, with one known gap: where three second-order surfaces
/// (ball surfaces seen along a common tangent line) meet at one second-order point, a region
/// that only opens at third order is not seen.
///
/// Implicit leaves: located by the sign of f(p) as evaluated (point_in_implicit); at a point where
/// f(p) == 0 the local constraint is a plane with a normal from a central-difference estimate of
/// the gradient (step 1e-6 max(1, |p|∞)), without curvature: approximate, like the function itself.
/// A zero or non-finite gradient estimate makes the leaf locally `inside` if f >= 0 at the six
/// points p ± step e_k and `outside` otherwise.
///
/// Mesh leaves (CsgMesh, a closed triangle mesh): located exactly by inside::MeshIndex (its
/// solid rule: winding number positive, parity only for inconsistent orientation). A mesh is not
/// locally an intersection of half-spaces (a reflex edge, a saddle vertex), so each leaf classifies
/// the symbolic samples itself: its local constraints are the planes of the triangles that contain
/// p (so every cell of the arrangement is wholly in or out of the mesh), and it decides a sample q
/// by the same perturbed +x ray count as MeshIndex, with q's symbolic offset from p ordered before
/// the ray's own perturbation (0, e, e²): every test is linear in the ray origin, so its sign is
/// the first non-zero one of its value at p and its products with v, w, u1, u2, e_y, e_z, all
/// exact. Exact, like MeshIndex on closed meshes. A point on the boundary of one leaf only, a mesh
/// read by winding number, is answered by that mesh's index (the star of its triangles through p)
/// without sampling: each leaf occurs once in the tree, so the other leaves' definite answers and
/// that leaf's `boundary` decide the tree exactly. An open mesh (border or non-manifold edges,
/// where MeshIndex falls back on the approximate winding number) is refused by CsgSolid::prepare; a
/// mesh without triangles is the empty solid (every point outside: a union with it is its other
/// operands).
///
/// Extending: a new kind of leaf adds an alternative to CsgLeaf, its exact locate, its local
/// constraints at a boundary point, and either the rule that it fills exactly the cells on the
/// positive side of its constraints or its own classification of a symbolic sample (as meshes).

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "contain/core/location.h"
#include "contain/core/parallel.h"
#include "contain/core/result.h"
#include "contain/inside/mesh_index.h"
#include "contain/shapes/csg.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// A validated CSG tree flattened for queries (the prepared object). Immutable; locate() may be
/// called from several threads at once, provided implicit leaves' functions allow it.
class CsgSolid {
 public:
  /// Validates every leaf: finite numbers (invalid_value), radius >= 0 (invalid_value),
  /// box min <= max on every axis (invalid_value), half-space normal not zero (degenerate),
  /// an implicit leaf holding a function (invalid_value), a mesh with valid numbers and indices
  /// (invalid_value) that is closed (degenerate); messages name the leaf by its position in the
  /// tree ("intersect[1].subtract[0]: radius is negative"). Each mesh leaf is indexed once
  /// (inside::MeshIndex with `mesh_options`, O(n log n + grid)), also when it appears in several
  /// leaves. O(size of the tree) for the rest.
  [[nodiscard]] static Result<CsgSolid> prepare(const Csg& tree,
                                                const MeshIndexOptions& mesh_options = {});

  /// Where p lies, with the semantics of this header. Cost: one exact locate per leaf; at points
  /// on some leaf's boundary, the neighbourhood analysis (exact arithmetic, polynomial in the
  /// number k of local constraints, ~k^4 tree evaluations, small k in practice; a mesh leaf adds
  /// O(n) to find the triangles through p and an exact ray test per sample against the few
  /// triangles that p's +x ray touches degenerately).
  [[nodiscard]] Location locate(Vec3 p) const;

  /// locate() for every point, in parallel (core/parallel.h); out[i] is the answer for
  /// points[i], the same whatever the thread count. Precondition: out.size() == points.size()
  /// (asserted: `batch_size`).
  void locate(std::span<const Vec3> points, std::span<Location> out,
              const BatchOptions& options = {}) const;

  /// Number of leaves of the tree.
  [[nodiscard]] std::size_t leaf_count() const { return leaves_.size(); }

 private:
  struct Node {
    CsgOp op = CsgOp::leaf;
    std::int32_t first = 0;  // leaf: index into leaves_; else first index into children_
    std::int32_t count = 0;  // number of children
  };

  template <class LeafValue>
  [[nodiscard]] int evaluate(std::int32_t node, const LeafValue& leaf_value) const;

  std::vector<Node> nodes_;  // nodes_[0] is the root; children precede nothing in particular
  std::vector<std::int32_t> children_;
  std::vector<CsgLeaf> leaves_;
  // Per leaf: the prepared index of a mesh leaf (shared between leaves of one mesh), else null.
  std::vector<std::shared_ptr<const MeshIndex>> mesh_indexes_;
};

/// One-shot form of CsgSolid::locate.
[[nodiscard]] Location point_in_csg(const CsgSolid& solid, Vec3 p);

}  // namespace contain::inside
