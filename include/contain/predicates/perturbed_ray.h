#pragma once
/// \file
/// The perturbed +x ray: exact ray parity against triangles by symbolic perturbation, the one
/// implementation behind point in polyhedron (inside::MeshIndex), the CSG mesh leaves
/// (inside::CsgSolid, from symbolic sample points) and mesh-in-mesh containment
/// (collide::MeshPair).
///
/// **Perturbed +x ray rule** (docs/robustness.md). The ray from q goes along +x, from the
/// symbolically perturbed origin q_e = (q.x, q.y + e, q.z + e^2), 0 < e infinitesimal (Simulation
/// of Simplicity, Edelsbrunner and Muecke 1990, for one moving point). Projected along x onto the
/// (y, z) plane, q_e lies on no edge line of a triangle that is not itself parallel to x, so the
/// perturbed ray meets every triangle in its interior or misses it: no edge or vertex is ever hit,
/// and each decision is a sign of a polynomial in e, read from its first non-zero coefficient:
///   orient2d_yz(a, b, q_e) = orient2d_yz(a, b, q) - (b.z - a.z) e + (b.y - a.y) e^2.
/// Triangles whose projection has zero area (parallel to x, or degenerate) are never met.
/// Where the ray meets the triangle's plane: with n = (b - a) x (c - a) (n.x = orient2d_yz(a, b,
/// c) = s), the hit of the ray from m lies beyond m iff orient3d(a, b, c, m) = -s; if m is in the
/// plane, the perturbed hit is at x = m.x - (n.y e + n.z e^2) / n.x, read the same way; if also
/// n.y = n.z = 0 (a triangle in the plane x = m.x), the hit is at m.x exactly.
/// The count of hits beyond q, for q not on the surface, has the parity of q's inside-ness for
/// any closed (every edge of an even number of triangles) surface: the perturbed ray is generic.
///
/// Origins that are themselves symbolic. Every test above is linear in the origin: its value at
/// q + d is its value at q plus g . d, g its gradient. An origin q + d with d an infinitesimal
/// displacement ordered before the ray's own (e) is decided by the value at q, then by the sign
/// of g . d, then by the ray's terms. The `Offset` parameter supplies that middle step, asked
/// only where the test vanishes at q (so that g . d is also the test's value at q + d):
/// `Offset::symbolic` is true, `offset.along_yz(a, b)` is the sign of g . d for the test
/// orient2d_yz(a, b, .) and `offset.along_normal(a, b, c)` for orient3d(a, b, c, .) (gradient
/// (b - a) x (c - a)); an offset made of input points reads these signs with the predicates
/// themselves. NoOffset, the default, is a plain point and compiles to the tests above.

#include <algorithm>

#include "contain/predicates/big_float.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/sign.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// The origin is the point itself: no displacement before the ray's.
struct NoOffset {
  static constexpr bool symbolic = false;
  [[nodiscard]] Sign along_yz(Vec3, Vec3) const { return Sign::zero; }
  [[nodiscard]] Sign along_normal(Vec3, Vec3, Vec3) const { return Sign::zero; }
};

/// Sign of orient2d in the (y, z) plane of (a, b, q_e), never zero for a.yz != b.yz.
template <class Offset = NoOffset>
[[nodiscard]] Sign perturbed_orient_yz(Vec3 a, Vec3 b, Vec3 q, const Offset& offset = {}) {
  const Sign o = orient2d({a.y, a.z}, {b.y, b.z}, {q.y, q.z});
  if (o != Sign::zero) return o;
  if constexpr (Offset::symbolic) {
    const Sign d = offset.along_yz(a, b);
    if (d != Sign::zero) return d;
  }
  if (b.z != a.z) return a.z > b.z ? Sign::positive : Sign::negative;
  if (b.y != a.y) return b.y > a.y ? Sign::positive : Sign::negative;
  return Sign::zero;  // a and b project to one point: only in a triangle with s == 0
}

