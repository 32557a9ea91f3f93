#pragma once
/// \file
/// Polynomials over GMP rationals for the oracles of the tests: Sturm counts, root isolation
/// by bisection, and the sign of another polynomial at a root by refinement (gcd for a common
/// root, else bisect until the other polynomial has no root left in the interval). A different
/// route from the library's Tarski queries on dyadic big numbers.
///
/// Built in rationals, decided in integers: a polynomial is scaled by the lcm of its
/// denominators (a positive factor: same roots, same signs) and its sign at x = n/d is the sign
/// of the homogeneous d^deg p(n/d), so no evaluation canonicalises a rational with a gcd; gcds,
/// squarefree parts and Sturm sequences are primitive pseudo-remainder sequences (signs kept).

#include <gmpxx.h>

#include <vector>

#include "contain/predicates/sign.h"

namespace contain::test {

/// Lowest degree first, no zero leading coefficient (zero: empty).
using QPoly = std::vector<mpq_class>;
/// Integer coefficients, lowest degree first, no zero leading coefficient.
using ZPoly = std::vector<mpz_class>;

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
/// p times the positive number that makes its coefficients coprime integers, the leading one
/// positive: two polynomials are equal up to a nonzero factor when these are equal.
[[nodiscard]] ZPoly primitive_part(const QPoly& p);

/// A root: the rational `lo` when `exact`, else the one root of the squarefree `p` in (lo, hi).
struct QRoot {
  ZPoly p;
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
