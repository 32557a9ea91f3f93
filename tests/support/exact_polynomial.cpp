#include "support/exact_polynomial.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>

namespace contain::test {
namespace {

// For both kinds of coefficients (rationals to build, integers to decide).
template <class Poly>
void trim_zeros(Poly& p) {
  while (!p.empty() && sgn(p.back()) == 0)
    p.pop_back();
}

template <class Poly>
Poly derivative_of(const Poly& p) {
  if (p.size() <= 1) return {};
  Poly r(p.size() - 1);
  for (std::size_t k = 1; k < p.size(); ++k)
    r[k - 1] = p[k] * static_cast<unsigned long>(k);
  trim_zeros(r);
  return r;
}

}  // namespace

void trim(QPoly& p) {
  trim_zeros(p);
}

int degree(const QPoly& p) {
  return static_cast<int>(p.size()) - 1;
}

QPoly operator+(const QPoly& a, const QPoly& b) {
  QPoly r(std::max(a.size(), b.size()));
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i < a.size()) r[i] += a[i];
    if (i < b.size()) r[i] += b[i];
  }
  trim(r);
  return r;
}

QPoly operator-(const QPoly& a, const QPoly& b) {
  QPoly r(std::max(a.size(), b.size()));
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i < a.size()) r[i] += a[i];
    if (i < b.size()) r[i] -= b[i];
  }
  trim(r);
  return r;
}

QPoly operator*(const QPoly& a, const QPoly& b) {
  if (a.empty() || b.empty()) return {};
  QPoly r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j)
      r[i + j] += a[i] * b[j];
  }
  trim(r);
  return r;
}

QPoly qlinear(const mpq_class& a0, const mpq_class& a1) {
  QPoly r{a0, a1 - a0};
  trim(r);
  return r;
}

mpq_class evaluate(const QPoly& p, const mpq_class& x) {
  mpq_class acc = 0;
  for (std::size_t k = p.size(); k-- > 0;)
    acc = acc * x + p[k];
  return acc;
}

QPoly derivative(const QPoly& p) {
  return derivative_of(p);
}

