#pragma once
// Exact oracle for sections and shadows of solids, in GMP rationals, written independently of
// the library: winding numbers of a closed mesh just above and just below a point of an
// axis-aligned plane, from a ray along the axis through the point moved by (e, e^2) in the
// plane's coordinates (e = 2^-300, a concrete stand-in for the symbolic perturbation: for
// coordinates of magnitude 2^-40 .. 2^20 no projected edge passes through the moved point and no
// crossing height ties with the plane except on triangles lying in it).

#include <gmpxx.h>

#include "contain/shapes/mesh.h"
#include "contain/values/vec.h"

namespace contain::test {

/// Winding numbers of the mesh at (p, c + d) and (p, c - d) for d -> 0+, where p = (u, v) are
/// the plane's coordinates (u, v, axis) right-handed: (x, y) for axis 2, (y, z) for 0, (z, x)
/// for 1.
struct SideWindings {
  int above = 0;
  int below = 0;
};
[[nodiscard]] SideWindings oracle_side_windings(const Mesh& mesh, int axis, Vec2 p, double c);

/// Is (p, c) an interior point of the solid {winding > 0}, for p off the section's boundary?
[[nodiscard]] bool oracle_in_section(const Mesh& mesh, int axis, Vec2 p, double c);

/// Is p (moved by (e, e^2)) inside the projection of some triangle along the axis?
[[nodiscard]] bool oracle_in_shadow(const Mesh& mesh, int axis, Vec2 p);

/// The exact point where the segment a-b crosses the plane coordinate axis == c (a_axis != b_axis),
/// in the plane's coordinates (u, v).
struct QPoint2 {
  mpq_class u, v;
};
[[nodiscard]] QPoint2 oracle_crossing(Vec3 a, Vec3 b, int axis, double c);

}  // namespace contain::test
