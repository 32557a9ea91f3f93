#include "contain/predicates/cross_dot.h"

#include <array>
#include <cmath>

#include "contain/predicates/big_float.h"
#include "predicates/expansion.h"
#include "predicates/stages.h"

namespace contain::predicates {

namespace detail {

namespace {

// ((b - a) x (p - a)) . ((b - a) x (c - a)) from the differences (b - a, p - a, c - a).
template <class D>
Sign cross_dot_of(const std::array<D, 9>& d) {
  const D &ux = d[0], &uy = d[1], &uz = d[2], &vx = d[3], &vy = d[4], &vz = d[5], &wx = d[6],
          &wy = d[7], &wz = d[8];
  const auto n1x = uy * vz - uz * vy;
  const auto n1y = uz * vx - ux * vz;
  const auto n1z = ux * vy - uy * vx;
  const auto n2x = uy * wz - uz * wy;
  const auto n2y = uz * wx - ux * wz;
  const auto n2z = ux * wy - uy * wx;
  return (n1x * n2x + n1y * n2y + n1z * n2z).sign();
}

}  // namespace

Sign cross_dot_expansion(Vec3 a, Vec3 b, Vec3 p, Vec3 c) {
  std::array<Expansion<2>, 9> diff;
  if (differences(std::array{b.x, b.y, b.z, p.x, p.y, p.z, c.x, c.y, c.z},
                  std::array{a.x, a.y, a.z, a.x, a.y, a.z, a.x, a.y, a.z}, diff)) {
    return cross_dot_of(heads(diff));
  }
  return cross_dot_of(diff);
}

Sign cross_dot_big(Vec3 a, Vec3 b, Vec3 p, Vec3 c) {
  const BigFloat ax(a.x), ay(a.y), az(a.z);
  return cross_dot_of(std::array{BigFloat(b.x) - ax, BigFloat(b.y) - ay, BigFloat(b.z) - az,
                                 BigFloat(p.x) - ax, BigFloat(p.y) - ay, BigFloat(p.z) - az,
                                 BigFloat(c.x) - ax, BigFloat(c.y) - ay, BigFloat(c.z) - az});
}

// After the filter: out of line, so that the filter stays small and free of the stages'
// setup.
[[gnu::noinline]] Sign cross_dot_exact(Vec3 a, Vec3 b, Vec3 p, Vec3 c) {
  if (in_expansion_range<4>(a.x, a.y, a.z, b.x, b.y, b.z, p.x, p.y, p.z, c.x, c.y, c.z)) {
    return cross_dot_expansion(a, b, p, c);
  }
  std::array v{a.x, a.y, a.z, b.x, b.y, b.z, p.x, p.y, p.z, c.x, c.y, c.z};
  if (scale_into_expansion_range<4>(v)) {
    return cross_dot_expansion({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]},
                               {v[9], v[10], v[11]});
  }
  return cross_dot_big(a, b, p, c);
}

}  // namespace detail

// Filter. Each monomial of the degree-4 expression passes through at most k = 11 roundings (four
// differences, two inner products, two inner subtractions, the outer product, two sums), so
// |error| <= gamma_11 * permanent < 12 eps * computed permanent (docs/robustness.md). An
// underflowed inner product is multiplied by a component of the other cross product, so the
// guard is scaled by 1 + the sum of the cross products' component permanents.
Sign cross_dot(Vec3 a, Vec3 b, Vec3 p, Vec3 c) {
  constexpr double kBound = 12.0 * unit_roundoff<double>;
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = p.x - a.x, vy = p.y - a.y, vz = p.z - a.z;
  const double wx = c.x - a.x, wy = c.y - a.y, wz = c.z - a.z;
  const double p1 = uy * vz, p2 = uz * vy, p3 = uz * vx, p4 = ux * vz, p5 = ux * vy, p6 = uy * vx;
  const double q1 = uy * wz, q2 = uz * wy, q3 = uz * wx, q4 = ux * wz, q5 = ux * wy, q6 = uy * wx;
  const double value = ((p1 - p2) * (q1 - q2) + (p3 - p4) * (q3 - q4)) + (p5 - p6) * (q5 - q6);
  const double m1 = std::fabs(p1) + std::fabs(p2), m2 = std::fabs(p3) + std::fabs(p4),
               m3 = std::fabs(p5) + std::fabs(p6);
  const double k1 = std::fabs(q1) + std::fabs(q2), k2 = std::fabs(q3) + std::fabs(q4),
               k3 = std::fabs(q5) + std::fabs(q6);
  const double permanent = (m1 * k1 + m2 * k2) + m3 * k3;
  const double errbound =
      kBound * permanent + detail::kUnderflowGuard * (1.0 + (m1 + m2 + m3) + (k1 + k2 + k3));
  if (value > errbound) return Sign::positive;
  if (-value > errbound) return Sign::negative;
  return detail::cross_dot_exact(a, b, p, c);
}

}  // namespace contain::predicates
