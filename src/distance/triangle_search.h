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
#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/values/triangle.h"
#include "contain/values/vec.h"
#include "distance/search_tree.h"

namespace contain::distance::detail {

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
  SearchTree tree_;
  double slack_ = 0.0;  // bound on a computed closest point's distance from its triangle, squared
};

/// Ericson's closest point of the triangle to p in doubles (only a guess; see above).
[[nodiscard]] Vec3 approximate_closest_point(Vec3 p, const Triangle3& t);

/// The bounds of one triangle (exposed for the tests).
void triangle_bounds(Vec3 p, const Triangle3& t, double slack, double& lo, double& hi);

/// The slack for triangles whose coordinates are at most `max_abs` in magnitude.
[[nodiscard]] double triangle_slack(double max_abs);

}  // namespace contain::distance::detail
