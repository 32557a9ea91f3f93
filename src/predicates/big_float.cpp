#include "contain/predicates/big_float.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <span>

namespace contain::predicates {

namespace {

using Limbs = std::vector<std::uint32_t>;

// a << bits, as a new magnitude.
Limbs shifted_left(const Limbs& a, std::int64_t bits) {
  const std::int64_t limbs = bits / 32;
  const int rest = static_cast<int>(bits % 32);
  Limbs out(a.size() + static_cast<std::size_t>(limbs) + 1, 0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::uint64_t v = static_cast<std::uint64_t>(a[i]) << rest;
    out[i + static_cast<std::size_t>(limbs)] |= static_cast<std::uint32_t>(v);
    out[i + static_cast<std::size_t>(limbs) + 1] |= static_cast<std::uint32_t>(v >> 32);
  }
  while (!out.empty() && out.back() == 0)
    out.pop_back();
  return out;
}

int compare(const Limbs& a, const Limbs& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  for (std::size_t i = a.size(); i-- > 0;) {
    if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
  }
  return 0;
}

Limbs add(const Limbs& a, const Limbs& b) {
  const Limbs& longer = a.size() >= b.size() ? a : b;
  const Limbs& shorter = a.size() >= b.size() ? b : a;
  Limbs out(longer.size() + 1, 0);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < longer.size(); ++i) {
    const std::uint64_t s = carry + longer[i] + (i < shorter.size() ? shorter[i] : 0U);
    out[i] = static_cast<std::uint32_t>(s);
    carry = s >> 32;
  }
  out[longer.size()] = static_cast<std::uint32_t>(carry);
  return out;
}

// a - b for a >= b.
Limbs subtract(const Limbs& a, const Limbs& b) {
  Limbs out(a.size(), 0);
  std::int64_t borrow = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::int64_t d = static_cast<std::int64_t>(a[i]) - borrow -
                     static_cast<std::int64_t>(i < b.size() ? b[i] : 0U);
    borrow = d < 0 ? 1 : 0;
    if (d < 0) d += std::int64_t{1} << 32;
    out[i] = static_cast<std::uint32_t>(d);
  }
  return out;
}

// 128-bit products of 64-bit limbs (a GCC and Clang extension, which both compilers of the
// project have).
__extension__ typedef unsigned __int128 Wide128;

// The schoolbook product, a.size() + b.size() limbs: on 64-bit limbs (pairs of 32-bit ones)
// with 128-bit products, a quarter of the multiplications of 32-bit limbs.
Limbs multiply_schoolbook(std::span<const std::uint32_t> a, std::span<const std::uint32_t> b) {
  const auto wide = [](std::span<const std::uint32_t> x) {
    std::vector<std::uint64_t> w((x.size() + 1) / 2, 0);
    for (std::size_t i = 0; i < x.size(); ++i)
      w[i / 2] |= static_cast<std::uint64_t>(x[i]) << (32 * (i % 2));
    return w;
  };
  const std::vector<std::uint64_t> wa = wide(a), wb = wide(b);
  std::vector<std::uint64_t> r(wa.size() + wb.size(), 0);
  for (std::size_t i = 0; i < wa.size(); ++i) {
    Wide128 carry = 0;
    for (std::size_t j = 0; j < wb.size(); ++j) {
      const Wide128 t = static_cast<Wide128>(wa[i]) * wb[j] + r[i + j] + carry;
      r[i + j] = static_cast<std::uint64_t>(t);
      carry = t >> 64;
    }
    r[i + wb.size()] = static_cast<std::uint64_t>(carry);
  }
  // The product is below 2^(32 (a.size() + b.size())): the 32-bit limbs beyond are zero.
  Limbs out(a.size() + b.size(), 0);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = static_cast<std::uint32_t>(r[i / 2] >> (32 * (i % 2)));
  return out;
}

Limbs shifted_limbs(Limbs a, std::size_t limbs) {
  a.insert(a.begin(), limbs, 0U);
  return a;
}

