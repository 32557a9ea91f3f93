#pragma once
/// \file
/// The exact oracle of the tests: every predicate again in GMP rationals, which represent each
/// double exactly, so the answers here are the true signs on the given doubles.

#include <gmpxx.h>

#include <optional>

#include "contain/predicates/sign.h"
#include "contain/shapes/mesh.h"
#include "contain/values/plane.h"
#include "contain/values/sphere.h"
#include "contain/values/vec.h"

namespace contain::test {

struct QVec2 {
  mpq_class x, y;
};
struct QVec3 {
  mpq_class x, y, z;
};

[[nodiscard]] QVec2 exact(Vec2 p);
[[nodiscard]] QVec3 exact(Vec3 p);

/// Vector arithmetic on exact points, shared by the oracles (each stays independent of the
/// library, not of the others' arithmetic).
[[nodiscard]] QVec3 qsub(const QVec3& a, const QVec3& b);
[[nodiscard]] QVec3 qcross(const QVec3& a, const QVec3& b);
[[nodiscard]] mpq_class qdot(const QVec3& a, const QVec3& b);
[[nodiscard]] bool qzero(const QVec3& a);
[[nodiscard]] Sign sign_of(const mpq_class& v);
/// The rational point where segment p q crosses the plane of t0 t1 t2, or nothing where p and q
/// are not strictly on opposite sides of it.
[[nodiscard]] std::optional<QVec3> exact_segment_plane_crossing(Vec3 p, Vec3 q, Vec3 t0, Vec3 t1,
                                                                Vec3 t2);

/// The exact volume a mesh encloses: the sum of its signed tetrahedra from the origin.
[[nodiscard]] mpq_class exact_volume(const Mesh& mesh);

[[nodiscard]] Sign exact_orient2d(Vec2 a, Vec2 b, Vec2 c);
[[nodiscard]] Sign exact_orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
[[nodiscard]] Sign exact_side_of_plane(const Plane& plane, Vec3 p);
[[nodiscard]] Sign exact_side_of_line(const HalfPlane& half_plane, Vec2 p);
[[nodiscard]] Sign exact_side_of_sphere(const Sphere& sphere, Vec3 p);
[[nodiscard]] Sign exact_side_of_circle(const Circle& circle, Vec2 p);
[[nodiscard]] Sign exact_cross_dot(Vec3 a, Vec3 b, Vec3 p, Vec3 c);

}  // namespace contain::test
