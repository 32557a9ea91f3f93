// Point in polygon, single-threaded: 1,000,000 points uniform in the bounding box of
//   star10000  scenes::star_ring(10000, radii uniform in [0.5, 1]): a random star, very spiky
//              (a horizontal line crosses hundreds of edges),
//   blob10000  a smooth random star of 10,000 vertices: radius 1 + sum_k (0.3/k) u_k
//              sin(k angle + phase_k), k = 2..12 (concave lobes, few crossings per line),
//   star100    scenes::star_ring(100, radii uniform in [0.5, 1]),
// through
//   contain   inside::PolygonIndex (exact; batch call on 1 thread; build time reported apart),
//   crossing  a plain even-odd crossing loop over the edges (PNPOLY style, floating point),
//   boost     boost::geometry::within (no index),
//   geos      GEOSPreparedContains_r on a prepared polygon (point geometries made before timing),
//   cgal      CGAL::bounded_side_2, Exact_predicates_inexact_constructions_kernel (no index).
// The O(n)-per-point peers run on the first 20,000 points for the 10,000-vertex polygons, GEOS on
// the first 100,000 of star10000 (their rates are per point, like the others). Answers are checked
// outside the timed loops against the index, itself checked against the one-shot
// inside::point_in_polygon; a uniform point on an edge has probability ~0, so a boolean "inside" is
// compared with location == inside. Counters: points_per_s, x_contain (contain's rate / this rate),
// mismatches. Rates are points per second of thread CPU time (the 2-core machine is shared; wall
// time varies with its load).
#include <benchmark/benchmark.h>
#include <geos_c.h>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "contain/inside/point_in_polygon.h"
#include "contain/inside/polygon_index.h"
#include "scenes/scenes.h"

#ifdef CONTAIN_BENCH_HAS_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#endif

