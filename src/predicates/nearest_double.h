#pragma once
// The double nearest to an exact value given as a quotient (or base + offset / D) of expressions
// in the input doubles, IEEE 754's rounding of a single operation (ties to even), in three
// stages: a priori bounds in long double (`Mag`), running error bounds (`ErrLD`), and exact
// big-number comparisons with the rounding boundaries. Shared by rounded_distance.cpp,
// rounded_crossing.cpp and rounded_volume.cpp; derivation in docs/robustness.md, "Distance".

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>

#include "contain/core/next_double.h"
#include "contain/predicates/big_float.h"
#include "contain/predicates/bounded.h"
#include "contain/predicates/unit_roundoff.h"

namespace contain::predicates::detail {

using LD = long double;
// The stages below rely on the x87 extended format: a rounding midpoint of doubles (54
// significant bits) is exact in LD, and products of up to six doubles neither overflow nor
// underflow in it (15-bit exponent), so `Mag` carries no absolute error term. A long double
// with a wider significand and exponent (IEEE binary128) keeps both properties.
static_assert(std::numeric_limits<LD>::digits >= 64 &&
                  std::numeric_limits<LD>::max_exponent >= 16384 &&
                  std::numeric_limits<LD>::min_exponent <= -16381,
              "nearest_double.h needs long double to be the 64-bit x87 extended format (or wider)");
using ErrLD = BasicBounded<LD>;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr LD kU = unit_roundoff<LD>;

// Rounding boundaries of a candidate c: the midpoints to its neighbours. Beyond +-DBL_MAX the
// boundary is DBL_MAX + 2^970 (half an ulp of DBL_MAX), where IEEE 754 starts rounding to
// infinity. Each midpoint has at most 54 significant bits, so it is exact in long double
// (64-bit significand) and in BigFloat.
// The neighbours of a candidate, inline (contain/core/next_double.h).
using contain::next_down;
using contain::next_up;
constexpr double kHalfUlpOfMax = 0x1p970;

// The midpoint between c and its neighbour above (c < +inf).
inline LD upper_mid(double c) {
  if (c == DBL_MAX) return static_cast<LD>(DBL_MAX) + static_cast<LD>(kHalfUlpOfMax);
  if (c == -kInf) return -(static_cast<LD>(DBL_MAX) + static_cast<LD>(kHalfUlpOfMax));
  return (static_cast<LD>(c) + static_cast<LD>(next_up(c))) / 2;
}
inline LD lower_mid(double c) {
  return -upper_mid(-c);
}
inline BigFloat upper_mid_big(double c) {
  if (c == DBL_MAX) return BigFloat(DBL_MAX) + BigFloat(kHalfUlpOfMax);
  if (c == -kInf) return BigFloat() - (BigFloat(DBL_MAX) + BigFloat(kHalfUlpOfMax));
  return (BigFloat(c) + BigFloat(next_up(c))).scaled(-1);
}
inline BigFloat lower_mid_big(double c) {
  return BigFloat() - upper_mid_big(-c);
}

// Of two neighbouring doubles (or DBL_MAX and infinity), the one with an even significand.
inline double even_of(double x, double y) {
  return (std::bit_cast<std::uint64_t>(x) & 1U) == 0 ? x : y;
}

// ---- quotients X / D, D > 0 ------------------------------------------------------------------

// |X - x| for x = n / d as computed (d - e_d > 0): at most (e_n + |n / d| e_d) / (d - e_d) +
// u |x|, with |n / d| <= |x| (1 + u); the factor (1 + 16u) covers the roundings of the bound
// itself.
inline LD quotient_error(const ErrLD& n, const ErrLD& d, LD x) {
  return ((n.error + std::fabs(x) * (1 + kU) * d.error) / (d.value - d.error) + kU * std::fabs(x)) *
         (1 + 16 * kU);
}

// The double nearest to a value within `bound` of x, when both midpoints to the neighbours of
// c = (double) x are farther than that (the factor covers the rounding of the difference).
inline bool certify_nearest(LD x, LD bound, double& out) {
  if (!std::isfinite(x) || !std::isfinite(bound)) return false;
  const double c = static_cast<double>(x);
  if (c != -kInf && !((x - lower_mid(c)) > bound * (1 + 4 * kU))) return false;
  if (c != kInf && !((upper_mid(c) - x) > bound * (1 + 4 * kU))) return false;
  out = c;
  return true;
}

// Both values and their bounds finite: the long double stages decide nothing otherwise.
inline bool all_finite(const ErrLD& n, const ErrLD& d) {
  return std::isfinite(n.value) && std::isfinite(n.error) && std::isfinite(d.value) &&
         std::isfinite(d.error);
}

inline bool quotient_stage_a(const ErrLD& n, const ErrLD& d, double& out) {
  if (!all_finite(n, d)) return false;
  if (n.value == 0 && n.error == 0) {
    out = 0.0;
    return true;
  }
  if (!(d.value - d.error > 0)) return false;
  const LD x = n.value / d.value;
  return certify_nearest(x, quotient_error(n, d, x), out);
}

inline double quotient_stage_b(const BigFloat& n, const BigFloat& d) {
  if (n.sign() == Sign::zero) return 0.0;
  std::int64_t en = 0;
  std::int64_t ed = 0;
  const double fn = n.frexp(en);
  const double fd = d.frexp(ed);
  double c = std::ldexp(fn / fd, static_cast<int>(std::clamp<std::int64_t>(en - ed, -2200, 2200)));
  for (int step = 0; step < 64; ++step) {
    if (c != -kInf) {
      const Sign s = (n - lower_mid_big(c) * d).sign();
      if (s == Sign::negative) {
        c = c == kInf ? DBL_MAX : next_down(c);
        continue;
      }
      if (s == Sign::zero) return even_of(c == -DBL_MAX ? -kInf : next_down(c), c);
    }
    if (c != kInf) {
      const Sign s = (n - upper_mid_big(c) * d).sign();
      if (s == Sign::positive) {
        c = c == -kInf ? -DBL_MAX : next_up(c);
        continue;
      }
      if (s == Sign::zero) return even_of(c, c == DBL_MAX ? kInf : next_up(c));
    }
    return c;
  }
  return c;
}

// ---- stage 0: values with a priori bounds ----------------------------------------------------

// A long double value with the magnitude of its expression and its rounding depth, for a bound
// computed once at the end instead of carried through each operation (ErrLD): about a third of
// the work, and enough for all but the answers within a few units of 2^-64 of a rounding
// boundary, which go on to the running-error stage and then the exact one.
//
// The analysis (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., 3.1 and 3.3):
// an expression of sums, differences and products evaluated in floating point, k roundings deep
// at most, is within gamma_k = k u / (1 - k u) of its exact value times the exact expression of
// the absolute values of its monomials, M. A difference (or sum) of two input doubles is
// (a - b)(1 + d): it counts as a leaf of magnitude |a - b| with one rounding, so a point far from
// the origin does not inflate M by its coordinates. m is M computed in long double, at least
// M (1 - u)^k, so the error is at most gamma_k (1 - u)^-k m <= (k + 0.01) u m for k <= 16, and
// m (2k + 1) u, rounded once, covers it. Products of doubles cannot overflow or underflow in
// long double (15-bit exponent) at the degrees used here (at most 6), so there is no absolute
// error term; on a platform whose long double is double the values can: `bounded` then gives an
// infinite or NaN bound, which the stages refuse.
struct Mag {
  LD v = 0;
  LD m = 0;
  int k = 0;          // rounding depth
  bool leaf = false;  // an input double, exact

