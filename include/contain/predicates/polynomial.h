#pragma once
/// \file
/// Exact univariate polynomials and their real roots: the exact half of the filtered
/// polynomial-sign facility (the filtered half for motions is `moving_points.h`).
///
/// A `Polynomial` has exact dyadic coefficients (big numbers: integers times powers of two), so
/// sums and products of polynomials built from doubles never round. On it: the exact sign at a
/// double, the isolation of its distinct real roots in an interval (Sturm sequences on the
/// squarefree part, bisection on doubles, then on dyadic numbers), the exact sign of another
/// polynomial at such a root (a Tarski query: sign variations of a signed remainder sequence, no
/// refinement) and the exact rounding of a root down to a double. Continuous collision (the
/// coplanarity cubic of moving points and the inclusion tests at its roots) is the first user;
/// anything that needs signs of polynomials at algebraic numbers can use it.
///
/// Cost: heap-allocated big numbers (figures: docs/benchmarks.md); meant as the exact fallback
/// behind floating-point filters. Thread safety: values;
/// const calls may run concurrently. Reference: S. Basu, R. Pollack, M.-F. Roy, "Algorithms in
/// Real Algebraic Geometry", 2nd ed., Springer 2006, sections 1.2 (signed remainder sequences),
/// 2.2.2 (Sturm, Sylvester's theorem on Tarski queries) and 8.3 (pseudo-remainders).

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "contain/predicates/sign.h"

namespace contain::predicates {

class BigFloat;

/// c0 + c1 t + c2 t^2 + ... with exact dyadic coefficients. The zero polynomial has degree -1.
class Polynomial {
 public:
  /// The zero polynomial.
  Polynomial();
  /// The polynomial with these (finite) double coefficients, lowest degree first.
  explicit Polynomial(std::span<const double> coefficients);
  /// The constant c (finite).
  [[nodiscard]] static Polynomial constant(double c);
  /// The straight path from `at0` (t = 0) to `at1` (t = 1): at0 + t (at1 - at0), exactly.
  [[nodiscard]] static Polynomial linear(double at0, double at1);

  Polynomial(const Polynomial&);
  Polynomial(Polynomial&&) noexcept;
  Polynomial& operator=(const Polynomial&);
  Polynomial& operator=(Polynomial&&) noexcept;
  ~Polynomial();

  /// -1 for the zero polynomial.
  [[nodiscard]] int degree() const;
  [[nodiscard]] bool is_zero() const { return degree() < 0; }
  /// The exact sign of coefficient k (zero beyond the degree).
  [[nodiscard]] Sign coefficient_sign(int k) const;

  /// The exact sign of the value at t (finite).
  [[nodiscard]] Sign sign_at(double t) const;

  [[nodiscard]] Polynomial derivative() const;

  friend Polynomial operator+(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator-(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator*(const Polynomial& a, const Polynomial& b);
  friend Polynomial operator-(const Polynomial& a);

 private:
  friend class PolynomialAccess;
  std::vector<BigFloat> c_;  // lowest degree first, no zero leading coefficient
};

/// One real root of a polynomial, isolated: `lower() <= root <= upper()` (doubles), equal when
/// the root is exactly that double. Internally it keeps the squarefree part of the polynomial
/// and an interval with exact dyadic ends holding this root and no other, so that signs of other
/// polynomials at it and its rounding are exact.
class RealRoot {
 public:
  /// A double below or equal to the root (the largest double below the interval kept).
  [[nodiscard]] double lower() const { return lower_; }
  /// A double above or equal to the root.
  [[nodiscard]] double upper() const { return upper_; }
  /// True when the root is the double `lower() == upper()`.
  [[nodiscard]] bool is_double() const { return exact_; }

  struct State;  // the polynomial and the exact interval (private to the implementation)
  explicit RealRoot(std::shared_ptr<const State> state, double lower, double upper, bool exact)
      : state_(std::move(state)), lower_(lower), upper_(upper), exact_(exact) {}
  [[nodiscard]] const State& state() const { return *state_; }

 private:
  std::shared_ptr<const State> state_;
  double lower_ = 0.0;
  double upper_ = 0.0;
  bool exact_ = false;
};

/// The distinct real roots of `p` in the closed interval [lo, hi] (finite doubles, lo <= hi), in
/// increasing order, each isolated from the others. Precondition: p is not the zero polynomial
/// (whose roots are every number). Multiple roots are reported once. O(d^2) big-number
/// operations per bisection step, O(log) steps per root (more for roots closer than a double
/// apart, which are separated on dyadic numbers).
[[nodiscard]] std::vector<RealRoot> real_roots(const Polynomial& p, double lo, double hi);

/// The root of p in (lo, hi), given that (lo, hi) holds exactly one root of p, that root simple
/// (p(lo) and p(hi) of opposite signs), as a certified filter brackets a root: the exact stage
/// can then decide signs at it without isolating p's other roots. Precondition (checked in debug
/// builds): lo < hi finite, p(lo) p(hi) < 0.
[[nodiscard]] RealRoot root_between(const Polynomial& p, double lo, double hi);

/// The same root described by the linear polynomial `linear` (degree 1), when it is that
/// polynomial's root (a rational): signs at it are then single evaluations, where the root's own
/// polynomial may need an exact zero test. Nothing when it is not (or `linear` is no line).
[[nodiscard]] std::optional<RealRoot> as_root_of_linear(const RealRoot& root,
                                                        const Polynomial& linear);

/// The exact sign of q at the root: q's value there is an algebraic number, decided by a Tarski
/// query (Sylvester's theorem: sign variations of the signed remainder sequence of the root's
/// squarefree polynomial P and P' q mod P at the interval's ends) without refining the root.
[[nodiscard]] Sign sign_at(const Polynomial& q, const RealRoot& root);

/// The largest double <= the root (the root itself when it is a double), found by bisection on
/// doubles with exact signs. Every root of a polynomial lies between -DBL_MAX and DBL_MAX when
/// it was isolated in a finite interval, so this is always a finite double.
[[nodiscard]] double floor_to_double(const RealRoot& root);

/// The smallest double >= the root.
[[nodiscard]] double ceil_to_double(const RealRoot& root);

}  // namespace contain::predicates
