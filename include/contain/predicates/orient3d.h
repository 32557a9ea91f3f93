#pragma once
/// \file
/// Exact 3D orientation.

#include <cfloat>
#include <cmath>

#include "contain/predicates/sign.h"
#include "contain/predicates/unit_roundoff.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// Sign of det[b - a, c - a, d - a] = ((b - a) x (c - a)) . (d - a), exactly on the given doubles:
/// positive when d lies on the side of the plane through a, b, c that the normal
/// (b - a) x (c - a) points to (where a, b, c look counter-clockwise); zero when coplanar.
/// Note: this is the opposite sign convention from Shewchuk's orient3d (and the same as CGAL's
/// orientation). Filter, exact expansion fallback (expansion range 2^-300..2^330, inputs outside
/// it rescaled by a power of two when their exponents allow) and big-number fallback, as
/// `orient2d`. The filter is inline; the exact stages are not (their cost: docs/benchmarks.md).
/// Rules and bounds: docs/robustness.md.
[[nodiscard]] inline Sign orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d);

namespace detail {
/// The exact stages of `orient3d`, out of line.
[[nodiscard]] Sign orient3d_exact(Vec3 a, Vec3 b, Vec3 c, Vec3 d);
}  // namespace detail

// Filter: Shewchuk's orient3d stage A (pivot d; his determinant is the negative of ours).
// Without underflow, |error| <= (7 + 56 eps) eps * permanent, the rounding of the bound
// included; raised to (7 + 64 eps) eps to absorb the rounding of the added underflow guard. An
// underflowed 2x2 product is multiplied by one z difference, so the guard DBL_MIN is scaled by
// 1 + |adz| + |bdz| + |cdz|. Overflow makes the bound infinite or NaN and the comparisons fail.
inline Sign orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  constexpr double kBound = (7.0 + 64.0 * unit_roundoff<double>)*unit_roundoff<double>;
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double adz = a.z - d.z, bdz = b.z - d.z, cdz = c.z - d.z;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double abs_adz = std::fabs(adz), abs_bdz = std::fabs(bdz), abs_cdz = std::fabs(cdz);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * abs_adz +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * abs_bdz +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * abs_cdz;
  const double errbound = kBound * permanent + DBL_MIN * (1.0 + abs_adz + abs_bdz + abs_cdz);
  if (det > errbound) return Sign::negative;
  if (-det > errbound) return Sign::positive;
  return detail::orient3d_exact(a, b, c, d);
}

}  // namespace contain::predicates
