#include "exact_number.h"

#include <algorithm>
#include <cmath>

namespace contain::inside::detail {
namespace {

using Digits = std::vector<std::uint32_t>;

void trim(Digits& d) {
  while (!d.empty() && d.back() == 0)
    d.pop_back();
}

int compare(const Digits& a, const Digits& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (std::size_t i = a.size(); i-- > 0;) {
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  }
  return 0;
}

Digits shifted_left(const Digits& a, std::int64_t bits) {
  const auto words = static_cast<std::size_t>(bits / 32);
  const auto rest = static_cast<unsigned>(bits % 32);
  Digits out(words, 0);
  out.reserve(words + a.size() + 1);
  std::uint32_t carry = 0;
  for (std::uint32_t d : a) {
    out.push_back(rest == 0 ? d : ((d << rest) | carry));
    carry = rest == 0 ? 0 : (d >> (32 - rest));
  }
  if (carry != 0) out.push_back(carry);
  return out;
}

Digits add_magnitudes(const Digits& a, const Digits& b) {
  Digits out;
  out.reserve(std::max(a.size(), b.size()) + 1);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
    const std::uint64_t s = carry + (i < a.size() ? a[i] : 0) + (i < b.size() ? b[i] : 0);
    out.push_back(static_cast<std::uint32_t>(s));
    carry = s >> 32;
  }
  if (carry != 0) out.push_back(static_cast<std::uint32_t>(carry));
  return out;
}

// Precondition: a >= b.
Digits subtract_magnitudes(const Digits& a, const Digits& b) {
  Digits out(a.size());
  std::int64_t borrow = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::int64_t s = static_cast<std::int64_t>(a[i]) - (i < b.size() ? b[i] : 0) - borrow;
    borrow = s < 0 ? 1 : 0;
    if (s < 0) s += std::int64_t{1} << 32;
    out[i] = static_cast<std::uint32_t>(s);
  }
  trim(out);
  return out;
}

}  // namespace

ExactNumber::ExactNumber(double value) {
  if (value == 0) return;
  int e = 0;
  const double m = std::frexp(std::fabs(value), &e);  // |value| = m 2^e, m in [0.5, 1)
  const auto mantissa = static_cast<std::uint64_t>(std::ldexp(m, 53));
  negative_ = value < 0;
  digits_ = {static_cast<std::uint32_t>(mantissa), static_cast<std::uint32_t>(mantissa >> 32)};
  exponent_ = e - 53;
  normalize();
}

void ExactNumber::normalize() {
  trim(digits_);
  if (digits_.empty()) {
    negative_ = false;
    exponent_ = 0;
    return;
  }
  // Drop low zero words so that numbers stay short.
  std::size_t zeros = 0;
  while (digits_[zeros] == 0)
    ++zeros;
  if (zeros > 0) {
    digits_.erase(digits_.begin(), digits_.begin() + static_cast<std::ptrdiff_t>(zeros));
    exponent_ += 32 * static_cast<std::int64_t>(zeros);
  }
}

Sign ExactNumber::sign() const {
  if (digits_.empty()) return Sign::zero;
  return negative_ ? Sign::negative : Sign::positive;
}

ExactNumber ExactNumber::add(const ExactNumber& a, const ExactNumber& b, bool negate_b) {
  if (b.digits_.empty()) return a;
  const bool b_negative = negate_b ? !b.negative_ : b.negative_;
  if (a.digits_.empty()) {
    ExactNumber r = b;
    r.negative_ = b_negative;
    return r;
  }
  const std::int64_t e = std::min(a.exponent_, b.exponent_);
  const Digits da = shifted_left(a.digits_, a.exponent_ - e);
  const Digits db = shifted_left(b.digits_, b.exponent_ - e);
  ExactNumber r;
  r.exponent_ = e;
  if (a.negative_ == b_negative) {
    r.digits_ = add_magnitudes(da, db);
    r.negative_ = a.negative_;
  } else if (compare(da, db) >= 0) {
    r.digits_ = subtract_magnitudes(da, db);
    r.negative_ = a.negative_;
  } else {
    r.digits_ = subtract_magnitudes(db, da);
    r.negative_ = b_negative;
  }
  r.normalize();
  return r;
}

ExactNumber operator+(const ExactNumber& a, const ExactNumber& b) {
  return ExactNumber::add(a, b, false);
}
ExactNumber operator-(const ExactNumber& a, const ExactNumber& b) {
  return ExactNumber::add(a, b, true);
}

ExactNumber operator*(const ExactNumber& a, const ExactNumber& b) {
  ExactNumber r;
  if (a.digits_.empty() || b.digits_.empty()) return r;
  Digits out(a.digits_.size() + b.digits_.size(), 0);
  for (std::size_t i = 0; i < a.digits_.size(); ++i) {
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < b.digits_.size(); ++j) {
      const std::uint64_t t =
          static_cast<std::uint64_t>(a.digits_[i]) * b.digits_[j] + out[i + j] + carry;
      out[i + j] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    out[i + b.digits_.size()] = static_cast<std::uint32_t>(carry);
  }
  r.digits_ = std::move(out);
  r.exponent_ = a.exponent_ + b.exponent_;
  r.negative_ = a.negative_ != b.negative_;
  r.normalize();
  return r;
}

ExactVec3 exact(Vec3 v) {
  return {ExactNumber(v.x), ExactNumber(v.y), ExactNumber(v.z)};
}
ExactVec3 operator+(const ExactVec3& a, const ExactVec3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
ExactVec3 operator-(const ExactVec3& a, const ExactVec3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
ExactVec3 operator-(const ExactVec3& a) {
  return {-a.x, -a.y, -a.z};
}
ExactVec3 operator*(const ExactNumber& s, const ExactVec3& a) {
  return {s * a.x, s * a.y, s * a.z};
}
ExactNumber dot(const ExactVec3& a, const ExactVec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
ExactVec3 cross(const ExactVec3& a, const ExactVec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
bool is_zero(const ExactVec3& a) {
  return a.x.is_zero() && a.y.is_zero() && a.z.is_zero();
}

}  // namespace contain::inside::detail
