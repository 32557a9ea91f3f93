// libFuzzer target: point in polygon on random and degenerate rings (repeated points, zero-area
// rings, spikes, collinear edges, rings of 1 or 2 points, 2^±1000 scalings). Claims checked:
// - the one-shot point_in_polygon and PolygonIndex (coarse, default and fine grids, one-by-one
//   and batch) give the same answer for every point and fill rule;
// - fill rules nest: inside under even-odd, positive or negative implies inside under nonzero;
// - the angle-sum reference agrees on boundary points always, and elsewhere wherever the point
//   is clearly away from every edge (its floating-point angles cannot round to a wrong turn).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "contain/inside/point_in_polygon.h"
#include "contain/inside/point_in_polygon_angle_sum.h"
#include "contain/inside/polygon_index.h"
#include "fuzz_support.h"

namespace {

using namespace contain;

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// True when the angle sum is certain to round to the right winding number: every coordinate in
// a comfortable range and the point farther from every edge than a millionth of the scale.
bool clearly_off_boundary(const std::vector<Ring>& rings, Vec2 p) {
  double scale = std::max(std::abs(p.x), std::abs(p.y));
  for (const Ring& ring : rings) {
    for (const Vec2& v : ring)
      scale = std::max({scale, std::abs(v.x), std::abs(v.y)});
  }
  if (scale == 0.0 || scale > 1e100 || scale < 1e-100) return false;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (distance_to_segment(p, ring[i], ring[(i + 1) % ring.size()]) <= 1e-6 * scale) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::FuzzInput in(data, size);
  in.choose_scale();
  std::vector<Ring> rings(1 + in.byte() % 3);
  for (Ring& ring : rings) {
    ring.resize(1 + in.byte() % 12);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      // Sometimes repeat an earlier vertex: spikes, pinches, zero-length edges.
      const std::uint8_t how = in.byte();
      ring[i] = (i > 0 && how % 8 == 0) ? ring[how / 8 % i] : in.point2();
    }
  }
  std::vector<Vec2> points;
  for (int k = 0; k < 6; ++k) {
    const std::uint8_t how = in.byte();
    const Ring& ring = rings[how % rings.size()];
    const Vec2 u = ring[how / 4 % ring.size()], v = ring[(how / 4 + 1) % ring.size()];
    switch (how % 3) {
      case 0:
        points.push_back(u);  // a vertex
        break;
      case 1:
        points.push_back({u.x / 2 + v.x / 2, u.y / 2 + v.y / 2});  // on (or next to) an edge
        break;
      default:
        points.push_back(in.point2());
    }
  }

  if (std::getenv("FUZZ_VERBOSE") != nullptr) {
    for (const Ring& ring : rings) {
      std::fprintf(stderr, "ring:");
      for (const Vec2& v : ring)
        std::fprintf(stderr, " (%a, %a)", v.x, v.y);
      std::fprintf(stderr, "\n");
    }
    for (const Vec2& p : points)
      std::fprintf(stderr, "point (%a, %a)\n", p.x, p.y);
  }
  for (const Fill fill : {Fill::even_odd, Fill::nonzero, Fill::positive, Fill::negative}) {
    // Grids capped small: a far vertex makes the grid as fine as max_cells allows, and the
    // default 2^20 cells cost seconds per input here, more where coordinates span 2^±900 and
    // the predicates go to big numbers (the answers do not depend on the grid).
    const inside::PolygonIndex index(rings, {.fill = fill, .min_cells = 64, .max_cells = 1 << 10});
    const inside::PolygonIndex coarse(rings, {.fill = fill, .min_cells = 1, .max_cells = 4});
    const inside::PolygonIndex fine(
        rings, {.fill = fill, .cells_per_edge = 64, .min_cells = 1, .max_cells = 1 << 12});
    std::vector<Location> batch(points.size());
    index.locate(points, batch, {.threads = 1});
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec2 p = points[i];
      const Location truth = inside::point_in_polygon(rings, p, {.fill = fill});
      FUZZ_CHECK(index.locate(p) == truth);
      FUZZ_CHECK(coarse.locate(p) == truth);
      FUZZ_CHECK(fine.locate(p) == truth);
      FUZZ_CHECK(batch[i] == truth);
      const Location angle = inside::point_in_polygon_angle_sum(rings, p, {.fill = fill});
      if (truth == Location::boundary || angle == Location::boundary) {
        FUZZ_CHECK(angle == truth);
      } else if (clearly_off_boundary(rings, p)) {
        FUZZ_CHECK(angle == truth);
      }
      if (truth == Location::inside) {
        FUZZ_CHECK(inside::point_in_polygon(rings, p, {.fill = Fill::nonzero}) == Location::inside);
      }
    }
  }
  return 0;
}
