#pragma once
/// \file
/// Exact 3D orientation among the points of one small set, with one filter bound for the set.

#include <algorithm>
#include <array>
#include <cassert>
#include <cfloat>
#include <cmath>
#include <cstddef>

#include "contain/geometry/vec.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/sign.h"

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
  explicit Orient3dSet(const std::array<Vec3, N>& points) : p_(points) {
    Vec3 lo = points[0], hi = points[0];
    for (std::size_t i = 1; i < N; ++i) {
      lo = {std::min(lo.x, points[i].x), std::min(lo.y, points[i].y), std::min(lo.z, points[i].z)};
      hi = {std::max(hi.x, points[i].x), std::max(hi.y, points[i].y), std::max(hi.z, points[i].z)};
    }
    // Every computed difference of two coordinates is at most the computed extent in absolute
    // value (rounding is monotone), so every permanent is below 6 Dx Dy Dz. Extents of 2^340
    // or more could overflow a product (an infinite determinant would pass a finite bound):
    // then the bound is infinite and the exact stages answer.
    const double dx = hi.x - lo.x, dy = hi.y - lo.y, dz = hi.z - lo.z;
    constexpr double kBound = 50.0 * 0x1p-53;
    errbound_ = std::max(dx, std::max(dy, dz)) < 0x1p340
                    ? kBound * (dx * dy * dz) + DBL_MIN * (1.0 + dx + dy + dz)
                    : INFINITY;
  }

  /// The point with index i < N.
  [[nodiscard]] const Vec3& point(std::size_t i) const { return p_[i]; }

  /// The plane through points a, b, c (indices < N). O(1).
  [[nodiscard]] Plane plane(std::size_t a, std::size_t b, std::size_t c) const {
    assert(a < N && b < N && c < N);
    const Vec3 pa = p_[a], pb = p_[b], pc = p_[c];
    const double bax = pb.x - pa.x, bay = pb.y - pa.y, baz = pb.z - pa.z;
    const double cax = pc.x - pa.x, cay = pc.y - pa.y, caz = pc.z - pa.z;
    return {a, b, c, bay * caz - baz * cay, baz * cax - bax * caz, bax * cay - bay * cax};
  }

  /// Exactly orient3d(point(plane.a), point(plane.b), point(plane.c), point(d)), d < N. O(1).
  [[nodiscard]] Sign sign(const Plane& plane, std::size_t d) const {
    assert(d < N);
    const Vec3 pa = p_[plane.a], pd = p_[d];
    const double det =
        (plane.nx * (pd.x - pa.x) + plane.ny * (pd.y - pa.y)) + plane.nz * (pd.z - pa.z);
    // Formed without branching on the sign (random input makes such branches unpredictable);
    // only the rare undecided case branches.
    const bool positive = det > errbound_, negative = -det > errbound_;
    if (positive == negative) [[unlikely]] {  // both false: the filter cannot tell
      return detail::orient3d_exact(pa, p_[plane.b], p_[plane.c], pd);
    }
    return static_cast<Sign>(static_cast<int>(positive) - static_cast<int>(negative));
  }

  /// Exactly orient3d(point(a), point(b), point(c), point(d)), all indices < N. O(1).
  [[nodiscard]] Sign orient3d(std::size_t a, std::size_t b, std::size_t c, std::size_t d) const {
    return sign(plane(a, b, c), d);
  }

 private:
  std::array<Vec3, N> p_;
  double errbound_;
};

}  // namespace contain::predicates
