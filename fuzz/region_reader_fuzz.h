#pragma once
// The common body of the region reader targets: any text gives a region or an error, never a
// crash; a region read has finite rings of at least 3 points, survives a round trip through
// both writers, and can be prepared and queried.

#include <cmath>
#include <string>

#include "contain/inside/point_in_polygon.h"
#include "contain/inside/polygon_index.h"
#include "contain/io/geojson.h"
#include "contain/io/wkt.h"
#include "fuzz_support.h"

namespace contain::fuzz {

inline void check_region(const MultiPolygon& region) {
  for (const Polygon& polygon : region.polygons) {
    for (const Ring& ring : polygon.rings) {
      FUZZ_CHECK(ring.size() >= 3);
      for (const Vec2& p : ring)
        FUZZ_CHECK(std::isfinite(p.x) && std::isfinite(p.y));
    }
  }
  auto wkt = io::parse_wkt(io::format_wkt(region), "round trip");
  if (!wkt) std::fprintf(stderr, "%s\n", wkt.error().what().c_str());
  FUZZ_CHECK(wkt.ok());
  FUZZ_CHECK(wkt->all_rings() == region.all_rings());
  auto json = io::parse_geojson(io::format_geojson(region), "round trip");
  if (!json) std::fprintf(stderr, "%s\n", json.error().what().c_str());
  FUZZ_CHECK(json.ok());
  FUZZ_CHECK(json->all_rings() == region.all_rings());
  // Every vertex lies on its ring: a query there must not report the far outside.
  if (region.all_rings().size() < 8) {
    const inside::PolygonIndex index(region);
    for (const Ring& ring : region.all_rings()) {
      const Vec2 v = ring.front();
      FUZZ_CHECK(index.locate(v) == inside::point_in_polygon(region, v));
    }
  }
}

}  // namespace contain::fuzz
