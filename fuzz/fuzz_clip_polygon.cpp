// libFuzzer target: OGC-valid regions (random rings made valid by the boolean engine's union)
// clipped by a box, by the box's four half-planes and by the box as a convex ring, with box sides
// often on the region's coordinates (vertices and edges on the sides, crossings at corners).
// Claims checked:
// - every result is valid by the exact OGC checker of the tests (tests/clip/boolean_checks.h);
// - the box cut's area is the boolean engine's (region intersected with the box as a polygon)
//   within the documented rounding of crossings, and so are the other two forms';
// - BoxClipper gives clip_polygon's result bit for bit.
#include <algorithm>
#include <cmath>
#include <vector>

#include "clip/boolean_checks.h"
#include "contain/clip/box_clipper.h"
#include "contain/clip/clip_polygon.h"
#include "contain/clip/polygon_boolean.h"
#include "fuzz_support.h"

namespace {

using namespace contain;

double area(const MultiPolygon& m) {
  return test::exact_signed_area(m).get_d();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::FuzzInput in(data, size);
  in.choose_scale();
  std::vector<Ring> rings(1 + in.byte() % 3);
  std::vector<double> coordinates;
  for (Ring& ring : rings) {
    ring.resize(3 + in.byte() % 8);
    for (Vec2& v : ring) {
      v = in.point2();
      coordinates.push_back(v.x);
      coordinates.push_back(v.y);
    }
  }
  const std::vector<Ring> none;
  const MultiPolygon region =
      clip::polygon_boolean(rings, none, {.op = clip::Op::union_, .fill = Fill::even_odd});
  // Box sides: mostly the region's own coordinates, else fuzzed ones.
  double side[4];
  for (double& s : side) {
    const std::uint8_t how = in.byte();
    s = how % 3 != 0 ? coordinates[how % coordinates.size()] : in.coordinate();
  }
  const Box2 box{{std::min(side[0], side[1]), std::min(side[2], side[3])},
                 {std::max(side[0], side[1]), std::max(side[2], side[3])}};
  const MultiPolygon cut = clip::clip_polygon(region, box);
  const ::testing::AssertionResult valid = test::is_valid_ogc(cut);
  if (!valid) std::fprintf(stderr, "box: %s\n", valid.message());
  FUZZ_CHECK(valid);
  FUZZ_CHECK(clip::BoxClipper(region).clip(box) == cut);
  const std::vector<HalfPlane> planes{
      {1, 0, -box.min.x}, {-1, 0, box.max.x}, {0, 1, -box.min.y}, {0, -1, box.max.y}};
  const MultiPolygon by_planes = clip::clip_polygon(region, planes);
  FUZZ_CHECK(test::is_valid_ogc(by_planes));
  const Ring frame{box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
  const MultiPolygon by_ring = clip::clip_polygon(region, frame);
  FUZZ_CHECK(test::is_valid_ogc(by_ring));
  double e = 0.0;
  for (const double c : coordinates)
    e = std::max(e, std::abs(c));
  e = 2 * std::max({e, std::abs(box.min.x), std::abs(box.min.y), std::abs(box.max.x),
                    std::abs(box.max.y)});
  if (box.min.x < box.max.x && box.min.y < box.max.y && e * e < 1e300) {
    const MultiPolygon engine = clip::polygon_boolean(region.all_rings(), std::vector<Ring>{frame},
                                                      {.op = clip::Op::intersection});
    // Each side moves each crossing point by a few ulps of the extent; at most 24 ring edges.
    const double tolerance = 1e-12 * e * e * 64;
    FUZZ_CHECK(std::abs(area(cut) - area(engine)) <= tolerance);
    FUZZ_CHECK(std::abs(area(by_planes) - area(engine)) <= tolerance);
    FUZZ_CHECK(std::abs(area(by_ring) - area(engine)) <= tolerance);
  }
  return 0;
}
