// Private: the minimal enclosing ball in floating point, for Vec2 (circles) and Vec3 (spheres).
//
// Outline
//   1. Core set: the extreme points along a few fixed directions of a strided sample.
//   2. Welzl's move-to-front algorithm on the core set (MtfSolver) gives its minimal ball.
//   3. One pass over all points collects those outside that ball; if there are none, done;
//      else they join the core set (shuffled with a fixed seed) and step 2 runs again.
//      After kMaxRounds rounds (not met in practice) move-to-front runs on all points, which is
//      expected O(n) on its own.
//   Typically two or three rounds touch all n points; the rest works on a few thousand points.
//
// Numerics (Gärtner 1999, "Fast and robust smallest enclosing balls"): the support points are
// kept as q0 and the Gram-Schmidt-orthogonalised differences v_i = q_i - q0 - (projection on
// v_1..v_{i-1}); pushing a point moves the center along the new v only, c_m = c_{m-1} + f v_m with
// f = e / z, z = 2 |v_m|^2 and e = |p - c_{m-1}|^2 - r_{m-1}^2, which follows from requiring
// |p - c_m| = |q_i - c_m| for all support points. Every quantity is at most quadratic in the
// coordinates, so nothing overflows while squared distances do not. A point whose v_m is tiny
// (z <= eps^2 r^2: it lies numerically in the affine hull of the support, e.g. a duplicate, or a
// fourth coplanar point) is not pushed; that is what makes degenerate sets safe. We use modified
// Gram-Schmidt (projections taken one after another) for a little more stability.
//
// The "outside" test during the search is |p - c|^2 - r^2 > tolerance with a tolerance of
// 2^-47 (r^2 + r |c|_inf): far above the rounding noise of the center and of the squared distance
// (a few 2^-53 of the same terms), so cospherical points do not trigger endless re-solves, and
// small enough that the radius stays within ~2^-48 (1 + |c|_inf / r) relative of the optimum.
// Those tests only steer the search; containment is decided afterwards by the exact predicate
// (enclose.h), which encloses any point the tolerance let slip.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "bound/ball_common.h"

namespace contain::bound::detail {

inline constexpr double kSearchTolerance = 0x1p-47;
inline constexpr int kMaxRounds = 24;
inline constexpr std::uint64_t kShuffleSeed = 0x6A09E667F3BCC909ULL;

/// Welzl's move-to-front minimal ball with Gärtner's incremental solve. The list is reordered.
template <class P>
class MtfSolver {
 public:
  static constexpr int kDim = dimension<P>;

  /// The minimal ball of `list` (non-empty): recursion depth at most kDim + 1.
  void solve(std::vector<P>& list) {
    size_ = 0;
    current_center_ = P{};
    current_sqr_radius_ = -1.0;
    threshold_ = -std::numeric_limits<double>::infinity();
    move_to_front(list, list.size());
  }

  /// True when p lies outside the current ball by more than the search tolerance.
  [[nodiscard]] bool violates(const P& p) const {
    return squared_length(p - current_center_) - current_sqr_radius_ > threshold_;
  }

  [[nodiscard]] P center() const { return current_center_; }
  [[nodiscard]] double squared_radius() const { return current_sqr_radius_; }

 private:
  // mb(list[0, end), support): Welzl's recursion with the list order as the random order, and the
  // violator moved to the front so later passes meet it early (Welzl 1991, section 3).
  void move_to_front(std::vector<P>& list, std::size_t end) {
    if (size_ == kDim + 1) return;
    for (std::size_t k = 0; k < end; ++k) {
      if (!violates(list[k]) || !push(list[k])) continue;
      move_to_front(list, k);
      --size_;
      std::rotate(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(k),
                  list.begin() + static_cast<std::ptrdiff_t>(k) + 1);
    }
  }