namespace {

using contain::Location;
using contain::Ring;
using contain::Vec2;

constexpr std::size_t kPoints = 1'000'000;
constexpr std::size_t kSlowPoints = 20'000;  // O(n) peers on the 10,000-vertex polygon

struct Scene {
  Ring ring;
  std::vector<Vec2> points;
  std::vector<Location> truth;  // from the index (checked against the one-shot test)
  double contain_rate = 0.0;
};

Ring blob_ring(int vertices, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), phase(0.0, 2.0 * std::numbers::pi);
  std::vector<double> amplitude, shift;
  for (int k = 2; k <= 12; ++k) {
    amplitude.push_back(0.3 / k * u(rng));
    shift.push_back(phase(rng));
  }
  Ring ring;
  for (int i = 0; i < vertices; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / vertices;
    double r = 1.0;
    for (int k = 2; k <= 12; ++k) {
      r += amplitude[static_cast<std::size_t>(k - 2)] *
           std::sin(k * angle + shift[static_cast<std::size_t>(k - 2)]);
    }
    ring.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  return ring;
}

enum SceneId : int { star10000 = 0, blob10000 = 1, star100 = 2 };

int vertex_count(int id) {
  return id == star100 ? 100 : 10000;
}

Scene& scene(int id) {
  static std::map<int, Scene> scenes;
  auto it = scenes.find(id);
  if (it != scenes.end()) return it->second;
  Scene& s = scenes[id];
  s.ring = id == blob10000 ? blob_ring(10000, 42)
                           : contain::scenes::star_ring(vertex_count(id), {0, 0}, 0.5, 1.0, 42);
  const std::vector<Ring> rings{s.ring};
  s.points = contain::scenes::uniform_points(contain::bounding_box(rings), kPoints, 7);
  const contain::inside::PolygonIndex index(std::span<const Ring>(rings), {});
  s.truth.resize(kPoints);
  index.locate(s.points, s.truth, {.threads = 0});
  std::size_t bad = 0;
  for (std::size_t k = 0; k < kPoints; k += 50) {
    bad +=
        contain::inside::point_in_polygon(std::span<const Ring>(rings), s.points[k]) != s.truth[k]
            ? 1
            : 0;
  }
  if (bad != 0) std::fprintf(stderr, "index disagrees with point_in_polygon on %zu points\n", bad);
  return s;
}

std::size_t point_count(int id) {
  return vertex_count(id) > 1000 ? kSlowPoints : kPoints;
}

template <class Inside>
std::size_t mismatches(const Scene& s, std::size_t count, Inside&& inside) {
  std::size_t bad = 0;
  for (std::size_t k = 0; k < count; ++k) {
    bad += inside(k) != (s.truth[k] == Location::inside) ? 1 : 0;
  }
  return bad;
}

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Runs the timed loop: `body(count)` processes the first `count` points once.
template <class Body>
void run(benchmark::State& state, Scene& s, std::size_t count, std::size_t bad, bool is_contain,
         Body&& body) {
  double seconds = 0.0;
  std::size_t done = 0;
  for (auto _ : state) {
    const double start = thread_seconds();
    body(count);
    seconds += thread_seconds() - start;
    done += count;
  }
  const double rate = static_cast<double>(done) / seconds;
  if (is_contain) s.contain_rate = rate;
  state.counters["points_per_s"] = rate;
  state.counters["x_contain"] = s.contain_rate > 0 ? s.contain_rate / rate : 0.0;
  state.counters["mismatches"] = static_cast<double>(bad);
  state.SetItemsProcessed(static_cast<std::int64_t>(done));
}

void contain_index(benchmark::State& state) {
  Scene& s = scene(static_cast<int>(state.range(0)));
  const std::vector<Ring> rings{s.ring};
  const double build_start = thread_seconds();
  const contain::inside::PolygonIndex index(std::span<const Ring>(rings), {});
  const double build_ms = 1e3 * (thread_seconds() - build_start);
  std::vector<Location> out(kPoints);
  index.locate(s.points, out, {.threads = 1});
  std::size_t bad = 0;
  for (std::size_t k = 0; k < kPoints; ++k)
    bad += out[k] != s.truth[k] ? 1 : 0;
  run(state, s, kPoints, bad, true, [&](std::size_t count) {
    index.locate(std::span<const Vec2>(s.points).first(count), std::span<Location>(out),
                 {.threads = 1});
    benchmark::DoNotOptimize(out.data());
  });
  state.counters["build_ms"] = build_ms;
  state.counters["cells"] = static_cast<double>(index.stats().cells);
  state.counters["edge_refs"] = static_cast<double>(index.stats().edge_refs);
}

bool crossing_inside(const Ring& ring, Vec2 p) {
  bool inside = false;
  const std::size_t n = ring.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 a = ring[i], b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
      inside = !inside;
    }
  }
  return inside;
}

void crossing_loop(benchmark::State& state) {
  Scene& s = scene(static_cast<int>(state.range(0)));
  const std::size_t count = point_count(static_cast<int>(state.range(0)));
  const std::size_t bad =
      mismatches(s, count, [&](std::size_t k) { return crossing_inside(s.ring, s.points[k]); });
  std::vector<char> out(count);
  run(state, s, count, bad, false, [&](std::size_t n) {
    for (std::size_t k = 0; k < n; ++k)
      out[k] = crossing_inside(s.ring, s.points[k]) ? 1 : 0;
    benchmark::DoNotOptimize(out.data());
  });
}

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint, false>;  // counter-clockwise, closed

void boost_within(benchmark::State& state) {
  Scene& s = scene(static_cast<int>(state.range(0)));
  const std::size_t count = point_count(static_cast<int>(state.range(0)));
  BPolygon polygon;
  for (const Vec2& v : s.ring)
    bg::append(polygon.outer(), BPoint(v.x, v.y));
  bg::append(polygon.outer(), BPoint(s.ring.front().x, s.ring.front().y));
  const std::size_t bad = mismatches(s, count, [&](std::size_t k) {
    return bg::within(BPoint(s.points[k].x, s.points[k].y), polygon);
  });
  std::vector<char> out(count);
  run(state, s, count, bad, false, [&](std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
      out[k] = bg::within(BPoint(s.points[k].x, s.points[k].y), polygon) ? 1 : 0;
    }
    benchmark::DoNotOptimize(out.data());
  });
}

