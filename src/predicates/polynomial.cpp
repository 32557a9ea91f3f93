#include "contain/predicates/polynomial.h"

#include <cassert>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>

#include "contain/predicates/big_float.h"
#include "predicates/double_order.h"
#include "predicates/polynomial_state.h"

namespace contain::predicates {

using detail::Coeffs;
using predicates::BigFloat;

// ---- coefficient vectors --------------------------------------------------------------------

namespace detail {

namespace {

BigFloat negated(const BigFloat& x) {
  return BigFloat() - x;
}

}  // namespace

void trim(Coeffs& c) {
  while (!c.empty() && c.back().sign() == Sign::zero)
    c.pop_back();
}

int degree_of(const Coeffs& c) {
  return static_cast<int>(c.size()) - 1;
}

Coeffs add(const Coeffs& a, const Coeffs& b) {
  Coeffs r(std::max(a.size(), b.size()));
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i < a.size() && i < b.size()) {
      r[i] = a[i] + b[i];
    } else {
      r[i] = i < a.size() ? a[i] : b[i];
    }
  }
  trim(r);
  return r;
}

Coeffs negate(const Coeffs& a) {
  Coeffs r(a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    r[i] = negated(a[i]);
  return r;
}

Coeffs multiply(const Coeffs& a, const Coeffs& b) {
  if (a.empty() || b.empty()) return {};
  Coeffs r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j)
      r[i + j] = r[i + j] + a[i] * b[j];
  }
  trim(r);
  return r;
}

Coeffs derivative(const Coeffs& a) {
  if (a.size() <= 1) return {};
  Coeffs r(a.size() - 1);
  for (std::size_t k = 1; k < a.size(); ++k)
    r[k - 1] = a[k] * BigFloat(static_cast<double>(k));
  trim(r);
  return r;
}

Sign sign_at(const Coeffs& c, const BigFloat& x) {
  if (c.empty()) return Sign::zero;
  BigFloat acc = c.back();
  for (std::size_t k = c.size() - 1; k-- > 0;)
    acc = acc * x + c[k];
  return acc.sign();
}

namespace {

// The pseudo-remainder lc(b)^(m - n + 1) a - q b (m, n the degrees of a and b).
Coeffs pseudo_remainder(const Coeffs& a, const Coeffs& b) {
  assert(!b.empty());
  const int n = degree_of(b);
  const int m = degree_of(a);
  if (m < n) return a;
  const BigFloat lc = b.back();
  Coeffs r = a;
  for (int k = m; k >= n; --k) {
    // Coefficient k becomes lc rk - rk lc = 0: dropped without its two products.
    const BigFloat rk = std::move(r.back());
    r.pop_back();
    for (BigFloat& x : r)
      x = lc * x;
    for (int j = 0; j < n; ++j) {
      const auto i = static_cast<std::size_t>(j + k - n);
      r[i] = r[i] - rk * b[static_cast<std::size_t>(j)];
    }
  }
  trim(r);
  return r;
}

int sign_int(const BigFloat& x) {
  return static_cast<int>(x.sign());
}

BigFloat power(const BigFloat& x, int e) {
  BigFloat r(1.0);
  for (int k = 0; k < e; ++k)
    r = r * x;
  return r;
}

}  // namespace

// c * rem(a, b) with c > 0: the pseudo-remainder, negated when lc(b)^(m - n + 1) is negative,
// so that signed remainder sequences keep their sign variations.
Coeffs positive_pseudo_remainder(const Coeffs& a, const Coeffs& b) {
  Coeffs r = pseudo_remainder(a, b);
  const int m = degree_of(a), n = degree_of(b);
  if (m >= n && b.back().sign() == Sign::negative && (m - n + 1) % 2 == 1) r = negate(r);
  return r;
}

