#pragma once
// Private to contain::distance: the closest triangles of a point, found in floating point with
// proven bounds (search_tree.h), so that the exact stage sees only the triangles that can be
// closest.
//
// Per triangle: an approximate closest point q (Ericson, "Real-Time Collision Detection",
// 5.1.5, in doubles) gives
//   hi: |p - q|^2 plus a bound on q's distance from the triangle and on the rounding of q,
//       an upper bound of the squared distance whatever q is;
//   lo: the separation along w = p - q: every point x of the triangle has
//       |p - x| >= (p - x) . w / |w| >= min over the corners v of (p - v) . w / |w|,
//       because (p - x) . w is linear in x and the triangle is the hull of its corners; this
//       holds for any w, and is tight (equal to |p - q|) when q is the exact closest point.
// Both are computed with rounding error bounds (docs/robustness.md, "Distance"); any overflow,
// underflow or NaN turns them into lo = 0, hi = +inf, which only makes the search keep more
// triangles.

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/predicates/unit_roundoff.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"
#include "distance/search_tree.h"

namespace contain::distance::detail {

/// A proven test "every point of the triangle is farther than sqrt(best) from p", by the
/// plane normal to w (any direction) at distance sqrt(best) from p: every x of the triangle has
/// |p - x| >= (p - x) . w / |w| (Cauchy-Schwarz), and (p - x) . w is linear in x, so the
/// triangle lies beyond when each corner v has v . w < p . w - sqrt(best) |w|. With all
/// coordinates at most M in magnitude, each dot product v . w is within 4 eps M |w|_1 of its
/// computed value, p . w within 4 eps sum |p_i w_i|; the threshold c subtracts
/// m = 16 eps (sum |p_i w_i| + M |w|_1 + b + |p . w|) + 2^-1000, which covers those errors, the
/// roundings of c itself (at most 3 eps (|p . w| + b + m)) and products that underflow. NaN or
/// overflow leave c = -inf (no triangle is beyond). Three dot products per triangle, against a
/// closest point and three bounded separations for the full bounds.
class HalfSpaceTest {
 public:
  HalfSpaceTest() = default;
  /// best >= 0 the squared distance bound; max_abs bounds every coordinate of the triangles.
  HalfSpaceTest(Vec3 p, Vec3 w, double best, double max_abs);
  [[nodiscard]] bool operator()(const Triangle3& t) const {
    return dot(t.a, w_) < c_ && dot(t.b, w_) < c_ && dot(t.c, w_) < c_;
  }

 private:
  Vec3 w_{};
  double c_ = -std::numeric_limits<double>::infinity();
};

/// A proven lower bound of the squared distance from any point to a triangle by the triangle's
/// own plane: with n a unit normal as rounded (any direction would do) and d = n . a as rounded,
/// every point x of the triangle has |n . x - d| <= e (e bounds the three corners' offsets,
/// rounding included, and n . x is linear in x), so |p - x| >= (|n . p - d| - e) / |n|.
/// Six doubles, set once per triangle; a query costs one dot product. Where the distance is
/// mostly across the plane (a point inside a tube or a concave part, seen by the triangles
/// around it) this puts a triangle out before its closest point is computed. Degenerate
/// triangles, overflow and underflow give 0 (no bound).
class PlaneBound {
 public:
  PlaneBound() = default;
  explicit PlaneBound(const Triangle3& t);
  [[nodiscard]] double lower(Vec3 p) const {
    constexpr double kEps = predicates::unit_roundoff<double>;
    const double t = (n_.x * p.x + n_.y * p.y) + n_.z * p.z;
    const double perm = (std::fabs(n_.x * p.x) + std::fabs(n_.y * p.y)) + std::fabs(n_.z * p.z);
    // |n . p - d| >= |t - d| (1 - eps) - 3.01 eps perm (the dot product's error), each operation
    // below rounding once more: the factors (1 - 4 eps), 8 eps and (1 - 8 eps) cover them.
    const double g = std::fabs(t - d_) * (1 - 4 * kEps) - (8 * kEps * perm + e_);
    if (!(g >= 0x1p-500) || !(g <= 0x1p500)) return 0.0;
    const double r = g * k_;
    return r * r * (1 - 8 * kEps);
  }

 private:
  Vec3 n_{};
  double d_ = 0.0;
  double e_ = 0.0;
  double k_ = 0.0;  // a lower bound of 1 / |n|; 0: no bound
};

class TriangleSearch {
 public:
  TriangleSearch() = default;
  /// Triangles numbered 0..n-1 in the order given.
  TriangleSearch(std::span<const Triangle3> triangles, const bvh::BuildOptions& options);

  [[nodiscard]] bool empty() const { return tree_.empty(); }
  [[nodiscard]] const Triangle3& triangle(std::int32_t i) const {
    return triangles_[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] std::size_t size() const { return triangles_.size(); }

  /// The contenders for the closest triangle of p (SearchTree::contenders).
  void contenders(Vec3 p, std::vector<Contender>& out, SearchStats* stats = nullptr,
                  std::int32_t hint = -1) const;

  /// SearchTree::within over the triangles.
  [[nodiscard]] int within(Vec3 p, double d2_lo, double d2_hi, std::vector<Contender>& out) const;

 private:
  std::vector<Triangle3> triangles_;  // in the order given
  std::vector<Triangle3> ordered_;    // in the tree's leaf order
  std::vector<PlaneBound> planes_;    // in the tree's leaf order
  SearchTree tree_;
  double max_abs_ = 0.0;  // largest coordinate magnitude of the triangles
  double slack_ = 0.0;    // bound on a computed closest point's distance from its triangle, squared
};

/// Ericson's closest point of the triangle to p in doubles (only a guess; see above).
[[nodiscard]] Vec3 approximate_closest_point(Vec3 p, const Triangle3& t);

/// The bounds of one triangle (exposed for the tests); returns w = p - q.
Vec3 triangle_bounds(Vec3 p, const Triangle3& t, double slack, double& lo, double& hi);

/// The slack for triangles whose coordinates are at most `max_abs` in magnitude.
[[nodiscard]] double triangle_slack(double max_abs);

}  // namespace contain::distance::detail
