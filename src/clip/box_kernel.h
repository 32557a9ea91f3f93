#pragma once
// The branch-free Liang-Barsky kernel of the box batch: floating point with a certificate.
//
// Per axis k with d_k = b_k - a_k: r = 1 / d_k, the face parameters (min_k - a_k) r and
// (max_k - a_k) r, entering = their min, exiting = their max (IEEE infinities handle a
// parallel axis). lo = max(0, entering), hi = min(1, exiting), kept iff lo <= hi.
//
// Certificate. Each computed face parameter is (v - a) * (1 / (b - a)) with three roundings
// and one exact-sign operand, so |t_computed - t| <= (1 + eps)^3 - 1 < 3.01 eps |t| when no
// operand overflows or underflows (guarded below); max and min are exact, 0 and 1 are exact.
// If |hi - lo| > 8.01 eps (|lo| + |hi|) + 2^-900 the sign of hi - lo is the exact one, and
// the parameter comparisons with 0 are exact anyway (v - a has the exact sign). Everything
// else -- ties, near ties, parallel segments on a face (0 * inf), coordinates beyond 2^900
// or differences below 2^-900 -- is flagged (kept = 2) and redone by the exact Liang-Barsky.
//
// Points: p(t) = a + t d (b exactly at t = 1), the coordinate of the face that set lo (hi)
// replaced by the face value, then clamped into the box (where the true point lies).

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "contain/geometry/box.h"
#include "contain/geometry/segment.h"

namespace contain::clip::detail {

template <int D>
struct KernelBox {
  double min[D];
  double max[D];
};

// Branch-free select: x where c, else y (bit masks, so no compiler turns it into a jump).
[[nodiscard]] inline double select(bool c, double x, double y) {
  const std::uint64_t m = std::uint64_t{0} - static_cast<std::uint64_t>(c);
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(x) & m) |
                               (std::bit_cast<std::uint64_t>(y) & ~m));
}

template <int D>
inline void box_kernel(const double* in, double* out, std::uint8_t* kept, std::size_t count,
                       const KernelBox<D>& box) {
  constexpr double big = 0x1p900;
  constexpr double tiny = 0x1p-900;
  constexpr double margin = 8.01 * 0x1p-53;
  for (std::size_t i = 0; i < count; ++i) {
    const double* s = in + 2 * D * i;
    double enter[D], exit[D], d[D];
    double lo = 0.0, hi = 1.0;
    bool unsure = false;
    for (int k = 0; k < D; ++k) {
      const double a = s[k], b = s[D + k];
      d[k] = b - a;
      // A parallel axis (d = +-0) gives r = +-inf and face parameters -inf / +inf inside the
      // slab, both +inf or both -inf outside it: the right answer without a special case;
      // only a point on a face plane (0 * inf = NaN) is unsure.
      const double r = 1.0 / d[k];
      const double t1 = (box.min[k] - a) * r, t2 = (box.max[k] - a) * r;
      const bool ordered = t1 < t2;
      enter[k] = select(ordered, t1, t2);
      exit[k] = select(ordered, t2, t1);
      const double ad = std::fabs(d[k]);
      unsure |= !(std::fabs(a) < big) | !(std::fabs(b) < big) | ((ad < tiny) & (ad != 0.0)) |
                (t1 != t1) | (t2 != t2);
      lo = select(lo < enter[k], enter[k], lo);
      hi = select(exit[k] < hi, exit[k], hi);
    }
    const double lo_c = select(lo < 2.0, lo, 2.0), hi_c = select(hi > -1.0, hi, -1.0);
    const double gap = hi_c - lo_c;
    unsure |= std::fabs(gap) <= margin * (std::fabs(lo_c) + std::fabs(hi_c)) + tiny;
    const bool keep = gap >= 0.0;
    double* o = out + 2 * D * i;
    for (int k = 0; k < D; ++k) {
      const double a = s[k], b = s[D + k];
      const bool forward = d[k] > 0.0;
      double p0 = a + lo_c * d[k];
      double p1 = select(hi_c == 1.0, b, a + hi_c * d[k]);
      p0 = select(lo == enter[k], select(forward, box.min[k], box.max[k]), p0);
      p1 = select(hi == exit[k], select(forward, box.max[k], box.min[k]), p1);
      p0 = select(p0 < box.min[k], box.min[k], select(box.max[k] < p0, box.max[k], p0));
      p1 = select(p1 < box.min[k], box.min[k], select(box.max[k] < p1, box.max[k], p1));
      o[k] = p0;
      o[D + k] = p1;
    }
    kept[i] = static_cast<std::uint8_t>(static_cast<int>(keep) + static_cast<int>(unsure) * 2);
  }
}

