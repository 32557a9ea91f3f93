#pragma once
/// \file
/// Polynomials over GMP rationals for the oracles of the tests: exact division, Sturm counts,
/// root isolation by bisection on rationals, and the sign of another polynomial at a root by
/// refinement (gcd for a common root, else bisect until the other polynomial has no root left
/// in the interval). A different route from the library's Tarski queries on dyadic big numbers.

#include <gmpxx.h>

#include <vector>

#include "contain/predicates/sign.h"

namespace contain::test {

/// Lowest degree first, no zero leading coefficient (zero: empty).
using QPoly = std::vector<mpq_class>;

void trim(QPoly& p);
[[nodiscard]] int degree(const QPoly& p);
[[nodiscard]] QPoly operator+(const QPoly& a, const QPoly& b);
[[nodiscard]] QPoly operator-(const QPoly& a, const QPoly& b);
[[nodiscard]] QPoly operator*(const QPoly& a, const QPoly& b);
/// The straight path a0 + t (a1 - a0).
[[nodiscard]] QPoly qlinear(const mpq_class& a0, const mpq_class& a1);
[[nodiscard]] mpq_class evaluate(const QPoly& p, const mpq_class& x);
[[nodiscard]] Sign sign_at(const QPoly& p, const mpq_class& x);
[[nodiscard]] QPoly derivative(const QPoly& p);
/// The remainder of a divided by b (b not zero).
[[nodiscard]] QPoly remainder(const QPoly& a, const QPoly& b);
[[nodiscard]] QPoly quotient(const QPoly& a, const QPoly& b);
[[nodiscard]] QPoly gcd(QPoly a, QPoly b);
[[nodiscard]] QPoly squarefree(const QPoly& p);

/// A root: the rational `lo` when `exact`, else the one root of the squarefree `p` in (lo, hi).
struct QRoot {
  QPoly p;
  mpq_class lo, hi;
  bool exact = false;
};

/// Distinct roots of p (not zero) in [lo, hi], increasing.
[[nodiscard]] std::vector<QRoot> isolate_roots(const QPoly& p, const mpq_class& lo,
                                               const mpq_class& hi);
/// Sign of q at the root.
[[nodiscard]] Sign sign_at(const QPoly& q, QRoot root);
/// -1, 0, 1 as x <, =, > the root.
[[nodiscard]] int compare(const mpq_class& x, const QRoot& root);
/// The largest double <= the root (a root in [-DBL_MAX, DBL_MAX]).
[[nodiscard]] double floor_to_double(const QRoot& root);

}  // namespace contain::test
