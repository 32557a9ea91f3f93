#pragma once
// Floating-point expansion arithmetic: exact sums and products of doubles represented as
// unevaluated sums of non-overlapping doubles, after J. R. Shewchuk, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", Discrete & Computational
// Geometry 18 (1997) 305-363 (Two-Sum, Two-Product, Fast-Expansion-Sum, Scale-Expansion,
// all with zero elimination).
//
// Exactness needs IEEE 754 binary64 with round-to-nearest-even, no overflow, and no
// underflow inside a product. The callers guarantee the last two with an exponent range check
// of their inputs (see `in_expansion_range` below and docs/robustness.md, "Regimes"); the
// predicates library is compiled with -ffp-contract=off so that no a*b+c is fused behind the
// algorithms' back.
//
// `Expansion<N>` holds at most N components in increasing order of magnitude, none zero, so
// the empty expansion is 0 and the sign is the sign of the last component. The capacity of a
// result is known at compile time (sum: N+M, product: 2NM), so a polynomial is written as an
// ordinary expression and needs no heap.

#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>

#include "contain/predicates/sign.h"

namespace contain::predicates::detail {

// --- error-free transformations on two doubles --------------------------------------------

/// x + y = a + b exactly, with x = fl(a + b). Needs |a| >= |b| (or a == 0).
inline void fast_two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  y = b - (x - a);
}

/// x + y = a + b exactly, with x = fl(a + b) (Knuth's branch-free Two-Sum).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double b_virtual = x - a;
  const double a_virtual = x - b_virtual;
  y = (a - a_virtual) + (b - b_virtual);
}

/// x + y = a - b exactly, with x = fl(a - b).
inline void two_diff(double a, double b, double& x, double& y) {
  x = a - b;
  const double b_virtual = a - x;
  const double a_virtual = x + b_virtual;
  y = (a - a_virtual) + (b_virtual - b);
}

/// Dekker's split: a = hi + lo with hi and lo of at most 26 significant bits each.
/// Needs |a| < 2^996 so that the scaled value does not overflow.
inline void split(double a, double& hi, double& lo) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double c = kSplitter * a;
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

/// x + y = a * b exactly, with x = fl(a * b). Needs no overflow and ulp(a) * ulp(b) >= 2^-1074
/// (the tail must be representable). Uses a hardware FMA when the target has one, Dekker's
/// product otherwise (a libm fma emulated in software would be far slower than Dekker).
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
#if defined(__FMA__) || defined(__FP_FAST_FMA)
  y = std::fma(a, b, -x);
#else
  double a_hi, a_lo, b_hi, b_lo;
  split(a, a_hi, a_lo);
  split(b, b_hi, b_lo);
  const double err1 = x - a_hi * b_hi;
  const double err2 = err1 - a_lo * b_hi;
  const double err3 = err2 - a_hi * b_lo;
  y = a_lo * b_lo - err3;
#endif
}

/// two_product with b already split into b_hi + b_lo (Scale-Expansion multiplies many
/// components by the same b).
inline void two_product_presplit(double a, double b, double b_hi, double b_lo, double& x,
                                 double& y) {
  x = a * b;
#if defined(__FMA__) || defined(__FP_FAST_FMA)
  (void)b_hi;
  (void)b_lo;
  y = std::fma(a, b, -x);
#else
  double a_hi, a_lo;
  split(a, a_hi, a_lo);
  const double err1 = x - a_hi * b_hi;
  const double err2 = err1 - a_lo * b_hi;
  const double err3 = err2 - a_hi * b_lo;
  y = a_lo * b_lo - err3;
#endif
}

/// x2 + x1 + x0 = (a1 + a0) - b exactly, a nonoverlapping expansion (x0 smallest; zeros kept).
inline void two_one_diff(double a1, double a0, double b, double& x2, double& x1, double& x0) {
  double i;
  two_diff(a0, b, i, x0);
  two_sum(a1, i, x2, x1);
}

/// x3 + x2 + x1 + x0 = (a1 + a0) - (b1 + b0) exactly (Shewchuk's Two-Two-Diff), branch-free.
inline void two_two_diff(double a1, double a0, double b1, double b0, double& x3, double& x2,
                         double& x1, double& x0) {
  double j;
  double zero;
  two_one_diff(a1, a0, b0, j, zero, x0);
  two_one_diff(j, zero, b1, x3, x2, x1);
}

