#pragma once
/// \file
/// Where a segment crosses an axis-aligned plane, rounded once: each coordinate the double
/// nearest to the exact one (ties to even), as IEEE 754 rounds a single operation.

#include "contain/values/vec.h"

namespace contain::predicates {

/// The point where the segment a-b crosses the plane `coordinate axis == c` (axis 0, 1, 2 for
/// x, y, z): coordinate `axis` is c, and each other coordinate the double nearest to the exact
/// a_j + (b_j - a_j) (c - a_axis) / (b_axis - a_axis). Symmetric in a and b (the exact value is),
/// so the two triangles of an edge get the same point; an endpoint on the plane is returned bit
/// for bit. Precondition: finite doubles, a_axis != b_axis, c between them (inclusive).
/// Method: the quotient stages of rounded_distance.h (long double with a priori, then running
/// error bounds; the exact BigFloat comparison with the rounding boundaries where they do not
/// decide, about one call in 10^4 on random input). O(1).
[[nodiscard]] Vec3 rounded_axis_crossing(Vec3 a, Vec3 b, int axis, double c);

}  // namespace contain::predicates

namespace contain::predicates {

/// The point where the segment p-q crosses the plane through a, b, c, rounded once: each
/// coordinate the double nearest to the exact p_i + (q_i - p_i) d_p / (d_p - d_q), with
/// d_x = ((b - a) x (c - a)) . (x - a) (ties to even). Symmetric in p and q and the same for
/// any order of a, b, c (the exact point is). Precondition: finite doubles, a, b, c not
/// collinear, p and q strictly on opposite sides of the plane.
/// Method: the quotient stages of rounded_axis_crossing (long double with a priori error bounds,
/// about every coordinate on inputs of like magnitudes; the exact BigFloat comparison with the
/// rounding boundaries where they do not decide). O(1).
[[nodiscard]] Vec3 rounded_plane_crossing(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c);

}  // namespace contain::predicates
