#pragma once
// Exact points of the mesh boolean: homogeneous coordinates (X, Y, Z, W), W > 0, on the one big
// number, so that every point the arrangement makes (an input vertex, an edge through a plane,
// two segments crossing in a triangle's plane) is held without rounding and every decision on
// it is the sign of a polynomial (rule solid-exact-points in docs/robustness.md). Private to
// clip.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

#include "contain/predicates/big_float.h"
#include "contain/predicates/sign.h"
#include "contain/values/vec.h"

namespace contain::clip::solid {

using predicates::BigFloat;
using predicates::BigVec3;

/// Homogeneous coordinates (X, Y, Z, W) of a point, W > 0, exact.
struct Homogeneous {
  std::array<BigFloat, 3> x;
  BigFloat w;
};

/// Bounds of a point's coordinates: lo[i] <= x[i] / w <= hi[i].
struct Enclosure {
  std::array<double, 3> lo{}, hi{};
};

/// Where the segment p q crosses the plane of the triangle a b c: the doubles that define a
/// crossing point, kept instead of its big numbers, which are made from them when a predicate
/// first needs them and kept in `exact` (not thread-safe: the engine runs on one thread); and
/// the crossing's enclosure.
struct Crossing {
  Vec3 p, q, a, b, c;
  Enclosure bounds;
  mutable std::shared_ptr<const Homogeneous> exact;
};

/// The most points of doubles a constructed point keeps as its hull (below).
inline constexpr std::size_t hull_capacity = 6;

/// Points of doubles of which a point is a convex combination with every weight positive (the
/// first `size`; none known when size is 0). A predicate affine in each of its points (an
/// orientation, a side of a plane, a difference of coordinates) is then a sum, with positive
/// weights, of its values at the hulls' points, each decided on doubles: where none of those
/// signs is opposite to another, they decide it, exact zeros included (a point constructed on
/// a line or a plane of doubles is there by construction, and its hull is on it too).
struct Hull {
  std::array<Vec3, hull_capacity> points{};
  std::size_t size = 0;
};

/// The big numbers of another constructed point, its enclosure and its hull.
struct Constructed {
  Homogeneous numbers;
  Enclosure bounds;
  Hull hull;
};

/// (x / w, y / w, z / w) with w > 0, the big numbers shared (immutable) by the copies of a point.
/// A point of doubles (`exact_point(v)`) is only v (no big numbers: made from v when a predicate
/// needs them), so that predicates on points of doubles only take the filtered predicates of
/// `predicates` and most input vertices never allocate a big number. A crossing (`line_plane`)
/// is likewise only its `Crossing` and its nearest doubles v, rounded by a filtered predicate:
/// most crossings never allocate a big number either. Every point also has an enclosure of its
/// coordinates, lo[i] <= x[i] / w <= hi[i] (lo = hi = v for a point of doubles; v's neighbours
/// for a crossing): the floating-point filter that decides most predicates on implicit points
/// without the big numbers (rule solid-exact-points).
///
/// 56 bytes: the enclosure of an implicit point is kept with its shared numbers or crossing and
/// a point of doubles has none (it is v), because a point store holds one point per input
/// vertex (7 MB at two 131k-triangle spheres, 14 MB with an enclosure in each) and its pages
/// are first touched, each a page fault.
struct ExactPoint {
  std::shared_ptr<const Constructed> exact;  ///< set for the other constructed points
  std::shared_ptr<const Crossing> crossing;  ///< set for a crossing
  Vec3 v{};  ///< the point (plain) or its nearest doubles (a crossing)
  /// The point is `v`, doubles: neither a crossing nor another constructed point.
  [[nodiscard]] bool plain() const { return !exact && !crossing; }
  /// Bounds of the point's coordinates (lo = hi = v for a point of doubles).
  [[nodiscard]] Enclosure enclosure() const {
    if (crossing) return crossing->bounds;
    if (exact) return exact->bounds;
    return {{v.x, v.y, v.z}, {v.x, v.y, v.z}};
  }
};
#if defined(__x86_64__) && defined(__LP64__)
// The size the comments above and PointStore::written_exactly count with (two shared_ptr, v).
static_assert(sizeof(ExactPoint) == 56);
#endif

/// The double point v.
[[nodiscard]] ExactPoint exact_point(Vec3 v);

/// The exact normal (b - a) x (c - a) of a triangle of doubles.
[[nodiscard]] BigVec3 exact_normal(Vec3 a, Vec3 b, Vec3 c);

/// Where the segment p q meets the plane of the triangle a b c. Precondition: a, b, c not
/// collinear; p and q lie strictly on opposite sides of the plane.
[[nodiscard]] ExactPoint line_plane(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c);

/// The same point for predicates only: its coordinates enclosed by interval arithmetic, `v` an
/// approximation and not its nearest doubles (the rounding's exact stage, which crossings of
/// nearly parallel planes take, is skipped: for the check of a written mesh, which asks only
/// whether triangles meet). Not for the point store.
[[nodiscard]] ExactPoint line_plane_enclosed(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c);

/// Where the lines p1 p2 and q1 q2, all four in the plane through a with normal n, cross.
/// `axis` is dropped to project (n[axis] != 0). Precondition: the projected lines cross in one
/// point. `proper`: they cross strictly inside both segments p1 p2 and q1 q2 (decided exactly by
/// the caller), so that the point's hull is known from its ends'.
[[nodiscard]] ExactPoint line_line(const ExactPoint& p1, const ExactPoint& p2, const ExactPoint& q1,
                                   const ExactPoint& q2, Vec3 a, const BigVec3& n, int axis,
                                   bool proper = false);

/// The plane a triangle is worked in: the axis whose normal component is largest in magnitude
/// (dropped) and that component's sign.
struct Projection {
  int axis = 2;
  Sign sense = Sign::positive;
};

/// The projection of `p` dropping coordinate `axis`, the other two in cyclic order (so that
/// orient2d there is the sign of the normal's `axis` component).
inline Vec2 drop_axis(Vec3 p, int axis) {
  if (axis == 0) return {p.y, p.z};
  if (axis == 1) return {p.z, p.x};
  return {p.x, p.y};
}

/// `dropped_axis` of the exact normal (b - a) x (c - a) and that component's sign, decided by a
/// filter in doubles where the largest component is certainly larger than the others by a
/// relative 2^-31 (so that `dropped_axis`'s comparison by exponent and rounded significand picks
/// it too); nothing where it cannot tell (the exact normal must).
[[nodiscard]] std::optional<Projection> filtered_projection(Vec3 a, Vec3 b, Vec3 c);

/// The first axis k in which the direction nt x nu of the line where the planes of triangles t
/// and u meet is non-zero (nt = (t1 - t0) x (t2 - t0), nu likewise), decided by a filter in
/// doubles; nothing where the filter cannot decide (the exact normals must).
[[nodiscard]] std::optional<int> filtered_line_axis(const std::array<Vec3, 3>& t,
                                                    const std::array<Vec3, 3>& u);

/// Component i (0, 1, 2) of v.
[[nodiscard]] const BigFloat& component(const BigVec3& v, int i);

/// Exact equality of the points.
[[nodiscard]] bool same_point(const ExactPoint& a, const ExactPoint& b);

/// Sign of coordinate i of a - b.
[[nodiscard]] Sign compare_coordinate(const ExactPoint& a, const ExactPoint& b, int i);

/// Sign of the 2D orientation of a, b, c projected by dropping `axis` (the remaining axes in
/// cyclic order axis + 1, axis + 2, so a triangle whose normal has n[axis] > 0 turns positive).
[[nodiscard]] Sign orient2d_dropped(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c,
                                    int axis);

/// Sign of det[q - p, a - p, b - p] decided by a floating-point filter on the points'
/// enclosures, or nothing where it cannot tell (the exact predicate must).
[[nodiscard]] std::optional<Sign> filtered_orient3d(const ExactPoint& p, const ExactPoint& q,
                                                    const ExactPoint& a, const ExactPoint& b);

/// Sign of n . (p - a): the side of the plane through a with normal n that p lies on.
[[nodiscard]] Sign plane_side(const ExactPoint& p, Vec3 a, const BigVec3& n);

/// The hull of p: p itself for a point of doubles, the segment's ends for a crossing, the kept
/// hull of another constructed point (none when it has none).
[[nodiscard]] Hull hull_of(const ExactPoint& p);

/// The same point as big numbers only (no crossing, no hull): predicates on it take the filters
/// and the big numbers, never a shortcut by construction (the tests compare the two).
[[nodiscard]] ExactPoint without_shortcuts(const ExactPoint& p);

/// The centroid of three points (a refined face's corners) for the rays of the labels, made of
/// the corners without big numbers: its enclosure (interval sums of the corners'), its hull (the
/// corners' hulls together), and the exact point only where those cannot decide a predicate
/// (then made once). Not thread-safe (the engine runs on one thread).
class LazyCentroid {
 public:
  LazyCentroid(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c);
  [[nodiscard]] const Enclosure& enclosure() const { return bounds_; }
  /// orient2d_dropped(a, b, centroid, axis). `plane` (three points of doubles, not collinear)
  /// and its exact normal `n`: a plane the three corners lie in, exactly.
  [[nodiscard]] Sign orient2d(Vec3 a, Vec3 b, int axis, const std::array<Vec3, 3>& plane,
                              const BigVec3& n) const;
  /// plane_side(centroid, a, n) for the plane of a, b, c with n = exact_normal(a, b, c).
  [[nodiscard]] Sign plane_side(Vec3 a, Vec3 b, Vec3 c, const BigVec3& n) const;
  /// The exact centroid, made on first use.
  [[nodiscard]] const ExactPoint& point() const;

 private:
  std::array<ExactPoint, 3> corners_;
  Enclosure bounds_;
  std::array<Vec3, 3 * hull_capacity> hull_{};
  std::size_t hull_size_ = 0;  // 0: some corner's hull is unknown
  mutable std::optional<ExactPoint> exact_;
};

/// (a + b) / 2 and (a + b + c) / 3, exactly.
[[nodiscard]] ExactPoint midpoint(const ExactPoint& a, const ExactPoint& b);
[[nodiscard]] ExactPoint centroid(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c);

/// Each coordinate rounded to the nearest double (ties to even). Precondition: the coordinates
/// are within the double range (they lie in the inputs' hull).
[[nodiscard]] Vec3 nearest_double(const ExactPoint& p);

}  // namespace contain::clip::solid

namespace contain::clip::solid {

/// (b - a) times the positive factor a.w b.w: a vector with the direction of b - a, exact.
[[nodiscard]] BigVec3 direction(const ExactPoint& a, const ExactPoint& b);

}  // namespace contain::clip::solid
