#pragma once
// The branch-free Liang-Barsky kernel of the box batch: floating point with a certificate.
//
// Per axis k with d_k = b_k - a_k: r = 1 / d_k, the face parameters (min_k - a_k) r and
// (max_k - a_k) r, entering = their min, exiting = their max; a parallel axis (d_k == 0)
// contributes (-inf, +inf) when a_k is in the slab and (+inf, -inf) otherwise, chosen by
// selects. lo = max(0, entering), hi = min(1, exiting), kept iff lo <= hi.
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

template <int D>
inline void box_kernel(const double* in, double* out, std::uint8_t* kept, std::size_t count,
                       const KernelBox<D>& box) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double big = 0x1p900;
  constexpr double tiny = 0x1p-900;
  constexpr double margin = 8.01 * 0x1p-53;
  for (std::size_t i = 0; i < count; ++i) {
    const double* s = in + 2 * D * i;
    double enter[D], exit[D], face_in[D], face_out[D], d[D];
    double lo = 0.0, hi = 1.0;
    bool unsure = false;
    for (int k = 0; k < D; ++k) {
      const double a = s[k], b = s[D + k];
      d[k] = b - a;
      const double r = 1.0 / d[k];
      const double t_min = (box.min[k] - a) * r, t_max = (box.max[k] - a) * r;
      const bool parallel = d[k] == 0.0;
      const bool in_slab = (a >= box.min[k]) & (a <= box.max[k]);
      const bool forward = d[k] > 0.0;
      const double e = forward ? t_min : t_max;
      const double x = forward ? t_max : t_min;
      enter[k] = parallel ? (in_slab ? -inf : inf) : e;
      exit[k] = parallel ? (in_slab ? inf : -inf) : x;
      face_in[k] = forward ? box.min[k] : box.max[k];
      face_out[k] = forward ? box.max[k] : box.min[k];
      const double ad = std::fabs(d[k]);
      unsure |= !(std::fabs(a) < big) | !(std::fabs(b) < big) | ((ad < tiny) & !parallel) |
                (parallel & ((a == box.min[k]) | (a == box.max[k])));
      lo = lo > enter[k] ? lo : enter[k];
      hi = hi < exit[k] ? hi : exit[k];
    }
    const double lo_c = lo < 2.0 ? lo : 2.0, hi_c = hi > -1.0 ? hi : -1.0;
    const double gap = hi_c - lo_c;
    unsure |= std::fabs(gap) <= margin * (std::fabs(lo_c) + std::fabs(hi_c)) + tiny;
    const bool keep = gap >= 0.0;
    double* o = out + 2 * D * i;
    for (int k = 0; k < D; ++k) {
      const double a = s[k], b = s[D + k];
      double p0 = a + lo_c * d[k];
      double p1 = hi_c == 1.0 ? b : a + hi_c * d[k];
      p0 = (lo == enter[k]) & (lo > 0.0) ? face_in[k] : p0;
      p1 = (hi == exit[k]) & (hi < 1.0) ? face_out[k] : p1;
      p0 = p0 < box.min[k] ? box.min[k] : (p0 > box.max[k] ? box.max[k] : p0);
      p1 = p1 < box.min[k] ? box.min[k] : (p1 > box.max[k] ? box.max[k] : p1);
      o[k] = p0;
      o[D + k] = p1;
    }
    kept[i] = static_cast<std::uint8_t>(unsure ? 2 : (keep ? 1 : 0));
  }
}

}  // namespace contain::clip::detail
