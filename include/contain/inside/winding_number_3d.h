#pragma once
/// \file
/// The generalized winding number of a triangle mesh at a point (Jacobson, Kavan and
/// Sorkine-Hornung, "Robust Inside-Outside Segmentation using Generalized Winding Numbers",
/// SIGGRAPH 2013): the signed solid angle of the surface seen from the point over 4 pi.

#include "contain/shapes/mesh.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::inside {

/// The signed solid angle of `triangle` seen from `p` (Van Oosterom and Strackee 1983),
/// positive when p lies behind it (on the side its normal (b - a) x (c - a) points away from),
/// in [-2 pi, 2 pi]. Floating point. 0 when p is a vertex or the triangle is degenerate.
[[nodiscard]] double solid_angle(const Triangle3& triangle, Vec3 p);

/// The sum of the solid angles of every triangle over 4 pi. For a closed, outward oriented
/// surface: 1 inside, 0 outside (an integer: the winding number); for an open or non-manifold
/// one a smooth function that jumps by 1 across the surface and is about 1/2 at a hole. Floating
/// point: approximate near the surface (and undefined on it). O(n) for n triangles; use
/// `FastWindingNumber` for many points.
[[nodiscard]] double generalized_winding_number(const Mesh& mesh, Vec3 p);

}  // namespace contain::inside