// Collins' subresultant PRS: T_0 = a, T_1 = b, T_{k+1} = prem(T_{k-1}, T_k) / (g h^d) with
// g = lc(T_{k-1}) and h = g^d / h^(d-1) from the step before (g = h = 1 at first); every division
// is exact (Knuth, TAOCP vol. 2, 4.6.1, Algorithm C; Brown 1971), so coefficient sizes grow
// linearly instead of exponentially. T_k = c_k sRem_k for the signed remainder sequence
// sRem_{k+1} = -rem(sRem_{k-1}, sRem_k); from rem(T_{k-1}, T_k) = -c_{k-1} sRem_{k+1},
// c_{k+1} = -lc(T_k)^(d+1) c_{k-1} / (g h^d), whose sign is tracked and divided out, so every
// element returned is a positive multiple of sRem_k. Precondition: deg a >= deg b.
std::vector<Coeffs> signed_remainder_sequence(const Coeffs& a, const Coeffs& b) {
  std::vector<Coeffs> out{a};
  if (b.empty()) return out;
  out.push_back(b);
  Coeffs prev = a, cur = b;
  int c_prev = 1, c_cur = 1;
  BigFloat g(1.0), h(1.0);
  for (;;) {
    const int d = degree_of(prev) - degree_of(cur);
    assert(d >= 0);
    Coeffs r = pseudo_remainder(prev, cur);
    if (r.empty()) break;
    const int lc_sign = sign_int(cur.back());
    const int divisor_sign = sign_int(g) * (d % 2 == 1 ? sign_int(h) : 1);  // of g h^d
    const int c_next = -((d + 1) % 2 == 0 ? 1 : lc_sign) * c_prev * divisor_sign;
    if (r.size() == 1) {
      // A constant ends the sequence, and its users (sign variations, gcds up to a constant
      // factor) need its sign only: r / (g h^d) times c_next's sign, without the division by a
      // number of thousands of bits or the step that would find the next remainder zero.
      const int last = sign_int(r[0]) * divisor_sign * c_next;
      out.push_back({BigFloat(last > 0 ? 1.0 : -1.0)});
      break;
    }
    const BigFloat divisor = g * power(h, d);
    for (BigFloat& x : r)
      x = exact_quotient(x, divisor);
    g = cur.back();
    h = d == 0 ? h : (d == 1 ? g : exact_quotient(power(g, d), power(h, d - 1)));
    prev = std::move(cur);
    cur = std::move(r);
    c_prev = c_cur;
    c_cur = c_next;
    out.push_back(c_cur > 0 ? cur : negate(cur));
  }
  return out;
}

// q with lc(g)^(m - n + 1) a = q g, for g dividing a exactly.
Coeffs pseudo_quotient(const Coeffs& a, const Coeffs& g) {
  const int n = degree_of(g);
  const int m = degree_of(a);
  assert(m >= n && n >= 0);
  const BigFloat lc = g.back();
  Coeffs r = a;
  Coeffs q(static_cast<std::size_t>(m - n + 1));
  for (int k = m; k >= n; --k) {
    const BigFloat rk = r[static_cast<std::size_t>(k)];
    for (BigFloat& x : q)
      x = lc * x;
    q[static_cast<std::size_t>(k - n)] = q[static_cast<std::size_t>(k - n)] + rk;
    r.pop_back();  // coefficient k becomes lc rk - rk lc = 0
    for (BigFloat& x : r)
      x = lc * x;
    for (int j = 0; j < n; ++j) {
      const auto i = static_cast<std::size_t>(j + k - n);
      r[i] = r[i] - rk * g[static_cast<std::size_t>(j)];
    }
  }
  trim(q);
  return q;
}

Coeffs gcd(Coeffs a, Coeffs b) {
  if (degree_of(a) < degree_of(b)) std::swap(a, b);
  if (b.empty()) return a;
  return signed_remainder_sequence(a, b).back();
}