/// The sign of a nonoverlapping expansion whose zeros were not eliminated: the sign of its
/// largest nonzero component. `c` is ordered smallest first.
template <std::size_t K>
[[nodiscard]] inline Sign sign_of_largest(const std::array<double, K>& c) {
  for (std::size_t i = K; i-- > 0;) {
    if (c[i] != 0.0) return sign_of(c[i]);
  }
  return Sign::zero;
}

// --- operations on raw component arrays ----------------------------------------------------

/// h = e + f (Shewchuk's Fast-Expansion-Sum-Zeroelim, with empty inputs allowed and no read
/// past either end). h must not alias e or f and must hold elen + flen components. Returns the
/// length of h (0 when the sum is zero).
inline int fast_expansion_sum_zeroelim(int elen, const double* e, int flen, const double* f,
                                       double* h) {
  if (elen == 0 || flen == 0) {
    const int n = elen + flen;
    const double* src = elen == 0 ? f : e;
    for (int i = 0; i < n; ++i)
      h[i] = src[i];
    return n;
  }
  int ei = 0;
  int fi = 0;
  double e_now = e[0];
  double f_now = f[0];
  // Takes the component of smaller magnitude next (e on ties), as the merge of Theorem 13.
  auto e_first = [&] { return (f_now > e_now) == (f_now > -e_now); };
  double q;
  if (e_first()) {
    q = e_now;
    if (++ei < elen) e_now = e[ei];
  } else {
    q = f_now;
    if (++fi < flen) f_now = f[fi];
  }
  int hi = 0;
  double q_new;
  double hh;
  if (ei < elen && fi < flen) {
    if (e_first()) {
      fast_two_sum(e_now, q, q_new, hh);
      if (++ei < elen) e_now = e[ei];
    } else {
      fast_two_sum(f_now, q, q_new, hh);
      if (++fi < flen) f_now = f[fi];
    }
    q = q_new;
    if (hh != 0.0) h[hi++] = hh;
    while (ei < elen && fi < flen) {
      if (e_first()) {
        two_sum(q, e_now, q_new, hh);
        if (++ei < elen) e_now = e[ei];
      } else {
        two_sum(q, f_now, q_new, hh);
        if (++fi < flen) f_now = f[fi];
      }
      q = q_new;
      if (hh != 0.0) h[hi++] = hh;
    }
  }
  while (ei < elen) {
    two_sum(q, e[ei], q_new, hh);
    ++ei;
    q = q_new;
    if (hh != 0.0) h[hi++] = hh;
  }
  while (fi < flen) {
    two_sum(q, f[fi], q_new, hh);
    ++fi;
    q = q_new;
    if (hh != 0.0) h[hi++] = hh;
  }
  if (q != 0.0) h[hi++] = q;
  return hi;
}

/// h = e * b (Shewchuk's Scale-Expansion-Zeroelim). h must hold 2 * elen components.
inline int scale_expansion_zeroelim(int elen, const double* e, double b, double* h) {
  if (elen == 0 || b == 0.0) return 0;
  double b_hi, b_lo;
  split(b, b_hi, b_lo);
  double q;
  double hh;
  two_product_presplit(e[0], b, b_hi, b_lo, q, hh);
  int hi = 0;
  if (hh != 0.0) h[hi++] = hh;
  for (int i = 1; i < elen; ++i) {
    double product1;
    double product0;
    two_product_presplit(e[i], b, b_hi, b_lo, product1, product0);
    double sum;
    two_sum(q, product0, sum, hh);
    if (hh != 0.0) h[hi++] = hh;
    fast_two_sum(product1, sum, q, hh);
    if (hh != 0.0) h[hi++] = hh;
  }
  if (q != 0.0) h[hi++] = q;
  return hi;
}

// --- fixed-capacity expansions ---------------------------------------------------------------

/// An exact real number as the sum of at most N non-overlapping doubles, smallest first.
template <int N>
struct Expansion {
  static_assert(N >= 1);
  std::array<double, N> c;  // only the first n are meaningful
  int n = 0;

  Expansion() = default;
  /// The double x as an expansion (empty when x is zero).
  explicit Expansion(double x) {
    static_assert(N >= 1);
    c[0] = x;
    n = x != 0.0 ? 1 : 0;
  }

  /// The exact sign: the sign of the largest component.
  [[nodiscard]] Sign sign() const { return n == 0 ? Sign::zero : sign_of(c[n - 1]); }
};

