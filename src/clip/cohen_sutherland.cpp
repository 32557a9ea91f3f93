#include "contain/clip/cohen_sutherland.h"

#include <bit>

#include "clip/box_exact.h"

namespace contain::clip {
namespace {

template <class V, class Box>
std::uint8_t code_of(const V& p, const Box& box) {
  std::uint8_t code = 0;
  for (int k = 0; k < detail::dimension<V>; ++k) {
    const double x = detail::coord(p, k);
    if (x < detail::coord(box.min, k)) code |= static_cast<std::uint8_t>(1u << (2 * k));
    if (x > detail::coord(box.max, k)) code |= static_cast<std::uint8_t>(1u << (2 * k + 1));
  }
  return code;
}

// The exact code word of the true point of a parameter (see box_exact.h).
template <class V, class Box>
std::uint8_t code_of(const detail::BoxLine<V>& line, const detail::BoxParam& p, const Box& box) {
  if (!p.is_face()) return code_of(p.value == 0.0 ? line.a() : line.b(), box);
  std::uint8_t code = 0;
  for (int j = 0; j < detail::dimension<V>; ++j) {
    if (j == p.axis) continue;
    if (line.crossing_coord_sign(p, j, detail::coord(box.min, j)) < 0) {
      code |= static_cast<std::uint8_t>(1u << (2 * j));
    }
    if (line.crossing_coord_sign(p, j, detail::coord(box.max, j)) > 0) {
      code |= static_cast<std::uint8_t>(1u << (2 * j + 1));
    }
  }
  return code;
}

// The section's loop: trivial accept, trivial reject, else clip at the first differing bit.
template <class V, class Box>
typename detail::SegmentOf<V>::Clipped clip_to_box(const V& a, const V& b, const Box& box) {
  if (box.empty()) return detail::nothing<V>();
  const detail::BoxLine<V> line(a, b);
  detail::BoxParam p0 = detail::start_param, p1 = detail::end_param;
  std::uint8_t c0 = code_of(a, box), c1 = code_of(b, box);
  // Each step clears, for good, one bit of one endpoint: at most 2 D steps.
  for (int step = 0; step <= 2 * detail::dimension<V>; ++step) {
    if ((c0 | c1) == 0) return detail::box_result(line, box, p0, p1);  // trivial accept
    if ((c0 & c1) != 0) return detail::nothing<V>();                   // trivial reject
    const int bit = std::countr_zero(static_cast<unsigned>(c0 ^ c1));
    const int axis = bit / 2;
    const detail::BoxParam face{
        axis, (bit & 1) == 0 ? detail::coord(box.min, axis) : detail::coord(box.max, axis)};
    if ((c0 >> bit) & 1u) {
      p0 = face;
      c0 = code_of(line, face, box);
    } else {
      p1 = face;
      c1 = code_of(line, face, box);
    }
  }
  return detail::nothing<V>();  // unreachable: the codes are exact
}

}  // namespace

std::uint8_t outcode(Vec2 p, const Box2& box) {
  return code_of(p, box);
}
std::uint8_t outcode(Vec3 p, const Box3& box) {
  return code_of(p, box);
}

ClippedSegment2 cohen_sutherland(const Segment2& segment, const Box2& box) {
  return clip_to_box(segment.a, segment.b, box);
}
ClippedSegment3 cohen_sutherland(const Segment3& segment, const Box3& box) {
  return clip_to_box(segment.a, segment.b, box);
}

}  // namespace contain::clip