// Below this many limbs in the shorter factor, the schoolbook product is faster.
constexpr std::size_t kKaratsubaLimbs = 96;

// The product of two magnitudes (high zero limbs allowed). Karatsuba (Knuth, TAOCP vol. 2,
// 4.3.3): with a = a0 + a1 B^h, b = b0 + b1 B^h, ab = z0 + (z1 - z0 - z2) B^h + z2 B^2h for
// z0 = a0 b0, z2 = a1 b1, z1 = (a0 + a1)(b0 + b1): three half-size products instead of four, so
// the big numbers of exact polynomial stages (thousands of limbs for inputs of mixed magnitudes)
// multiply in O(n^1.58).
Limbs multiply_limbs(std::span<const std::uint32_t> a, std::span<const std::uint32_t> b) {
  if (a.size() < b.size()) std::swap(a, b);
  if (b.size() < kKaratsubaLimbs) return multiply_schoolbook(a, b);
  const std::size_t h = (a.size() + 1) / 2;
  if (b.size() <= h) {  // unbalanced: split a only
    return add(multiply_limbs(a.first(h), b), shifted_limbs(multiply_limbs(a.subspan(h), b), h));
  }
  const auto a0 = a.first(h), a1 = a.subspan(h), b0 = b.first(h), b1 = b.subspan(h);
  const Limbs z0 = multiply_limbs(a0, b0), z2 = multiply_limbs(a1, b1);
  const Limbs sa = add(Limbs(a0.begin(), a0.end()), Limbs(a1.begin(), a1.end()));
  const Limbs sb = add(Limbs(b0.begin(), b0.end()), Limbs(b1.begin(), b1.end()));
  const Limbs z1 = subtract(subtract(multiply_limbs(sa, sb), z0), z2);
  return add(add(z0, shifted_limbs(z1, h)), shifted_limbs(z2, 2 * h));
}

// Zero limbs between two nonzero ones from which a magnitude is split into separate runs.
constexpr std::size_t kGapLimbs = 3;

// The runs of a magnitude: its nonzero stretches separated by kGapLimbs zero limbs or more
// (offset of the first limb, limbs).
struct Run {
  std::size_t offset;
  std::span<const std::uint32_t> limbs;
};

std::vector<Run> runs_of(std::span<const std::uint32_t> a) {
  std::vector<Run> out;
  std::size_t i = 0;
  while (i < a.size()) {
    while (i < a.size() && a[i] == 0)
      ++i;
    if (i == a.size()) break;
    std::size_t end = i + 1, zeros = 0;
    for (std::size_t k = i + 1; k < a.size() && zeros < kGapLimbs; ++k) {
      zeros = a[k] == 0 ? zeros + 1 : 0;
      if (a[k] != 0) end = k + 1;
    }
    out.push_back({i, a.subspan(i, end - i)});
    i = end;
  }
  return out;
}

// r += p * B^offset, in place (r long enough for the sum; p's high zero limbs are skipped).
void add_into(Limbs& r, const Limbs& p, std::size_t offset) {
  std::size_t n = p.size();
  while (n > 0 && p[n - 1] == 0)
    --n;
  std::uint64_t carry = 0;
  std::size_t i = 0;
  for (; i < n; ++i) {
    const std::uint64_t s = carry + r[offset + i] + p[i];
    r[offset + i] = static_cast<std::uint32_t>(s);
    carry = s >> 32;
  }
  for (std::size_t k = offset + i; carry != 0; ++k) {
    const std::uint64_t s = carry + r[k];
    r[k] = static_cast<std::uint32_t>(s);
    carry = s >> 32;
  }
}

// The value of a factor of at most two limbs (a double's mantissa, a bisection point, a Taylor
// shift's origin, a short run of a sparse magnitude) as one 64-bit word.
std::uint64_t short_word(std::span<const std::uint32_t> s) {
  return s.size() == 1 ? s[0] : (static_cast<std::uint64_t>(s[1]) << 32) | s[0];
}

