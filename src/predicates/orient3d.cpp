#include "contain/predicates/orient3d.h"

#include <array>
#include <cmath>

#include "predicates/big_float.h"
#include "predicates/expansion.h"
#include "predicates/stages.h"

namespace contain::predicates {

namespace detail {

namespace {

// ((b - a) x (c - a)) . (d - a) from the differences (b - a, c - a, d - a) as exact numbers.
template <class D>
Sign orient3d_of(const std::array<D, 9>& d) {
  const auto nx = d[1] * d[5] - d[2] * d[4];
  const auto ny = d[2] * d[3] - d[0] * d[5];
  const auto nz = d[0] * d[4] - d[1] * d[3];
  return (nx * d[6] + ny * d[7] + nz * d[8]).sign();
}

}  // namespace

Sign orient3d_expansion(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  std::array<Expansion<2>, 9> diff;
  if (differences(std::array{b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z},
                  std::array{a.x, a.y, a.z, a.x, a.y, a.z, a.x, a.y, a.z}, diff)) {
    return orient3d_of(heads(diff));
  }
  return orient3d_of(diff);
}

Sign orient3d_big(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const BigFloat ax(a.x), ay(a.y), az(a.z);
  return orient3d_of(std::array{BigFloat(b.x) - ax, BigFloat(b.y) - ay, BigFloat(b.z) - az,
                                BigFloat(c.x) - ax, BigFloat(c.y) - ay, BigFloat(c.z) - az,
                                BigFloat(d.x) - ax, BigFloat(d.y) - ay, BigFloat(d.z) - az});
}

Sign orient3d_exact(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  std::array v{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  if (scale_into_expansion_range<3>(v)) {
    return orient3d_expansion({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]},
                              {v[9], v[10], v[11]});
  }
  return orient3d_big(a, b, c, d);
}

}  // namespace detail

// Filter: Shewchuk's orient3d stage A (pivot d; his determinant is the negative of ours).
// Without underflow, |error| <= (7 + 56 eps) eps * permanent including the rounding of the
// bound; raised to (7 + 64 eps) eps to absorb the rounding of the added underflow guard. An
// underflowed 2x2 product is multiplied by one z difference, so the guard is scaled by
// 1 + |adz| + |bdz| + |cdz|. Overflow makes the bound infinite or NaN and the comparisons fail.
Sign orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  constexpr double kBound = (7.0 + 64.0 * detail::kEpsilon) * detail::kEpsilon;
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
  const double errbound =
      kBound * permanent + detail::kUnderflowGuard * (1.0 + abs_adz + abs_bdz + abs_cdz);
  if (det > errbound) return Sign::negative;
  if (-det > errbound) return Sign::positive;
  return detail::orient3d_exact(a, b, c, d);
}

}  // namespace contain::predicates
