#pragma once
/// \file
/// Point in a triangle in 3D ("Algorithms of Informatics" vol. 2, § 22.4, figures 22.23 and 22.24).

#include <cstdint>

#include "contain/core/location.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// The two tests of § 22.4.
enum class TriangleMethod : std::uint8_t {
  /// Same-side test with cross and dot products: p is inside when, for each edge, p and the third
  /// vertex lie on the same side (predicates::cross_dot). Valid for any p in the prism obtained
  /// by extruding the triangle perpendicular to its plane: it answers whether p projects
  /// orthogonally into the closed triangle.
  same_side,
  /// Projection onto the coordinate plane where the triangle's normal has its largest component,
  /// then three 2D orientation tests (predicates::orient2d) after ordering the vertices
  /// counter-clockwise. Answers for the projection along that axis; for points in the triangle's
  /// plane this is the same answer as `same_side`.
  projected,
};

/// How point_in_triangle works.
struct PointInTriangleOptions {
  TriangleMethod method = TriangleMethod::projected;
};

/// Where `p`, a point in the plane of `triangle`, lies relative to the closed triangle:
/// `inside` in its relative interior, `boundary` on an edge or at a vertex, `outside` otherwise.
///
/// Both methods are exact for points exactly in the triangle's plane (every decision is an exact
/// predicate on the given doubles; checked against a GMP oracle). For points off the plane each
/// answers for its own projection: `same_side` for the orthogonal projection, `projected` for the
/// projection along the chosen coordinate axis.
///
/// The projection axis is the largest component of the floating-point normal. That choice need
/// not be exact: for a point in the plane any axis along which the triangle does not project to
/// a segment gives the same answer, since projecting the plane onto such a coordinate plane is
/// an affine bijection that maps the triangle, its edges and its vertices onto their images. The
/// only wrong choice is an axis along which the projected triangle is degenerate; that is tested
/// exactly (orient2d == 0) and the next axis taken.
///
/// Degenerate triangles (collinear or coincident vertices, tested exactly) are the segment or
/// point they span: `boundary` on it, `outside` elsewhere, whatever the method.
/// O(1). Reference: "Algorithms of Informatics" vol. 2, § 22.4, "point in triangle";
/// exercise 22.4-5 is its 2D form.
[[nodiscard]] Location point_in_triangle(const Triangle3& triangle, Vec3 p,
                                         const PointInTriangleOptions& options = {});

}  // namespace contain::inside