template <int N, int M>
[[nodiscard]] Expansion<N + M> operator+(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<N + M> h;
  h.n = fast_expansion_sum_zeroelim(e.n, e.c.data(), f.n, f.c.data(), h.c.data());
  return h;
}

template <int N>
[[nodiscard]] Expansion<N> operator-(const Expansion<N>& e) {
  Expansion<N> h;
  h.n = e.n;
  for (int i = 0; i < e.n; ++i)
    h.c[i] = -e.c[i];
  return h;
}

template <int N, int M>
[[nodiscard]] Expansion<N + M> operator-(const Expansion<N>& e, const Expansion<M>& f) {
  return e + (-f);
}

/// The difference of two doubles: Two-Diff, zero tail dropped.
[[nodiscard]] inline Expansion<2> operator-(const Expansion<1>& e, const Expansion<1>& f) {
  const double a = e.n != 0 ? e.c[0] : 0.0;
  const double b = f.n != 0 ? f.c[0] : 0.0;
  double x;
  double y;
  two_diff(a, b, x, y);
  Expansion<2> h;
  h.n = 0;
  if (y != 0.0) h.c[h.n++] = y;
  if (x != 0.0) h.c[h.n++] = x;
  return h;
}

/// The product of two doubles: Two-Product, zero tail dropped.
[[nodiscard]] inline Expansion<2> operator*(const Expansion<1>& e, const Expansion<1>& f) {
  Expansion<2> h;
  h.n = 0;
  if (e.n == 0 || f.n == 0) return h;
  double x;
  double y;
  two_product(e.c[0], f.c[0], x, y);
  if (y != 0.0) h.c[h.n++] = y;
  h.c[h.n++] = x;
  return h;
}

/// e * f: one Scale-Expansion per component of the shorter operand, summed.
template <int N, int M>
[[nodiscard]] Expansion<2 * N * M> operator*(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<2 * N * M> result;
  result.n = 0;
  if (e.n == 0 || f.n == 0) return result;
  // Scale the longer expansion by each component of the shorter one.
  const bool e_longer = e.n >= f.n;
  const int long_n = e_longer ? e.n : f.n;
  const double* long_c = e_longer ? e.c.data() : f.c.data();
  const int short_n = e_longer ? f.n : e.n;
  const double* short_c = e_longer ? f.c.data() : e.c.data();
  if (short_n == 1) {
    result.n = scale_expansion_zeroelim(long_n, long_c, short_c[0], result.c.data());
    return result;
  }
  constexpr int kScaled = 2 * (N > M ? N : M);
  std::array<double, kScaled> scaled;
  std::array<double, 2 * N * M> other;
  double* acc = result.c.data();
  double* spare = other.data();
  int acc_n = scale_expansion_zeroelim(long_n, long_c, short_c[0], acc);
  for (int j = 1; j < short_n; ++j) {
    const int scaled_n = scale_expansion_zeroelim(long_n, long_c, short_c[j], scaled.data());
    const int sum_n = fast_expansion_sum_zeroelim(acc_n, acc, scaled_n, scaled.data(), spare);
    double* t = acc;
    acc = spare;
    spare = t;
    acc_n = sum_n;
  }
  if (acc != result.c.data()) {
    for (int i = 0; i < acc_n; ++i)
      result.c[i] = acc[i];
  }
  result.n = acc_n;
  return result;
}

// --- differences of inputs -------------------------------------------------------------------

/// out[i] = minuend[i] - subtrahend[i] exactly (Two-Diff); returns true when every difference is
/// a single double (all tails zero), as for inputs on a common grid. Predicates then evaluate
/// their polynomial on `heads(out)`, with far smaller expansions (Shewchuk's stage B idea).
template <std::size_t K>
[[nodiscard]] inline bool differences(const std::array<double, K>& minuend,
                                      const std::array<double, K>& subtrahend,
                                      std::array<Expansion<2>, K>& out) {
  bool exact = true;
  for (std::size_t i = 0; i < K; ++i) {
    // Written in place: a temporary copied as a block after element-wise stores stalls on
    // store-to-load forwarding, which cost more than the whole exact evaluation.
    double x;
    double y;
    two_diff(minuend[i], subtrahend[i], x, y);
    Expansion<2>& h = out[i];
    h.n = 0;
    if (y != 0.0) h.c[h.n++] = y;
    if (x != 0.0) h.c[h.n++] = x;
    exact &= y == 0.0;
  }
  return exact;
}

