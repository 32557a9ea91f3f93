#pragma once
// Private helpers of the bounding-ball algorithms, shared by 2D and 3D: the point type is Vec2 or
// Vec3, and every operation used here exists for both.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "contain/values/max_abs.h"
#include "contain/values/vec.h"

namespace contain::bound::detail {

template <class P>
inline constexpr int dimension = static_cast<int>(sizeof(P) / sizeof(double));

/// p * 2^e, coordinate by coordinate (exact unless the result leaves the normal range; a factor
/// 2^e itself could overflow where the products do not).
[[nodiscard]] inline Vec2 scaled(Vec2 p, int e) {
  return {std::ldexp(p.x, e), std::ldexp(p.y, e)};
}
[[nodiscard]] inline Vec3 scaled(Vec3 p, int e) {
  return {std::ldexp(p.x, e), std::ldexp(p.y, e), std::ldexp(p.z, e)};
}

/// A ball in floating point, before the exact containment pass.
template <class P>
struct FpBall {
  P center;
  double radius = 0.0;
};

/// SplitMix64 (Steele, Lea, Flood 2014): a tiny generator whose sequence is the same on every
/// platform, unlike std::shuffle with the standard distributions.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }

 private:
  std::uint64_t state_;
};

/// Fisher-Yates on [begin, end) with SplitMix64 (modulo reduction: its bias, below 2^-40 for any
/// realistic range, does not matter to the expected running time).
template <class T>
void shuffle(std::vector<T>& items, std::size_t begin, std::size_t end, SplitMix64& rng) {
  for (std::size_t i = end; i > begin + 1; --i) {
    const std::size_t j = begin + static_cast<std::size_t>(rng.next() % (i - begin));
    std::swap(items[i - 1], items[j]);
  }
}

/// The point of `points` farthest from `from` (the first on ties); floating point, which is all
/// the heuristics that call it need.
template <class P>
[[nodiscard]] P farthest_from(std::span<const P> points, P from) {
  P best = points.front();
  double best_d2 = -1.0;
  for (const P& p : points) {
    const double d2 = squared_length(p - from);
    if (d2 > best_d2) {
      best_d2 = d2;
      best = p;
    }
  }
  return best;
}

}  // namespace contain::bound::detail
