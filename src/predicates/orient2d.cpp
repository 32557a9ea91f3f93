#include "contain/predicates/orient2d.h"

#include <array>
#include <cmath>

#include "predicates/big_float.h"
#include "predicates/expansion.h"
#include "predicates/stages.h"

namespace contain::predicates {

namespace detail {

namespace {

// det[b - a, c - a] from the differences (b - a, c - a) as exact numbers.
template <class D>
Sign orient2d_of(const std::array<D, 4>& d) {
  return (d[0] * d[3] - d[1] * d[2]).sign();
}

}  // namespace

Sign orient2d_expansion(Vec2 a, Vec2 b, Vec2 c) {
  std::array<Expansion<2>, 4> d;
  if (differences(std::array{b.x, b.y, c.x, c.y}, std::array{a.x, a.y, a.x, a.y}, d)) {
    return orient2d_of(heads(d));
  }
  return orient2d_of(d);
}

Sign orient2d_big(Vec2 a, Vec2 b, Vec2 c) {
  const BigFloat ax(a.x), ay(a.y);
  return orient2d_of(
      std::array{BigFloat(b.x) - ax, BigFloat(b.y) - ay, BigFloat(c.x) - ax, BigFloat(c.y) - ay});
}

Sign orient2d_exact(Vec2 a, Vec2 b, Vec2 c) {
  std::array v{a.x, a.y, b.x, b.y, c.x, c.y};
  if (scale_into_expansion_range<2>(v)) {
    return orient2d_expansion({v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]});
  }
  return orient2d_big(a, b, c);
}

}  // namespace detail

// Filter: Shewchuk's orient2d stage A (pivot c, which gives the same determinant). Without
// underflow, |error| <= (3 + 16 eps) eps (|detleft| + |detright|) including the rounding of the
// bound itself; the coefficient is raised to (3 + 32 eps) eps to absorb the rounding of the added
// underflow guard, which covers the at most two products that may have underflowed.
// Overflow makes the bound infinite or NaN, and the comparisons then fail.
Sign orient2d(Vec2 a, Vec2 b, Vec2 c) {
  constexpr double kBound = (3.0 + 32.0 * detail::kEpsilon) * detail::kEpsilon;
  const double detleft = (a.x - c.x) * (b.y - c.y);
  const double detright = (a.y - c.y) * (b.x - c.x);
  const double det = detleft - detright;
  const double errbound =
      kBound * (std::fabs(detleft) + std::fabs(detright)) + detail::kUnderflowGuard;
  if (det > errbound) return Sign::positive;
  if (-det > errbound) return Sign::negative;
  return detail::orient2d_exact(a, b, c);
}

}  // namespace contain::predicates
