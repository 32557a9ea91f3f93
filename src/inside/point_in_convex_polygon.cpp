#include "contain/inside/point_in_convex_polygon.h"

#include "contain/predicates/orient2d.h"

namespace contain::inside {

Location point_in_convex_polygon(const Ring& ring, Vec2 point,
                                 const PointInPolygonOptions& options) {
  const std::size_t n = ring.size();
  // The orientation: the first turn that is not straight (skipping repeated points).
  Sign orientation = Sign::zero;
  for (std::size_t i = 0; i < n && orientation == Sign::zero; ++i) {
    orientation = predicates::orient2d(ring[i], ring[(i + 1) % n], ring[(i + 2) % n]);
  }
  if (orientation == Sign::zero) return Location::outside;  // zero area: encloses nothing
  if (!is_filled(options.fill, to_int(orientation))) return Location::outside;

  bool on_line = false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i];
    const Vec2 b = ring[(i + 1) % n];
    if (a == b) continue;
    const Sign side = predicates::orient2d(a, b, point);
    if (side == -orientation) return Location::outside;
    if (side == Sign::zero) on_line = true;
  }
  return on_line ? Location::boundary : Location::inside;
}

}  // namespace contain::inside
