#pragma once
/// \file
/// Convex polyhedra as data: the intersection of half-spaces ("Algorithms of Informatics" vol. 2,
/// § 22.4, figure 22.22), validated; inside::point_in_convex locates points in them.

#include <cstdint>
#include <span>
#include <vector>

#include "contain/core/result.h"
#include "contain/shapes/mesh.h"
#include "contain/values/box.h"
#include "contain/values/plane.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::shapes {

/// A convex polyhedron (or any intersection of closed half-spaces), validated and ready for
/// queries (inside::point_in_convex). Built either from planes (a x + b y + c z + d >= 0 each,
/// normals inward), from an axis-aligned box, or from a closed convex triangle mesh, whose faces
/// are kept as triangles so that every side test is predicates::orient3d on three input
/// vertices: a plane through them computed in floating point would not be exact. Boxes and
/// meshes also keep their corners, the faces around each corner and a support function, the
/// preparation that GJK-guided queries (collide::ConvexShape, distance::ConvexDistance) share.
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

  /// A closed box: located by its six axis planes (exact coefficients, so planes() and not
  /// faces() serve point location and clipping), bounded by its 8 corners and 12 triangles
  /// (vertices(), face_indices()) for support queries. Precondition: min <= max on every axis,
  /// finite values; flat boxes (min == max on some axis) are fine, their flat sides are
  /// degenerate triangles. O(1).
  [[nodiscard]] static ConvexPolyhedron from_box(const Box3& box);

  /// The half-spaces given to from_planes or of from_box (empty for a mesh-based polyhedron).
  [[nodiscard]] const std::vector<Plane>& planes() const { return planes_; }
  /// The faces of a mesh-based polyhedron, counter-clockwise seen from outside (empty otherwise).
  [[nodiscard]] const std::vector<Triangle3>& faces() const { return faces_; }

  /// The boundary's corners: for from_mesh the distinct vertices used by its faces, in
  /// lexicographic order (x, then y, then z); for from_box the 8 corners, corner i at
  /// (i & 1 ? max.x : min.x, i & 2 ? max.y : min.y, i & 4 ? max.z : min.z); empty for
  /// from_planes (no vertices: the region may be unbounded).
  [[nodiscard]] const std::vector<Vec3>& vertices() const { return vertices_; }
  /// The boundary's triangles over vertices(), counter-clockwise seen from outside: face k is
  /// faces()[k] for from_mesh; a box's two triangles per side. Empty for from_planes.
  [[nodiscard]] const std::vector<TriangleIndices>& face_indices() const { return face_indices_; }
  /// Face k of face_indices() as a triangle. Precondition: k < face_indices().size().
  [[nodiscard]] Triangle3 face(std::int32_t k) const;
  /// The faces (indices into face_indices()) that have vertex `v` (an index into vertices())
  /// as a corner, ascending. Precondition: v < vertices().size(). O(1).
  [[nodiscard]] std::span<const std::int32_t> faces_around(std::int32_t v) const;

  /// The index of a vertex farthest in `direction`: the greatest dot(direction, vertex) in
  /// floating point, ties (and a zero direction) to the lowest index. For GJK (bound::gjk), a
  /// floating-point guide whose answers are decided exactly elsewhere. -1 when there are no
  /// vertices (from_planes). O(V).
  [[nodiscard]] std::int32_t support_index(Vec3 direction) const;
  /// vertices()[support_index(direction)]; (NaN, NaN, NaN) when there are no vertices.
  [[nodiscard]] Vec3 support(Vec3 direction) const;

 private:
  void index_faces_around();

  std::vector<Plane> planes_;
  std::vector<Triangle3> faces_;
  std::vector<Vec3> vertices_;
  std::vector<TriangleIndices> face_indices_;
  // Faces around vertex v: around_list_[around_start_[v] .. around_start_[v + 1]).
  std::vector<std::int32_t> around_start_;
  std::vector<std::int32_t> around_list_;
};

/// ConvexPolyhedron::support_index's rule on any list of points (a polyhedron's vertices placed
/// by a transform): the index of the greatest dot(direction, point) in floating point, ties to
/// the lowest index; -1 for no points. O(n).
[[nodiscard]] std::int32_t support_index(std::span<const Vec3> points, Vec3 direction);

}  // namespace contain::shapes

// Users and every layer above spell this name contain::X (docs/architecture.md, "Namespaces").
namespace contain {
using shapes::ConvexPolyhedron;
using shapes::support_index;
}  // namespace contain