  // Adds p to the support: the new ball is the smallest with all support points on its sphere.
  // Returns false (support unchanged) when p is numerically in the affine hull of the support.
  bool push(const P& p) {
    const int m = size_;
    if (m == 0) {
      q0_ = p;
      center_[0] = p;
      sqr_radius_[0] = 0.0;
    } else {
      P v = p - q0_;
      for (int i = 1; i < m; ++i)
        v = v - (2.0 * dot(v_[i], v) / z_[i]) * v_[i];
      const double z = 2.0 * squared_length(v);
      // Conditioning guard of Gärtner's push, eps^2 relative to the current squared radius.
      constexpr double kEps2 =
          std::numeric_limits<double>::epsilon() * std::numeric_limits<double>::epsilon();
      if (!(z > kEps2 * current_sqr_radius_)) return false;
      const double e = squared_length(p - center_[m - 1]) - sqr_radius_[m - 1];
      const double f = e / z;
      v_[m] = v;
      z_[m] = z;
      center_[m] = center_[m - 1] + f * v;
      sqr_radius_[m] = sqr_radius_[m - 1] + 0.5 * e * f;
    }
    current_center_ = center_[m];
    current_sqr_radius_ = sqr_radius_[m];
    threshold_ = kSearchTolerance *
                 (current_sqr_radius_ + std::sqrt(current_sqr_radius_) * max_abs(current_center_));
    ++size_;
    return true;
  }

  int size_ = 0;
  P q0_{};
  std::array<P, kDim + 1> v_{};
  std::array<double, kDim + 1> z_{};
  std::array<P, kDim + 1> center_{};
  std::array<double, kDim + 1> sqr_radius_{};
  P current_center_{};
  double current_sqr_radius_ = -1.0;
  double threshold_ = 0.0;
};

// Directions whose extreme points seed the core set: the axes, and for 3D the cube diagonals
// too (the minimal ball of a box-like set is spanned by its corners).
template <class P>
inline constexpr auto kExtremeDirections = std::array<P, 4>{{{1, 0}, {0, 1}, {1, 1}, {1, -1}}};
template <>
inline constexpr auto kExtremeDirections<Vec3> = std::array<Vec3, 7>{
    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}}};

// Points sampled for the extremes: the seed only has to be good, not exact (the passes over all
// points repair it), and a strided sample of this size is nearly as good as all points.
inline constexpr std::size_t kExtremeSample = 1 << 15;

/// The points of minimum and maximum dot product with each direction, without repeats, over an
/// evenly strided sample of at most about kExtremeSample points.
template <class P>
[[nodiscard]] std::vector<P> extreme_points(std::span<const P> points) {
  constexpr auto& directions = kExtremeDirections<P>;
  constexpr std::size_t kCount = directions.size();
  std::array<double, kCount> low{};
  std::array<double, kCount> high{};
  std::array<std::size_t, kCount> low_at{};
  std::array<std::size_t, kCount> high_at{};
  low.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  const std::size_t stride = std::max<std::size_t>(1, points.size() / kExtremeSample);
  for (std::size_t i = 0; i < points.size(); i += stride) {
    for (std::size_t d = 0; d < kCount; ++d) {
      const double s = dot(points[i], directions[d]);
      if (s < low[d]) {
        low[d] = s;
        low_at[d] = i;
      }
      if (s > high[d]) {
        high[d] = s;
        high_at[d] = i;
      }
    }
  }
  std::vector<std::size_t> chosen;
  for (std::size_t d = 0; d < kCount; ++d) {
    chosen.push_back(low_at[d]);
    chosen.push_back(high_at[d]);
  }
  std::sort(chosen.begin(), chosen.end());
  chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
  std::vector<P> out;
  out.reserve(chosen.size());
  for (std::size_t i : chosen)
    out.push_back(points[i]);
  return out;
}

/// The minimal enclosing ball of `points` in floating point (see the outline at the top).
/// Precondition: non-empty, finite, largest coordinate within [2^-300, 2^300] or zero.
template <class P>
[[nodiscard]] FpBall<P> min_ball(std::span<const P> points) {
  MtfSolver<P> solver;
  std::vector<P> core = extreme_points(points);
  solver.solve(core);
  SplitMix64 rng(kShuffleSeed);
  std::vector<P> outside;
  for (int round = 0;; ++round) {
    outside.clear();
    for (const P& p : points) {
      if (solver.violates(p)) outside.push_back(p);
    }
    if (outside.empty()) break;
    if (round == kMaxRounds) {
      core.assign(points.begin(), points.end());
      shuffle(core, 0, core.size(), rng);
      solver.solve(core);
      break;
    }
    // The previous core (its support near the front) rebuilds the old ball quickly; the new
    // points follow in random order, which is what the expected-linear bound needs.
    shuffle(outside, 0, outside.size(), rng);
    core.insert(core.end(), outside.begin(), outside.end());
    solver.solve(core);
  }
  return {solver.center(), std::sqrt(std::max(solver.squared_radius(), 0.0))};
}

}  // namespace contain::bound::detail
