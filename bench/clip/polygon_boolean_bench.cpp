// Polygon intersection, single-threaded, contain beside its peers on the same scenes:
//   smooth1k    two smooth random concave stars of 1,000 vertices (radius 1 + sum_k (0.3/k) u_k
//               sin(k angle + phase_k), k = 2..12), the second centred at (0.1, 0.05);
//   smooth100k  the same with 100,000 vertices each;
//   spiky1k     two scenes::star_ring(1000, radii uniform in [0.2, 1]) about (0, 0) and
//               (0.05, 0.03): edges cross thousands of times, hundreds of output pieces;
//   squares     1,000 axis-aligned squares of side 0.05 at uniform positions in the box of a
//               10,000-vertex smooth star, each intersected with it (one call per square; the
//               time is for all 1,000).
// Peers: Clipper 1 (libpolyclipping 6.4, integer coordinates: the doubles scaled by 2^29 and
// rounded, so |x| < 2^30 keeps its fast 64-bit path; result areas scaled back), Boost.Geometry
// 1.74 bg::intersection (double, counter-clockwise closed polygons), GEOS 3.11 C API
// GEOSIntersection_r (geometries built outside the timed loop).
// Checked outside the timed loops: contain's result is valid for GEOS (GEOSisValid_r) and its
// area obeys |A n B| + |A u B| = |A| + |B| (relative residual reported); each peer's area is
// reported relative to contain's (area_rel_vs_contain). Times: ms per case of thread CPU time
// (the 2-core machine is shared); pieces: output polygons. Ratios are in the results file.
#include <benchmark/benchmark.h>
#include <geos_c.h>
#include <polyclipping/clipper.hpp>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "contain/clip/polygon_boolean.h"
#include "scenes/scenes.h"

namespace {

namespace bg = boost::geometry;
using contain::MultiPolygon;
using contain::Ring;
using contain::Vec2;
namespace clip = contain::clip;

using BPoint = bg::model::d2::point_xy<double>;
using BPolygon = bg::model::polygon<BPoint, false, true>;
using BMulti = bg::model::multi_polygon<BPolygon>;

Ring blob_ring(int vertices, std::uint64_t seed, Vec2 center) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double amp[11], shift[11];
  for (int k = 0; k < 11; ++k) {
    amp[k] = u(rng);
    shift[k] = 2 * std::numbers::pi * u(rng);
  }
  Ring ring;
  for (int i = 0; i < vertices; ++i) {
    const double angle = 2 * std::numbers::pi * i / vertices;
    double r = 1.0;
    for (int k = 2; k <= 12; ++k)
      r += (0.3 / k) * amp[k - 2] * std::sin(k * angle + shift[k - 2]);
    ring.push_back({center.x + r * std::cos(angle), center.y + r * std::sin(angle)});
  }
  return ring;
}

struct Case {
  std::vector<Ring> a;
  std::vector<std::vector<Ring>> b;  // one clip region per call (squares: 1,000)
};

enum CaseId : int { smooth1k = 0, smooth100k = 1, spiky1k = 2, squares = 3 };
const char* const kNames[] = {"smooth1k", "smooth100k", "spiky1k", "squares"};

const Case& scene(int id) {
  static std::map<int, Case> cache;
  auto it = cache.find(id);
  if (it != cache.end()) return it->second;
  Case c;
  switch (id) {
    case smooth1k:
    case smooth100k: {
      const int n = id == smooth1k ? 1000 : 100000;
      c.a = {blob_ring(n, 1, {0, 0})};
      c.b = {{blob_ring(n, 2, {0.1, 0.05})}};
      break;
    }
    case spiky1k:
      c.a = {contain::scenes::star_ring(1000, {0, 0}, 0.2, 1.0, 11)};
      c.b = {{contain::scenes::star_ring(1000, {0.05, 0.03}, 0.2, 1.0, 12)}};
      break;
    default: {
      c.a = {blob_ring(10000, 3, {0, 0})};
      std::mt19937_64 rng(5);
      std::uniform_real_distribution<double> u(-1.4, 1.4);
      for (int i = 0; i < 1000; ++i) {
        const double x = u(rng), y = u(rng), s = 0.05;
        c.b.push_back({{{x, y}, {x + s, y}, {x + s, y + s}, {x, y + s}}});
      }
    }
  }
  return cache.emplace(id, std::move(c)).first->second;
}

