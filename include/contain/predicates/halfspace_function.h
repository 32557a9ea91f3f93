#pragma once
/// \file
/// Values of half-space functions s(p) (positive inside) in floating point with a proven error
/// bound, and exactly as BigFloat, for the decisions that no single predicate answers: the
/// comparisons of crossing parameters of Cyrus-Beck and the polygon and mesh clippers (which of
/// two crossings comes first along a segment), or any sign of a product difference of such
/// values. Each function type offers side(p) (an exact predicate), approx(p) (value and bound)
/// and exact(p) (the BigFloat value); sign_of_product_difference filters with the bounds and
/// falls back on exact().
///
/// Bounds: every s here is a sum of products of at most three rounded factors (coefficients,
/// coordinates, coordinate differences), evaluated with at most 7 roundings per monomial; each
/// bound below is at least gamma_8 = 8 eps / (1 - 8 eps) times the sum of the absolute values of
/// the computed monomials (the permanent), with the permanent itself rounded up by the margin, and
/// DBL_MIN-scaled guards for underflowing products (docs/robustness.md, "Filters"). A non-finite
/// value or bound means overflow: the caller goes exact.

#include <cfloat>
#include <cmath>

#include "contain/predicates/big_float.h"
#include "contain/predicates/bounded.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/side_of_plane.h"
#include "contain/predicates/unit_roundoff.h"
#include "contain/values/plane.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// A half-space a x + b y + c z + d >= 0.
struct PlaneFunction {
  Plane plane;
  [[nodiscard]] Sign side(Vec3 p) const { return side_of_plane(plane, p); }
  [[nodiscard]] Bounded approx(Vec3 p) const {
    const double tx = plane.a * p.x, ty = plane.b * p.y, tz = plane.c * p.z;
    const double perm = ((std::fabs(tx) + std::fabs(ty)) + std::fabs(tz)) + std::fabs(plane.d);
    return {((tx + ty) + tz) + plane.d, 8.0 * unit_roundoff<double> * perm + 4.0 * DBL_MIN};
  }
  [[nodiscard]] BigFloat exact(Vec3 p) const {
    return BigFloat(plane.a) * BigFloat(p.x) + BigFloat(plane.b) * BigFloat(p.y) +
           BigFloat(plane.c) * BigFloat(p.z) + BigFloat(plane.d);
  }
};

/// A half-plane a x + b y + c >= 0.
struct LineFunction {
  HalfPlane line;
  [[nodiscard]] Sign side(Vec2 p) const { return side_of_line(line, p); }
  [[nodiscard]] Bounded approx(Vec2 p) const {
    const double tx = line.a * p.x, ty = line.b * p.y;
    const double perm = (std::fabs(tx) + std::fabs(ty)) + std::fabs(line.c);
    return {(tx + ty) + line.c, 8.0 * unit_roundoff<double> * perm + 4.0 * DBL_MIN};
  }
  [[nodiscard]] BigFloat exact(Vec2 p) const {
    return BigFloat(line.a) * BigFloat(p.x) + BigFloat(line.b) * BigFloat(p.y) + BigFloat(line.c);
  }
};

/// The half-plane left of the directed edge p->q: orient2d(p, q, v) >= 0.
struct EdgeFunction {
  Vec2 p;
  Vec2 q;
  [[nodiscard]] Sign side(Vec2 v) const { return orient2d(p, q, v); }
  [[nodiscard]] Bounded approx(Vec2 v) const {
    const double l = (q.x - p.x) * (v.y - p.y), r = (q.y - p.y) * (v.x - p.x);
    return {l - r, 8.0 * unit_roundoff<double> * (std::fabs(l) + std::fabs(r)) + 4.0 * DBL_MIN};
  }
  [[nodiscard]] BigFloat exact(Vec2 v) const {
    return (BigFloat(q.x) - BigFloat(p.x)) * (BigFloat(v.y) - BigFloat(p.y)) -
           (BigFloat(q.y) - BigFloat(p.y)) * (BigFloat(v.x) - BigFloat(p.x));
  }
};

/// The inner side of a face a, b, c that is counter-clockwise seen from outside:
/// orient3d(a, c, b, p) = ((c - a) x (b - a)) . (p - a) >= 0.
struct FaceFunction {
  Triangle3 face;
  [[nodiscard]] Sign side(Vec3 p) const { return orient3d(face.a, face.c, face.b, p); }
  [[nodiscard]] Bounded approx(Vec3 p) const {
    const Vec3 u = face.c - face.a, w = face.b - face.a, r = p - face.a;
    const double nx1 = u.y * w.z, nx2 = u.z * w.y;
    const double ny1 = u.z * w.x, ny2 = u.x * w.z;
    const double nz1 = u.x * w.y, nz2 = u.y * w.x;
    const double value = (nx1 - nx2) * r.x + (ny1 - ny2) * r.y + (nz1 - nz2) * r.z;
    const double perm = (std::fabs(nx1) + std::fabs(nx2)) * std::fabs(r.x) +
                        (std::fabs(ny1) + std::fabs(ny2)) * std::fabs(r.y) +
                        (std::fabs(nz1) + std::fabs(nz2)) * std::fabs(r.z);
    const double guard = 4.0 * DBL_MIN * (1.0 + std::fabs(r.x) + std::fabs(r.y) + std::fabs(r.z));
    return {value, 16.0 * unit_roundoff<double> * perm + guard};
  }
  [[nodiscard]] BigFloat exact(Vec3 p) const {
    const BigFloat ux = BigFloat(face.c.x) - BigFloat(face.a.x),
                   uy = BigFloat(face.c.y) - BigFloat(face.a.y),
                   uz = BigFloat(face.c.z) - BigFloat(face.a.z);
    const BigFloat wx = BigFloat(face.b.x) - BigFloat(face.a.x),
                   wy = BigFloat(face.b.y) - BigFloat(face.a.y),
                   wz = BigFloat(face.b.z) - BigFloat(face.a.z);
    const BigFloat rx = BigFloat(p.x) - BigFloat(face.a.x), ry = BigFloat(p.y) - BigFloat(face.a.y),
                   rz = BigFloat(p.z) - BigFloat(face.a.z);
    return (uy * wz - uz * wy) * rx + (uz * wx - ux * wz) * ry + (ux * wy - uy * wx) * rz;
  }
};

/// sign(x1 y1 - x2 y2) for approximations of four values, falling back to `exact()` (which must
/// return the exact BigFloat of the expression) when the filter cannot decide.
template <class Exact>
[[nodiscard]] Sign sign_of_product_difference(const Bounded& x1, const Bounded& y1,
                                              const Bounded& x2, const Bounded& y2, Exact exact) {
  const double p1 = x1.value * y1.value, p2 = x2.value * y2.value;
  const double diff = p1 - p2;
  const double error =
      (std::fabs(x1.value) * y1.error + x1.error * std::fabs(y1.value) + x1.error * y1.error +
       std::fabs(x2.value) * y2.error + x2.error * std::fabs(y2.value) + x2.error * y2.error +
       3.0 * unit_roundoff<double> * (std::fabs(p1) + std::fabs(p2))) *
      (1.0 + 16.0 * unit_roundoff<double>)+8.0 * DBL_MIN;
  if (std::isfinite(diff) && std::isfinite(error)) {
    if (diff > error) return Sign::positive;
    if (-diff > error) return Sign::negative;
  }
  return exact().sign();
}

}  // namespace contain::predicates
