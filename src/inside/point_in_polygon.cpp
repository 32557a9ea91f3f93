#include "contain/inside/point_in_polygon.h"

#include "inside/polygon_kernel.h"

namespace contain::inside {

Location point_in_polygon(std::span<const Ring> rings, Vec2 point,
                          const PointInPolygonOptions& options) {
  detail::RayAccumulator ray(point);
  for (const Ring& ring : rings)
    ray.add_ring(ring);
  return ray.location(options.fill);
}

Location point_in_polygon(const Polygon& polygon, Vec2 point,
                          const PointInPolygonOptions& options) {
  return point_in_polygon(std::span<const Ring>(polygon.rings), point, options);
}

Location point_in_polygon(const MultiPolygon& polygons, Vec2 point,
                          const PointInPolygonOptions& options) {
  detail::RayAccumulator ray(point);
  for (const Polygon& polygon : polygons.polygons) {
    for (const Ring& ring : polygon.rings)
      ray.add_ring(ring);
  }
  return ray.location(options.fill);
}

}  // namespace contain::inside
