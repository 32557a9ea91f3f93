#pragma once
// Private to contain::distance: oriented boxes around the nodes of a triangle hierarchy, and a
// proven floating-point lower bound on the distance between two of them, one placed by a pose,
// for the mesh-pair descent (the role of PQP's and FCL's RSS volumes: tight around surface
// patches at any orientation, where axis-aligned boxes are as thick as the patch is wide).
//
// A box is the set {c + a0 e0 + a1 e1 + a2 e2 : |a_k| <= h_k} for the stored doubles c, e_k,
// h_k, exactly (e_k orthonormal to within phi <= 2^-40, from a principal-axes frame). The build
// proves that it holds every vertex below the node (so every triangle: a box is convex).
//
// Lower bound (a separating axis): for any direction w, every x of box A and y of box B placed
// by (R, t) satisfy |x - y| >= (min over A of x . w - max over B of y . w) / |w|, and
//   min over A of x . w = c_A . w - sum_k h_Ak |e_Ak . w|,
//   max over B of y . w = t . w + c_B . u + sum_k h_Bk |e_Bk . u|,   u = R^T w,
// since (R e) . w = e . (R^T w). The margin (oriented_box.cpp) covers the floating-point
// evaluation of both, u's rounding, and the distance between the exact placed vertices and the
// placed vertices as Transform::apply computes them (which every exact decision uses).

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/shapes/mesh.h"
#include "contain/values/transform.h"
#include "contain/values/vec.h"

namespace contain::distance::detail {

struct OrientedBox {
  Vec3 c;         // centre
  Vec3 e[3];      // axes, orthonormal to within 2^-40
  double h[3]{};  // half-widths along the axes, rounded so that every vertex is inside
};

/// The oriented box of every node of `bvh` (built over `mesh`'s triangles, items = triangle
/// indices), indexed like bvh.nodes(): principal axes of the node's vertices (Jacobi), or the
/// coordinate axes where those fail the orthonormality check. O(n log n).
[[nodiscard]] std::vector<OrientedBox> oriented_boxes(const bvh::Bvh& bvh, const Mesh& mesh);

/// For each node of a hierarchy, positions [first, end) of `items()` that hold every item under
/// it (children come after their parent; a range may hold more than the node's own items).
[[nodiscard]] std::vector<std::pair<std::int32_t, std::int32_t>> item_ranges(
    std::span<const bvh::Node> nodes);

/// The principal axes of `points` (eigenvectors of their covariance), orthonormal within 2^-40
/// as computed, or the coordinate axes where those fail that check (fewer than two points, NaN).
void principal_axes(std::span<const Vec3> points, Vec3 e[3]);

/// Does `box` hold `p` (exactly, in rational arithmetic on the doubles)? For tests: evaluated
/// with a margin that only says "yes" when it is certain; false may be a near miss.
[[nodiscard]] bool oriented_box_surely_holds(const OrientedBox& box, Vec3 p);

/// max over `boxes` of |c|_inf + h_0 + h_1 + h_2 (every vertex coordinate is below 1.01 times
/// that): the scale of the rounding margin.
[[nodiscard]] double oriented_extent(std::span<const OrientedBox> boxes);

/// A pose of B with what the bound needs precomputed.
struct OrientedPose {
  Transform tb;
  // Margin per unit of |w|_1: every rounding of one bound evaluation, u's rounding, and the
  // placed vertices' offsets from their exact images (see oriented_box.cpp).
  double margin = 0;
};

/// The pose `tb` for boxes of A (world) and of B (local) whose oriented_extent are `extent_a`
/// and `extent_b`.
[[nodiscard]] OrientedPose oriented_pose(const Transform& tb, double extent_a, double extent_b);

/// A lower bound of the squared distance between box `a` (world) and box `b` (local to B, placed
/// by `pose`), along w = c_a - `placed_cb` (any w is valid; the placed centre of b is a good
/// one). 0 when the boxes may meet or on any overflow or NaN.
[[nodiscard]] double oriented_box_lower(const OrientedBox& a, const OrientedBox& b, Vec3 placed_cb,
                                        const OrientedPose& pose);

}  // namespace contain::distance::detail
