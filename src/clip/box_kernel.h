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

}  // namespace contain::clip::detail
