// The public entry of the polygon booleans: the engine (boolean/engine.h) does the work.

#include "contain/clip/polygon_boolean.h"

#include <vector>

#include "clip/boolean/engine.h"

namespace contain::clip {

MultiPolygon polygon_boolean(std::span<const Ring> a, std::span<const Ring> b,
                             const PolygonBooleanOptions& options) {
  return detail::boolean_engine(a, b, options, nullptr);
}

PolygonBooleanResult polygon_boolean_with_stats(std::span<const Ring> a, std::span<const Ring> b,
                                                const PolygonBooleanOptions& options) {
  PolygonBooleanResult result;
  result.region = detail::boolean_engine(a, b, options, &result.stats);
  return result;
}

MultiPolygon polygon_boolean(const MultiPolygon& a, const MultiPolygon& b,
                             const PolygonBooleanOptions& options) {
  const std::vector<Ring> ra = a.all_rings(), rb = b.all_rings();
  return polygon_boolean(ra, rb, options);
}

MultiPolygon polygon_boolean(const Polygon& a, const Polygon& b,
                             const PolygonBooleanOptions& options) {
  return polygon_boolean(a.rings, b.rings, options);
}

}  // namespace contain::clip