  Mag() = default;
  explicit Mag(double x) : v(x), m(std::fabs(static_cast<LD>(x))), k(0), leaf(true) {}
  Mag(LD value, LD magnitude, int depth) : v(value), m(magnitude), k(depth) {}

  friend Mag operator+(const Mag& a, const Mag& b) {
    const LD r = a.v + b.v;
    if (a.leaf && b.leaf) return {r, std::fabs(r), 1};
    return {r, a.m + b.m, std::max(a.k, b.k) + 1};
  }
  friend Mag operator-(const Mag& a, const Mag& b) {
    const LD r = a.v - b.v;
    if (a.leaf && b.leaf) return {r, std::fabs(r), 1};
    return {r, a.m + b.m, std::max(a.k, b.k) + 1};
  }
  friend Mag operator*(const Mag& a, const Mag& b) {
    return {a.v * b.v, a.m * b.m, std::max(a.k, b.k) + 1};
  }
};

inline ErrLD bounded(const Mag& x) {
  if (x.k == 0) return {x.v, 0};  // an input double
  if (x.k > 16) return {x.v, std::numeric_limits<LD>::infinity()};
  return {x.v, x.m * (static_cast<LD>(2 * x.k + 1) * kU)};
}

// Stage A for base + sign * OFF / D (D > 0, base and sign exact): y = off / d within
// ey of OFF / D (the bound of quotient_stage_a), x = base + sign y rounded once more (u |x|);
// the factor (1 + 4u) covers the roundings of the bound. An offset exactly 0 leaves base.
inline bool offset_stage_a(double base, double sign, const ErrLD& off, const ErrLD& d,
                           double& out) {
  if (!std::isfinite(off.value) || !std::isfinite(off.error) || !std::isfinite(d.value) ||
      !std::isfinite(d.error)) {
    return false;
  }
  if (off.value == 0 && off.error == 0) {
    out = base;
    return true;
  }
  if (!(d.value - d.error > 0)) return false;
  const LD y = off.value / d.value;
  const LD x = static_cast<LD>(base) + static_cast<LD>(sign) * y;
  return certify_nearest(x, (quotient_error(off, d, y) + kU * std::fabs(x)) * (1 + 4 * kU), out);
}

}  // namespace contain::predicates::detail