namespace {

int zdegree(const ZPoly& p) {
  return static_cast<int>(p.size()) - 1;
}

// p times the lcm of its denominators.
ZPoly integral(const QPoly& p) {
  mpz_class l = 1;
  for (const mpq_class& c : p)
    mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  ZPoly z(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    mpz_divexact(z[i].get_mpz_t(), l.get_mpz_t(), p[i].get_den_mpz_t());
    z[i] *= p[i].get_num();
  }
  return z;
}

// Divided by the gcd of its coefficients (positive: signs kept).
void make_primitive(ZPoly& p) {
  mpz_class g = 0;
  for (const mpz_class& c : p)
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
  if (g <= 1) return;
  for (mpz_class& c : p)
    mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
}

// Sign of p at x = n / d (d > 0): that of d^deg p(n / d) = sum p_k n^k d^(deg - k), by Horner
// in integers; a power of two d (every point of a bisection from dyadic ends) is a shift.
int zsign(const ZPoly& p, const mpq_class& x) {
  if (p.empty()) return 0;
  const mpz_class& n = x.get_num();
  const mpz_class& d = x.get_den();
  const bool dyadic = mpz_popcount(d.get_mpz_t()) == 1;
  const mp_bitcnt_t e = mpz_sizeinbase(d.get_mpz_t(), 2) - 1;
  mpz_class acc = p.back(), term, power = d;
  for (std::size_t k = p.size() - 1, j = 1; k-- > 0; ++j) {
    acc *= n;
    if (dyadic) {
      mpz_mul_2exp(term.get_mpz_t(), p[k].get_mpz_t(), e * j);
    } else {
      term = p[k] * power;
      power *= d;
    }
    acc += term;
  }
  return sgn(acc);
}

Sign to_sign(int s) {
  return s > 0 ? Sign::positive : (s < 0 ? Sign::negative : Sign::zero);
}

// lc(b)^steps a = quotient b + remainder, deg remainder < deg b (b not zero); returns steps.
int pseudo_divide(ZPoly a, const ZPoly& b, ZPoly* quotient, ZPoly& remainder) {
  assert(!b.empty());
  int steps = 0;
  if (quotient) quotient->assign(a.size() >= b.size() ? a.size() - b.size() + 1 : 0, 0);
  while (!a.empty() && a.size() >= b.size()) {
    const std::size_t shift = a.size() - b.size();
    const mpz_class lead = a.back();
    for (mpz_class& c : a)
      c *= b.back();
    for (std::size_t j = 0; j < b.size(); ++j)
      a[j + shift] -= lead * b[j];
    a.pop_back();
    trim_zeros(a);
    if (quotient) {
      for (mpz_class& c : *quotient)
        c *= b.back();
      (*quotient)[shift] = lead;
    }
    ++steps;
  }
  remainder = std::move(a);
  return steps;
}

// The gcd up to a nonzero factor: a primitive remainder sequence.
ZPoly zgcd(ZPoly a, ZPoly b) {
  while (!b.empty()) {
    ZPoly r;
    pseudo_divide(a, b, nullptr, r);
    make_primitive(r);
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}

// a / b for b dividing a, up to a nonzero factor.
ZPoly exact_quotient(const ZPoly& a, const ZPoly& b) {
  ZPoly q, r;
  pseudo_divide(a, b, &q, r);
  assert(r.empty());
  make_primitive(q);
  return q;
}

ZPoly zsquarefree(const ZPoly& p) {
  if (zdegree(p) < 2) return p;
  const ZPoly g = zgcd(p, derivative_of(p));
  return zdegree(g) < 1 ? p : exact_quotient(p, g);
}

// p / (t - x) for a root x = n / d of p, up to a nonzero factor.
ZPoly without_root(const ZPoly& p, const mpq_class& x) {
  return exact_quotient(p, ZPoly{-x.get_num(), x.get_den()});
}

// The Sturm sequence up to positive factors: rem(a, b) is the pseudo-remainder over
// lc(b)^steps, so its negation is the pseudo-remainder times -sign(lc(b))^steps.
std::vector<ZPoly> sturm(const ZPoly& p) {
  std::vector<ZPoly> s{p, derivative_of(p)};
  while (!s.back().empty()) {
    ZPoly r;
    const int steps = pseudo_divide(s[s.size() - 2], s.back(), nullptr, r);
    make_primitive(r);
    if (sgn(s.back().back()) > 0 || steps % 2 == 0) {
      for (mpz_class& c : r)
        c = -c;
    }
    s.push_back(std::move(r));
  }
  s.pop_back();
  return s;
}

int variations(const std::vector<ZPoly>& s, const mpq_class& x) {
  int count = 0, last = 0;
  for (const ZPoly& p : s) {
    const int v = zsign(p, x);
    if (v == 0) continue;
    if (last != 0 && v != last) ++count;
    last = v;
  }
  return count;
}

// Roots of the squarefree p in (a, b), neither a root; va, vb the Sturm variations there.
void isolate(const ZPoly& p, const std::vector<ZPoly>& s, const mpq_class& a, const mpq_class& b,
             int va, int vb, std::vector<QRoot>& out) {
  const int count = va - vb;
  if (count == 0) return;
  if (count == 1) {
    out.push_back({p, a, b, false});
    return;
  }
  const mpq_class m = (a + b) / 2;
  if (zsign(p, m) == 0) {
    const ZPoly q = without_root(p, m);
    const std::vector<ZPoly> sq = sturm(q);
    const int vm = variations(sq, m);
    isolate(q, sq, a, m, variations(sq, a), vm, out);
    out.push_back({p, m, m, true});
    isolate(q, sq, m, b, vm, variations(sq, b), out);
    return;
  }
  const int vm = variations(s, m);
  isolate(p, s, a, m, va, vm, out);
  isolate(p, s, m, b, vm, vb, out);
}

// Largest double <= x.
double floor_double(const mpq_class& x) {
  double d = x.get_d();  // rounds towards zero
  if (mpq_class(d) > x) d = std::nextafter(d, -std::numeric_limits<double>::infinity());
  return d;
}

// Doubles in increasing order as integers (-0 as +0).
std::int64_t order_key(double d) {
  const auto bits = std::bit_cast<std::int64_t>(d);
  return bits >= 0 ? bits : -(bits & std::numeric_limits<std::int64_t>::max());
}

double from_order_key(std::int64_t k) {
  return k >= 0 ? std::bit_cast<double>(k) : -std::bit_cast<double>(-k);
}

}  // namespace

Sign sign_at(const QPoly& p, const mpq_class& x) {
  return to_sign(zsign(integral(p), x));
}

ZPoly primitive_part(const QPoly& p) {
  ZPoly z = integral(p);
  make_primitive(z);
  if (!z.empty() && sgn(z.back()) < 0) {
    for (mpz_class& c : z)
      c = -c;
  }
  return z;
}

std::vector<QRoot> isolate_roots(const QPoly& p, const mpq_class& lo, const mpq_class& hi) {
  std::vector<QRoot> out;
  ZPoly q = integral(p);
  make_primitive(q);
  q = zsquarefree(q);
  if (zdegree(q) < 1) return out;
  const bool root_lo = zsign(q, lo) == 0;
  const bool root_hi = lo != hi && zsign(q, hi) == 0;
  if (root_lo) {
    out.push_back({q, lo, lo, true});
    q = without_root(q, lo);
  }
  if (root_hi) q = without_root(q, hi);
  if (lo < hi && zdegree(q) >= 1) {
    const std::vector<ZPoly> s = sturm(q);
    isolate(q, s, lo, hi, variations(s, lo), variations(s, hi), out);
  }
  if (root_hi) out.push_back({q, hi, hi, true});
  return out;
}

Sign sign_at(const QPoly& q, QRoot root) {
  if (root.exact) return sign_at(q, root.lo);
  if (q.empty()) return Sign::zero;
  ZPoly zq = integral(q);
  make_primitive(zq);
  const ZPoly g = zgcd(root.p, zq);
  if (zdegree(g) >= 1 && zsign(g, root.lo) * zsign(g, root.hi) < 0) return Sign::zero;
  // q has no root at the root: bisect until q has none in the interval either. The check (a
  // Sturm count at both ends) costs several evaluations, a bisection step one: check after 1,
  // 2, 4, ... 64 steps, not after each.
  const std::vector<ZPoly> s = sturm(zsquarefree(zq));
  const int s_lo = zsign(root.p, root.lo);
  for (int steps = 1;; steps = std::min(2 * steps, 64)) {
    const int q_lo = zsign(zq, root.lo);
    if (q_lo != 0 && zsign(zq, root.hi) != 0 && variations(s, root.lo) == variations(s, root.hi)) {
      return to_sign(q_lo);
    }
    for (int i = 0; i < steps; ++i) {
      const mpq_class m = (root.lo + root.hi) / 2;
      const int sm = zsign(root.p, m);
      if (sm == 0) return to_sign(zsign(zq, m));
      (sm == s_lo ? root.lo : root.hi) = m;
    }
  }
}

int compare(const mpq_class& x, const QRoot& root) {
  if (root.exact) return sgn(x - root.lo);
  if (x <= root.lo) return -1;
  if (x >= root.hi) return 1;
  const int sx = zsign(root.p, x);
  if (sx == 0) return 0;
  return sx == zsign(root.p, root.lo) ? -1 : 1;
}

double floor_to_double(const QRoot& root) {
  if (root.exact) return floor_double(root.lo);
  // Binary search on the doubles in order: below <= the root < above, at most 64 steps.
  std::int64_t below = order_key(floor_double(root.lo));
  std::int64_t above = order_key(std::nextafter(floor_double(root.hi), INFINITY));
  // The keys span up to 2^64 (a negative end and a positive one): the midpoint in unsigned.
  for (;;) {
    const std::uint64_t span =
        static_cast<std::uint64_t>(above) - static_cast<std::uint64_t>(below);
    if (span <= 1) break;
    const auto mid = static_cast<std::int64_t>(static_cast<std::uint64_t>(below) + span / 2);
    (compare(mpq_class(from_order_key(mid)), root) <= 0 ? below : above) = mid;
  }
  return from_order_key(below);
}

}  // namespace contain::test
