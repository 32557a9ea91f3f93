#pragma once
// Private to contain::distance: the closest triangles of a point, found in floating point with
// proven bounds, so that the exact stage sees only the triangles that can be closest.
//
// Search: depth first over a BVH of the triangles, the nearer child first, pruning a node whose
// box is farther (squared distance, a lower bound rounded down) than the best upper bound so
// far. Per triangle: an approximate closest point q (Ericson, "Real-Time Collision Detection",
// 5.1.5, in doubles) gives
//   hi: |p - q|^2 plus a bound on q's distance from the triangle and on the rounding of q,
//       an upper bound of the squared distance whatever q is;
//   lo: the separation along w = p - q: every point x of the triangle has
//       |p - x| >= (p - x) . w / |w| >= min over the corners v of (p - v) . w / |w|,
//       because (p - x) . w is linear in x and the triangle is the hull of its corners; this
//       holds for any w, and is tight (equal to |p - q|) when q is the exact closest point.
// Both are computed with rounding error bounds (docs/robustness.md, "Distance"); any overflow,
// underflow or NaN turns them into lo = 0, hi = +inf, which only makes the search keep more
// triangles. A triangle whose lo exceeds the final best hi cannot be closest.

#include <cstdint>
#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/geometry/box.h"
#include "contain/geometry/triangle.h"
#include "contain/geometry/vec.h"

namespace contain::distance::detail {

/// A triangle that may be the closest, with bounds on its squared distance.
struct Contender {
  std::int32_t triangle;  // index given to the search
  double lo;
  double hi;
};

/// Counts of a search, for benchmarks.
struct SearchStats {
  std::size_t nodes = 0;
  std::size_t triangles = 0;
};

class TriangleSearch {
 public:
  TriangleSearch() = default;
  /// Triangles numbered 0..n-1 in the order given.
  explicit TriangleSearch(std::span<const Triangle3> triangles, const bvh::BuildOptions& options);

  [[nodiscard]] bool empty() const { return tris_.empty(); }
  [[nodiscard]] const Triangle3& triangle(std::int32_t i) const {
    return triangles_[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] std::size_t size() const { return triangles_.size(); }
  [[nodiscard]] const bvh::Bvh& hierarchy() const { return bvh_; }

  /// The contenders for the closest triangle of p (every triangle whose squared distance may be
  /// the least), into `out` (cleared first). Never empty for a non-empty set. `hint`, a triangle
  /// index or -1, is bounded first: a near triangle (the previous point's closest, in a batch of
  /// nearby points) prunes the search from the start. It never changes the contenders' decision.
  void contenders(Vec3 p, std::vector<Contender>& out, SearchStats* stats = nullptr,
                  std::int32_t hint = -1) const;

  /// Three-valued "some triangle within squared distance d2" from the bounds: +1 proven (some hi
  /// <= d2), -1 disproven (every lo > d2), 0 undecided; the undecided triangles go to `out`.
  [[nodiscard]] int within(Vec3 p, double d2_lo, double d2_hi, std::vector<Contender>& out) const;

 private:
  struct Tri {
    Vec3 a, b, c;
    std::int32_t index;
  };
  // The hierarchy again, as one node per inner node holding both children's boxes (rounded
  // outward to float): one cache line per step of the descent.
  struct PairNode {
    float lo[2][3];
    float hi[2][3];
    std::int32_t child[2];  // inner: PairNode index; leaf: first position in tris_
    std::int32_t count[2];  // leaf: number of triangles; inner: 0
  };
  void build_pair_nodes();
  void bound_leaf(Vec3 p, std::int32_t first, std::int32_t count, std::int32_t skip, double& best,
                  std::vector<Contender>& out, std::size_t& bounded) const;

  std::vector<Triangle3> triangles_;    // in the order given
  std::vector<Tri> tris_;               // in the hierarchy's leaf order
  std::vector<std::int32_t> position_;  // triangle index -> position in tris_
  bvh::Bvh bvh_;
  std::vector<PairNode> pairs_;  // empty when the root is a leaf
  double slack_ =
      0.0;  // bound on a computed closest point's distance from its triangle, squared, inflated
};

/// Lower bound of the squared distance from p to the closed box (rounded down; +inf beyond the
/// double range).
[[nodiscard]] double box_lower_bound(Vec3 p, const Box3& box);

/// The bounds of one triangle (exposed for the tests).
void triangle_bounds(Vec3 p, const Triangle3& t, double slack, double& lo, double& hi);

/// The slack for triangles whose coordinates are at most `max_abs` in magnitude.
[[nodiscard]] double triangle_slack(double max_abs);

}  // namespace contain::distance::detail
