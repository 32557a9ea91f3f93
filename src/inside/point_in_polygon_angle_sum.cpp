#include "contain/inside/point_in_polygon_angle_sum.h"

#include <cmath>
#include <numbers>

#include "inside/polygon_kernel.h"

namespace contain::inside {

Location point_in_polygon_angle_sum(std::span<const Ring> rings, Vec2 point,
                                    const PointInPolygonOptions& options) {
  // Exact first: the floating-point sum cannot tell a point on an edge (angle pi) from one near it.
  for (const Ring& ring : rings) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (detail::on_segment(ring[i], ring[(i + 1) % n], point)) {
        return point_in_polygon(rings, point, options);
      }
    }
  }
  double sum = 0.0;
  for (const Ring& ring : rings) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 u = ring[i] - point;
      const Vec2 v = ring[(i + 1) % n] - point;
      sum += std::atan2(cross(u, v), dot(u, v));
    }
  }
  const int winding = static_cast<int>(std::lround(sum / (2.0 * std::numbers::pi)));
  return is_filled(options.fill, winding) ? Location::inside : Location::outside;
}

Location point_in_polygon_angle_sum(const Polygon& polygon, Vec2 point,
                                    const PointInPolygonOptions& options) {
  return point_in_polygon_angle_sum(std::span<const Ring>(polygon.rings), point, options);
}

}  // namespace contain::inside
