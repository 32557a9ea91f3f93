#pragma once
/// \file
/// Do two convex shapes (spheres, boxes, convex polyhedra) meet? GJK on support functions, with
/// exact decisions for polytope pairs.

#include "contain/core/result.h"
#include "contain/shapes/convex_polyhedron.h"
#include "contain/values/box.h"
#include "contain/values/sphere.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::collide {

/// A closed convex shape given by its support function (the farthest point in a direction):
/// a sphere, an axis-aligned box, or a convex polyhedron built from a closed convex mesh
/// (ConvexPolyhedron::from_mesh). Boxes and polyhedra are polytopes: a ConvexPolyhedron
/// (ConvexPolyhedron::from_box for a box) holds their vertices, faces and support function and
/// locates points exactly for `convex_convex`'s exact stage.
class ConvexShape {
 public:
  /// A closed ball. Precondition: radius >= 0, finite values.
  [[nodiscard]] static ConvexShape sphere(const Sphere& sphere);
  /// A closed box. Precondition: not empty (min <= max on every axis), finite values; flat boxes
  /// (min == max on some axis) are fine.
  [[nodiscard]] static ConvexShape box(const Box3& box);
  /// A convex polyhedron built from a mesh (its faces()); ErrorKind::unsupported for a
  /// polyhedron given only by planes (it has no vertices to support a direction with). O(1)
  /// beyond the copy.
  [[nodiscard]] static Result<ConvexShape> polyhedron(const ConvexPolyhedron& polyhedron);

  /// A point of the shape farthest in `direction` (any point for direction 0). O(1) for spheres
  /// and boxes, O(V) for polyhedra (ConvexPolyhedron::support). Floating point for spheres (a
  /// rounded centre + r d / |d|).
  [[nodiscard]] Vec3 support(Vec3 direction) const;
  /// True for boxes and polyhedra.
  [[nodiscard]] bool is_polytope() const { return !solid_.vertices().empty(); }
  /// The polytope (empty for a sphere).
  [[nodiscard]] const ConvexPolyhedron& polytope() const { return solid_; }

 private:
  ConvexShape() = default;
  Sphere sphere_{};
  ConvexPolyhedron solid_;  // polytopes
};

/// What `convex_convex` found.
struct ConvexContact {
  /// The closed shapes share a point.
  bool intersect = false;
  /// GJK's distance estimate (0 when GJK found the origin in the Minkowski difference or the
  /// exact stage found contact); floating point.
  double distance = 0.0;
  /// True when `intersect` was decided exactly: for two polytopes (boxes, polyhedra); false
  /// when a sphere is involved.
  bool exact = false;
};

/// Closed convex shapes a and b: do they share a point? GJK (Gilbert, Johnson and Keerthi
/// 1988; closest point of the simplex by Johnson's sub-algorithm in the form of Ericson,
/// "Real-Time Collision Detection" 9.5) on the Minkowski difference a - b.
///
/// GJK is floating point by nature: its iterates are rounded support points. So:
/// - two polytopes (boxes, polyhedra): the answer is exact. A separating direction found by GJK
///   is certified by an exact test (predicates::side_of_plane on every vertex of both against
///   one plane with GJK's normal); without a certificate (touching, intersecting, or too close
///   for doubles) the exact stage decides: the closed solids meet iff some pair of faces meets
///   (tri_tri) or a vertex of one is in the other (exact point location).
/// - a sphere involved: the answer is GJK's, floating point: separated iff the distance
///   estimate exceeds about 1e-12 of the shapes' size; touching within that margin counts as
///   intersecting. `exact` is false.
/// Complexity: GJK O(iterations (V_a + V_b)), at most 64 iterations; the exact stage
/// O(F_a F_b + V_a F_b + V_b F_a), taken for touching and intersecting polytope pairs.
[[nodiscard]] ConvexContact convex_convex(const ConvexShape& a, const ConvexShape& b);

}  // namespace contain::collide