/// The single-double expansions of differences known to be exact.
template <std::size_t K>
[[nodiscard]] inline std::array<Expansion<1>, K> heads(const std::array<Expansion<2>, K>& d) {
  std::array<Expansion<1>, K> out;
  for (std::size_t i = 0; i < K; ++i)
    out[i] = Expansion<1>(d[i].n == 0 ? 0.0 : d[i].c[0]);
  return out;
}

// --- the regime in which expansion arithmetic is exact --------------------------------------

/// Input magnitudes for which every expansion evaluation of a polynomial of the given degree in
/// differences of the inputs (at most 12 monomials, as in the predicates here) neither
/// overflows nor underflows inside a product. With |x| < 2^hi every intermediate stays below
/// 2^1010 (Dekker's split needs its operands below 2^996, which holds for all factors); with
/// |x| >= 2^lo every nonzero input is a multiple of 2^(lo - 52), so every product of up to
/// `degree` of them is a multiple of 2^(degree (lo - 52)) >= 2^-1074 and its tail is
/// representable. Derivation in docs/robustness.md.
template <int Degree>
struct ExpansionRange;
template <>
struct ExpansionRange<2> {
  static constexpr int lo = -480;
  static constexpr int hi = 500;
};
template <>
struct ExpansionRange<3> {
  static constexpr int lo = -300;
  static constexpr int hi = 330;
};
template <>
struct ExpansionRange<4> {
  static constexpr int lo = -210;
  static constexpr int hi = 250;
};

/// 2^e as a constant expression (std::ldexp is not constexpr before C++23).
[[nodiscard]] constexpr double pow2(int e) {
  double r = 1.0;
  for (; e > 0; --e)
    r *= 2.0;
  for (; e < 0; ++e)
    r *= 0.5;
  return r;
}

/// True when x is 0 or 2^lo <= |x| < 2^hi for the degree's range.
template <int Degree>
[[nodiscard]] inline bool in_expansion_range(double x) {
  constexpr double min_abs = pow2(ExpansionRange<Degree>::lo);
  constexpr double max_abs = pow2(ExpansionRange<Degree>::hi);
  const double a = std::fabs(x);
  return (a < max_abs) & ((a >= min_abs) | (a == 0.0));
}

/// True when every value is in the degree's range. Variadic over scalars on purpose: an array
/// built from register arguments is reloaded through memory, and the store-to-load forwarding
/// stall costs more than the check.
template <int Degree, class... Doubles>
[[nodiscard]] inline bool in_expansion_range(double x, Doubles... rest) {
  // int operands: a branch-free & (clang's -Wbitwise-instead-of-logical flags & on bool calls).
  return (static_cast<int>(in_expansion_range<Degree>(x)) & ... &
          static_cast<int>(in_expansion_range<Degree>(rest))) != 0;
}

/// For a predicate whose polynomial is homogeneous in all its inputs (orient2d, orient3d,
/// cross_dot, side_of_sphere, side_of_circle): multiplies every value by one power of two 2^k,
/// k >= 0 or < 0, so that all lie in the degree's expansion range, and returns true; returns
/// false (values untouched) when their exponents spread wider than the range. The scaling is
/// exact (the results are normal doubles, so no bit is lost even from a subnormal input) and
/// multiplies the polynomial by the positive 2^(k degree), so the sign is unchanged.
template <int Degree, std::size_t K>
[[nodiscard]] inline bool scale_into_expansion_range(std::array<double, K>& values) {
  const bool in_range = std::apply(
      [](auto... x) { return in_expansion_range<Degree>(static_cast<double>(x)...); }, values);
  if (in_range) return true;
  constexpr int lo = ExpansionRange<Degree>::lo;
  constexpr int hi = ExpansionRange<Degree>::hi;
  int e_min = hi;
  int e_max = lo;
  bool any = false;
  for (const double x : values) {
    if (x == 0.0) continue;
    const int e = std::ilogb(x);  // floor(log2 |x|), exact for subnormals too
    e_min = e < e_min ? e : e_min;
    e_max = e > e_max ? e : e_max;
    any = true;
  }
  if (!any || e_max - e_min >= hi - lo) return false;  // (all zero was in range above)
  // Moves e_min to lo plus half the free room: e_min + k >= lo and e_max + k <= hi - 1.
  const int free_room = (hi - 1 - lo) - (e_max - e_min);
  const int k = lo - e_min + free_room / 2;
  for (double& x : values)
    x = std::ldexp(x, k);
  return true;
}

}  // namespace contain::predicates::detail
