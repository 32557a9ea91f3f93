#include "contain/predicates/rounded_volume.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#endif

#include "contain/predicates/big_float.h"
#include "contain/predicates/unit_roundoff.h"
#include "expansion.h"
#include "nearest_double.h"

namespace contain::predicates {

namespace {

using detail::LD;
using Triangles = std::span<const std::array<std::int32_t, 3>>;

// Within 2^+-200 (or zero) every part below is an exact double: a coordinate is a multiple of
// 2^-252, so x * y, its leading double p and their difference pe are multiples of 2^-504, and
// p * z, pe * z and their parts multiples of 2^-756, far above the subnormals; no product nears
// overflow (2^600). Beyond, the exact stage decides.
bool in_split_range(double x) {
  const double m = std::fabs(x);
  return m == 0.0 || (m >= 0x1p-200 && m <= 0x1p200);
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

// A running sum in three levels: the exact sum of the terms is hi + lo + the exact sum of the
// errors of lo's Two-Sums, whose rounded sum is lo2; `error_mass` sums those errors'
// magnitudes, for a bound of what lo2's roundings lost. Every part is exact (in_split_range), so
// that bound is the only one: of order u^2 of the small parts, which are of order u of the
// products, and it does not grow with the coordinates' distance from the origin the way a
// rounded sum of the small parts would (their roundings, of order u of terms that cancel, made
// a mesh of 10^5 triangles 10^3 from the origin fall to the exact stage).
struct Accumulator {
  double hi = 0.0;
  double lo = 0.0;
  double lo2 = 0.0;
  double error_mass = 0.0;
  std::size_t errors = 0;

  void add_small(double x) {
    double s = 0.0;
    double e = 0.0;
    detail::two_sum(lo, x, s, e);
    lo = s;
    lo2 += e;
    error_mass += std::fabs(e);
  }

  // Adds x * y * z = p z + pe z = q + qe + r + re exactly (x * y = p + pe, p * z = q + qe,
  // pe * z = r + re); q joins hi by Two-Sum, its error and the other three parts join lo.
  template <bool Fma>
  void add_product(double x, double y, double z) {
    double p = 0.0;
    double pe = 0.0;
    product_parts<Fma>(x, y, p, pe);
    double q = 0.0;
    double qe = 0.0;
    product_parts<Fma>(p, z, q, qe);
    double r = 0.0;
    double re = 0.0;
    product_parts<Fma>(pe, z, r, re);
    double s = 0.0;
    double e = 0.0;
    detail::two_sum(hi, q, s, e);
    hi = s;
    add_small(e);
    add_small(qe);
    add_small(r);
    add_small(re);
    errors += 4;
  }
};

// Adds a . (b x c) of the triangle t by the six products of the cofactor expansion.
template <bool Fma>
inline void add_determinant(Accumulator& sum, std::span<const Vec3> vertices,
                            const std::array<std::int32_t, 3>& t) {
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

// The sum over the triangles of a . (b x c).
template <bool Fma>
inline Accumulator determinant_sum(std::span<const Vec3> vertices, Triangles triangles) {
  Accumulator sum;
  for (const auto& t : triangles)
    add_determinant<Fma>(sum, vertices, t);
  return sum;
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
// Four accumulators side by side, one a lane (AVX2): each lane is an `Accumulator` of its own
// (the same exact parts, the same error terms), summed into one at the end.
// (No initializers: the vector type is only usable inside the functions built for AVX2.)
struct Lanes {
  __m256d hi, lo, lo2, error_mass;
};

[[gnu::target("avx2,fma"), gnu::always_inline]] inline void lanes_clear(Lanes& l) {
  l.hi = _mm256_setzero_pd();
  l.lo = _mm256_setzero_pd();
  l.lo2 = _mm256_setzero_pd();
  l.error_mass = _mm256_setzero_pd();
}

[[gnu::target("avx2,fma"), gnu::always_inline]] inline void lanes_two_sum(__m256d a, __m256d b,
                                                                          __m256d& x, __m256d& y) {
  x = _mm256_add_pd(a, b);
  const __m256d b_virtual = _mm256_sub_pd(x, a);
  const __m256d a_virtual = _mm256_sub_pd(x, b_virtual);
  y = _mm256_add_pd(_mm256_sub_pd(a, a_virtual), _mm256_sub_pd(b, b_virtual));
}

[[gnu::target("avx2,fma"), gnu::always_inline]] inline void lanes_add_small(Lanes& l, __m256d x) {
  __m256d s;
  __m256d e;
  lanes_two_sum(l.lo, x, s, e);
  l.lo = s;
  l.lo2 = _mm256_add_pd(l.lo2, e);
  l.error_mass = _mm256_add_pd(l.error_mass, _mm256_andnot_pd(_mm256_set1_pd(-0.0), e));
}

// Accumulator::add_product in every lane: x y z = q + qe + r + re exactly (fmsub: the exact
// error of a product, one rounding of an exact value).
[[gnu::target("avx2,fma"), gnu::always_inline]] inline void lanes_add_product(Lanes& l, __m256d x,
                                                                              __m256d y,
                                                                              __m256d z) {
  const __m256d p = _mm256_mul_pd(x, y);
  const __m256d pe = _mm256_fmsub_pd(x, y, p);
  const __m256d q = _mm256_mul_pd(p, z);
  const __m256d qe = _mm256_fmsub_pd(p, z, q);
  const __m256d r = _mm256_mul_pd(pe, z);
  const __m256d re = _mm256_fmsub_pd(pe, z, r);
  __m256d s;
  __m256d e;
  lanes_two_sum(l.hi, q, s, e);
  l.hi = s;
  lanes_add_small(l, e);
  lanes_add_small(l, qe);
  lanes_add_small(l, r);
  lanes_add_small(l, re);
}

// The lanes' sums into `sum`: each lane's hi by Two-Sum (its error and the lane's lo joining lo
// as two more error terms), its lo2 and error mass added. lo2 is then the rounded sum of every
// error term, in another order than one accumulator's (the bound on it holds for any order:
// Higham, "Accuracy and Stability of Numerical Algorithms", 4.2, for the count `errors` of all
// the terms).
[[gnu::target("avx2,fma")]] void merge_lanes(const Lanes& l, std::size_t errors_a_lane,
                                             Accumulator& sum) {
  alignas(32) double hi[4], lo[4], lo2[4], mass[4];
  _mm256_store_pd(hi, l.hi);
  _mm256_store_pd(lo, l.lo);
  _mm256_store_pd(lo2, l.lo2);
  _mm256_store_pd(mass, l.error_mass);
  for (int k = 0; k < 4; ++k) {
    double s = 0.0;
    double e = 0.0;
    detail::two_sum(sum.hi, hi[k], s, e);
    sum.hi = s;
    sum.add_small(e);
    sum.add_small(lo[k]);
    sum.lo2 += lo2[k];
    sum.error_mass += mass[k];
    sum.errors += errors_a_lane + 2;
  }
}

// The library is built for the baseline x86-64, without fused multiply-add or AVX2; where the
// processor has both, two triangles' twelve products go through three vectors of four lanes
// (the exact products two operations each instead of Dekker's seventeen), an odd last triangle
// through the scalar accumulator. Flattened: GCC left the scalar `add_product` out of line,
// built for the baseline, where each std::fma was a call into libm. The library's
// -ffp-contract=off keeps every other operation as written (no product fused into a sum).
[[gnu::target("avx2,fma"), gnu::flatten]] Accumulator determinant_sum_avx2(
    std::span<const Vec3> vertices, Triangles triangles) {
  Lanes first, second, third;
  lanes_clear(first);
  lanes_clear(second);
  lanes_clear(third);
  const std::size_t pairs = triangles.size() / 2;
  for (std::size_t k = 0; k < pairs; ++k) {
    const auto& t = triangles[2 * k];
    const auto& u = triangles[2 * k + 1];
    const Vec3 a = vertices[static_cast<std::size_t>(t[0])];
    const Vec3 b = vertices[static_cast<std::size_t>(t[1])];
    const Vec3 c = vertices[static_cast<std::size_t>(t[2])];
    const Vec3 d = vertices[static_cast<std::size_t>(u[0])];
    const Vec3 e = vertices[static_cast<std::size_t>(u[1])];
    const Vec3 f = vertices[static_cast<std::size_t>(u[2])];
    // The six products of each determinant, as in determinant_sum (_mm256_set_pd: last lane
    // first).
    lanes_add_product(first, _mm256_set_pd(-a.y, a.y, -a.x, a.x), _mm256_set_pd(b.x, b.z, b.z, b.y),
                      _mm256_set_pd(c.z, c.x, c.y, c.z));
    lanes_add_product(second, _mm256_set_pd(-d.x, d.x, -a.z, a.z),
                      _mm256_set_pd(e.z, e.y, b.y, b.x), _mm256_set_pd(f.y, f.z, c.x, c.y));
    lanes_add_product(third, _mm256_set_pd(-d.z, d.z, -d.y, d.y), _mm256_set_pd(e.y, e.x, e.x, e.z),
                      _mm256_set_pd(f.x, f.y, f.z, f.x));
  }
  Accumulator sum;
  for (const Lanes* l : {&first, &second, &third})
    merge_lanes(*l, 4 * pairs, sum);
  if (triangles.size() % 2 != 0) add_determinant<true>(sum, vertices, triangles.back());
  return sum;
}
Accumulator fastest_determinant_sum(std::span<const Vec3> vertices, Triangles triangles) {
  static const bool has_avx2_fma =
      __builtin_cpu_supports("fma") != 0 && __builtin_cpu_supports("avx2") != 0;
  return has_avx2_fma ? determinant_sum_avx2(vertices, triangles)
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

namespace detail {

std::optional<double> filtered_signed_volume(std::span<const Vec3> vertices, Triangles triangles,
                                             VolumeSum how) {
  bool in_range = true;
  for (const Vec3& v : vertices)
    in_range = in_range && in_split_range(v.x) && in_split_range(v.y) && in_split_range(v.z);
  if (!in_range) return std::nullopt;
  const Accumulator sum = how == VolumeSum::scalar ? determinant_sum<false>(vertices, triangles)
                                                   : fastest_determinant_sum(vertices, triangles);
  // lo2, the recursive sum of m exact errors, is within gamma_m of their magnitudes' sum of
  // their exact sum (Higham, "Accuracy and Stability of Numerical Algorithms", 4.2);
  // 2 (m + 2) u covers that and the rounding of error_mass itself while m u < 1/4. Then
  // hi + lo + lo2 in long double, two roundings, and the division by 6, one more.
  constexpr double u = unit_roundoff<double>;
  const double m = static_cast<double>(sum.errors);
  if (!(m * u < 0.25 && std::isfinite(sum.hi) && std::isfinite(sum.lo) &&
        std::isfinite(sum.error_mass))) {
    return std::nullopt;
  }
  const LD low_error = static_cast<LD>(2.0 * (m + 2.0) * u) * static_cast<LD>(sum.error_mass);
  const LD leading = static_cast<LD>(sum.hi) + static_cast<LD>(sum.lo);
  const LD six_volume = leading + static_cast<LD>(sum.lo2);
  const LD x = six_volume / 6;
  const LD bound =
      ((low_error + kU * (std::fabs(leading) + std::fabs(six_volume))) / 6 + kU * std::fabs(x)) *
      (1 + 16 * kU);
  double out = 0.0;
  if (!certify_nearest(x, bound, out)) return std::nullopt;
  return out;
}

}  // namespace detail

double rounded_signed_volume(std::span<const Vec3> vertices, Triangles triangles) {
  if (const std::optional<double> fast = detail::filtered_signed_volume(vertices, triangles)) {
    return *fast;
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