// The squarefree part a / gcd(a, a') up to a constant factor: the same distinct roots, all simple.
Coeffs squarefree(const Coeffs& a) {
  if (degree_of(a) < 2) return a;
  const Coeffs da = derivative(a);
  // No common root modulo two primes proves a squarefree (gcd_degree_bound): that spares the
  // exact gcd, a remainder sequence on numbers of thousands of bits for hostile CCD queries.
  if (gcd_degree_bound(a, da) == 0) return a;
  const Coeffs g = gcd(a, da);
  if (degree_of(g) < 1) return a;
  return pseudo_quotient(a, g);
}

// a / (t - x) for a root x of a (synthetic division, exact).
Coeffs deflate(const Coeffs& a, const BigFloat& x) {
  assert(a.size() >= 2);
  Coeffs q(a.size() - 1);
  q.back() = a.back();
  for (std::size_t k = q.size() - 1; k-- > 0;)
    q[k] = a[k + 1] + x * q[k + 1];
  return q;
}

std::vector<Coeffs> sturm_sequence(const Coeffs& p) {
  return signed_remainder_sequence(p, derivative(p));
}

// Sign variations of a sequence of polynomials at x (zeros skipped).
int variations(const std::vector<Coeffs>& seq, const BigFloat& x) {
  int count = 0;
  Sign last = Sign::zero;
  for (const Coeffs& c : seq) {
    const Sign s = sign_at(c, x);
    if (s == Sign::zero) continue;
    if (last != Sign::zero && s != last) ++count;
    last = s;
  }
  return count;
}

}  // namespace detail

// ---- Polynomial ----------------------------------------------------------------------------

Polynomial::Polynomial() = default;
Polynomial::Polynomial(const Polynomial&) = default;
Polynomial::Polynomial(Polynomial&&) noexcept = default;
Polynomial& Polynomial::operator=(const Polynomial&) = default;
Polynomial& Polynomial::operator=(Polynomial&&) noexcept = default;
Polynomial::~Polynomial() = default;

Polynomial::Polynomial(std::span<const double> coefficients) {
  c_.reserve(coefficients.size());
  for (const double c : coefficients)
    c_.emplace_back(c);
  detail::trim(c_);
}

Polynomial Polynomial::constant(double c) {
  return Polynomial(std::span<const double>(&c, 1));
}

Polynomial Polynomial::linear(double at0, double at1) {
  Polynomial p;
  p.c_ = {BigFloat(at0), BigFloat(at1) - BigFloat(at0)};
  detail::trim(p.c_);
  return p;
}

int Polynomial::degree() const {
  return detail::degree_of(c_);
}

Sign Polynomial::coefficient_sign(int k) const {
  if (k < 0 || k > degree()) return Sign::zero;
  return c_[static_cast<std::size_t>(k)].sign();
}

Sign Polynomial::sign_at(double t) const {
  return detail::sign_at_double(c_, t);  // the long double filter, then Horner in big numbers
}

Polynomial Polynomial::derivative() const {
  Polynomial r;
  r.c_ = detail::derivative(c_);
  return r;
}

Polynomial operator+(const Polynomial& a, const Polynomial& b) {
  Polynomial r;
  r.c_ = detail::add(a.c_, b.c_);
  return r;
}

Polynomial operator-(const Polynomial& a) {
  Polynomial r;
  r.c_ = detail::negate(a.c_);
  return r;
}

Polynomial operator-(const Polynomial& a, const Polynomial& b) {
  Polynomial r;
  r.c_ = detail::add(a.c_, detail::negate(b.c_));
  return r;
}

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  Polynomial r;
  r.c_ = detail::multiply(a.c_, b.c_);
  return r;
}

const detail::Coeffs& PolynomialAccess::coefficients(const Polynomial& p) {
  return p.c_;
}

// ---- roots ---------------------------------------------------------------------------------

