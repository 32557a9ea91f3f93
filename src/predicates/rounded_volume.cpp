#include "contain/predicates/rounded_volume.h"

#include <cmath>
#include <cstddef>

#include "contain/predicates/big_float.h"
#include "contain/predicates/unit_roundoff.h"
#include "expansion.h"
#include "nearest_double.h"

namespace contain::predicates {

namespace {

using detail::LD;
using Triangles = std::span<const std::array<std::int32_t, 3>>;

// Within 2^+-300 (or zero) a product of three coordinates and the parts below are exact or
// carry the bounded roundings accounted for: no overflow, no underflow.
bool in_split_range(double x) {
  const double m = std::fabs(x);
  return m == 0.0 || (m >= 0x1p-300 && m <= 0x1p300);
}

// x * y = p + e exactly: by a fused multiply-add where the processor has one (chosen once at
// run time), else by Dekker's splitting (expansion.h).
template <bool Fma>
inline void product_parts(double x, double y, double& p, double& e) {
  if constexpr (Fma) {
    p = x * y;
    e = std::fma(x, y, -p);
  } else {
    detail::two_product(x, y, p, e);
  }
}

// A running sum: the exact sum of the terms is hi plus the exact sum of small parts, whose
// rounded sum is lo; `small_mass` sums the small parts' magnitudes, for a bound of what lo's
// roundings and the parts' own roundings lost.
struct Accumulator {
  double hi = 0.0;
  double lo = 0.0;
  double small_mass = 0.0;
  std::size_t small_parts = 0;

  // Adds x * y * z: x * y = p + pe and p * z = q + qe exactly; q joins hi by Two-Sum (its error
  // e joins lo), qe + pe * z joins lo rounded twice (within 2u (|qe| + |pe z|) (1 + u) of its
  // exact value; |pe z| <= u |x y z|, so the bound is of order u^2 of the product).
  template <bool Fma>
  void add_product(double x, double y, double z) {
    double p = 0.0;
    double pe = 0.0;
    product_parts<Fma>(x, y, p, pe);
    double q = 0.0;
    double qe = 0.0;
    product_parts<Fma>(p, z, q, qe);
    double s = 0.0;
    double e = 0.0;
    detail::two_sum(hi, q, s, e);
    hi = s;
    const double r = pe * z;
    lo += e + (qe + r);
    small_mass += std::fabs(e) + std::fabs(qe) + std::fabs(r);
    small_parts += 3;
  }
};

// The sum over the triangles of a . (b x c), by the six products of the cofactor expansion.
template <bool Fma>
inline Accumulator determinant_sum(std::span<const Vec3> vertices, Triangles triangles) {
  Accumulator sum;
  for (const auto& t : triangles) {
    const Vec3 a = vertices[static_cast<std::size_t>(t[0])];
    const Vec3 b = vertices[static_cast<std::size_t>(t[1])];
    const Vec3 c = vertices[static_cast<std::size_t>(t[2])];
    sum.add_product<Fma>(a.x, b.y, c.z);
    sum.add_product<Fma>(-a.x, b.z, c.y);
    sum.add_product<Fma>(a.y, b.z, c.x);
    sum.add_product<Fma>(-a.y, b.x, c.z);
    sum.add_product<Fma>(a.z, b.x, c.y);
    sum.add_product<Fma>(-a.z, b.y, c.x);
  }
  return sum;
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
// The library is built for the baseline x86-64, without fused multiply-add; where the processor
// has it, the exact products cost two operations instead of Dekker's seventeen.
[[gnu::target("fma")]] Accumulator determinant_sum_fma(std::span<const Vec3> vertices,
                                                       Triangles triangles) {
  return determinant_sum<true>(vertices, triangles);
}
Accumulator fastest_determinant_sum(std::span<const Vec3> vertices, Triangles triangles) {
  static const bool has_fma = __builtin_cpu_supports("fma") != 0;
  return has_fma ? determinant_sum_fma(vertices, triangles)
                 : determinant_sum<false>(vertices, triangles);
}
#else
Accumulator fastest_determinant_sum(std::span<const Vec3> vertices, Triangles triangles) {
  return determinant_sum<false>(vertices, triangles);
}
#endif

BigFloat exact_determinant(Vec3 a, Vec3 b, Vec3 c) {
  const BigFloat ax(a.x), ay(a.y), az(a.z), bx(b.x), by(b.y), bz(b.z), cx(c.x), cy(c.y), cz(c.z);
  return ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
}

}  // namespace

double rounded_signed_volume(std::span<const Vec3> vertices, Triangles triangles) {
  bool in_range = true;
  for (const Vec3& v : vertices)
    in_range = in_range && in_split_range(v.x) && in_split_range(v.y) && in_split_range(v.z);
  if (in_range) {
    const Accumulator sum = fastest_determinant_sum(vertices, triangles);
    // lo, the recursive sum of m small parts each rounded at most twice, is within
    // (gamma_m + 2u (1 + u)) of their magnitudes' sum of their exact sum (Higham, "Accuracy and
    // Stability of Numerical Algorithms", 4.2); 2 (m + 2) u covers that and the rounding of
    // small_mass itself while m u < 1/4.
    constexpr double u = unit_roundoff<double>;
    const double m = static_cast<double>(sum.small_parts);
    if (m * u < 0.25 && std::isfinite(sum.hi) && std::isfinite(sum.small_mass)) {
      const LD low_error = static_cast<LD>(2.0 * (m + 2.0) * u) * static_cast<LD>(sum.small_mass);
      const LD six_volume = static_cast<LD>(sum.hi) + static_cast<LD>(sum.lo);
      const LD x = six_volume / 6;
      const LD bound =
          ((low_error + detail::kU * std::fabs(six_volume)) / 6 + detail::kU * std::fabs(x)) *
          (1 + 16 * detail::kU);
      double out = 0.0;
      if (detail::certify_nearest(x, bound, out)) return out;
    }
  }
  BigFloat six_volume;
  for (const auto& t : triangles) {
    six_volume = six_volume + exact_determinant(vertices[static_cast<std::size_t>(t[0])],
                                                vertices[static_cast<std::size_t>(t[1])],
                                                vertices[static_cast<std::size_t>(t[2])]);
  }
  return detail::quotient_stage_b(six_volume, BigFloat(6.0));
}

}  // namespace contain::predicates
