#include "contain/clip/segment_halfspace.h"

#include <algorithm>

#include "clip/segment_common.h"
#include "contain/predicates/halfspace_function.h"

namespace contain::clip {
namespace {

template <class V, class F>
SegmentCase case_of(const V& a, const V& b, const F& f) {
  const bool in_a = f.side(a) != Sign::negative, in_b = f.side(b) != Sign::negative;
  if (in_a && in_b) return SegmentCase::inside;
  if (!in_a && !in_b) return SegmentCase::outside;
  return SegmentCase::crossing;
}

template <class V, class F>
double parameter(const V& a, const V& b, const F& f) {
  const double sa = f.approx(a).value, sb = f.approx(b).value;
  return sa / (sa - sb);
}

template <class V, class F>
typename detail::SegmentOf<V>::Clipped clip_by_function(const V& a, const V& b, const F& f) {
  const Sign sa = f.side(a), sb = f.side(b);
  const bool in_a = sa != Sign::negative, in_b = sb != Sign::negative;
  if (in_a && in_b) return detail::kept(a, b, 0.0, 1.0);
  if (!in_a && !in_b) return detail::nothing<V>();
  // One in, one out: the out endpoint moves to the crossing; an in endpoint on the plane is the
  // crossing itself (touching).
  if (sa == Sign::zero) return detail::kept(a, a, 0.0, 0.0);
  if (sb == Sign::zero) return detail::kept(b, b, 1.0, 1.0);
  const double t = std::clamp(parameter(a, b, f), 0.0, 1.0);
  V p = detail::point_at(a, b, t);
  auto inside = [&](const V& q) { return f.side(q) != Sign::negative; };
  if (in_a) {
    const double t1 = detail::adjust_inward(a, b, t, 0.0, p, inside);
    return detail::kept(a, p, 0.0, t1);
  }
  const double t0 = detail::adjust_inward(a, b, t, 1.0, p, inside);
  return detail::kept(p, b, t0, 1.0);
}

}  // namespace

SegmentCase segment_case(const Segment3& s, const Plane& h) {
  return case_of(s.a, s.b, predicates::PlaneFunction{h});
}
SegmentCase segment_case(const Segment2& s, const HalfPlane& h) {
  return case_of(s.a, s.b, predicates::LineFunction{h});
}
double crossing_parameter(const Segment3& s, const Plane& h) {
  return parameter(s.a, s.b, predicates::PlaneFunction{h});
}
double crossing_parameter(const Segment2& s, const HalfPlane& h) {
  return parameter(s.a, s.b, predicates::LineFunction{h});
}
ClippedSegment3 clip_segment(const Segment3& s, const Plane& h) {
  return clip_by_function(s.a, s.b, predicates::PlaneFunction{h});
}
ClippedSegment2 clip_segment(const Segment2& s, const HalfPlane& h) {
  return clip_by_function(s.a, s.b, predicates::LineFunction{h});
}

}  // namespace contain::clip