void geos_prepared(benchmark::State& state) {
  Scene& s = scene(static_cast<int>(state.range(0)));
  const std::size_t count = state.range(0) == star10000 ? 100'000 : kPoints;
  GEOSContextHandle_t ctx = GEOS_init_r();
  GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx, static_cast<unsigned>(s.ring.size() + 1), 2);
  for (std::size_t i = 0; i <= s.ring.size(); ++i) {
    const Vec2 v = s.ring[i % s.ring.size()];
    GEOSCoordSeq_setXY_r(ctx, seq, static_cast<unsigned>(i), v.x, v.y);
  }
  GEOSGeometry* shell = GEOSGeom_createLinearRing_r(ctx, seq);
  GEOSGeometry* polygon = GEOSGeom_createPolygon_r(ctx, shell, nullptr, 0);
  const GEOSPreparedGeometry* prepared = GEOSPrepare_r(ctx, polygon);
  std::vector<GEOSGeometry*> points(count);
  for (std::size_t k = 0; k < count; ++k) {
    points[k] = GEOSGeom_createPointFromXY_r(ctx, s.points[k].x, s.points[k].y);
  }
  const std::size_t bad = mismatches(s, count, [&](std::size_t k) {
    return GEOSPreparedContains_r(ctx, prepared, points[k]) == 1;
  });
  std::vector<char> out(count);
  run(state, s, count, bad, false, [&](std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
      out[k] = GEOSPreparedContains_r(ctx, prepared, points[k]) == 1 ? 1 : 0;
    }
    benchmark::DoNotOptimize(out.data());
  });
  for (GEOSGeometry* p : points)
    GEOSGeom_destroy_r(ctx, p);
  GEOSPreparedGeom_destroy_r(ctx, prepared);
  GEOSGeom_destroy_r(ctx, polygon);
  GEOS_finish_r(ctx);
}

#ifdef CONTAIN_BENCH_HAS_CGAL
void cgal_bounded_side(benchmark::State& state) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  Scene& s = scene(static_cast<int>(state.range(0)));
  const std::size_t count = point_count(static_cast<int>(state.range(0)));
  std::vector<K::Point_2> polygon;
  for (const Vec2& v : s.ring)
    polygon.emplace_back(v.x, v.y);
  std::vector<K::Point_2> points;
  for (std::size_t k = 0; k < count; ++k)
    points.emplace_back(s.points[k].x, s.points[k].y);
  auto inside = [&](std::size_t k) {
    return CGAL::bounded_side_2(polygon.begin(), polygon.end(), points[k], K()) ==
           CGAL::ON_BOUNDED_SIDE;
  };
  const std::size_t bad = mismatches(s, count, inside);
  std::vector<char> out(count);
  run(state, s, count, bad, false, [&](std::size_t n) {
    for (std::size_t k = 0; k < n; ++k)
      out[k] = inside(k) ? 1 : 0;
    benchmark::DoNotOptimize(out.data());
  });
}
#endif

void register_all() {
  for (int id : {star10000, blob10000, star100}) {
    const char* names[] = {"/star10000", "/blob10000", "/star100"};
    const std::string suffix = names[id];
    auto add = [&](const std::string& name, void (*fn)(benchmark::State&)) {
      benchmark::RegisterBenchmark((name + suffix).c_str(), fn)
          ->Arg(id)
          ->Unit(benchmark::kMillisecond)
          ->MinTime(1.0);
    };
    add("contain_index", contain_index);  // first: the others report x_contain against it
    add("crossing_loop", crossing_loop);
    add("boost_within", boost_within);
    add("geos_prepared", geos_prepared);
#ifdef CONTAIN_BENCH_HAS_CGAL
    add("cgal_bounded_side", cgal_bounded_side);
#endif
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