double area(const MultiPolygon& m) {
  double sum = 0;
  for (const auto& p : m.polygons) {
    for (const Ring& r : p.rings)
      sum += 0.5 * contain::signed_area2(r);
  }
  return sum;
}

// contain's reference per case: total area, pieces, time.
struct Reference {
  double area = 0;
  std::size_t pieces = 0;
};
std::map<int, Reference>& references() {
  static std::map<int, Reference> r;
  return r;
}

void report_vs_contain(benchmark::State& state, int id, double peer_area, std::size_t pieces) {
  const Reference& ref = references()[id];
  state.counters["pieces"] = static_cast<double>(pieces);
  state.counters["area_rel_vs_contain"] =
      ref.area != 0 ? std::abs(peer_area - ref.area) / std::abs(ref.area) : 0.0;
}

// --- contain --------------------------------------------------------------------------------

void BM_contain(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  MultiPolygon last;
  double total = 0;
  std::size_t pieces = 0;
  for (auto _ : state) {
    total = 0;
    pieces = 0;
    for (const auto& b : c.b) {
      last = clip::polygon_boolean(c.a, b, {.op = clip::Op::intersection});
      benchmark::DoNotOptimize(last);
      pieces += last.polygons.size();
    }
  }
  // Checks, untimed: GEOS validity of every result and the area identity.
  GEOSContextHandle_t geos = GEOS_init_r();
  bool valid = true;
  double residual = 0, scale = 0;
  total = 0;
  for (const auto& b : c.b) {
    const MultiPolygon i = clip::polygon_boolean(c.a, b, {.op = clip::Op::intersection});
    const MultiPolygon u = clip::polygon_boolean(c.a, b, {.op = clip::Op::union_});
    const std::vector<Ring> none;
    const double aa = area(clip::polygon_boolean(c.a, none, {.op = clip::Op::union_}));
    const double ab = area(clip::polygon_boolean(b, none, {.op = clip::Op::union_}));
    residual = std::max(residual, std::abs(area(i) + area(u) - aa - ab));
    scale = std::max(scale, aa + ab);
    total += area(i);
    std::string wkt;
    for (const auto& p : i.polygons) {
      wkt += wkt.empty() ? "MULTIPOLYGON(" : ",";
      wkt += "(";
      for (std::size_t r = 0; r < p.rings.size(); ++r) {
        wkt += r ? ",(" : "(";
        for (const Vec2 v : p.rings[r]) {
          char buf[64];
          std::snprintf(buf, sizeof buf, "%.17g %.17g,", v.x, v.y);
          wkt += buf;
        }
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.17g %.17g)", p.rings[r][0].x, p.rings[r][0].y);
        wkt += buf;
      }
      wkt += ")";
    }
    wkt += wkt.empty() ? "MULTIPOLYGON EMPTY" : ")";
    GEOSWKTReader* reader = GEOSWKTReader_create_r(geos);
    GEOSGeometry* g = GEOSWKTReader_read_r(geos, reader, wkt.c_str());
    if (g == nullptr || GEOSisValid_r(geos, g) != 1) valid = false;
    if (g != nullptr) GEOSGeom_destroy_r(geos, g);
    GEOSWKTReader_destroy_r(geos, reader);
  }
  GEOS_finish_r(geos);
  references()[id] = {total, pieces};
  state.counters["pieces"] = static_cast<double>(pieces);
  state.counters["valid_geos"] = valid ? 1 : 0;
  state.counters["area_identity_rel"] = residual / scale;
  state.SetLabel(kNames[id]);
}

// --- Clipper 1 ------------------------------------------------------------------------------

constexpr double kClipperScale = 536870912.0;  // 2^29

ClipperLib::Path to_clipper(const Ring& ring) {
  ClipperLib::Path path;
  for (const Vec2 v : ring) {
    path.push_back({static_cast<ClipperLib::cInt>(std::llround(v.x * kClipperScale)),
                    static_cast<ClipperLib::cInt>(std::llround(v.y * kClipperScale))});
  }
  return path;
}