// r += a * w * B^base, in place (r long enough for the sum): one pass of 32 x 64-bit products,
// where the general product splits both factors into runs and widens them to 64-bit limbs.
void add_short_product_into(Limbs& r, std::span<const std::uint32_t> a, std::uint64_t w,
                            std::size_t base) {
  Wide128 carry = 0;
  std::size_t i = 0;
  for (; i < a.size(); ++i) {
    const Wide128 t = static_cast<Wide128>(a[i]) * w + r[base + i] + carry;
    r[base + i] = static_cast<std::uint32_t>(t);
    carry = t >> 32;
  }
  for (std::size_t k = base + i; carry != 0; ++k) {
    const Wide128 t = static_cast<Wide128>(r[k]) + carry;
    r[k] = static_cast<std::uint32_t>(t);
    carry = t >> 32;
  }
}

// a * b for b of at most two limbs: one allocation and one pass.
Limbs multiply_by_short(std::span<const std::uint32_t> a, std::span<const std::uint32_t> b) {
  Limbs out(a.size() + 2, 0);
  add_short_product_into(out, a, short_word(b), 0);
  return out;
}

// Below this many limbs in both factors, splitting into runs gains nothing.
constexpr std::size_t kRunLimbs = 8;

// r += x * y * B^(offsets), in place, for a run of at most two limbs in x or y (r long enough):
// the pairs of short runs that sparse magnitudes (sums of far-apart doubles) multiply by the
// dozen, without a product allocated for each.
void add_product_into(Limbs& r, const Run& x, const Run& y) {
  const bool x_longer = x.limbs.size() >= y.limbs.size();
  add_short_product_into(r, x_longer ? x.limbs : y.limbs, short_word(x_longer ? y.limbs : x.limbs),
                         x.offset + y.offset);
}

// The product of two magnitudes, run by run: numbers built from doubles of mixed magnitudes
// (1e300 + 1e-300 spans 2000 bits, two of them nonzero limbs) are mostly zero limbs, which a
// dense product would multiply all the same.
Limbs multiply_magnitudes(std::span<const std::uint32_t> a, std::span<const std::uint32_t> b) {
  if (a.size() < b.size()) std::swap(a, b);
  if (b.size() <= 2) return multiply_by_short(a, b);
  if (a.size() < kRunLimbs) return multiply_schoolbook(a, b);
  const std::vector<Run> ra = runs_of(a), rb = runs_of(b);
  if (ra.size() == 1 && rb.size() == 1 && ra[0].offset == 0 && rb[0].offset == 0 &&
      ra[0].limbs.size() == a.size() && rb[0].limbs.size() == b.size()) {
    return multiply_limbs(a, b);
  }
  Limbs r(a.size() + b.size() + 1, 0);
  for (const Run& x : ra) {
    for (const Run& y : rb) {
      if (x.limbs.size() <= 2 || y.limbs.size() <= 2) {
        add_product_into(r, x, y);
      } else {
        add_into(r, multiply_limbs(x.limbs, y.limbs), x.offset + y.offset);
      }
    }
  }
  return r;
}

}  // namespace

BigFloat::BigFloat(double x) {
  assert(std::isfinite(x) && "BigFloat takes finite doubles only");
  // A broken precondition in a release build: zero, not an endless loop over the mantissa of
  // frexp(inf) (an exact predicate handed an infinity must still return, if meaninglessly).
  if (x == 0.0 || !std::isfinite(x)) return;
  negative_ = x < 0.0;
  int e = 0;
  // frexp is exact, subnormals included: |x| = f * 2^e with f in [0.5, 1).
  const double f = std::frexp(std::fabs(x), &e);
  std::uint64_t m = static_cast<std::uint64_t>(std::ldexp(f, 53));
  exponent_ = e - 53;
  while ((m & 1U) == 0) {
    m >>= 1;
    ++exponent_;
  }
  limbs_ = {static_cast<std::uint32_t>(m), static_cast<std::uint32_t>(m >> 32)};
  normalize();
}

Sign BigFloat::sign() const {
  if (limbs_.empty()) return Sign::zero;
  return negative_ ? Sign::negative : Sign::positive;
}

