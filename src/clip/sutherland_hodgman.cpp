#include "contain/clip/sutherland_hodgman.h"

#include "clip/convex_functions.h"
#include "clip/ring_clip.h"

namespace contain::clip {

Ring sutherland_hodgman(const Ring& ring, const HalfPlane& half_plane) {
  return detail::sutherland_hodgman_ring(ring, predicates::LineFunction{half_plane});
}

Ring sutherland_hodgman(const Ring& ring, std::span<const HalfPlane> half_planes) {
  Ring out = ring;
  for (const HalfPlane& h : half_planes) {
    if (out.empty()) break;
    out = detail::sutherland_hodgman_ring(out, predicates::LineFunction{h});
  }
  return out;
}

Ring sutherland_hodgman(const Ring& ring, const Ring& convex_ring) {
  const auto edges = detail::edge_functions(convex_ring);
  if (!edges) return {};
  Ring out = ring;
  for (const auto& e : *edges) {
    if (out.empty()) break;
    out = detail::sutherland_hodgman_ring(out, e);
  }
  return out;
}

std::vector<Vec3> sutherland_hodgman(std::span<const Vec3> polygon, const Plane& half_space) {
  return detail::sutherland_hodgman_ring(std::vector<Vec3>(polygon.begin(), polygon.end()),
                                         predicates::PlaneFunction{half_space});
}

std::vector<Vec3> sutherland_hodgman(std::span<const Vec3> polygon,
                                     std::span<const Plane> half_spaces) {
  std::vector<Vec3> out(polygon.begin(), polygon.end());
  for (const Plane& h : half_spaces) {
    if (out.empty()) break;
    out = detail::sutherland_hodgman_ring(out, predicates::PlaneFunction{h});
  }
  return out;
}

}  // namespace contain::clip
