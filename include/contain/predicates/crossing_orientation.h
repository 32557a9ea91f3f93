#pragma once
/// \file
/// Exact orientations of points constructed from doubles without constructing them: a point
/// where a segment crosses a plane, and the centroid of three points (the mesh boolean's
/// refinement and labels, where such points lie on lines of doubles by construction and the
/// orientation is an exact zero that no floating-point filter can settle).

#include "contain/predicates/sign.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// Sign of orient2d(a, b, x'), x' the projection (coordinates u and v: 0, 1 or 2) of the point x
/// where the segment p q crosses the plane through t0, t1, t2. Precondition: t0, t1, t2 not
/// collinear, p and q strictly on opposite sides of their plane. Exact: the orientation is affine
/// in x = (dq p - dp q) / (dq - dp) (dp, dq the sides of p and q, orient3d), so its sign is that
/// of dp f(q) - dq f(p) times the sign of dp (f the orientation at p and q): expansion
/// arithmetic where every difference of the inputs is a double and their exponents allow, big
/// numbers otherwise. With a = (c, 0) and b = (c, 1) it is the sign of c - x_u.
[[nodiscard]] Sign orient2d_of_crossing(Vec2 a, Vec2 b, Vec3 p, Vec3 q, Vec3 t0, Vec3 t1, Vec3 t2,
                                        int u, int v);

/// Sign of orient2d(a, b, c0) + orient2d(a, b, c1) + orient2d(a, b, c2): the orientation of a, b
/// and the centroid of c0, c1, c2 (three times it), exactly.
[[nodiscard]] Sign orient2d_of_centroid(Vec2 a, Vec2 b, Vec2 c0, Vec2 c1, Vec2 c2);

/// Sign of orient3d(a, b, c, d0) + orient3d(a, b, c, d1) + orient3d(a, b, c, d2): the side of the
/// plane through a, b, c that the centroid of d0, d1, d2 lies on (orient3d's convention), exactly.
[[nodiscard]] Sign orient3d_of_centroid(Vec3 a, Vec3 b, Vec3 c, Vec3 d0, Vec3 d1, Vec3 d2);

}  // namespace contain::predicates
