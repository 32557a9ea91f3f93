#pragma once
/// \file
/// Exact 3D orientation among the points of one small set, with one filter bound for the set.

#include <algorithm>
#include <array>
#include <cassert>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <utility>

#include "contain/predicates/orient3d.h"
#include "contain/predicates/sign.h"
#include "contain/predicates/unit_roundoff.h"
#include "contain/values/vec.h"

namespace contain::predicates {

/// N points (e.g. the six vertices of a triangle pair) and exact `orient3d` among them by index,
/// with a semi-static filter: one error bound, formed from the extent of the whole set, serves
/// every determinant of four of its points. A query then costs a dot product and two
/// comparisons; a plane's normal is formed once for several queries. Answers are exactly
/// `orient3d(point(a), point(b), point(c), point(d))` (the same sign convention and the same
/// exact stages when the filter cannot decide). Indices are the only way to name points, so no
/// query can leave the set the bound was made for. The filter is weaker than `orient3d`'s when
/// the set is much larger than the four points in play; then the exact stages answer. Bound:
/// 50 eps Dx Dy Dz + DBL_MIN (1 + Dx + Dy + Dz), D the set's extent per axis
/// (docs/robustness.md). Construction O(N).
template <std::size_t N>
class Orient3dSet {
  static_assert(N >= 1);

 public:
  /// A plane through three points of the set, by index, with its normal
  /// (b - a) x (c - a) rounded once.
  struct Plane {
    std::size_t a, b, c;
    double nx, ny, nz;
  };

  /// The set; any finite doubles.
  explicit Orient3dSet(const std::array<Vec3, N>& points)
      : Orient3dSet(points, std::make_index_sequence<N>()) {}

  /// The point with index i < N.
  [[nodiscard]] Vec3 point(std::size_t i) const { return {x_[i], y_[i], z_[i]}; }

  /// The plane through points a, b, c (indices < N). O(1).
  [[nodiscard]] Plane plane(std::size_t a, std::size_t b, std::size_t c) const {
    assert(a < N && b < N && c < N);
    const double bax = x_[b] - x_[a], bay = y_[b] - y_[a], baz = z_[b] - z_[a];
    const double cax = x_[c] - x_[a], cay = y_[c] - y_[a], caz = z_[c] - z_[a];
    return {a, b, c, bay * caz - baz * cay, baz * cax - bax * caz, bax * cay - bay * cax};
  }

  /// Exactly orient3d(point(plane.a), point(plane.b), point(plane.c), point(d)), d < N. O(1).
  [[nodiscard]] Sign sign(const Plane& plane, std::size_t d) const {
    assert(d < N);
    const std::size_t a = plane.a;
    const double det =
        (plane.nx * (x_[d] - x_[a]) + plane.ny * (y_[d] - y_[a])) + plane.nz * (z_[d] - z_[a]);
    // Formed without branching on the sign (random input makes such branches unpredictable);
    // only the rare undecided case branches.
    const bool positive = det > errbound_, negative = -det > errbound_;
    if (positive == negative) [[unlikely]] {  // both false: the filter cannot tell
      return detail::orient3d_exact(point(a), point(plane.b), point(plane.c), point(d));
    }
    return static_cast<Sign>(static_cast<int>(positive) - static_cast<int>(negative));
  }

  /// Exactly orient3d(point(a), point(b), point(c), point(d)), all indices < N. O(1).
  [[nodiscard]] Sign orient3d(std::size_t a, std::size_t b, std::size_t c, std::size_t d) const {
    return sign(plane(a, b, c), d);
  }

 private:
  // Unrolled by the fold expressions (a loop over N stays a loop at -O2 and costs more than
  // the queries it serves).
  template <std::size_t... I>
  Orient3dSet(const std::array<Vec3, N>& points, std::index_sequence<I...>)
      : x_{points[I].x...}, y_{points[I].y...}, z_{points[I].z...} {
    double lo_x = x_[0], hi_x = x_[0], lo_y = y_[0], hi_y = y_[0], lo_z = z_[0], hi_z = z_[0];
    ((lo_x = std::min(lo_x, x_[I]), hi_x = std::max(hi_x, x_[I]), lo_y = std::min(lo_y, y_[I]),
      hi_y = std::max(hi_y, y_[I]), lo_z = std::min(lo_z, z_[I]), hi_z = std::max(hi_z, z_[I])),
     ...);
    // Every computed difference of two coordinates is at most the computed extent in absolute
    // value (rounding is monotone), so every permanent is below 6 Dx Dy Dz. Extents of 2^340
    // or more could overflow a product (an infinite determinant would pass a finite bound):
    // then the bound is infinite and the exact stages answer.
    const double dx = hi_x - lo_x, dy = hi_y - lo_y, dz = hi_z - lo_z;
    constexpr double kBound = 50.0 * unit_roundoff<double>;
    errbound_ = std::max(dx, std::max(dy, dz)) < 0x1p340
                    ? kBound * (dx * dy * dz) + DBL_MIN * (1.0 + dx + dy + dz)
                    : INFINITY;
  }
  // Coordinates by axis: plain loads for the queries.
  double x_[N], y_[N], z_[N];
  double errbound_;
};

}  // namespace contain::predicates
