#pragma once
// Exact oracle for point in polyhedron, in GMP rationals, written independently of the library:
// the perturbed ray of the **perturbed +x ray rule** is a concrete ray here, its origin moved by
// (0, e, e^2) with e = 2^-300, and every intersection is computed as an exact rational. For the
// test inputs (coordinates of magnitude 2^-40 .. 2^20) every non-zero coefficient of the
// symbolic expansion dominates the terms after it at this e, so the concrete ray decides as the
// symbolic one.

#include "contain/core/location.h"
#include "contain/shapes/mesh.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::test {

/// Does the ray from (q.x, q.y + e, q.z + e^2) along +x pass through the triangle, at x > q.x?
[[nodiscard]] bool oracle_ray_crosses(const Triangle3& t, Vec3 q);

/// Is q on the closed triangle (exactly)?
[[nodiscard]] bool oracle_on_triangle(const Triangle3& t, Vec3 q);

/// boundary if q is on a triangle, else the parity of oracle_ray_crosses (closed meshes).
[[nodiscard]] Location oracle_locate(const Mesh& mesh, Vec3 q);

/// The winding number at q off the surface, exactly: the crossings of oracle_ray_crosses, each
/// signed by the exact sign of the triangle's normal along x (for a closed mesh of inconsistent
/// orientation, its parity is still the crossing parity).
[[nodiscard]] int oracle_winding(const Mesh& mesh, Vec3 q);

}  // namespace contain::test
