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
#include <cstring>
#include <limits>
#include <span>

#include "contain/core/parallel.h"
#include "contain/predicates/unit_roundoff.h"
#include "contain/values/box.h"
#include "contain/values/segment.h"

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

// The reference kernel, one segment at a time: every vector version below computes bit for bit
// what this one does (tests/clip/clip_segments_test.cpp checks it); it also does their tails.
template <int D>
inline void box_kernel_scalar(const double* in, double* out, std::uint8_t* kept, std::size_t count,
                              const KernelBox<D>& box) {
  constexpr double big = 0x1p900;
  constexpr double tiny = 0x1p-900;
  constexpr double margin = 8.01 * predicates::unit_roundoff<double>;
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
// The same kernel on W = 2 or 4 segments at once with GCC/Clang vector extensions: SSE2 pairs
// on every x86-64 (NEON on AArch64), AVX2 quadruples where the CPU has them (chosen at run time
// by `box_kernel_for`; no -march needed). Lane l holds segment l; the arithmetic is the scalar
// kernel's, operation for operation, with no contraction into FMA (the AVX2 target has no FMA
// instructions, and GCC does not contract in ISO C++ mode), so every lane is bit for bit what
// `box_kernel_scalar` computes. Comparisons give lane masks, selects
// are blends, and the selects of a larger or smaller value are max / min instructions.
//
// Layout. A segment is 2D doubles (a_0 .. a_{D-1}, b_0 .. b_{D-1}), read as D pairs of two
// doubles. The lane vectors of coordinates 2p and 2p + 1 are the low and high interleave of
// pair p of the even segments with pair p of the odd ones (unpcklpd / unpckhpd within each
// 128-bit half): a 4 x 2 transpose per pair instead of one scalar insert per coordinate, and
// the same transpose backwards for the output.
//
// The lane helpers pass 32-byte vectors by value: they are always inlined into the one function
// compiled for AVX2, so no call crosses the ABI difference GCC warns about (-Wpsabi, turned off
// for clip_segments.cpp, the one file that instantiates them, in segment_sources.cmake).
using V2 = double __attribute__((vector_size(16)));
using M2 = long long __attribute__((vector_size(16)));
using V4 = double __attribute__((vector_size(32)));
using M4 = long long __attribute__((vector_size(32)));

template <class V>
struct Lanes;
template <>
struct Lanes<V2> {
  using M = M2;
  static constexpr int count = 2;
};
template <>
struct Lanes<V4> {
  using M = M4;
  static constexpr int count = 4;
};

template <class V>
[[gnu::always_inline]] inline V splat(double x) {
  if constexpr (Lanes<V>::count == 2) {
    return V{x, x};
  } else {
    return V{x, x, x, x};
  }
}

// Lane selects: x where m, else y.
template <class V, class M>
[[gnu::always_inline]] inline V select_lanes(M m, V x, V y) {
  return m ? x : y;
}

// x > y ? x : y and x < y ? x : y, lane by lane (y where unordered): the scalar kernel's selects
// of the larger / smaller value. Written with the comparison inside the select, GCC and Clang
// emit x86 maxpd / minpd, which compute exactly this (operand order, NaN and -0 included).
template <class V>
[[gnu::always_inline]] inline V max_lanes(V x, V y) {
  return x > y ? x : y;
}
template <class V>
[[gnu::always_inline]] inline V min_lanes(V x, V y) {
  return x < y ? x : y;
}
// |x| by the sign bit.
template <class V>
[[gnu::always_inline]] inline V abs_lanes(V x) {
  using M = typename Lanes<V>::M;
  const M mask = reinterpret_cast<M>(splat<V>(std::bit_cast<double>(~(std::uint64_t{1} << 63))));
  return reinterpret_cast<V>(reinterpret_cast<M>(x) & mask);
}

// The D coordinate pairs of W consecutive segments at `s` as 2D lane vectors.
template <class V, int D>
[[gnu::always_inline]] inline void load_lanes(const double* s, V* c) {
  constexpr int stride = 2 * D;
#pragma GCC unroll 4
  for (int p = 0; p < D; ++p) {
    V2 e, o;
    std::memcpy(&e, s + 2 * p, sizeof e);
    std::memcpy(&o, s + stride + 2 * p, sizeof o);
    if constexpr (Lanes<V>::count == 2) {
      c[2 * p] = __builtin_shufflevector(e, o, 0, 2);
      c[2 * p + 1] = __builtin_shufflevector(e, o, 1, 3);
    } else {
      V2 e2, o2;
      std::memcpy(&e2, s + 2 * stride + 2 * p, sizeof e2);
      std::memcpy(&o2, s + 3 * stride + 2 * p, sizeof o2);
      const V4 even = __builtin_shufflevector(e, e2, 0, 1, 2, 3);
      const V4 odd = __builtin_shufflevector(o, o2, 0, 1, 2, 3);
      c[2 * p] = __builtin_shufflevector(even, odd, 0, 4, 2, 6);
      c[2 * p + 1] = __builtin_shufflevector(even, odd, 1, 5, 3, 7);
    }
  }
}

// The inverse of load_lanes.
template <class V, int D>
[[gnu::always_inline]] inline void store_lanes(const V* c, double* s) {
  constexpr int stride = 2 * D;
#pragma GCC unroll 4
  for (int p = 0; p < D; ++p) {
    if constexpr (Lanes<V>::count == 2) {
      const V2 e = __builtin_shufflevector(c[2 * p], c[2 * p + 1], 0, 2);
      const V2 o = __builtin_shufflevector(c[2 * p], c[2 * p + 1], 1, 3);
      std::memcpy(s + 2 * p, &e, sizeof e);
      std::memcpy(s + stride + 2 * p, &o, sizeof o);
    } else {
      const V4 even = __builtin_shufflevector(c[2 * p], c[2 * p + 1], 0, 4, 2, 6);
      const V4 odd = __builtin_shufflevector(c[2 * p], c[2 * p + 1], 1, 5, 3, 7);
      const V2 e = __builtin_shufflevector(even, even, 0, 1);
      const V2 e2 = __builtin_shufflevector(even, even, 2, 3);
      const V2 o = __builtin_shufflevector(odd, odd, 0, 1);
      const V2 o2 = __builtin_shufflevector(odd, odd, 2, 3);
      std::memcpy(s + 2 * p, &e, sizeof e);
      std::memcpy(s + stride + 2 * p, &o, sizeof o);
      std::memcpy(s + 2 * stride + 2 * p, &e2, sizeof e2);
      std::memcpy(s + 3 * stride + 2 * p, &o2, sizeof o2);
    }
  }
}

// The low byte of each lane of `flags` (0 to 3) to kept[0 .. W).
template <class V>
[[gnu::always_inline]] inline void store_flags(typename Lanes<V>::M flags, std::uint8_t* kept) {
  if constexpr (Lanes<V>::count == 2) {
    using Bytes = unsigned char __attribute__((vector_size(16)));
    using Low = unsigned char __attribute__((vector_size(2)));
    const Bytes b = reinterpret_cast<Bytes>(flags);
    const Low low = __builtin_shufflevector(b, b, 0, 8);
    std::memcpy(kept, &low, sizeof low);
  } else {
    using Bytes = unsigned char __attribute__((vector_size(32)));
    using Low = unsigned char __attribute__((vector_size(4)));
    const Bytes b = reinterpret_cast<Bytes>(flags);
    const Low low = __builtin_shufflevector(b, b, 0, 8, 16, 24);
    std::memcpy(kept, &low, sizeof low);
  }
}

template <class V, int D>
[[gnu::always_inline]] inline void box_kernel_lanes(const double* in, double* out,
                                                    std::uint8_t* kept, std::size_t count,
                                                    const KernelBox<D>& box) {
  using M = typename Lanes<V>::M;
  constexpr std::size_t width = Lanes<V>::count;
  const V big = splat<V>(0x1p900), tiny = splat<V>(0x1p-900),
          margin = splat<V>(8.01 * predicates::unit_roundoff<double>);
  const V zero = splat<V>(0.0), one = splat<V>(1.0), two = splat<V>(2.0),
          minus_one = splat<V>(-1.0);
  // The box in lanes, read once: `out` could alias `box` as far as the compiler knows.
  V box_min[D], box_max[D];
  for (int k = 0; k < D; ++k) {
    box_min[k] = splat<V>(box.min[k]);
    box_max[k] = splat<V>(box.max[k]);
  }
  std::size_t i = 0;
  for (; i + width <= count; i += width) {
    V c[2 * D];
    load_lanes<V, D>(in + 2 * D * i, c);
    V d[D], enter[D], exit[D];
    V lo = zero, hi = one;
    M unsure = reinterpret_cast<M>(zero);
#pragma GCC unroll 4
    for (int k = 0; k < D; ++k) {
      const V a = c[k], b = c[D + k];
      d[k] = b - a;
      const V r = one / d[k];
      const V mn = box_min[k], mx = box_max[k];
      const V t1 = (mn - a) * r, t2 = (mx - a) * r;
      enter[k] = min_lanes(t1, t2);  // t1 < t2 ? t1 : t2
      exit[k] = max_lanes(t2, t1);   // t1 < t2 ? t2 : t1
      const V ad = abs_lanes<V>(d[k]);
      unsure |= ~(abs_lanes<V>(a) < big) | ~(abs_lanes<V>(b) < big) | ((ad < tiny) & (ad != zero)) |
                (t1 != t1) | (t2 != t2);
      lo = max_lanes(enter[k], lo);  // lo < enter ? enter : lo
      hi = min_lanes(exit[k], hi);   // exit < hi ? exit : hi
    }
    const V lo_c = min_lanes(lo, two), hi_c = max_lanes(hi, minus_one);
    const V gap = hi_c - lo_c;
    unsure |= abs_lanes<V>(gap) <= margin * (abs_lanes<V>(lo_c) + abs_lanes<V>(hi_c)) + tiny;
    const M keep = gap >= zero;
    V p[2 * D];
#pragma GCC unroll 4
    for (int k = 0; k < D; ++k) {
      const V a = c[k], b = c[D + k];
      const V mn = box_min[k], mx = box_max[k];
      const M forward = d[k] > zero;
      V p0 = a + lo_c * d[k];
      V p1 = select_lanes<V, M>(hi_c == one, b, a + hi_c * d[k]);
      p0 = select_lanes<V, M>(lo == enter[k], select_lanes<V, M>(forward, mn, mx), p0);
      p1 = select_lanes<V, M>(hi == exit[k], select_lanes<V, M>(forward, mx, mn), p1);
      // Clamped into [mn, mx] as the scalar kernel's two selects do.
      p[k] = max_lanes(mn, min_lanes(mx, p0));
      p[D + k] = max_lanes(mn, min_lanes(mx, p1));
    }
    store_lanes<V, D>(p, out + 2 * D * i);
    store_flags<V>((keep & 1) | (unsure & 2), kept + i);
  }
  if (i < count) box_kernel_scalar<D>(in + 2 * D * i, out + 2 * D * i, kept + i, count - i, box);
}
#endif

/// The instruction sets the batch kernel has a version for.
enum class KernelIsa { portable, avx2 };

template <int D>
using BoxKernel = void (*)(const double* in, double* out, std::uint8_t* kept, std::size_t count,
                           const KernelBox<D>& box);

template <int D>
void box_kernel_portable(const double* in, double* out, std::uint8_t* kept, std::size_t count,
                         const KernelBox<D>& box) {
#if defined(__GNUC__)
  box_kernel_lanes<V2, D>(in, out, kept, count, box);
#else
  box_kernel_scalar<D>(in, out, kept, count, box);
#endif
}

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define CONTAIN_CLIP_KERNEL_AVX2 1
template <int D>
[[gnu::target("avx2")]] void box_kernel_avx2(const double* in, double* out, std::uint8_t* kept,
                                             std::size_t count, const KernelBox<D>& box) {
  box_kernel_lanes<V4, D>(in, out, kept, count, box);
}
#endif

/// Whether this CPU (and its OS) runs the version for `isa`.
[[nodiscard]] inline bool kernel_isa_available(KernelIsa isa) {
  if (isa == KernelIsa::portable) return true;
#if defined(CONTAIN_CLIP_KERNEL_AVX2)
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

/// The version for `isa`; the portable one where this build or this CPU has none.
template <int D>
[[nodiscard]] BoxKernel<D> box_kernel_for(KernelIsa isa) {
#if defined(CONTAIN_CLIP_KERNEL_AVX2)
  if (isa == KernelIsa::avx2 && kernel_isa_available(isa)) return &box_kernel_avx2<D>;
#endif
  (void)isa;
  return &box_kernel_portable<D>;
}

/// The widest version this CPU runs, chosen once.
template <int D>
[[nodiscard]] BoxKernel<D> best_box_kernel() {
  static const BoxKernel<D> kernel = box_kernel_for<D>(KernelIsa::avx2);
  return kernel;
}

/// `clip_segments` against a box with the kernel version `box_kernel_for(isa)`;
/// `clip_segments` itself takes the widest this CPU runs. For the tests and the
/// benchmark: the results are the same bit for bit whatever the version.
void clip_segments_with(std::span<const Segment3> segments, const Box3& box,
                        std::span<Segment3> out, std::span<std::uint8_t> kept,
                        const BatchOptions& options, KernelIsa isa);
void clip_segments_with(std::span<const Segment2> segments, const Box2& box,
                        std::span<Segment2> out, std::span<std::uint8_t> kept,
                        const BatchOptions& options, KernelIsa isa);

/// The kernel alone on one thread, without the exact pass: flags[i] bit 0 = kept, bit 1 =
/// unsure (the exact Liang-Barsky decides). Preconditions as `clip_segments`, non-empty box.
void run_box_kernel(std::span<const Segment3> segments, const Box3& box, std::span<Segment3> out,
                    std::span<std::uint8_t> flags, KernelIsa isa);
void run_box_kernel(std::span<const Segment2> segments, const Box2& box, std::span<Segment2> out,
                    std::span<std::uint8_t> flags, KernelIsa isa);

}  // namespace contain::clip::detail
