#include "contain/predicates/compare_distance.h"

#include <array>
#include <cmath>

#include "contain/predicates/big_float.h"
#include "predicates/expansion.h"
#include "predicates/stages.h"

namespace contain::predicates {

namespace detail {

namespace {

// r^2 - |d|^2 from the radius and the differences d = p - center.
template <class R, class D, std::size_t K>
Sign side_of_ball_of(const R& r, const std::array<D, K>& d) {
  if constexpr (K == 3) {
    return (r * r - (d[0] * d[0] + d[1] * d[1] + d[2] * d[2])).sign();
  } else {
    return (r * r - (d[0] * d[0] + d[1] * d[1])).sign();
  }
}

}  // namespace

Sign side_of_sphere_expansion(const Sphere& s, Vec3 p) {
  std::array<Expansion<2>, 3> d;
  const Expansion<1> r(s.radius);
  if (differences(std::array{p.x, p.y, p.z}, std::array{s.center.x, s.center.y, s.center.z}, d)) {
    return side_of_ball_of(r, heads(d));
  }
  return side_of_ball_of(r, d);
}
Sign side_of_sphere_big(const Sphere& s, Vec3 p) {
  return side_of_ball_of(BigFloat(s.radius), std::array{BigFloat(p.x) - BigFloat(s.center.x),
                                                        BigFloat(p.y) - BigFloat(s.center.y),
                                                        BigFloat(p.z) - BigFloat(s.center.z)});
}
Sign side_of_circle_expansion(const Circle& s, Vec2 p) {
  std::array<Expansion<2>, 2> d;
  const Expansion<1> r(s.radius);
  if (differences(std::array{p.x, p.y}, std::array{s.center.x, s.center.y}, d)) {
    return side_of_ball_of(r, heads(d));
  }
  return side_of_ball_of(r, d);
}
Sign side_of_circle_big(const Circle& s, Vec2 p) {
  return side_of_ball_of(BigFloat(s.radius), std::array{BigFloat(p.x) - BigFloat(s.center.x),
                                                        BigFloat(p.y) - BigFloat(s.center.y)});
}

// After the filter: out of line, so that the filter stays small and free of the stages'
// setup.
[[gnu::noinline]] Sign side_of_sphere_exact(const Sphere& s, Vec3 p) {
  if (in_expansion_range<2>(s.radius, s.center.x, s.center.y, s.center.z, p.x, p.y, p.z)) {
    return side_of_sphere_expansion(s, p);
  }
  std::array v{s.radius, s.center.x, s.center.y, s.center.z, p.x, p.y, p.z};
  if (scale_into_expansion_range<2>(v)) {
    return side_of_sphere_expansion({{v[1], v[2], v[3]}, v[0]}, {v[4], v[5], v[6]});
  }
  return side_of_sphere_big(s, p);
}

// After the filter: out of line, so that the filter stays small and free of the stages'
// setup.
[[gnu::noinline]] Sign side_of_circle_exact(const Circle& s, Vec2 p) {
  if (in_expansion_range<2>(s.radius, s.center.x, s.center.y, p.x, p.y)) {
    return side_of_circle_expansion(s, p);
  }
  std::array v{s.radius, s.center.x, s.center.y, p.x, p.y};
  if (scale_into_expansion_range<2>(v)) {
    return side_of_circle_expansion({{v[1], v[2]}, v[0]}, {v[3], v[4]});
  }
  return side_of_circle_big(s, p);
}

}  // namespace detail

// Filter. The monomials of r r - ((dx dx + dy dy) + dz dz) pass through at most k = 6
// roundings (two differences, one product, two sums, the final subtraction), so
// |error| <= gamma_6 * permanent < 7 eps * computed permanent (docs/robustness.md). Every product
// is of differences or of r, never amplified after underflowing: the guard is added once.
Sign side_of_sphere(const Sphere& s, Vec3 p) {
  constexpr double kBound = 7.0 * unit_roundoff<double>;
  const double dx = p.x - s.center.x, dy = p.y - s.center.y, dz = p.z - s.center.z;
  const double r2 = s.radius * s.radius;
  const double d2 = (dx * dx + dy * dy) + dz * dz;
  const double value = r2 - d2;
  const double errbound = kBound * (r2 + d2) + detail::kUnderflowGuard;
  if (value > errbound) return Sign::positive;
  if (-value > errbound) return Sign::negative;
  return detail::side_of_sphere_exact(s, p);
}

// Filter as side_of_sphere with k = 5 roundings: bound 6 eps * permanent.
Sign side_of_circle(const Circle& s, Vec2 p) {
  constexpr double kBound = 6.0 * unit_roundoff<double>;
  const double dx = p.x - s.center.x, dy = p.y - s.center.y;
  const double r2 = s.radius * s.radius;
  const double d2 = dx * dx + dy * dy;
  const double value = r2 - d2;
  const double errbound = kBound * (r2 + d2) + detail::kUnderflowGuard;
  if (value > errbound) return Sign::positive;
  if (-value > errbound) return Sign::negative;
  return detail::side_of_circle_exact(s, p);
}

}  // namespace contain::predicates
