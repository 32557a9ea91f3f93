#include "contain/predicates/exact_rational.h"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "contain/predicates/big_float.h"
#include "predicates/double_order.h"

namespace contain::predicates {
namespace {

using detail::from_key;
using detail::key_distance;
using detail::middle_key;
using detail::order_key;
using predicates::BigFloat;

struct Integer {
  BigFloat value;
  bool negative = false;
  double approx = 0.0;  // correctly rounded (may be infinite for huge integers)
};

std::optional<Integer> parse_integer(std::string_view s) {
  Integer out;
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) {
    out.negative = s[i] == '-';
    ++i;
  }
  if (i == s.size()) return std::nullopt;
  // Nine digits at a time: each chunk and 10^9 are exact doubles, so every step is exact.
  const BigFloat billion(1e9);
  std::uint32_t chunk = 0;
  std::uint32_t scale = 1;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    if (c < '0' || c > '9') return std::nullopt;
    chunk = chunk * 10 + static_cast<std::uint32_t>(c - '0');
    scale *= 10;
    if (scale == 1000000000U) {
      out.value = out.value * billion + BigFloat(static_cast<double>(chunk));
      chunk = 0;
      scale = 1;
    }
  }
  if (scale > 1) {
    out.value =
        out.value * BigFloat(static_cast<double>(scale)) + BigFloat(static_cast<double>(chunk));
  }
  out.approx = std::strtod(std::string(s).c_str(), nullptr);
  return out;
}

// -1, 0, 1 as q * den <, =, > num (den > 0).
int compare(double q, const BigFloat& den, const BigFloat& num) {
  return static_cast<int>((BigFloat(q) * den - num).sign());
}

}  // namespace

std::optional<double> rational_to_double(std::string_view numerator, std::string_view denominator) {
  const std::optional<Integer> n = parse_integer(numerator);
  const std::optional<Integer> d = parse_integer(denominator);
  if (!n || !d || d->value.sign() == Sign::zero) return std::nullopt;
  // num / den with den > 0.
  const bool negative = n->negative != d->negative;
  const BigFloat num = negative ? BigFloat() - n->value : n->value;
  const BigFloat& den = d->value;
  if (num.sign() == Sign::zero) return 0.0;
  // Fast path: the rounded quotient of the rounded integers is within a few ulps of num / den.
  // Walk from it towards num / den; q * den - num is increasing in q, so two adjacent doubles
  // with opposite signs prove that num / den lies strictly between them.
  const double guess = (negative ? -1.0 : 1.0) * (std::fabs(n->approx) / std::fabs(d->approx));
  if (std::isfinite(guess)) {
    double q = guess;
    int c = compare(q, den, num);
    if (c == 0) return q;
    const double direction = c < 0 ? INFINITY : -INFINITY;
    for (int step = 0; step < 16; ++step) {
      const double next = std::nextafter(q, direction);
      if (!std::isfinite(next)) break;
      const int cn = compare(next, den, num);
      if (cn == 0) return next;
      if (cn != c) return std::nullopt;
      q = next;
    }
  }
  // General case: bisection on doubles, q * den against num (monotone in q, den > 0).
  std::int64_t lo = order_key(-DBL_MAX), hi = order_key(DBL_MAX);
  if (compare(from_key(lo), den, num) > 0 || compare(from_key(hi), den, num) < 0)
    return std::nullopt;
  while (key_distance(lo, hi) > 1) {
    const std::int64_t mid = middle_key(lo, hi);
    const int c = compare(from_key(mid), den, num);
    if (c == 0) return from_key(mid);
    (c < 0 ? lo : hi) = mid;
  }
  for (const std::int64_t k : {lo, hi}) {
    if (compare(from_key(k), den, num) == 0) return from_key(k);
  }
  return std::nullopt;
}

}  // namespace contain::predicates
