#include "contain/clip/cyrus_beck.h"

#include <vector>

#include "clip/convex_functions.h"
#include "clip/cyrus_beck_impl.h"

namespace contain::clip {

ClippedSegment3 cyrus_beck(const Segment3& segment, std::span<const Plane> half_spaces) {
  const auto functions = detail::plane_functions(half_spaces);
  return detail::cyrus_beck_clip<Vec3, predicates::PlaneFunction>(segment.a, segment.b, functions);
}

ClippedSegment3 cyrus_beck(const Segment3& segment, const ConvexPolyhedron& polyhedron) {
  if (!polyhedron.faces().empty()) {
    const auto functions = detail::face_functions(polyhedron.faces());
    return detail::cyrus_beck_clip<Vec3, predicates::FaceFunction>(segment.a, segment.b, functions);
  }
  return cyrus_beck(segment, std::span<const Plane>(polyhedron.planes()));
}

ClippedSegment2 cyrus_beck(const Segment2& segment, std::span<const HalfPlane> half_planes) {
  const auto functions = detail::line_functions(half_planes);
  return detail::cyrus_beck_clip<Vec2, predicates::LineFunction>(segment.a, segment.b, functions);
}

ClippedSegment2 cyrus_beck(const Segment2& segment, const Ring& convex_ring) {
  const auto edges = detail::edge_functions(convex_ring);
  if (!edges) return {};  // encloses nothing
  return detail::cyrus_beck_clip<Vec2, predicates::EdgeFunction>(segment.a, segment.b, *edges);
}

}  // namespace contain::clip
