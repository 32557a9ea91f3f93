// Floating-point filters in front of the exact root isolation and Tarski queries of
// polynomial.cpp, in long double with running error bounds (`BasicBounded<long double>`).
//
// Why: polynomials built from doubles of mixed magnitudes (1e300 next to 1e-300, as hostile
// continuous-collision queries give) have big-number coefficients of thousands of bits, and the
// subresultant sequences of the exact stage multiply them into hundreds of thousands: a second
// a query. Yet such signs are rarely close calls: the coefficients rounded to 53 bits, kept in
// long double's 15-bit exponent range (where no double's product of degree <= 8 overflows), and
// evaluated with a proven bound over an interval decide them in microseconds. Whatever the
// bounds leave open goes to the exact stage unchanged, so the answers stay exact.
//
// - Isolation: Descartes' rule of signs in the Bernstein basis on [lo, hi], de Casteljau
//   subdivision at dyadic midpoints with certified signs there (Basu, Pollack, Roy, "Algorithms
//   in Real Algebraic Geometry", 2nd ed., 10.2). One sign variation and opposite certified end
//   signs: exactly one root, simple, in the open interval.
// - Signs at a root: the polynomial over the root's bracket of doubles (interval Horner), the
//   bracket halved on the doubles (its signs certified the same way, exactly where not) until the
//   sign is certified or the bracket is two adjacent doubles.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>

#include "contain/predicates/bounded.h"
#include "contain/predicates/unit_roundoff.h"
#include "predicates/double_order.h"
#include "predicates/polynomial_state.h"

namespace contain::predicates::detail {

namespace {

using Wide = BasicBounded<long double>;
using WideCoeffs = std::vector<Wide>;

// Exponents beyond which a coefficient is left to the exact stage (long double's range is
// 2^+-16382; the margin keeps products with the interval's points finite).
constexpr std::int64_t kMaxExponent = 12000;
constexpr int kMaxDegree = 12;
constexpr int kMaxDepth = 64;

// c's coefficients within their bounds: BigFloat::frexp is within 2^-52 of the value relative
// (2^-50 taken), scaled by a power of two exactly. Nothing when an exponent is out of range.
std::optional<WideCoeffs> to_wide(const Coeffs& c) {
  WideCoeffs out;
  out.reserve(c.size());
  for (const BigFloat& x : c) {
    std::int64_t e = 0;
    const double m = x.frexp(e);
    if (m == 0.0) {
      out.emplace_back();
      continue;
    }
    if (e > kMaxExponent || e < -kMaxExponent) return std::nullopt;
    const long double v = std::ldexp(static_cast<long double>(m), static_cast<int>(e));
    out.emplace_back(v, std::fabs(v) * 0x1p-50L);
  }
  return out;
}

// A value whose bound covers p(t) for every t in [a, b] (doubles, a <= b): Horner on the
// interval as a bounded value (midpoint, radius rounded up).
Wide over(const WideCoeffs& p, double a, double b) {
  if (p.empty()) return {};
  const long double la = a, lb = b;
  const long double m = la + (lb - la) / 2;  // in [a, b]: rounding is monotone
  const long double r = std::max(lb - m, m - la) * (1 + 4 * unit_roundoff<long double>);
  const Wide t{m, r};
  Wide acc = p.back();
  for (std::size_t k = p.size() - 1; k-- > 0;)
    acc = acc * t + p[k];
  return acc;
}

std::optional<Sign> certified(const Wide& v) {
  if (!v.decided()) return std::nullopt;
  return v.sign();
}

// The exact sign of p at the double t: the filter, then Horner in big numbers.
Sign sign_at_double(const Coeffs& p, const WideCoeffs& pw, double t) {
  if (const std::optional<Sign> s = certified(over(pw, t, t))) return *s;
  return sign_at(p, BigFloat(t));
}

// ---- isolation -------------------------------------------------------------------------------

// g(s) = p(lo + (hi - lo) s), then its Bernstein coefficients on [0, 1] times a positive
// integer constant (the lcm of the binomials C(n, k)): b_k C(n, k) = sum_{i <= k} C(n - i, k - i)
// g_i, integers times bounded values.
WideCoeffs scaled_bernstein(const WideCoeffs& p, double lo, double hi) {
  const int n = static_cast<int>(p.size()) - 1;
  const Wide base(lo), step = Wide(hi) - Wide(lo);
  WideCoeffs g{p.back()};
  for (int k = n - 1; k >= 0; --k) {
    WideCoeffs next(g.size() + 1);
    for (std::size_t i = 0; i < g.size(); ++i) {
      next[i] = next[i] + g[i] * base;
      next[i + 1] = next[i + 1] + g[i] * step;
    }
    next[0] = next[0] + p[static_cast<std::size_t>(k)];
    g = std::move(next);
  }
  std::vector<std::vector<std::int64_t>> c(static_cast<std::size_t>(n + 1));
  for (int r = 0; r <= n; ++r) {
    c[static_cast<std::size_t>(r)].assign(static_cast<std::size_t>(r + 1), 1);
    for (int k = 1; k < r; ++k) {
      c[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)] =
          c[static_cast<std::size_t>(r - 1)][static_cast<std::size_t>(k - 1)] +
          c[static_cast<std::size_t>(r - 1)][static_cast<std::size_t>(k)];
    }
  }
  const auto choose = [&](int r, int k) {
    return c[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)];
  };
  std::int64_t lcm = 1;
  for (int k = 0; k <= n; ++k)
    lcm = std::lcm(lcm, choose(n, k));
  WideCoeffs b(static_cast<std::size_t>(n + 1));
  for (int k = 0; k <= n; ++k) {
    Wide sum;
    for (int i = 0; i <= k; ++i) {
      sum = sum + Wide(static_cast<double>(choose(n - i, k - i))) * g[static_cast<std::size_t>(i)];
    }
    b[static_cast<std::size_t>(k)] = sum * Wide(static_cast<double>(lcm / choose(n, k)));
  }
  return b;
}