void BigFloat::normalize() {
  while (!limbs_.empty() && limbs_.back() == 0)
    limbs_.pop_back();
  if (limbs_.empty()) {
    exponent_ = 0;
    negative_ = false;
    return;
  }
  // Whole zero limbs at the bottom move into the exponent, keeping magnitudes short.
  std::size_t zeros = 0;
  while (limbs_[zeros] == 0)
    ++zeros;
  if (zeros > 0) {
    limbs_.erase(limbs_.begin(), limbs_.begin() + static_cast<std::ptrdiff_t>(zeros));
    exponent_ += 32 * static_cast<std::int64_t>(zeros);
  }
}

BigFloat operator+(const BigFloat& a, const BigFloat& b) {
  if (a.limbs_.empty()) return b;
  if (b.limbs_.empty()) return a;
  // Align both magnitudes on the smaller exponent; shifting left is exact. The operand of that
  // exponent is used as it is (no copy).
  const std::int64_t e = std::min(a.exponent_, b.exponent_);
  Limbs shifted;
  if (a.exponent_ != e) shifted = shifted_left(a.limbs_, a.exponent_ - e);
  if (b.exponent_ != e) shifted = shifted_left(b.limbs_, b.exponent_ - e);
  const Limbs& ma = a.exponent_ != e ? shifted : a.limbs_;
  const Limbs& mb = b.exponent_ != e ? shifted : b.limbs_;
  BigFloat r;
  r.exponent_ = e;
  if (a.negative_ == b.negative_) {
    r.limbs_ = add(ma, mb);
    r.negative_ = a.negative_;
  } else if (compare(ma, mb) >= 0) {
    r.limbs_ = subtract(ma, mb);
    r.negative_ = a.negative_;
  } else {
    r.limbs_ = subtract(mb, ma);
    r.negative_ = b.negative_;
  }
  r.normalize();
  return r;
}

BigFloat operator-(const BigFloat& a, const BigFloat& b) {
  return a + -b;
}

std::strong_ordering operator<=>(const BigFloat& a, const BigFloat& b) {
  switch ((a - b).sign()) {
    case Sign::negative:
      return std::strong_ordering::less;
    case Sign::positive:
      return std::strong_ordering::greater;
    case Sign::zero:
      break;
  }
  return std::strong_ordering::equal;
}

BigFloat operator*(const BigFloat& a, const BigFloat& b) {
  BigFloat r;
  if (a.limbs_.empty() || b.limbs_.empty()) return r;
  r.limbs_ = multiply_magnitudes(a.limbs_, b.limbs_);
  r.exponent_ = a.exponent_ + b.exponent_;
  r.negative_ = a.negative_ != b.negative_;
  r.normalize();
  return r;
}

double BigFloat::frexp(std::int64_t& exponent) const {
  exponent = 0;
  if (limbs_.empty()) return 0.0;
  // The top three limbs (at least 65 significant bits, the top limb being nonzero) summed in
  // double: two roundings, a relative error below 2^-52.
  const std::size_t n = limbs_.size();
  double top = 0.0;
  std::int64_t shift = 32 * static_cast<std::int64_t>(n);
  for (std::size_t k = 0; k < 3; ++k) {
    top = top * 0x1p32 + (k < n ? static_cast<double>(limbs_[n - 1 - k]) : 0.0);
    shift -= 32;
  }
  int e = 0;
  const double f = std::frexp(top, &e);  // top = f * 2^e, f in [0.5, 1)
  exponent = shift + e + exponent_;
  return negative_ ? -f : f;
}

BigFloat BigFloat::scaled(std::int64_t k) const {
  BigFloat r = *this;
  if (!r.limbs_.empty()) r.exponent_ += k;
  return r;
}

namespace {

std::uint64_t power_mod(std::uint64_t base, std::uint64_t e, std::uint64_t m) {
  std::uint64_t r = 1 % m;
  for (; e != 0; e >>= 1) {
    if ((e & 1U) != 0) r = r * base % m;
    base = base * base % m;
  }
  return r;
}

}  // namespace