namespace {

using detail::from_key;
using detail::key_distance;
using detail::middle_key;
using detail::order_key;

// An end of an isolating interval: an exact dyadic number and the doubles around it (equal
// when it is a double). Bisection runs on doubles while a double lies strictly between the ends
// and on dyadic numbers after that, so a dyadic end always lies strictly between two adjacent
// doubles `below` and `above`, shared by both ends of its interval.
struct End {
  BigFloat x;
  double below = 0.0;
  double above = 0.0;
};

End double_end(double d) {
  return {BigFloat(d), d, d};
}

End middle(const End& a, const End& b) {
  if (a.below == a.above && b.below == b.above &&
      key_distance(order_key(a.below), order_key(b.below)) >= 2) {
    return double_end(from_key(middle_key(order_key(a.below), order_key(b.below))));
  }
  return {(a.x + b.x) * BigFloat(0.5), a.below, b.above};
}

// The discriminant c1^2 - 4 c0 c2 of a quadratic.
BigFloat discriminant(const detail::Coeffs& c) {
  return c[1] * c[1] - (c[0] * c[2]).scaled(2);
}

// Steps of the division below, each ~50 bits (10,000 bits: roots of quadratics with coefficients
// of a few thousand bits are at least ~2^-(their length) apart, relative).
constexpr int kQuotientSteps = 200;

// A dyadic number strictly between the two real roots of the squarefree quadratic c (positive
// discriminant): -c1 / (2 c2), the roots' midpoint, to ~50 more bits a step (long division by
// the rounded divisor, the remainder kept exact) until c's sign there is -sign(c2), which proves
// it between the roots. Roots this close (a vertex grazing a face: a near-double root) would take
// one Sturm bisection step per bit of their distance. Nothing when the steps run out.
std::optional<BigFloat> between_quadratic_roots(const detail::Coeffs& c) {
  const BigFloat num = BigFloat() - c[1], den = c[2].scaled(1);
  std::int64_t den_exp = 0;
  const double den_m = den.frexp(den_exp);
  BigFloat q;
  for (int step = 0; step < kQuotientSteps; ++step) {
    const BigFloat rest = num - den * q;
    if (!rest.is_zero()) {
      std::int64_t e = 0;
      const double m = rest.frexp(e);
      q = q + BigFloat(m / den_m).scaled(e - den_exp);
    }
    if (detail::sign_at(c, q) == -c[2].sign()) return q;
    if (rest.is_zero()) return std::nullopt;  // unreachable for a positive discriminant
  }
  return std::nullopt;
}

class Isolator {
 public:
  Isolator(detail::Coeffs p, std::vector<RealRoot>& out)
      : p_(std::move(p)), sturm_(detail::sturm_sequence(p_)), out_(out) {}

  [[nodiscard]] int variations(const BigFloat& x) const { return detail::variations(sturm_, x); }

  // Appends the roots in (a, b) in increasing order: va - vb of them (Sturm), a and b not roots.
  void isolate(const End& a, const End& b, int va, int vb) {
    const int count = va - vb;
    if (count <= 0) return;
    if (count == 1) {
      emit(a, b);
      return;
    }
    // A split point that is not a root: the middle, or, while that is a root, points halfway
    // towards a (p has finitely many roots, so this ends); for the two roots of a quadratic, a
    // point between them.
    End m = middle(a, b);
    if (detail::degree_of(p_) == 2) {
      if (const std::optional<BigFloat> x = between_quadratic_roots(p_)) {
        if (a.x < *x && *x < b.x) m = {*x, a.below, b.above};
      }
    }
    while (detail::sign_at(p_, m.x) == Sign::zero)
      m = middle(a, m);
    const int vm = variations(m.x);
    isolate(a, m, va, vm);
    isolate(m, b, vm, vb);
  }

 private:
  void emit(const End& a, const End& b) {
    auto s = std::make_shared<RealRoot::State>();
    s->p = p_;
    s->lo = a.x;
    s->hi = b.x;
    s->sign_lo = detail::sign_at(p_, a.x);
    out_.emplace_back(std::move(s), a.below, b.above, false);
  }

