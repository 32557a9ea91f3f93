#pragma once
/// \file
/// Exact binary floating-point numbers of unbounded size: an integer magnitude times a power of
/// two (dyadic rationals), the ring that holds every double and every sum and product of doubles
/// without rounding, overflow or underflow. The one big number of contain: the last resort of the
/// predicates for inputs whose exponents put expansion arithmetic at risk (|x| beyond
/// 2^±(200..500), subnormals), the CSG neighbourhood analysis (signs of polynomials of degree up
/// to 8 in the input doubles), clipping's crossing comparisons, and any new exact computation
/// that the filtered predicates do not cover. Slow (heap digits; Karatsuba beyond 48 limbs):
/// only for what a floating-point filter could not decide. Only signs and comparisons of these
/// values should reach a decision, so code using them stays an exact predicate in the sense of
/// docs/robustness.md.

#include <compare>
#include <cstdint>
#include <vector>

#include "contain/predicates/sign.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// ±magnitude * 2^exponent, the magnitude an unbounded unsigned integer. +, - and * are exact.
class BigFloat {
 public:
  /// Zero.
  BigFloat() = default;
  /// The double x, exactly. Precondition: x is finite.
  explicit BigFloat(double x);

  [[nodiscard]] Sign sign() const;
  [[nodiscard]] bool is_zero() const { return limbs_.empty(); }

  friend BigFloat operator+(const BigFloat& a, const BigFloat& b);
  friend BigFloat operator-(const BigFloat& a, const BigFloat& b);
  friend BigFloat operator*(const BigFloat& a, const BigFloat& b);
  friend BigFloat operator-(BigFloat a) {
    if (!a.limbs_.empty()) a.negative_ = !a.negative_;
    return a;
  }
  /// Exact comparison of the values (a representation is not unique: compare values only).
  friend std::strong_ordering operator<=>(const BigFloat& a, const BigFloat& b);
  friend bool operator==(const BigFloat& a, const BigFloat& b) { return (a <=> b) == 0; }
  /// a / b when b divides a in the dyadic rationals (b's odd part divides a's), exactly: the
  /// divisions of subresultant sequences (`polynomial.h`). Precondition: b != 0 and divides a.
  friend BigFloat exact_quotient(const BigFloat& a, const BigFloat& b);

  /// The value as m * 2^exponent with m a double, 0.5 <= |m| < 1, within a relative 2^-52 of
  /// the value; m = 0 and exponent = 0 for zero. For rounding quotients and square roots of exact
  /// values (predicates/rounded_distance.h), whose exponents may lie far outside the double range.
  [[nodiscard]] double frexp(std::int64_t& exponent) const;
  /// This value times 2^k, exactly.
  [[nodiscard]] BigFloat scaled(std::int64_t k) const;
  /// The value modulo an odd prime below 2^31 (a negative power of two through the inverse of
  /// 2), in [0, prime): for modular tests whose every answer is a certificate or a bound (the
  /// degree of a polynomial gcd, `polynomial_state.h`), never a sign.
  [[nodiscard]] std::uint32_t residue(std::uint32_t prime) const;

 private:
  void normalize();

  std::vector<std::uint32_t> limbs_;  // least significant first, no leading (high) zero limb
  std::int64_t exponent_ = 0;
  bool negative_ = false;
};

/// A 3D vector of exact numbers, for normals and their products (cross products of differences
/// of doubles, dot products with them) whose signs decide topology.
struct BigVec3 {
  BigFloat x, y, z;
};

/// The vector of doubles v, exactly. Precondition: v is finite.
[[nodiscard]] BigVec3 to_big(Vec3 v);
[[nodiscard]] BigVec3 operator+(const BigVec3& a, const BigVec3& b);
[[nodiscard]] BigVec3 operator-(const BigVec3& a, const BigVec3& b);
[[nodiscard]] BigVec3 operator-(const BigVec3& a);
[[nodiscard]] BigVec3 operator*(const BigFloat& s, const BigVec3& a);
[[nodiscard]] BigFloat dot(const BigVec3& a, const BigVec3& b);
[[nodiscard]] BigVec3 cross(const BigVec3& a, const BigVec3& b);
[[nodiscard]] bool is_zero(const BigVec3& a);

}  // namespace contain::predicates
