#include "contain/predicates/side_of_plane.h"

#include <array>
#include <cmath>

#include "contain/predicates/big_float.h"
#include "predicates/expansion.h"
#include "predicates/stages.h"

namespace contain::predicates {

namespace detail {

namespace {

template <class Num>
Sign side_of_plane_in(const Plane& h, Vec3 p) {
  return (Num(h.a) * Num(p.x) + Num(h.b) * Num(p.y) + Num(h.c) * Num(p.z) + Num(h.d)).sign();
}

template <class Num>
Sign side_of_line_in(const HalfPlane& h, Vec2 p) {
  return (Num(h.a) * Num(p.x) + Num(h.b) * Num(p.y) + Num(h.c)).sign();
}

}  // namespace

Sign side_of_plane_expansion(const Plane& plane, Vec3 p) {
  return side_of_plane_in<Expansion<1>>(plane, p);
}
Sign side_of_plane_big(const Plane& plane, Vec3 p) {
  return side_of_plane_in<BigFloat>(plane, p);
}
Sign side_of_line_expansion(const HalfPlane& half_plane, Vec2 p) {
  return side_of_line_in<Expansion<1>>(half_plane, p);
}
Sign side_of_line_big(const HalfPlane& half_plane, Vec2 p) {
  return side_of_line_in<BigFloat>(half_plane, p);
}

// After the filter: out of line, so that the filter stays small and free of the stages'
// setup.
[[gnu::noinline]] Sign side_of_plane_exact(const Plane& h, Vec3 p) {
  if (in_expansion_range<2>(h.a, h.b, h.c, h.d, p.x, p.y, p.z)) {
    return side_of_plane_expansion(h, p);
  }
  return side_of_plane_big(h, p);
}

// After the filter: out of line, so that the filter stays small and free of the stages'
// setup.
[[gnu::noinline]] Sign side_of_line_exact(const HalfPlane& h, Vec2 p) {
  if (in_expansion_range<2>(h.a, h.b, h.c, p.x, p.y)) {
    return side_of_line_expansion(h, p);
  }
  return side_of_line_big(h, p);
}

}  // namespace detail

// Filter. Every monomial of ((a x + b y) + c z) + d passes through at most k = 4 roundings
// (one product, three sums), so |error| <= gamma_4 * permanent < 5 eps * computed permanent
// with room for the rounding of the bound (docs/robustness.md, "Filters"). Products cannot be
// amplified after underflowing, so the guard is added once.
Sign side_of_plane(const Plane& h, Vec3 p) {
  constexpr double kBound = 5.0 * unit_roundoff<double>;
  const double tx = h.a * p.x, ty = h.b * p.y, tz = h.c * p.z;
  const double value = ((tx + ty) + tz) + h.d;
  const double permanent = ((std::fabs(tx) + std::fabs(ty)) + std::fabs(tz)) + std::fabs(h.d);
  const double errbound = kBound * permanent + detail::kUnderflowGuard;
  if (value > errbound) return Sign::positive;
  if (-value > errbound) return Sign::negative;
  return detail::side_of_plane_exact(h, p);
}

// Filter as side_of_plane with k = 3 roundings: bound 4 eps * permanent.
Sign side_of_line(const HalfPlane& h, Vec2 p) {
  constexpr double kBound = 4.0 * unit_roundoff<double>;
  const double tx = h.a * p.x, ty = h.b * p.y;
  const double value = (tx + ty) + h.c;
  const double permanent = (std::fabs(tx) + std::fabs(ty)) + std::fabs(h.c);
  const double errbound = kBound * permanent + detail::kUnderflowGuard;
  if (value > errbound) return Sign::positive;
  if (-value > errbound) return Sign::negative;
  return detail::side_of_line_exact(h, p);
}

}  // namespace contain::predicates
