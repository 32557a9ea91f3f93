#include "contain/predicates/compare_distance.h"

#include <array>
#include <cmath>

#include "predicates/big_float.h"
#include "predicates/expansion.h"
#include "predicates/stages.h"

namespace contain::predicates {

namespace detail {

namespace {

template <class Num>
Sign side_of_sphere_in(const Sphere& s, Vec3 p) {
  const Num r(s.radius);
  const auto dx = Num(p.x) - Num(s.center.x);
  const auto dy = Num(p.y) - Num(s.center.y);
  const auto dz = Num(p.z) - Num(s.center.z);
  return (r * r - (dx * dx + dy * dy + dz * dz)).sign();
}

template <class Num>
Sign side_of_circle_in(const Circle& s, Vec2 p) {
  const Num r(s.radius);
  const auto dx = Num(p.x) - Num(s.center.x);
  const auto dy = Num(p.y) - Num(s.center.y);
  return (r * r - (dx * dx + dy * dy)).sign();
}

}  // namespace

Sign side_of_sphere_expansion(const Sphere& sphere, Vec3 p) {
  return side_of_sphere_in<Expansion<1>>(sphere, p);
}
Sign side_of_sphere_big(const Sphere& sphere, Vec3 p) {
  return side_of_sphere_in<BigFloat>(sphere, p);
}
Sign side_of_circle_expansion(const Circle& circle, Vec2 p) {
  return side_of_circle_in<Expansion<1>>(circle, p);
}
Sign side_of_circle_big(const Circle& circle, Vec2 p) {
  return side_of_circle_in<BigFloat>(circle, p);
}

}  // namespace detail

// Filter. The monomials of r r - ((dx dx + dy dy) + dz dz) pass through at most k = 6
// roundings (two differences, one product, two sums, the final subtraction), so
// |error| <= gamma_6 * permanent < 7 eps * computed permanent (docs/robustness.md). Every product
// is of differences or of r, never amplified after underflowing: the guard is added once.
Sign side_of_sphere(const Sphere& s, Vec3 p) {
  constexpr double kBound = 7.0 * detail::kEpsilon;
  const double dx = p.x - s.center.x, dy = p.y - s.center.y, dz = p.z - s.center.z;
  const double r2 = s.radius * s.radius;
  const double d2 = (dx * dx + dy * dy) + dz * dz;
  const double value = r2 - d2;
  const double errbound = kBound * (r2 + d2) + detail::kUnderflowGuard;
  if (value > errbound) return Sign::positive;
  if (-value > errbound) return Sign::negative;
  std::array v{s.radius, s.center.x, s.center.y, s.center.z, p.x, p.y, p.z};
  if (detail::scale_into_expansion_range<2>(v)) {
    return detail::side_of_sphere_expansion({{v[1], v[2], v[3]}, v[0]}, {v[4], v[5], v[6]});
  }
  return detail::side_of_sphere_big(s, p);
}

// Filter as side_of_sphere with k = 5 roundings: bound 6 eps * permanent.
Sign side_of_circle(const Circle& s, Vec2 p) {
  constexpr double kBound = 6.0 * detail::kEpsilon;
  const double dx = p.x - s.center.x, dy = p.y - s.center.y;
  const double r2 = s.radius * s.radius;
  const double d2 = dx * dx + dy * dy;
  const double value = r2 - d2;
  const double errbound = kBound * (r2 + d2) + detail::kUnderflowGuard;
  if (value > errbound) return Sign::positive;
  if (-value > errbound) return Sign::negative;
  std::array v{s.radius, s.center.x, s.center.y, p.x, p.y};
  if (detail::scale_into_expansion_range<2>(v)) {
    return detail::side_of_circle_expansion({{v[1], v[2]}, v[0]}, {v[3], v[4]});
  }
  return detail::side_of_circle_big(s, p);
}

}  // namespace contain::predicates