// The most sign variations the sequence can have when some signs are unknown (an unknown may
// be negative, zero or positive; zeros are skipped): dynamic programming over the last nonzero
// sign chosen.
int max_variations(const std::vector<std::optional<Sign>>& signs) {
  constexpr int kNone = -1000;
  int neg = kNone, pos = kNone, all_zero = 0;
  for (const std::optional<Sign>& s : signs) {
    const bool may_neg = !s || *s == Sign::negative, may_pos = !s || *s == Sign::positive;
    const bool may_zero = !s || *s == Sign::zero;
    int next_neg = may_zero ? neg : kNone, next_pos = may_zero ? pos : kNone;
    if (may_neg) next_neg = std::max({next_neg, all_zero, neg, pos + 1});
    if (may_pos) next_pos = std::max({next_pos, all_zero, pos, neg + 1});
    all_zero = may_zero ? all_zero : kNone;
    neg = next_neg;
    pos = next_pos;
  }
  return std::max({neg, pos, all_zero, 0});
}

struct Isolation {
  const Coeffs& p;
  std::vector<RealRoot>& out;
};

// Roots of the polynomial with scaled Bernstein coefficients b on [a, b_end] (doubles), whose
// end signs are certified; false when the bounds do not certify an isolation.
bool isolate(const WideCoeffs& b, double a, double b_end, Sign s_a, Sign s_b, int depth,
             Isolation& iso) {
  std::vector<std::optional<Sign>> signs;
  signs.reserve(b.size());
  signs.push_back(s_a);
  for (std::size_t k = 1; k + 1 < b.size(); ++k)
    signs.push_back(certified(b[k]));
  signs.push_back(s_b);
  const int var = max_variations(signs);
  if (var == 0) return true;
  if (var == 1 && s_a != Sign::zero && s_b == -s_a) {
    auto state = std::make_shared<RealRoot::State>();
    state->p = iso.p;
    state->lo = BigFloat(a);
    state->hi = BigFloat(b_end);
    state->sign_lo = s_a;
    iso.out.emplace_back(std::move(state), a, b_end, false);
    return true;
  }
  if (depth >= kMaxDepth) return false;
  // The midpoint must be a double strictly inside (the dyadic midpoint of doubles is one unless
  // the ends are adjacent or far apart in exponent and precision).
  const double mid = a + 0.5 * (b_end - a);
  if (!(mid > a && mid < b_end) || BigFloat(mid) + BigFloat(mid) != BigFloat(a) + BigFloat(b_end)) {
    return false;
  }
  // de Casteljau at 1/2: the left half's coefficients are the first of each level, the right
  // half's the last (in reverse).
  const std::size_t n = b.size() - 1;
  WideCoeffs level = b, left(n + 1), right(n + 1);
  const Wide half(0.5);
  left[0] = level[0];
  right[n] = level[n];
  for (std::size_t r = 1; r <= n; ++r) {
    for (std::size_t k = 0; k + r <= n; ++k)
      level[k] = (level[k] + level[k + 1]) * half;
    left[r] = level[0];
    right[n - r] = level[n - r];
  }
  const std::optional<Sign> s_mid = certified(left[n]);
  if (!s_mid || *s_mid == Sign::zero) return false;
  return isolate(left, a, mid, s_a, *s_mid, depth + 1, iso) &&
         isolate(right, mid, b_end, *s_mid, s_b, depth + 1, iso);
}