void BM_clipper(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  ClipperLib::Paths a;
  for (const Ring& r : c.a)
    a.push_back(to_clipper(r));
  std::vector<ClipperLib::Paths> bs;
  for (const auto& b : c.b) {
    ClipperLib::Paths p;
    for (const Ring& r : b)
      p.push_back(to_clipper(r));
    bs.push_back(std::move(p));
  }
  double total = 0;
  std::size_t pieces = 0;
  for (auto _ : state) {
    total = 0;
    pieces = 0;
    for (const auto& b : bs) {
      ClipperLib::Clipper clipper;
      clipper.AddPaths(a, ClipperLib::ptSubject, true);
      clipper.AddPaths(b, ClipperLib::ptClip, true);
      ClipperLib::Paths out;
      clipper.Execute(ClipperLib::ctIntersection, out, ClipperLib::pftEvenOdd,
                      ClipperLib::pftEvenOdd);
      for (const auto& p : out) {
        total += ClipperLib::Area(p) / (kClipperScale * kClipperScale);
        pieces += ClipperLib::Orientation(p) ? 1 : 0;
      }
    }
  }
  report_vs_contain(state, id, total, pieces);
  state.SetLabel(kNames[id]);
}

// --- Boost.Geometry -------------------------------------------------------------------------

BPolygon to_boost(const std::vector<Ring>& rings) {
  BPolygon p;
  for (const Vec2 v : rings[0])
    bg::append(p.outer(), BPoint(v.x, v.y));
  bg::correct(p);
  return p;
}

void BM_boost(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  const BPolygon a = to_boost(c.a);
  std::vector<BPolygon> bs;
  for (const auto& b : c.b)
    bs.push_back(to_boost(b));
  double total = 0;
  std::size_t pieces = 0;
  for (auto _ : state) {
    total = 0;
    pieces = 0;
    for (const auto& b : bs) {
      BMulti out;
      bg::intersection(a, b, out);
      total += bg::area(out);
      pieces += out.size();
    }
  }
  report_vs_contain(state, id, total, pieces);
  state.SetLabel(kNames[id]);
}

// --- GEOS -----------------------------------------------------------------------------------

GEOSGeometry* to_geos(GEOSContextHandle_t h, const std::vector<Ring>& rings) {
  const Ring& r = rings[0];
  GEOSCoordSequence* seq = GEOSCoordSeq_create_r(h, static_cast<unsigned>(r.size() + 1), 2);
  for (std::size_t i = 0; i <= r.size(); ++i) {
    const Vec2 v = r[i % r.size()];
    GEOSCoordSeq_setXY_r(h, seq, static_cast<unsigned>(i), v.x, v.y);
  }
  return GEOSGeom_createPolygon_r(h, GEOSGeom_createLinearRing_r(h, seq), nullptr, 0);
}

void BM_geos(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  GEOSContextHandle_t h = GEOS_init_r();
  GEOSGeometry* a = to_geos(h, c.a);
  std::vector<GEOSGeometry*> bs;
  for (const auto& b : c.b)
    bs.push_back(to_geos(h, b));
  double total = 0;
  std::size_t pieces = 0;
  for (auto _ : state) {
    total = 0;
    pieces = 0;
    for (GEOSGeometry* b : bs) {
      GEOSGeometry* out = GEOSIntersection_r(h, a, b);
      double ar = 0;
      GEOSArea_r(h, out, &ar);
      total += ar;
      pieces += static_cast<std::size_t>(GEOSGetNumGeometries_r(h, out));
      GEOSGeom_destroy_r(h, out);
    }
  }
  for (GEOSGeometry* b : bs)
    GEOSGeom_destroy_r(h, b);
  GEOSGeom_destroy_r(h, a);
  GEOS_finish_r(h);
  report_vs_contain(state, id, total, pieces);
  state.SetLabel(kNames[id]);
}

void cases(benchmark::internal::Benchmark* b) {
  for (int id : {smooth1k, smooth100k, spiky1k, squares})
    b->Arg(id);
  b->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK(BM_contain)->Apply(cases);
BENCHMARK(BM_clipper)->Apply(cases);
BENCHMARK(BM_boost)->Apply(cases);
BENCHMARK(BM_geos)->Apply(cases);
BENCHMARK_MAIN();