  detail::Coeffs p_;
  std::vector<detail::Coeffs> sturm_;
  std::vector<RealRoot>& out_;
};

RealRoot exact_root(const detail::Coeffs& p, double x) {
  auto s = std::make_shared<RealRoot::State>();
  s->p = p;
  s->lo = BigFloat(x);
  s->hi = s->lo;
  s->sign_lo = Sign::zero;
  s->exact = true;
  return RealRoot(std::move(s), x, x, true);
}

}  // namespace

std::vector<RealRoot> real_roots(const Polynomial& p, double lo, double hi) {
  assert(!p.is_zero() && lo <= hi);
  const detail::Coeffs& c = PolynomialAccess::coefficients(p);
  // A quadratic: no real root for a negative discriminant; roots nearer each other than 2^-64
  // relative (a small discriminant next to c1^2) go to the exact isolation, whose split between
  // them takes a few steps, while the filter would descend frame after frame to its cap.
  bool close_pair = false;
  if (detail::degree_of(c) == 2) {
    const BigFloat d = discriminant(c);
    if (d.sign() == Sign::negative) return {};
    std::int64_t ed = 0, e1 = 0;
    const bool tiny = d.frexp(ed) != 0.0 && c[1].frexp(e1) != 0.0 && ed < 2 * e1 - 128;
    close_pair = tiny || d.is_zero();  // a double root: the filter cannot separate it
  }
  if (!close_pair) {
    if (std::optional<std::vector<RealRoot>> fast = detail::filtered_real_roots(c, lo, hi)) {
      return std::move(*fast);
    }
  }
  std::vector<RealRoot> out;
  detail::Coeffs sq = detail::squarefree(PolynomialAccess::coefficients(p));
  if (detail::degree_of(sq) < 1) return out;
  const BigFloat blo(lo), bhi(hi);
  const bool root_lo = detail::sign_at(sq, blo) == Sign::zero;
  const bool root_hi = lo != hi && detail::sign_at(sq, bhi) == Sign::zero;
  if (root_lo) {
    out.push_back(exact_root(sq, lo));
    sq = detail::deflate(sq, blo);
  }
  if (root_hi) sq = detail::deflate(sq, bhi);
  if (lo < hi && detail::degree_of(sq) >= 1) {
    Isolator iso(std::move(sq), out);
    iso.isolate(double_end(lo), double_end(hi), iso.variations(blo), iso.variations(bhi));
  }
  if (root_hi) out.push_back(exact_root(PolynomialAccess::coefficients(p), hi));
  return out;
}

RealRoot root_between(const Polynomial& p, double lo, double hi) {
  auto s = std::make_shared<RealRoot::State>();
  s->p = PolynomialAccess::coefficients(p);
  s->lo = BigFloat(lo);
  s->hi = BigFloat(hi);
  s->sign_lo = detail::sign_at(s->p, s->lo);
  assert(lo < hi && s->sign_lo != Sign::zero && detail::sign_at(s->p, s->hi) == -s->sign_lo);
  return RealRoot(std::move(s), lo, hi, false);
}

