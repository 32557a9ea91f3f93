#include "clip/convex_functions.h"

#include <algorithm>

namespace contain::clip::detail {

std::vector<predicates::PlaneFunction> plane_functions(std::span<const Plane> planes) {
  std::vector<predicates::PlaneFunction> out;
  out.reserve(planes.size());
  for (const Plane& p : planes)
    out.push_back({p});
  return out;
}

std::vector<predicates::LineFunction> line_functions(std::span<const HalfPlane> lines) {
  std::vector<predicates::LineFunction> out;
  out.reserve(lines.size());
  for (const HalfPlane& l : lines)
    out.push_back({l});
  return out;
}

std::vector<predicates::FaceFunction> face_functions(std::span<const Triangle3> faces) {
  std::vector<predicates::FaceFunction> out;
  out.reserve(faces.size());
  for (const Triangle3& f : faces)
    out.push_back({f});
  return out;
}

std::optional<std::vector<predicates::EdgeFunction>> edge_functions(const Ring& ring) {
  const std::size_t n = ring.size();
  Sign orientation = Sign::zero;
  for (std::size_t i = 0; i < n && orientation == Sign::zero; ++i) {
    for (std::size_t j = i + 1; j < n && orientation == Sign::zero; ++j) {
      if (ring[j] == ring[i]) continue;
      for (std::size_t k = j + 1; k < n; ++k) {
        orientation = predicates::orient2d(ring[i], ring[j], ring[k]);
        if (orientation != Sign::zero) break;
      }
      break;  // ring[i], ring[j] distinct: the first distinct pair decides
    }
  }
  if (orientation == Sign::zero) return std::nullopt;
  std::vector<predicates::EdgeFunction> edges;
  edges.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = ring[i], q = ring[(i + 1) % n];
    if (p == q) continue;
    edges.push_back(orientation == Sign::positive ? predicates::EdgeFunction{p, q}
                                                  : predicates::EdgeFunction{q, p});
  }
  return edges;
}

}  // namespace contain::clip::detail
