#pragma once
// Private to predicates: the exact coefficient vectors behind `Polynomial` and `RealRoot`, and
// the operations on them (pseudo-remainders, Sturm sequences, squarefree parts), for the other
// exact stages of this layer (the motion predicates' fallbacks).

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "contain/predicates/big_float.h"
#include "contain/predicates/polynomial.h"

namespace contain::predicates {

namespace detail {

/// Lowest degree first, no zero leading coefficient (the zero polynomial is empty).
using Coeffs = std::vector<BigFloat>;

void trim(Coeffs& c);
[[nodiscard]] int degree_of(const Coeffs& c);
[[nodiscard]] Coeffs add(const Coeffs& a, const Coeffs& b);
[[nodiscard]] Coeffs negate(const Coeffs& a);
[[nodiscard]] Coeffs multiply(const Coeffs& a, const Coeffs& b);
[[nodiscard]] Coeffs derivative(const Coeffs& a);
[[nodiscard]] Sign sign_at(const Coeffs& c, const BigFloat& x);
/// c rem(a, b) for some c > 0 (b not zero).
[[nodiscard]] Coeffs positive_pseudo_remainder(const Coeffs& a, const Coeffs& b);
/// c a / g for some c != 0, g dividing a.
[[nodiscard]] Coeffs pseudo_quotient(const Coeffs& a, const Coeffs& g);
/// A greatest common divisor up to a constant factor.
[[nodiscard]] Coeffs gcd(Coeffs a, Coeffs b);
/// a / gcd(a, a') up to a constant factor.
[[nodiscard]] Coeffs squarefree(const Coeffs& a);
/// a / (t - x) for a root x.
[[nodiscard]] Coeffs deflate(const Coeffs& a, const BigFloat& x);
/// a, b, then minus the remainders, each a positive multiple of the signed remainder sequence's
/// element (subresultant PRS with exact divisions), up to the last non-zero one; a constant last
/// element is given as +-1 (its sign: all that sign variations and gcds need). deg a >= deg b.
[[nodiscard]] std::vector<Coeffs> signed_remainder_sequence(const Coeffs& a, const Coeffs& b);
/// P, P', then minus the remainders (positively scaled), up to the last non-zero one.
[[nodiscard]] std::vector<Coeffs> sturm_sequence(const Coeffs& p);
/// Sign changes of the sequence's values at x, zeros skipped.
[[nodiscard]] int variations(const std::vector<Coeffs>& seq, const BigFloat& x);
/// An upper bound of the degree of gcd(a, b) (a, b not zero) from gcds modulo two primes
/// (polynomial_modular.cpp): 0 proves that a and b have no common root.
[[nodiscard]] int gcd_degree_bound(const Coeffs& a, const Coeffs& b);

// Filters in long double with error bounds (polynomial_filter.cpp): an answer is exact, nothing
// means the bounds did not decide.
/// The roots of p in [lo, hi] as `real_roots` gives them, when Descartes' rule on certified
/// Bernstein coefficients isolates them all (simple roots, none at lo, hi or a subdivision point).
[[nodiscard]] std::optional<std::vector<RealRoot>> filtered_real_roots(const Coeffs& p, double lo,
                                                                       double hi);
/// The sign of q at the root, certified over a bracket of doubles narrowed around it; with
/// `refine` false, nothing once the bracket is two adjacent doubles (no exact zero test, no
/// refinement below double spacing).
[[nodiscard]] std::optional<Sign> filtered_sign_at(const Coeffs& q, const RealRoot& root,
                                                   bool refine = true);
/// The exact sign of p at the double t: the filter first, then Horner in big numbers.
[[nodiscard]] Sign sign_at_double(const Coeffs& p, double t);

}  // namespace detail

namespace detail {

/// What sign queries at a root learnt about it (polynomial_filter.cpp), so that the next query
/// at the same root starts where the last one stopped instead of narrowing its bracket anew:
/// continuous collision asks the signs of several inclusion polynomials at each root, and on
/// hostile inputs each narrowing costs tens of frames of big-number Taylor shifts.
struct LearntBracket {
  /// The order keys of two doubles strictly around the root (the root's own double bracket
  /// narrowed by bisection), within [lower(), upper()].
  std::int64_t below = 0, above = 0;
  /// The deepest refined frame, if any: t = origin + width u maps u in [0, 1] onto an interval
  /// holding the root (and no other root of p); `p` is p(origin + width u) times a positive
  /// power of two (exact), of sign `sign_at_0` at u = 0; the root lies strictly between the
  /// doubles of u with keys `u_below` and `u_above`.
  struct Frame {
    Coeffs p;
    BigFloat origin, width;
    Sign sign_at_0 = Sign::zero;
    std::int64_t u_below = 0, u_above = 0;
    int level = 0;  // frames moved from t: deeper frames resolve the root more finely
  };
  std::shared_ptr<const Frame> frame;
};

}  // namespace detail

/// The root's squarefree polynomial p and an interval (lo, hi) holding exactly one root of it,
/// lo and hi not roots (sign_lo = sign of p(lo)); or, `exact`, the root lo == hi itself. The
/// learnt bracket is a cache (the same root whatever it holds), written by const sign queries
/// that may run concurrently: read and written under the mutex only.
struct RealRoot::State {
  detail::Coeffs p;
  BigFloat lo, hi;
  Sign sign_lo = Sign::zero;
  bool exact = false;

  mutable std::mutex mutex;
  mutable std::optional<detail::LearntBracket> learnt;
  /// p's discriminant once a closed form at the root (degree 2) needed it.
  mutable std::shared_ptr<const BigFloat> discriminant;

  /// A copy of what was learnt (nothing at first).
  [[nodiscard]] std::optional<detail::LearntBracket> learnt_bracket() const {
    const std::lock_guard<std::mutex> lock(mutex);
    return learnt;
  }
};

/// Read access to a polynomial's exact coefficients.
class PolynomialAccess {
 public:
  [[nodiscard]] static const detail::Coeffs& coefficients(const Polynomial& p);
};

}  // namespace contain::predicates