namespace {

// The discriminant of the root's quadratic, computed once per root (the closed form below may
// run for each of the rule's polynomials at it); the cache is shared by the root's copies.
std::shared_ptr<const BigFloat> discriminant_of(const RealRoot::State& s) {
  {
    const std::lock_guard<std::mutex> lock(s.mutex);
    if (s.discriminant) return s.discriminant;
  }
  auto d = std::make_shared<const BigFloat>(discriminant(s.p));
  const std::lock_guard<std::mutex> lock(s.mutex);
  if (!s.discriminant) s.discriminant = std::move(d);
  return s.discriminant;
}

// The sign of u^2 - w^2 d (u, w nonzero, d > 0) from the rounded values (BigFloat::frexp, each
// within 2^-52 relative: the ratio u^2 / (w^2 d) within 2^-48 of its rounding) when the ratio is
// not within 2^-40 of 1: the products of numbers of thousands of bits that the closed form would
// take (hostile coplanar CCD queries ask tens of them) are then spared. Nothing otherwise.
std::optional<Sign> square_minus_product_sign(const BigFloat& u, const BigFloat& w,
                                              const BigFloat& d) {
  std::int64_t eu = 0, ew = 0, ed = 0;
  const long double mu = u.frexp(eu), mw = w.frexp(ew), md = d.frexp(ed);
  if (mu == 0 || mw == 0 || md <= 0) return std::nullopt;
  // u^2 / (w^2 d) = (mu^2 / (mw^2 md)) 2^e, the mantissa ratio in (1/4, 8).
  const std::int64_t e = 2 * eu - 2 * ew - ed;
  if (e >= 4) return Sign::positive;
  if (e <= -4) return Sign::negative;
  const long double ratio = std::ldexp(mu * mu / (mw * mw * md), static_cast<int>(e));
  if (ratio > 1 + 0x1p-40L) return Sign::positive;
  if (ratio < 1 - 0x1p-40L) return Sign::negative;
  return std::nullopt;
}

// The sign of q at the root in (lo, hi) of the squarefree quadratic p = c + b t + a t^2, in
// closed form: the root is x = (-b + s sqrt(D)) / (2a) with s = sign p'(x) (p rises through it
// where p(lo) < 0) and D = b^2 - 4ac > 0; with r = r0 + r1 t a positive multiple of q mod p,
// 2a r(x) = U + W sqrt(D), U = 2a r0 - b r1, W = s r1, whose sign is that of U and W where they
// agree, else sign(U) sign(U^2 - W^2 D). A few products, where refining the root costs a frame
// per 53 bits of it (two roots of a grazing contact can be 2^-1000 apart).
Sign quadratic_sign_at(const detail::Coeffs& q, const RealRoot::State& s) {
  const detail::Coeffs& p = s.p;
  const detail::Coeffs r = detail::positive_pseudo_remainder(q, p);
  if (r.size() <= 1) return r.empty() ? Sign::zero : r[0].sign();
  const BigFloat two_a = p[2].scaled(1);
  const BigFloat u = two_a * r[0] - p[1] * r[1];
  const BigFloat w = s.sign_lo == Sign::negative ? r[1] : BigFloat() - r[1];
  Sign sum;
  if (u.sign() == Sign::zero || u.sign() == w.sign()) {
    sum = w.sign();
  } else if (w.sign() == Sign::zero) {
    sum = u.sign();
  } else {
    const std::shared_ptr<const BigFloat> kept = discriminant_of(s);
    const BigFloat& d = *kept;
    const std::optional<Sign> rounded = square_minus_product_sign(u, w, d);
    const Sign diff = rounded ? *rounded : (u * u - w * w * d).sign();
    sum = u.sign() == Sign::positive ? diff : -diff;
  }
  return p[2].sign() == Sign::positive ? sum : -sum;
}

}  // namespace

std::optional<RealRoot> as_root_of_linear(const RealRoot& root, const Polynomial& linear) {
  const RealRoot::State& s = root.state();
  const detail::Coeffs& l = PolynomialAccess::coefficients(linear);
  if (s.exact || detail::degree_of(l) != 1) return std::nullopt;
  // The line's root x lies in (lo, hi) where l changes sign there (lo and hi are not its root:
  // l has one), and it is this root when p(x) = 0 (p has no other root in (lo, hi)).
  const Sign at_lo = detail::sign_at(l, s.lo);
  if (at_lo == Sign::zero || detail::sign_at(l, s.hi) != -at_lo) return std::nullopt;
  if (!detail::positive_pseudo_remainder(s.p, l).empty()) return std::nullopt;
  auto state = std::make_shared<RealRoot::State>();
  state->p = l;
  state->lo = s.lo;
  state->hi = s.hi;
  state->sign_lo = at_lo;
  return RealRoot(std::move(state), root.lower(), root.upper(), false);
}

