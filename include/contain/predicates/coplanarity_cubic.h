#pragma once
/// \file
/// The coplanarity cubic of four points moving on straight lines, f(t) = orient3d(P_i(t),
/// P_j(t), P_k(t), P_l(t)) (`moving_points.h`), with certified floating-point answers: the
/// filtered half of the polynomial-sign facility for continuous collision (the exact half is
/// `polynomial.h`; a caller falls back to it when an answer here is empty).
///
/// Stages: (1) the four Bernstein coefficients of f on [0, 1] are sums of determinants of
/// differences of the input doubles (blossoming), computed with a static error bound like
/// `orient3d`'s; if they share a sign, f has no root in [0, 1]. (2) Roots in (0, 1) are isolated
/// by de Casteljau subdivision with running error bounds and Descartes' rule of signs in the
/// Bernstein basis (one sign change: exactly one simple root). (3) A root's bracket is narrowed
/// by Newton steps whose signs are certified. (4) Its rounding down to a double is decided on
/// the monomial coefficients in double-double arithmetic with running error bounds.
/// Bounds: docs/robustness.md ("Continuous collision").

#include <array>
#include <optional>

#include "contain/predicates/bounded.h"
#include "contain/predicates/moving_points.h"
#include "contain/predicates/sign.h"

namespace contain::predicates {

/// A root of the cubic strictly between the doubles lo < hi, the only root in [lo, hi], simple,
/// with f(lo) of sign `sign_lo` and f(hi) of the opposite sign (both certified non-zero).
struct RootBracket {
  double lo = 0.0;
  double hi = 1.0;
  Sign sign_lo = Sign::negative;
};

/// Up to three brackets in increasing order.
struct RootBrackets {
  std::array<RootBracket, 3> brackets{};
  int count = 0;
};

class CoplanarityCubic {
 public:
  /// f(t) = orient3d(P_p.i, P_p.j, P_p.k, P_p.l)(t); `p.kind` must be `orient3d`. Computes the
  /// Bernstein coefficients (~200 floating-point operations).
  CoplanarityCubic(const MovingPoints& points, MotionPolynomial p);

  /// The sign of f on all of [0, 1] when the Bernstein coefficients certify it (then f has no
  /// root in [0, 1]); nothing otherwise.
  [[nodiscard]] std::optional<Sign> sign_on_unit() const;

  /// The roots in the open interval (0, 1), given the exact signs of f at 0 and 1 (orient3d of
  /// the input points), in certified brackets; nothing when the filter cannot isolate them (a
  /// root within the error bounds of a subdivision point, a multiple root, coefficients too
  /// uncertain).
  [[nodiscard]] std::optional<RootBrackets> roots_in_open_unit(Sign at0, Sign at1) const;

  /// The bracket narrowed by certified Newton and bisection steps until it is at most `width`
  /// wide; with width 0, as far as the double-precision bounds allow (a few doubles, or two
  /// adjacent ones).
  [[nodiscard]] RootBracket narrow(RootBracket bracket, double width = 0.0) const;

  /// The largest double <= the root of the bracket: bisection on the doubles of the bracket, each
  /// sign decided in double-double arithmetic with running error bounds, or, where that does not
  /// decide (the root exactly a double, or within ~2^-100 relative of one), by the exact
  /// polynomial (`polynomial.h`). Always exact.
  [[nodiscard]] double floor(RootBracket bracket) const;

  /// f(t) at a double t in [0, 1], certified sign (double precision); nothing when uncertain.
  [[nodiscard]] std::optional<Sign> sign_at(double t) const;

 private:
  const MovingPoints& points_;
  MotionPolynomial p_;
  // Bernstein coefficients of 3 f: 3 D000, D100 + D010 + D001, D110 + D101 + D011, 3 D111.
  std::array<Bounded, 4> bernstein_{};
  double evaluation_error_ = 0.0;  // bound of `sign_at`'s evaluation, for every t in [0, 1]
};

}  // namespace contain::predicates