/// The sign s of the triangle's (y, z) projection, n.x of its normal; zero: never hit.
[[nodiscard]] inline Sign projected_sign(Vec3 a, Vec3 b, Vec3 c) {
  return orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z});
}

/// Does the perturbed line through q along x pass through the triangle (s = projected_sign !=
/// 0)? The orientation tests alone, complete for any origin.
template <class Offset = NoOffset>
[[nodiscard]] bool perturbed_line_hits_unboxed(Vec3 a, Vec3 b, Vec3 c, Sign s, Vec3 q,
                                               const Offset& offset = {}) {
  return perturbed_orient_yz(a, b, q, offset) == s && perturbed_orient_yz(b, c, q, offset) == s &&
         perturbed_orient_yz(c, a, q, offset) == s;
}

/// perturbed_line_hits_unboxed for a plain point q, with the (y, z) box test first: q_e can only
/// be inside if q.y in [min y, max y) and likewise z (the box test only saves time).
[[nodiscard]] inline bool perturbed_line_hits(Vec3 a, Vec3 b, Vec3 c, Sign s, Vec3 q) {
  if (!(q.y >= std::min({a.y, b.y, c.y}) && q.y < std::max({a.y, b.y, c.y}))) return false;
  if (!(q.z >= std::min({a.z, b.z, c.z}) && q.z < std::max({a.z, b.z, c.z}))) return false;
  return perturbed_line_hits_unboxed(a, b, c, s, q);
}

/// Where the perturbed line through m meets the triangle's plane, relative to m.x: +1 beyond,
/// -1 before, 0 exactly at m.x (a triangle in the plane x = m.x). Precondition: s != 0.
template <class Offset = NoOffset>
[[nodiscard]] int hit_side(Vec3 a, Vec3 b, Vec3 c, Sign s, Vec3 m, const Offset& offset = {}) {
  const int si = to_int(s);
  const Sign o = orient3d(a, b, c, m);
  if (o != Sign::zero) return -to_int(o) * si;
  if constexpr (Offset::symbolic) {
    const Sign d = offset.along_normal(a, b, c);
    if (d != Sign::zero) return -to_int(d) * si;
  }
  const Sign ny = orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x});
  if (ny != Sign::zero) return -to_int(ny) * si;
  const Sign nz = orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y});
  return -to_int(nz) * si;
}

/// The whole test for q not on the triangle, signed: +1 where the perturbed ray from q crosses
/// it along its normal (s > 0), -1 where against, 0 where it does not cross it. The sum over a
/// mesh whose directed edges all match is q's winding number.
[[nodiscard]] inline int perturbed_ray_crossing(Vec3 a, Vec3 b, Vec3 c, Vec3 q) {
  const Sign s = projected_sign(a, b, c);
  if (s == Sign::zero) return 0;
  return perturbed_line_hits(a, b, c, s, q) && hit_side(a, b, c, s, q) > 0 ? to_int(s) : 0;
}

/// The whole test for q not on the triangle: the perturbed ray from q crosses it.
[[nodiscard]] inline bool perturbed_ray_crosses(Vec3 a, Vec3 b, Vec3 c, Vec3 q) {
  return perturbed_ray_crossing(a, b, c, q) != 0;
}

/// The whole test for the symbolic origin q + d (see the file's comment): the perturbed ray from
/// it crosses the triangle. q may lie on the triangle; the origin q + d may not.
template <class Offset>
[[nodiscard]] bool perturbed_ray_crosses(Vec3 a, Vec3 b, Vec3 c, Vec3 q, const Offset& offset) {
  const Sign s = projected_sign(a, b, c);
  if (s == Sign::zero) return false;
  return perturbed_line_hits_unboxed(a, b, c, s, q, offset) && hit_side(a, b, c, s, q, offset) > 0;
}

}  // namespace contain::predicates
