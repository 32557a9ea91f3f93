#include "contain/clip/liang_barsky.h"

#include "clip/box_exact.h"

namespace contain::clip {

ClippedSegment2 liang_barsky(const Segment2& segment, const Box2& box) {
  return detail::liang_barsky_exact(segment.a, segment.b, box);
}
ClippedSegment3 liang_barsky(const Segment3& segment, const Box3& box) {
  return detail::liang_barsky_exact(segment.a, segment.b, box);
}

}  // namespace contain::clip
