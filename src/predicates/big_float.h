#pragma once
// Exact binary floating-point numbers of unbounded size: an integer magnitude times a power of
// two. The last-resort arithmetic of the predicates, for inputs whose exponents put expansion
// arithmetic at risk of overflow or underflow (|x| beyond 2^±(200..500), subnormals). Every
// finite double converts exactly, and +, -, * are exact, so a predicate evaluated here is exact
// for every finite input. Slow (heap, schoolbook multiplication) and used only in that regime.

#include <cstdint>
#include <vector>

#include "contain/predicates/sign.h"

namespace contain::predicates::detail {

/// ±magnitude * 2^exponent, the magnitude an unbounded unsigned integer.
class BigFloat {
 public:
  /// Zero.
  BigFloat() = default;
  /// The finite double x, exactly.
  explicit BigFloat(double x);

  [[nodiscard]] Sign sign() const;

  friend BigFloat operator+(const BigFloat& a, const BigFloat& b);
  friend BigFloat operator-(const BigFloat& a, const BigFloat& b);
  friend BigFloat operator*(const BigFloat& a, const BigFloat& b);
  /// a / b when b divides a in the dyadic rationals (b's odd part divides a's): exact division
  /// for the subresultant sequences of `polynomial.cpp`. Precondition: b != 0 and divides a.
  friend BigFloat exact_quotient(const BigFloat& a, const BigFloat& b);

 private:
  void normalize();

  std::vector<std::uint32_t> limbs_;  // least significant first, no leading (high) zero limb
  int exponent_ = 0;
  bool negative_ = false;
};

}  // namespace contain::predicates::detail
