#pragma once
// Private helpers of the segment clippers: coordinates by index, points on a segment, results,
// the inward adjustment of a rounded crossing point, and batches of one clipper per segment.

#include <cmath>
#include <cstdint>
#include <span>
#include <type_traits>

#include "contain/clip/clipped_segment.h"
#include "contain/core/parallel.h"
#include "contain/values/segment.h"
#include "contain/values/vec.h"

namespace contain::clip::detail {

// Runs `clip(segment)` (a ClippedSegment2/3) on every segment, on all threads: kept[i] and, where
// kept, out[i].
template <class S, class Clip>
void clip_each(std::span<const S> segments, std::span<S> out, std::span<std::uint8_t> kept,
               const BatchOptions& options, Clip clip) {
  parallel_for(segments.size(), options, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const auto r = clip(segments[i]);
      kept[i] = r.kept ? 1 : 0;
      if (r.kept) out[i] = r.segment;
    }
  });
}

template <class V>
inline constexpr int dimension = std::is_same_v<V, Vec3> ? 3 : 2;

template <class V>
[[nodiscard]] constexpr double coord(const V& v, int k) {
  if constexpr (std::is_same_v<V, Vec3>) {
    return k == 0 ? v.x : (k == 1 ? v.y : v.z);
  } else {
    return k == 0 ? v.x : v.y;
  }
}

template <class V>
constexpr void set_coord(V& v, int k, double value) {
  if constexpr (std::is_same_v<V, Vec3>) {
    (k == 0 ? v.x : (k == 1 ? v.y : v.z)) = value;
  } else {
    (k == 0 ? v.x : v.y) = value;
  }
}

template <class V>
struct SegmentOf;
template <>
struct SegmentOf<Vec2> {
  using Segment = Segment2;
  using Clipped = ClippedSegment2;
};
template <>
struct SegmentOf<Vec3> {
  using Segment = Segment3;
  using Clipped = ClippedSegment3;
};

/// p(t) = a + t (b - a), with the endpoints returned bit for bit at t = 0 and t = 1.
template <class V>
[[nodiscard]] V point_at(const V& a, const V& b, double t) {
  if (t <= 0.0) return a;
  if (t >= 1.0) return b;
  return a + t * (b - a);
}

template <class V>
[[nodiscard]] typename SegmentOf<V>::Clipped nothing() {
  return {};
}

template <class V>
[[nodiscard]] typename SegmentOf<V>::Clipped kept(const V& p0, const V& p1, double t0, double t1) {
  typename SegmentOf<V>::Clipped r;
  r.kept = true;
  r.segment = {p0, p1};
  r.t0 = t0;
  r.t1 = t1;
  return r;
}

/// Moves the rounded crossing point p(t) toward p(target) until `inside(point)` holds: steps of
/// 2^-52, 2^-51, ... of the way, then the target itself (whose point the caller knows is inside
/// or is the best available). Returns the parameter used and writes the point.
template <class V, class Inside>
double adjust_inward(const V& a, const V& b, double t, double target, V& point, Inside inside) {
  if (inside(point)) return t;
  for (int k = -52; k < 0; ++k) {
    const double tk = t + std::ldexp(target - t, k);
    const V pk = point_at(a, b, tk);
    if (inside(pk)) {
      point = pk;
      return tk;
    }
  }
  point = point_at(a, b, target);
  return target;
}

}  // namespace contain::clip::detail