// ---- signs at roots beyond double precision -----------------------------------------------

BigFloat magnitude(const BigFloat& x) {
  return x.sign() == Sign::negative ? -x : x;
}

BigFloat value_at(const Coeffs& q, const BigFloat& t) {
  BigFloat value = q.back();
  for (std::size_t k = q.size() - 1; k-- > 0;)
    value = value * t + q[k];
  return value;
}

// Max |q'| over [-m, m] and above: sum k |q_k| m^(k-1), exactly.
BigFloat derivative_bound(const Coeffs& q, const BigFloat& m) {
  BigFloat sum, power(1.0);
  for (std::size_t k = 1; k < q.size(); ++k) {
    sum = sum + BigFloat(static_cast<double>(k)) * magnitude(q[k]) * power;
    power = power * m;
  }
  return sum;
}

constexpr int kRefineSteps = 2048;

// The sign of q at the root when q keeps one sign on a bracket of the root: the root's interval
// (within the doubles a <= b) halved on dyadic numbers with exact signs of p, and q's exact
// values at the ends with a bound on its variation (|q(t) - q(lo)| <= max |q'| (hi - lo)).
// Signs that are not close calls at double precision are decided within ~64 more halvings;
// nothing when q (nearly) vanishes at the root: the caller's Tarski query answers.
std::optional<Sign> sign_on_refined(const Coeffs& q, const RealRoot::State& s, double a, double b) {
  BigFloat lo = std::max(s.lo, BigFloat(a)), hi = std::min(s.hi, BigFloat(b));
  Sign sign_lo = s.sign_lo;
  if (lo != s.lo) {
    sign_lo = sign_at(s.p, lo);
    if (sign_lo == Sign::zero) return sign_at(q, lo);
  }
  for (int step = 0; step < kRefineSteps; ++step) {
    if (step % 16 == 0) {
      const BigFloat ql = value_at(q, lo), qh = value_at(q, hi);
      if (ql.sign() != Sign::zero && qh.sign() == ql.sign()) {
        const BigFloat m = std::max(magnitude(lo), magnitude(hi));
        if (magnitude(ql) > derivative_bound(q, m) * (hi - lo)) return ql.sign();
      }
    }
    const BigFloat mid = (lo + hi).scaled(-1);
    const Sign sm = sign_at(s.p, mid);
    if (sm == Sign::zero) return sign_at(q, mid);
    (sm == sign_lo ? lo : hi) = mid;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<RealRoot>> filtered_real_roots(const Coeffs& p, double lo, double hi) {
  const int n = degree_of(p);
  if (!(lo < hi) || n < 1 || n > kMaxDegree) return std::nullopt;
  const std::optional<WideCoeffs> pw = to_wide(p);
  if (!pw) return std::nullopt;
  const Sign s_lo = sign_at_double(p, *pw, lo), s_hi = sign_at_double(p, *pw, hi);
  if (s_lo == Sign::zero || s_hi == Sign::zero) return std::nullopt;
  std::vector<RealRoot> out;
  Isolation iso{p, out};
  if (!isolate(scaled_bernstein(*pw, lo, hi), lo, hi, s_lo, s_hi, 0, iso)) return std::nullopt;
  return out;
}

std::optional<Sign> filtered_sign_at(const Coeffs& q, const RealRoot& root) {
  const RealRoot::State& s = root.state();
  if (q.empty()) return Sign::zero;
  const std::optional<WideCoeffs> qw = to_wide(q), pw = to_wide(s.p);
  if (!qw || !pw) return std::nullopt;
  std::int64_t a = order_key(root.lower()), b = order_key(root.upper());
  for (;;) {
    if (const std::optional<Sign> v = certified(over(*qw, from_key(a), from_key(b)))) return *v;
    if (key_distance(a, b) < 2) break;
    const std::int64_t mk = middle_key(a, b);
    const double m = from_key(mk);
    const BigFloat bm(m);
    bool below = false;  // m < the root
    if ((bm - s.lo).sign() != Sign::positive) {
      below = true;
    } else if ((bm - s.hi).sign() != Sign::negative) {
      below = false;
    } else {
      const Sign sm = sign_at_double(s.p, *pw, m);
      if (sm == Sign::zero) return sign_at(q, bm);  // the root is m
      below = sm == s.sign_lo;
    }
    (below ? a : b) = mk;
  }
  return sign_on_refined(q, s, from_key(a), from_key(b));
}

Sign sign_at_double(const Coeffs& p, double t) {
  const std::optional<WideCoeffs> pw = to_wide(p);
  if (pw) return sign_at_double(p, *pw, t);
  return sign_at(p, BigFloat(t));
}

}  // namespace contain::predicates::detail
