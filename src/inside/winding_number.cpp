#include "contain/inside/winding_number.h"

#include "inside/polygon_kernel.h"

namespace contain::inside {

int winding_number(std::span<const Ring> rings, Vec2 point) {
  int winding = 0;
  for (const Ring& ring : rings) {
    const std::size_t n = ring.size();
    if (n == 0) continue;
    Vec2 a = ring[n - 1];
    for (const Vec2& b : ring) {
      bool incident = false;  // edges through the point add nothing (right-up perturbation)
      winding += detail::ray_crossing(a, b, point, incident);
      a = b;
    }
  }
  return winding;
}

int winding_number(const Polygon& polygon, Vec2 point) {
  return winding_number(std::span<const Ring>(polygon.rings), point);
}

}  // namespace contain::inside