#if defined(__GNUC__)
// The same kernel on two segments at once with GCC/Clang vector extensions (SSE2 on every
// x86-64, NEON on AArch64; no -march needed): one division instruction per axis for two
// segments, comparisons as lane masks, selects as bit operations. Bit for bit the scalar
// kernel's arithmetic, lane by lane.
using V2 = double __attribute__((vector_size(16)));
using M2 = long long __attribute__((vector_size(16)));

[[nodiscard]] inline V2 select2(M2 m, V2 x, V2 y) {
  return reinterpret_cast<V2>((reinterpret_cast<M2>(x) & m) | (reinterpret_cast<M2>(y) & ~m));
}
[[nodiscard]] inline V2 abs2(V2 x) {
  const M2 mask = {0x7fffffffffffffffLL, 0x7fffffffffffffffLL};
  return reinterpret_cast<V2>(reinterpret_cast<M2>(x) & mask);
}

template <int D>
inline void box_kernel_pairs(const double* in, double* out, std::uint8_t* kept, std::size_t count,
                             const KernelBox<D>& box) {
  const V2 big = {0x1p900, 0x1p900}, tiny = {0x1p-900, 0x1p-900};
  const V2 margin = {8.01 * 0x1p-53, 8.01 * 0x1p-53};
  const V2 zero = {0.0, 0.0}, one = {1.0, 1.0}, two = {2.0, 2.0}, minus_one = {-1.0, -1.0};
  std::size_t i = 0;
  for (; i + 2 <= count; i += 2) {
    const double* s0 = in + 2 * D * i;
    const double* s1 = s0 + 2 * D;
    V2 a[D], b[D], d[D], enter[D], exit[D];
    V2 lo = zero, hi = one;
    M2 unsure = {0, 0};
    for (int k = 0; k < D; ++k) {
      a[k] = V2{s0[k], s1[k]};
      b[k] = V2{s0[D + k], s1[D + k]};
      d[k] = b[k] - a[k];
      const V2 r = one / d[k];
      const V2 mn = {box.min[k], box.min[k]}, mx = {box.max[k], box.max[k]};
      const V2 t1 = (mn - a[k]) * r, t2 = (mx - a[k]) * r;
      const M2 ordered = t1 < t2;
      enter[k] = select2(ordered, t1, t2);
      exit[k] = select2(ordered, t2, t1);
      const V2 ad = abs2(d[k]);
      unsure |= ~(abs2(a[k]) < big) | ~(abs2(b[k]) < big) | ((ad < tiny) & (ad != zero)) |
                (t1 != t1) | (t2 != t2);
      lo = select2(lo < enter[k], enter[k], lo);
      hi = select2(exit[k] < hi, exit[k], hi);
    }
    const V2 lo_c = select2(lo < two, lo, two), hi_c = select2(hi > minus_one, hi, minus_one);
    const V2 gap = hi_c - lo_c;
    unsure |= abs2(gap) <= margin * (abs2(lo_c) + abs2(hi_c)) + tiny;
    const M2 keep = gap >= zero;
    double* o0 = out + 2 * D * i;
    double* o1 = o0 + 2 * D;
    for (int k = 0; k < D; ++k) {
      const V2 mn = {box.min[k], box.min[k]}, mx = {box.max[k], box.max[k]};
      const M2 forward = d[k] > zero;
      V2 p0 = a[k] + lo_c * d[k];
      V2 p1 = select2(hi_c == one, b[k], a[k] + hi_c * d[k]);
      p0 = select2(lo == enter[k], select2(forward, mn, mx), p0);
      p1 = select2(hi == exit[k], select2(forward, mx, mn), p1);
      p0 = select2(p0 < mn, mn, select2(mx < p0, mx, p0));
      p1 = select2(p1 < mn, mn, select2(mx < p1, mx, p1));
      o0[k] = p0[0];
      o1[k] = p0[1];
      o0[D + k] = p1[0];
      o1[D + k] = p1[1];
    }
    kept[i] = static_cast<std::uint8_t>((keep[0] & 1) + (unsure[0] & 2));
    kept[i + 1] = static_cast<std::uint8_t>((keep[1] & 1) + (unsure[1] & 2));
  }
  if (i < count) box_kernel<D>(in + 2 * D * i, out + 2 * D * i, kept + i, count - i, box);
}
#else
template <int D>
inline void box_kernel_pairs(const double* in, double* out, std::uint8_t* kept, std::size_t count,
                             const KernelBox<D>& box) {
  box_kernel<D>(in, out, kept, count, box);
}
#endif

}  // namespace contain::clip::detail
