#include "contain/bound/bounding_circle.h"

#include <vector>

#include "bound/enclose.h"
#include "contain/predicates/compare_distance.h"

namespace contain::bound {

Result<Circle> bounding_circle(std::span<const Vec2> points, const BoundingCircleOptions& options) {
  auto ball = detail::enclose(points, options.method, [](Vec2 center, double radius, Vec2 p) {
    return predicates::side_of_circle(Circle{center, radius}, p);
  });
  if (!ball.ok()) return ball.error();
  return Circle{ball->center, ball->radius};
}

Result<Circle> bounding_circle(const Polygon& polygon, const BoundingCircleOptions& options) {
  std::vector<Vec2> points;
  for (const Ring& ring : polygon.rings)
    points.insert(points.end(), ring.begin(), ring.end());
  return bounding_circle(points, options);
}

Result<Circle> bounding_circle(const MultiPolygon& multi_polygon,
                               const BoundingCircleOptions& options) {
  std::vector<Vec2> points;
  for (const Polygon& polygon : multi_polygon.polygons) {
    for (const Ring& ring : polygon.rings) {
      points.insert(points.end(), ring.begin(), ring.end());
    }
  }
  return bounding_circle(points, options);
}

}  // namespace contain::bound
