#pragma once
/// \file
/// A hierarchy built in a mesh's own frame, placed by a transform per query: the world box of a
/// local node box, and bounds on the placed points, each proven to hold the points exactly as
/// `Transform::apply` computes them (the doubles every exact decision of a pair query is made
/// on). One rounding analysis for collide's and distance's pair queries.
///
/// Derivation. Coordinate i of apply(v) is ((r_i0 v_0 + r_i1 v_1) + r_i2 v_2) + t_i: a sum of
/// four terms, within gamma_4 < 4.01 eps of s_i = sum_j |r_ij| |v_j| + |t_i| from its exact
/// value (Higham, "Accuracy and Stability of Numerical Algorithms", 3.1), plus half a
/// denorm_min per product that underflows. Over a box lo <= v <= hi, the exact value lies in the
/// interval product t_i + sum_j [min(r lo, r hi), max(r lo, r hi)]_j, whose computed ends are
/// again within gamma_4 s_i of the exact ones, s_i now with max(|lo_j|, |hi_j|). So widening the
/// computed interval by 10 eps s_i (both errors, and s_i's own rounding) and 16 denorm_min holds
/// every apply(v) and every exact image R v + t.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "contain/predicates/unit_roundoff.h"
#include "contain/values/box.h"
#include "contain/values/transform.h"

namespace contain::bvh {

/// The closed world box holding apply(v) and the exact image R v + t of every v in `local` (a
/// non-empty box of finite doubles) placed by `transform`: an interval product per coordinate
/// widened by the proven rounding margin above. Inline: the pair descents call it per node.
/// O(1).
[[nodiscard]] inline Box3 placed_box(const Box3& local, const Transform& transform) {
  constexpr double eps = predicates::unit_roundoff<double>;
  const double lo[3] = {local.min.x, local.min.y, local.min.z};
  const double hi[3] = {local.max.x, local.max.y, local.max.z};
  const double t[3] = {transform.t.x, transform.t.y, transform.t.z};
  double mn[3], mx[3];
  for (std::size_t i = 0; i < 3; ++i) {
    double a = t[i], b = t[i], s = std::fabs(t[i]);
    for (std::size_t j = 0; j < 3; ++j) {
      const double r = transform.r[i][j];
      const double p = r * lo[j], q = r * hi[j];
      a += std::min(p, q);
      b += std::max(p, q);
      s += std::fabs(r) * std::max(std::fabs(lo[j]), std::fabs(hi[j]));
    }
    const double pad = 10 * eps * s + 16 * std::numeric_limits<double>::denorm_min();
    mn[i] = a - pad;
    mx[i] = b + pad;
  }
  return {{mn[0], mn[1], mn[2]}, {mx[0], mx[1], mx[2]}};
}

/// A bound on every coordinate of apply(v) for |v|_inf <= `max_abs`: max_i |t_i| + sum_j |r_ij|
/// max_abs, times 1 + 16 eps (gamma_4 of apply's rounding and this sum's own). O(1).
[[nodiscard]] inline double placed_max_abs(const Transform& transform, double max_abs) {
  const double t[3] = {transform.t.x, transform.t.y, transform.t.z};
  double out = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto& r = transform.r[i];
    out = std::max(
        out, std::fabs(t[i]) + ((std::fabs(r[0]) + std::fabs(r[1])) + std::fabs(r[2])) * max_abs);
  }
  return out * (1 + 16 * predicates::unit_roundoff<double>);
}

/// A bound on |apply(v)_i - (R v + t)_i|, every coordinate i, for |v|_inf <= `max_abs`: how far
/// a placed vertex lies from its exact image (gamma_4 of the largest s_i above, doubled for the
/// bound's own rounding, plus the underflow of three products). O(1).
[[nodiscard]] inline double placement_error(const Transform& transform, double max_abs) {
  return 8 * predicates::unit_roundoff<double> * placed_max_abs(transform, max_abs) +
         4 * std::numeric_limits<double>::denorm_min();
}

}  // namespace contain::bvh
