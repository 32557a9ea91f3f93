#include "support/exact_polynomial.h"

#include <cassert>
#include <cmath>
#include <limits>

namespace contain::test {

void trim(QPoly& p) {
  while (!p.empty() && sgn(p.back()) == 0)
    p.pop_back();
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

Sign sign_at(const QPoly& p, const mpq_class& x) {
  const int s = sgn(evaluate(p, x));
  return s > 0 ? Sign::positive : (s < 0 ? Sign::negative : Sign::zero);
}

QPoly derivative(const QPoly& p) {
  if (p.size() <= 1) return {};
  QPoly r(p.size() - 1);
  for (std::size_t k = 1; k < p.size(); ++k)
    r[k - 1] = p[k] * static_cast<long>(k);
  trim(r);
  return r;
}

namespace {

void divide(const QPoly& a, const QPoly& b, QPoly& q, QPoly& r) {
  assert(!b.empty());
  r = a;
  q.assign(a.size() >= b.size() ? a.size() - b.size() + 1 : 0, mpq_class(0));
  while (!r.empty() && r.size() >= b.size()) {
    const std::size_t shift = r.size() - b.size();
    const mpq_class factor = r.back() / b.back();
    q[shift] = factor;
    for (std::size_t j = 0; j < b.size(); ++j)
      r[j + shift] -= factor * b[j];
    r.pop_back();
    trim(r);
  }
  trim(q);
}

std::vector<QPoly> sturm(const QPoly& p) {
  std::vector<QPoly> s{p, derivative(p)};
  while (!s.back().empty()) {
    QPoly r = remainder(s[s.size() - 2], s.back());
    for (mpq_class& c : r)
      c = -c;
    s.push_back(r);
  }
  s.pop_back();
  return s;
}

int variations(const std::vector<QPoly>& s, const mpq_class& x) {
  int count = 0, last = 0;
  for (const QPoly& p : s) {
    const int v = sgn(evaluate(p, x));
    if (v == 0) continue;
    if (last != 0 && v != last) ++count;
    last = v;
  }
  return count;
}

// Roots of the squarefree p in (a, b), neither a root.
void isolate(const QPoly& p, const mpq_class& a, const mpq_class& b, std::vector<QRoot>& out) {
  const std::vector<QPoly> s = sturm(p);
  const int count = variations(s, a) - variations(s, b);
  if (count == 0) return;
  if (count == 1) {
    out.push_back({p, a, b, false});
    return;
  }
  const mpq_class m = (a + b) / 2;
  if (sgn(evaluate(p, m)) == 0) {
    const QPoly q = quotient(p, qlinear(-m, 1 - m));  // p / (t - m)
    isolate(q, a, m, out);
    out.push_back({p, m, m, true});
    isolate(q, m, b, out);
    return;
  }
  isolate(p, a, m, out);
  isolate(p, m, b, out);
}

// Largest double <= x.
double floor_double(const mpq_class& x) {
  double d = x.get_d();  // rounds towards zero
  if (mpq_class(d) > x) d = std::nextafter(d, -std::numeric_limits<double>::infinity());
  return d;
}

}  // namespace

QPoly remainder(const QPoly& a, const QPoly& b) {
  QPoly q, r;
  divide(a, b, q, r);
  return r;
}

QPoly quotient(const QPoly& a, const QPoly& b) {
  QPoly q, r;
  divide(a, b, q, r);
  return q;
}

QPoly gcd(QPoly a, QPoly b) {
  while (!b.empty()) {
    QPoly r = remainder(a, b);
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}

QPoly squarefree(const QPoly& p) {
  if (degree(p) < 2) return p;
  const QPoly g = gcd(p, derivative(p));
  return degree(g) < 1 ? p : quotient(p, g);
}

std::vector<QRoot> isolate_roots(const QPoly& p, const mpq_class& lo, const mpq_class& hi) {
  std::vector<QRoot> out;
  QPoly q = squarefree(p);
  if (degree(q) < 1) return out;
  const bool root_lo = sgn(evaluate(q, lo)) == 0;
  const bool root_hi = lo != hi && sgn(evaluate(q, hi)) == 0;
  if (root_lo) {
    out.push_back({q, lo, lo, true});
    q = quotient(q, qlinear(-lo, 1 - lo));
  }
  if (root_hi) q = quotient(q, qlinear(-hi, 1 - hi));
  if (lo < hi && degree(q) >= 1) isolate(q, lo, hi, out);
  if (root_hi) out.push_back({q, hi, hi, true});
  return out;
}

Sign sign_at(const QPoly& q, QRoot root) {
  if (root.exact) return sign_at(q, root.lo);
  if (q.empty()) return Sign::zero;
  const QPoly g = gcd(root.p, q);
  if (degree(g) >= 1 && sgn(evaluate(g, root.lo)) * sgn(evaluate(g, root.hi)) < 0) {
    return Sign::zero;
  }
  // q has no root at the root: bisect until q has none in the interval either.
  const std::vector<QPoly> s = sturm(squarefree(q));
  const int s_lo = sgn(evaluate(root.p, root.lo));
  for (;;) {
    if (sgn(evaluate(q, root.lo)) != 0 && sgn(evaluate(q, root.hi)) != 0 &&
        variations(s, root.lo) == variations(s, root.hi)) {
      return sign_at(q, root.lo);
    }
    const mpq_class m = (root.lo + root.hi) / 2;
    const int sm = sgn(evaluate(root.p, m));
    if (sm == 0) return sign_at(q, m);
    (sm == s_lo ? root.lo : root.hi) = m;
  }
}

int compare(const mpq_class& x, const QRoot& root) {
  if (root.exact) return sgn(x - root.lo);
  if (x <= root.lo) return -1;
  if (x >= root.hi) return 1;
  const int sx = sgn(evaluate(root.p, x));
  if (sx == 0) return 0;
  return sx == sgn(evaluate(root.p, root.lo)) ? -1 : 1;
}

double floor_to_double(const QRoot& root) {
  if (root.exact) return floor_double(root.lo);
  QRoot r = root;
  const int s_lo = sgn(evaluate(r.p, r.lo));
  for (;;) {
    const double a = floor_double(r.lo);
    const double b = floor_double(r.hi);
    if (a == b) return a;  // a <= lo < root < hi < next(a)
    if (compare(mpq_class(b), r) == 0) return b;
    const mpq_class m = (r.lo + r.hi) / 2;
    const int sm = sgn(evaluate(r.p, m));
    if (sm == 0) return floor_double(m);
    (sm == s_lo ? r.lo : r.hi) = m;
  }
}

}  // namespace contain::test
