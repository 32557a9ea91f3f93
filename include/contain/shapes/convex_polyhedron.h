#pragma once
/// \file
/// Convex polyhedra as data: the intersection of half-spaces ("Algorithms of Informatics" vol. 2,
/// § 22.4, figure 22.22), validated; inside::point_in_convex locates points in them.

#include <vector>

#include "contain/core/result.h"
#include "contain/shapes/mesh.h"
#include "contain/values/plane.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::shapes {

/// A convex polyhedron (or any intersection of closed half-spaces), validated and ready for
/// queries (inside::point_in_convex). Built either from planes (a x + b y + c z + d >= 0 each,
/// normals inward) or from a closed convex triangle mesh, whose faces are kept as triangles so that
/// every side test is predicates::orient3d on three input vertices: a plane through them computed
/// in floating point would not be exact.
///
/// A point is `inside` when it is strictly inside every half-space, `boundary` when it is on some
/// of the planes and inside the others, `outside` otherwise. The answer is about the closed set
/// itself: an intersection with no interior (x >= 0 and -x >= 0) answers `boundary` on the plane
/// x = 0 (inside::CsgSolid, whose operations are regularised, treats it as empty).
class ConvexPolyhedron {
 public:
  /// The intersection of the half-spaces. Rejects NaN/Inf coefficients (invalid_value) and a zero
  /// normal a = b = c = 0 (degenerate), naming the plane's index. An empty list is accepted and
  /// is all of space (the intersection of no half-spaces): every point is `inside`. The region may
  /// be unbounded or empty; that is not an error. O(n).
  [[nodiscard]] static Result<ConvexPolyhedron> from_planes(std::vector<Plane> planes);

  /// The solid bounded by a closed convex triangle mesh. Requires (all tests exact):
  /// - closed and consistently oriented: every directed edge (i, j) is used by exactly one
  ///   triangle and (j, i) by exactly one other (edges are matched by vertex index, so vertices
  ///   must be welded); otherwise ErrorKind::invalid_value;
  /// - no degenerate triangle (three collinear vertices): ErrorKind::degenerate;
  /// - convex: no vertex of the mesh lies strictly outside the plane of any face, by orient3d on
  ///   the face's three vertices: ErrorKind::invalid_value ("not convex"), naming the face;
  /// - not flat (some vertex off some face's plane): ErrorKind::degenerate.
  /// Faces may be oriented outward (counter-clockwise seen from outside, the Mesh convention) or
  /// all inward; inward meshes are flipped. Coplanar faces (a quad split in two) are fine.
  /// O(F V) for the convexity check, fine for the small convex shapes this is meant for.
  [[nodiscard]] static Result<ConvexPolyhedron> from_mesh(const Mesh& mesh);

  /// The half-spaces given to from_planes (empty for a mesh-based polyhedron).
  [[nodiscard]] const std::vector<Plane>& planes() const { return planes_; }
  /// The faces of a mesh-based polyhedron, counter-clockwise seen from outside (empty otherwise).
  [[nodiscard]] const std::vector<Triangle3>& faces() const { return faces_; }

 private:
  std::vector<Plane> planes_;
  std::vector<Triangle3> faces_;
};

}  // namespace contain::shapes

// Users and every layer above spell this name contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using shapes::ConvexPolyhedron;
}  // namespace contain
