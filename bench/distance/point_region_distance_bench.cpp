// Distance from points to a 2D region's boundary, single-threaded: points uniform in the
// bounding box of
//   demo      scenes::demo_polygon() (a flower shell of 2,000 vertices with two holes),
//   star10000 scenes::star_ring(10000, radii in [0.5, 1]) (spiky),
//   blob10000 a smooth star of 10,000 vertices (as bench/inside/point_in_polygon_bench.cpp),
// through
//   contain  distance::RegionDistance (unsigned, closest point and edge; the distance rounded
//            once; batch call on 1 thread),
//   geos     GEOSPreparedDistance_r on the prepared boundary (the rings as a MultiLineString,
//            so that both measure the distance to the rings; GEOS's distance to the polygon
//            itself is 0 inside), point geometries made before timing; and
//            GEOSPreparedDistanceWithin_r against the same boundary for --within.
// Times are thread CPU seconds of one run. Answers are compared outside the timed loops:
// distances within 1e-12 relative (GEOS's are floating point), within answers equal.
// Usage: point_region_distance_bench [points]

#include <geos_c.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "contain/distance/region_distance.h"
#include "scenes/scenes.h"

namespace {

using contain::Ring;
using contain::Vec2;

double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
double timed(const std::function<void()>& f) {
  const double t0 = thread_seconds();
  f();
  return thread_seconds() - t0;
}

Ring blob(int n) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  double amp[13], phase[13];
  for (int k = 2; k <= 12; ++k) {
    amp[k] = 0.3 / k * u(rng);
    phase[k] = 2 * std::numbers::pi * u(rng);
  }
  Ring r;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    double rad = 1;
    for (int k = 2; k <= 12; ++k)
      rad += amp[k] * std::sin(k * a + phase[k]);
    r.push_back({rad * std::cos(a), rad * std::sin(a)});
  }
  return r;
}

void run(const char* name, const std::vector<Ring>& rings, std::size_t count) {
  const contain::distance::RegionDistance prepared{std::span<const Ring>(rings)};
  const std::vector<Vec2> points =
      contain::scenes::uniform_points(contain::bounding_box(rings), count, 2);
  std::vector<contain::distance::Closest2> ours(points.size()), with_point(points.size());
  const double t_contain =
      timed([&] { prepared.distance(points, ours, {.closest_point = false}, {.threads = 1}); });
  const double t_contain_point =
      timed([&] { prepared.distance(points, with_point, {}, {.threads = 1}); });
  // within: a tenth of the region's size
  const contain::Box2 box = contain::bounding_box(rings);
  const double d = 0.1 * std::max(box.max.x - box.min.x, box.max.y - box.min.y);
  std::vector<std::uint8_t> ours_within(points.size());
  const double t_contain_within =
      timed([&] { prepared.within(points, d, ours_within, {.threads = 1}); });

  GEOSContextHandle_t ctx = GEOS_init_r();
  std::vector<GEOSGeometry*> lines;
  for (const Ring& ring : rings) {
    GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx, static_cast<unsigned>(ring.size() + 1), 2);
    for (std::size_t i = 0; i <= ring.size(); ++i) {
      const Vec2 v = ring[i % ring.size()];
      GEOSCoordSeq_setXY_r(ctx, seq, static_cast<unsigned>(i), v.x, v.y);
    }
    lines.push_back(GEOSGeom_createLineString_r(ctx, seq));
  }
  GEOSGeometry* boundary = GEOSGeom_createCollection_r(ctx, GEOS_MULTILINESTRING, lines.data(),
                                                       static_cast<unsigned>(lines.size()));
  const GEOSPreparedGeometry* prep = GEOSPrepare_r(ctx, boundary);
  std::vector<GEOSGeometry*> gp(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
    gp[k] = GEOSGeom_createPointFromXY_r(ctx, points[k].x, points[k].y);
  std::vector<double> theirs(points.size());
  const double t_geos = timed([&] {
    for (std::size_t k = 0; k < points.size(); ++k)
      GEOSPreparedDistance_r(ctx, prep, gp[k], &theirs[k]);
  });
  std::vector<char> theirs_within(points.size());
  const double t_geos_within = timed([&] {
    for (std::size_t k = 0; k < points.size(); ++k)
      theirs_within[k] = GEOSPreparedDistanceWithin_r(ctx, prep, gp[k], d) == 1;
  });
  std::size_t differ = 0, differ_within = 0;
  double worst = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double rel = std::fabs(theirs[k] - ours[k].distance) / std::max(ours[k].distance, 1e-300);
    worst = std::max(worst, rel);
    differ += rel > 1e-12;
    differ_within += (theirs_within[k] != 0) != (ours_within[k] != 0);
  }
  for (GEOSGeometry* g : gp)
    GEOSGeom_destroy_r(ctx, g);
  GEOSPreparedGeom_destroy_r(ctx, prep);
  GEOSGeom_destroy_r(ctx, boundary);
  GEOS_finish_r(ctx);

  std::printf("%s: %zu edges, %zu points uniform in its box\n", name, prepared.size(),
              points.size());
  std::printf("  %-44s %8.4f s %12.3e points/s\n", "contain RegionDistance (distance, edge)",
              t_contain, static_cast<double>(points.size()) / t_contain);
  std::printf("  %-44s %8.4f s %12.3e points/s\n", "contain RegionDistance (+ closest point)",
              t_contain_point, static_cast<double>(points.size()) / t_contain_point);
  std::printf(
      "  %-44s %8.4f s %12.3e points/s  x %.2f  distances differing > 1e-12: %zu (worst "
      "%.1e)\n",
      "GEOS 3.11 GEOSPreparedDistance (boundary)", t_geos,
      static_cast<double>(points.size()) / t_geos, t_geos / t_contain, differ, worst);
  std::printf("  %-44s %8.4f s %12.3e points/s\n", "contain RegionDistance::within (exact)",
              t_contain_within, static_cast<double>(points.size()) / t_contain_within);
  std::printf("  %-44s %8.4f s %12.3e points/s  x %.2f  answers differing: %zu\n",
              "GEOS GEOSPreparedDistanceWithin (boundary)", t_geos_within,
              static_cast<double>(points.size()) / t_geos_within, t_geos_within / t_contain_within,
              differ_within);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t count = argc > 1 ? std::stoul(argv[1]) : 1'000'000;
  run("demo polygon (shell and two holes)", contain::scenes::demo_polygon().rings, count);
  run("star10000", {contain::scenes::star_ring(10000, {0, 0}, 0.5, 1.0, 1)}, count);
  run("blob10000", {blob(10000)}, count);
  return 0;
}
