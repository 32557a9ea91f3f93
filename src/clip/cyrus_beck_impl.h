#pragma once
// Cyrus-Beck over any list of half-space functions (exact_value.h): shared by the segment
// clipper and the batch forms.

#include <algorithm>
#include <span>
#include <vector>

#include "clip/segment_common.h"
#include "contain/predicates/halfspace_function.h"

namespace contain::clip::detail {

template <class V, class F>
[[nodiscard]] typename SegmentOf<V>::Clipped cyrus_beck_clip(const V& a, const V& b,
                                                             std::span<const F> functions) {
  // Per half-space: the exact endpoint signs decide its role (the section's three cases).
  int enter = -1, exit = -1;
  predicates::Bounded enter_a, enter_b, exit_a, exit_b;
  // sign(t_i - t_j) with t = s(a) / (s(a) - s(b)); numerator s_j(a) s_i(b) - s_i(a) s_j(b),
  // times sign(den_i) sign(den_j): den < 0 entering, > 0 exiting.
  auto compare = [&](int i, const predicates::Bounded& ia, const predicates::Bounded& ib, int den_i,
                     int j, const predicates::Bounded& ja, const predicates::Bounded& jb,
                     int den_j) {
    const Sign s = predicates::sign_of_product_difference(ja, ib, ia, jb, [&] {
      const auto& fi = functions[static_cast<std::size_t>(i)];
      const auto& fj = functions[static_cast<std::size_t>(j)];
      return fj.exact(a) * fi.exact(b) - fi.exact(a) * fj.exact(b);
    });
    return to_int(s) * den_i * den_j;
  };
  for (int i = 0; i < static_cast<int>(functions.size()); ++i) {
    const F& f = functions[static_cast<std::size_t>(i)];
    const Sign sa = f.side(a), sb = f.side(b);
    const bool in_a = sa != Sign::negative, in_b = sb != Sign::negative;
    if (in_a && in_b) continue;
    if (!in_a && !in_b) return nothing<V>();  // trivial reject
    const predicates::Bounded va = f.approx(a), vb = f.approx(b);
    if (!in_a) {
      if (enter < 0 || compare(i, va, vb, -1, enter, enter_a, enter_b, -1) > 0) {
        enter = i;
        enter_a = va;
        enter_b = vb;
      }
    } else if (exit < 0 || compare(i, va, vb, 1, exit, exit_a, exit_b, 1) < 0) {
      exit = i;
      exit_a = va;
      exit_b = vb;
    }
  }
  int order = -1;
  if (enter >= 0 && exit >= 0) {
    order = compare(enter, enter_a, enter_b, -1, exit, exit_a, exit_b, 1);
    if (order > 0) return nothing<V>();
  }
  // Rounded parameters; exact 1 or 0 where the crossing is at an endpoint on the plane.
  auto param = [](const predicates::Bounded& sa, const predicates::Bounded& sb, double fallback) {
    if (sb.value == 0.0 && sa.value != 0.0) return fallback;
    const double t = sa.value / (sa.value - sb.value);
    return std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : fallback;
  };
  double t0 = 0.0, t1 = 1.0;
  if (enter >= 0) {
    const F& f = functions[static_cast<std::size_t>(enter)];
    t0 = f.side(b) == Sign::zero ? 1.0 : param(enter_a, enter_b, 1.0);
  }
  if (exit >= 0) {
    const F& f = functions[static_cast<std::size_t>(exit)];
    t1 = f.side(a) == Sign::zero ? 0.0 : param(exit_a, exit_b, 0.0);
  }
  if (order == 0 || t1 < t0) {
    // Touching (exact) or a proper part shorter than the rounding: one point / ordered ends.
    if (order == 0) {
      const double t = enter >= 0 ? t0 : t1;
      const V p = point_at(a, b, t);
      return kept(p, p, t, t);
    }
    t1 = t0;
  }
  V p0 = point_at(a, b, t0), p1 = point_at(a, b, t1);
  auto inside = [&](const V& p) {
    return std::all_of(functions.begin(), functions.end(),
                       [&](const F& f) { return f.side(p) != Sign::negative; });
  };
  const double t0_in = enter >= 0 ? adjust_inward(a, b, t0, t1, p0, inside) : t0;
  const double t1_in = exit >= 0 ? adjust_inward(a, b, t1, t0_in, p1, inside) : t1;
  return kept(p0, p1, t0_in, std::max(t0_in, t1_in));
}

}  // namespace contain::clip::detail