Sign sign_at(const Polynomial& q, const RealRoot& root) {
  const RealRoot::State& s = root.state();
  if (s.exact) return detail::sign_at(PolynomialAccess::coefficients(q), s.lo);
  if (detail::degree_of(s.p) <= 2) {
    // Closed forms, which cost products of big numbers: the filter on doubles first. At the
    // root of a line, q's value is a positive multiple of q mod p, a constant.
    const detail::Coeffs& c = PolynomialAccess::coefficients(q);
    if (const std::optional<Sign> fast = detail::filtered_sign_at(c, root, false)) return *fast;
    if (detail::degree_of(s.p) == 2) return quadratic_sign_at(c, s);
    const detail::Coeffs r = detail::positive_pseudo_remainder(c, s.p);
    return r.empty() ? Sign::zero : r[0].sign();
  }
  if (const std::optional<Sign> fast =
          detail::filtered_sign_at(PolynomialAccess::coefficients(q), root)) {
    return *fast;
  }
  // Sylvester: sum over the roots x of P in (lo, hi) of sign q(x) = Var(SRemS(P, P' q); lo, hi),
  // and P' q may be replaced by its remainder modulo P (the Cauchy index of P' q / P does not
  // change) scaled by a positive constant. One root lies in (lo, hi): its sign is the sum.
  const detail::Coeffs& p = s.p;
  // q is reduced modulo P first (its value at the root is the remainder's, up to the positive
  // factor), so that P' q stays of degree < 2 deg P before the second reduction.
  const detail::Coeffs reduced =
      detail::positive_pseudo_remainder(PolynomialAccess::coefficients(q), p);
  const std::vector<detail::Coeffs> seq = detail::signed_remainder_sequence(
      p, detail::positive_pseudo_remainder(detail::multiply(detail::derivative(p), reduced), p));
  const int taq = detail::variations(seq, s.lo) - detail::variations(seq, s.hi);
  assert(taq >= -1 && taq <= 1);
  return taq > 0 ? Sign::positive : (taq < 0 ? Sign::negative : Sign::zero);
}

namespace {

// Bisection on doubles between root.lower() and root.upper(): returns the adjacent pair
// (below, above) around the root, or the root twice when it is a double.
std::pair<double, double> bracket_by_doubles(const RealRoot& root) {
  const RealRoot::State& s = root.state();
  if (s.exact) return {root.lower(), root.lower()};
  // From the narrowest double bracket that sign queries at the root learnt, if any.
  const std::optional<detail::LearntBracket> learnt = s.learnt_bracket();
  std::int64_t a = learnt ? learnt->below : order_key(root.lower());
  std::int64_t b = learnt ? learnt->above : order_key(root.upper());
  while (key_distance(a, b) >= 2) {
    const std::int64_t mk = middle_key(a, b);
    const double m = from_key(mk);
    const BigFloat bm(m);
    bool below;  // m < root
    if ((bm - s.lo).sign() != Sign::positive) {
      below = true;
    } else if ((bm - s.hi).sign() != Sign::negative) {
      below = false;
    } else {
      const Sign sm = detail::sign_at_double(s.p, m);
      if (sm == Sign::zero) return {m, m};
      below = sm == s.sign_lo;
    }
    (below ? a : b) = mk;
  }
  return {from_key(a), from_key(b)};
}

}  // namespace

double floor_to_double(const RealRoot& root) {
  return bracket_by_doubles(root).first;
}

double ceil_to_double(const RealRoot& root) {
  return bracket_by_doubles(root).second;
}

}  // namespace contain::predicates
