#pragma once
/// \file
/// Exact 3D orientation of many points against one plane, the plane's normal formed once.

#include <array>
#include <cfloat>
#include <cmath>

#include "contain/predicates/orient3d.h"
#include "contain/predicates/sign.h"
#include "contain/predicates/unit_roundoff.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// The plane through a, b, c prepared for many `orient3d(a, b, c, d)` queries: the normal
/// n = (b - a) x (c - a) and the permanents of its 2x2 minors are rounded once, and each query
/// costs one dot product n . (d - a) and its error bound instead of a full determinant. Every
/// answer is exactly `orient3d(a, b, c, d)`: the same sign convention (positive on the side the
/// normal of counter-clockwise a, b, c points to, zero when coplanar, zero for every d when a, b, c
/// are collinear or coincide), and the same exact stages when the filter cannot decide. Use it
/// where one plane meets several points, e.g. the vertices of a triangle against another triangle's
/// plane (Guigue and Devillers 2003). The filter bound, 9 eps times the permanent plus an underflow
/// guard, is derived in docs/robustness.md.
class Orient3dPlane {
 public:
  /// The plane through a, b, c (any doubles; degenerate triples give zero for every query).
  Orient3dPlane(Vec3 a, Vec3 b, Vec3 c) : a_(a), b_(b), c_(c) {
    const double bax = b.x - a.x, bay = b.y - a.y, baz = b.z - a.z;
    const double cax = c.x - a.x, cay = c.y - a.y, caz = c.z - a.z;
    const double yz = bay * caz, zy = baz * cay;
    const double zx = baz * cax, xz = bax * caz;
    const double xy = bax * cay, yx = bay * cax;
    nx_ = yz - zy;
    ny_ = zx - xz;
    nz_ = xy - yx;
    px_ = std::fabs(yz) + std::fabs(zy);
    py_ = std::fabs(zx) + std::fabs(xz);
    pz_ = std::fabs(xy) + std::fabs(yx);
  }

  /// Exactly `orient3d(a, b, c, d)`. O(1): a dot product and its error bound when the filter
  /// answers, the exact stages of `orient3d` otherwise.
  [[nodiscard]] Sign sign(Vec3 d) const {
    // (nx dx + ny dy) + nz dz with d - a: every monomial meets at most k = 8 roundings (three
    // leaf differences, the minor's product and subtraction, the product with the difference,
    // two sums), so (k + 1) eps = 9 eps times the permanent bounds the error and the rounding
    // of the bound itself. An underflowed minor product is multiplied by one difference: guard
    // DBL_MIN (1 + |dx| + |dy| + |dz|). Overflow makes the bound inf or NaN: both tests fail.
    // The sign is formed without branching on it (random input makes such branches
    // unpredictable); only the rare undecided case branches.
    constexpr double kBound = 9.0 * unit_roundoff<double>;
    const double dx = d.x - a_.x, dy = d.y - a_.y, dz = d.z - a_.z;
    const double det = (nx_ * dx + ny_ * dy) + nz_ * dz;
    const double adx = std::fabs(dx), ady = std::fabs(dy), adz = std::fabs(dz);
    const double permanent = (px_ * adx + py_ * ady) + pz_ * adz;
    const double errbound = kBound * permanent + DBL_MIN * (1.0 + adx + ady + adz);
    const bool positive = det > errbound, negative = -det > errbound;
    if (positive == negative) [[unlikely]] {  // both false: the filter cannot tell
      return detail::orient3d_exact(a_, b_, c_, d);
    }
    return static_cast<Sign>(static_cast<int>(positive) - static_cast<int>(negative));
  }

  /// Exactly {orient3d(a, b, c, p), orient3d(a, b, c, q), orient3d(a, b, c, r)}.
  [[nodiscard]] std::array<Sign, 3> signs(Vec3 p, Vec3 q, Vec3 r) const {
    return {sign(p), sign(q), sign(r)};
  }

 private:
  Vec3 a_, b_, c_;
  double nx_, ny_, nz_;  // (b - a) x (c - a), each component rounded
  double px_, py_, pz_;  // the minors' permanents
};

}  // namespace contain::predicates
