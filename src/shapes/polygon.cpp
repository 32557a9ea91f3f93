#include "contain/shapes/polygon.h"

#include <string>

namespace contain::shapes {

Result<Polygon> Polygon::from_rings(std::vector<Ring> rings) {
  for (std::size_t r = 0; r < rings.size(); ++r) {
    Ring& ring = rings[r];
    for (const Vec2& p : ring) {
      if (!is_finite(p)) {
        return Error{ErrorKind::invalid_value,
                     "ring " + std::to_string(r + 1) + " has a NaN or infinite coordinate"};
      }
    }
    if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
    if (ring.size() < 3) {
      return Error{ErrorKind::degenerate,
                   "ring " + std::to_string(r + 1) + " has fewer than 3 distinct points"};
    }
  }
  return Polygon{std::move(rings)};
}

bool MultiPolygon::empty() const {
  for (const Polygon& p : polygons) {
    if (!p.empty()) return false;
  }
  return true;
}

std::vector<Ring> MultiPolygon::all_rings() const {
  std::vector<Ring> out;
  for (const Polygon& p : polygons)
    out.insert(out.end(), p.rings.begin(), p.rings.end());
  return out;
}

Box2 bounding_box(std::span<const Ring> rings) {
  Box2 box;
  for (const Ring& ring : rings) {
    for (const Vec2& p : ring)
      box.expand(p);
  }
  return box;
}

double signed_area2(const Ring& ring) {
  double sum = 0.0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
    sum += cross(ring[i], ring[(i + 1) % n]);
  return sum;
}

}  // namespace contain::shapes