std::uint32_t BigFloat::residue(std::uint32_t prime) const {
  assert(prime % 2 == 1 && prime < (std::uint32_t{1} << 31));
  std::uint64_t r = 0;  // below prime < 2^31: r * 2^32 + limb fits in 64 bits
  for (std::size_t i = limbs_.size(); i-- > 0;)
    r = ((r << 32) | limbs_[i]) % prime;
  const std::uint64_t two = exponent_ >= 0 ? 2 : (prime + 1) / 2;  // (prime + 1) / 2 = 1 / 2
  const auto e = static_cast<std::uint64_t>(exponent_ >= 0 ? exponent_ : -exponent_);
  r = r * power_mod(two, e, prime) % prime;
  return static_cast<std::uint32_t>(negative_ && r != 0 ? prime - r : r);
}

BigVec3 to_big(Vec3 v) {
  return {BigFloat(v.x), BigFloat(v.y), BigFloat(v.z)};
}
BigVec3 operator+(const BigVec3& a, const BigVec3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
BigVec3 operator-(const BigVec3& a, const BigVec3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
BigVec3 operator-(const BigVec3& a) {
  return {-a.x, -a.y, -a.z};
}
BigVec3 operator*(const BigFloat& s, const BigVec3& a) {
  return {s * a.x, s * a.y, s * a.z};
}
BigFloat dot(const BigVec3& a, const BigVec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
BigVec3 cross(const BigVec3& a, const BigVec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
bool is_zero(const BigVec3& a) {
  return a.x.is_zero() && a.y.is_zero() && a.z.is_zero();
}

// Exact division by an odd divisor from the low limbs up (Jebelean's exact division): with
// inv = d0^-1 mod 2^32, each quotient limb is the current low limb of the remainder times inv,
// whose multiple of the divisor then cancels that limb exactly.
BigFloat exact_quotient(const BigFloat& a, const BigFloat& b) {
  assert(!b.limbs_.empty());
  BigFloat q;
  if (a.limbs_.empty()) return q;
  // b = odd * 2^(exponent + shift): move b's trailing zero bits into the exponent.
  Limbs divisor = b.limbs_;
  int shift = 0;
  while ((divisor[0] & 1U) == 0) {
    std::uint64_t carry = 0;
    for (std::size_t i = divisor.size(); i-- > 0;) {
      const std::uint64_t v = (carry << 32) | divisor[i];
      divisor[i] = static_cast<std::uint32_t>(v >> 1);
      carry = v & 1U;
    }
    ++shift;
  }
  while (!divisor.empty() && divisor.back() == 0)
    divisor.pop_back();
  // Newton's iteration for the inverse of an odd number modulo 2^32.
  std::uint32_t inv = divisor[0];
  for (int k = 0; k < 5; ++k)
    inv *= 2U - divisor[0] * inv;
  Limbs rem = a.limbs_;
  const std::size_t n = rem.size() >= divisor.size() ? rem.size() - divisor.size() + 1 : 1;
  rem.resize(rem.size() + 2, 0);
  Limbs quotient(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t qi = rem[i] * inv;
    quotient[i] = qi;
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < divisor.size(); ++j) {
      const std::uint64_t t = static_cast<std::uint64_t>(qi) * divisor[j] + carry;
      const std::uint64_t low = static_cast<std::uint32_t>(t);
      carry = t >> 32;
      if (rem[i + j] < low) ++carry;
      rem[i + j] -= static_cast<std::uint32_t>(low);
    }
    for (std::size_t k = i + divisor.size(); carry != 0 && k < rem.size(); ++k) {
      const std::uint64_t low = carry;
      carry = rem[k] < low ? 1 : 0;
      rem[k] -= static_cast<std::uint32_t>(low);
    }
  }
  q.limbs_ = std::move(quotient);
  q.exponent_ = a.exponent_ - b.exponent_ - shift;
  q.negative_ = a.negative_ != b.negative_;
  q.normalize();
  return q;
}

}  // namespace contain::predicates
