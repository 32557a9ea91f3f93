#pragma once
// Private to contain::inside: exact arithmetic on dyadic rationals (integer * 2^exponent), the
// ring that holds every double and every sum and product of doubles without rounding, overflow
// or underflow. Used by the CSG neighbourhood analysis, whose signs are polynomials of degree up
// to 8 in the input doubles (normals built from differences and cross products): beyond what
// predicates/ offers. Only signs of these exact values reach any decision, so this is an exact
// predicate in the sense of docs/robustness.md. Slow (heap digits) and only used at points that
// lie on the boundary of a CSG leaf.

#include <cstdint>
#include <vector>

#include "contain/predicates/sign.h"
#include "contain/values/vec.h"

namespace contain::inside::detail {

class ExactNumber {
 public:
  ExactNumber() = default;
  explicit ExactNumber(double value);  // precondition: finite

  [[nodiscard]] Sign sign() const;
  [[nodiscard]] bool is_zero() const { return digits_.empty(); }

  friend ExactNumber operator+(const ExactNumber& a, const ExactNumber& b);
  friend ExactNumber operator-(const ExactNumber& a, const ExactNumber& b);
  friend ExactNumber operator*(const ExactNumber& a, const ExactNumber& b);
  friend ExactNumber operator-(ExactNumber a) {
    if (!a.digits_.empty()) a.negative_ = !a.negative_;
    return a;
  }

 private:
  void normalize();
  static ExactNumber add(const ExactNumber& a, const ExactNumber& b, bool negate_b);

  bool negative_ = false;
  std::vector<std::uint32_t> digits_;  // magnitude, little-endian base 2^32, no leading zeros
  std::int64_t exponent_ = 0;          // value = +-digits * 2^exponent
};

struct ExactVec3 {
  ExactNumber x, y, z;
};

[[nodiscard]] ExactVec3 exact(Vec3 v);
[[nodiscard]] ExactVec3 operator+(const ExactVec3& a, const ExactVec3& b);
[[nodiscard]] ExactVec3 operator-(const ExactVec3& a, const ExactVec3& b);
[[nodiscard]] ExactVec3 operator-(const ExactVec3& a);
[[nodiscard]] ExactVec3 operator*(const ExactNumber& s, const ExactVec3& a);
[[nodiscard]] ExactNumber dot(const ExactVec3& a, const ExactVec3& b);
[[nodiscard]] ExactVec3 cross(const ExactVec3& a, const ExactVec3& b);
[[nodiscard]] bool is_zero(const ExactVec3& a);

}  // namespace contain::inside::detail
