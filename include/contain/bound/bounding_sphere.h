#pragma once
/// \file
/// Bounding spheres of 3D point sets and meshes (exercise 22.4-4): the minimal enclosing sphere
/// (Welzl 1991 with move-to-front, Gärtner 1999 numerics) or Ritter's fast approximation.

#include <span>

#include "contain/bound/mesh_vertices.h"
#include "contain/bound/sphere_method.h"
#include "contain/core/result.h"
#include "contain/shapes/mesh.h"
#include "contain/values/sphere.h"
#include "contain/values/vec.h"

namespace contain::bound {

/// Options of `bounding_sphere`, for designated initialisers:
/// `bounding_sphere(mesh, {.method = SphereMethod::ritter})`.
struct BoundingSphereOptions {
  /// The minimal sphere (default) or Ritter's approximation.
  SphereMethod method = SphereMethod::exact;
  /// Which mesh vertices are enclosed (the `Mesh` overload only).
  MeshVertices vertices = MeshVertices::referenced;
};

/// A closed ball holding every point.
///
/// Guarantee (both methods): `predicates::side_of_sphere(result, p) != Sign::negative` for every
/// input point p, decided exactly on the returned doubles. The search runs in floating point;
/// a final pass checks every point with the exact predicate and, where rounding left a point
/// outside, raises the radius to the smallest double that holds it.
///
/// `SphereMethod::exact`: the minimal enclosing ball. Its support (2 to 4 points on the sphere,
/// the center in their convex hull) is found by Welzl's move-to-front algorithm on a core set:
/// the extreme points along 7 directions first, then, pass by pass, the points outside the
/// current ball (in a seeded, reproducible shuffle), until no point is outside; recursion depth
/// is at most 4 whatever n. Circumcenters of support sets come from Gärtner's incremental
/// Gram-Schmidt solve in the affine hull of the support; a support point that is (numerically)
/// affinely dependent on the others is rejected, so duplicates, collinear, coplanar and
/// cospherical sets are handled without special cases. Points within a relative 2^-47 of the
/// current sphere count as on it during the search (the final exact pass still encloses them), so
/// the radius is within about 1e-14 * (1 + |center|_inf / r) relative of the true minimum; with
/// coordinates far larger than the radius, the rounding of the center to doubles bounds the
/// accuracy anyway. Expected O(n) time, a few linear passes; deterministic.
///
/// `SphereMethod::ritter`: Ritter's ball (farthest point from the first point, farthest from
/// that, then one growing pass), then the exact pass. O(n), radius >= the minimal one.
///
/// Coordinates of any finite magnitude work: the search runs on copies scaled by a power of two
/// when the largest coordinate lies outside [2^-300, 2^300]; where the center or radius is
/// subnormal, their spacing (4.9e-324) limits the accuracy instead. One point gives radius 0.
///
/// Errors: `ErrorKind::degenerate` for no points; `ErrorKind::invalid_value` for a NaN or infinite
/// coordinate (the message names the point's 0-based index); `ErrorKind::unsupported` when the
/// radius would exceed the largest double.
/// Reference: E. Welzl, "Smallest enclosing disks (balls and ellipsoids)", 1991; B. Gärtner,
/// "Fast and robust smallest enclosing balls", ESA 1999; J. Ritter, "An efficient bounding
/// sphere", Graphics Gems 1990.
[[nodiscard]] Result<Sphere> bounding_sphere(std::span<const Vec3> points,
                                             const BoundingSphereOptions& options = {});

/// The bounding sphere of a mesh's vertices, by default only those a triangle refers to
/// (`options.vertices`); as the point overload otherwise. A mesh with no vertex to enclose is
/// `ErrorKind::degenerate`.
[[nodiscard]] Result<Sphere> bounding_sphere(const Mesh& mesh,
                                             const BoundingSphereOptions& options = {});

}  // namespace contain::bound
