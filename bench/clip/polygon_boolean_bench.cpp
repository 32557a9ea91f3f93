// Polygon intersection and clipping by boxes, single-threaded unless said, contain beside its
// peers on the same scenes, in one run:
//   smooth1k    two smooth random concave stars of 1,000 vertices (radius 1 + sum_k (0.3/k) u_k
//               sin(k angle + phase_k), k = 2..12), the second centred at (0.1, 0.05);
//   smooth100k  the same with 100,000 vertices each;
//   spiky1k     two scenes::star_ring(1000, radii uniform in [0.2, 1]) about (0, 0) and
//               (0.05, 0.03): edges cross thousands of times, hundreds of output pieces;
//   squares     1,000 axis-aligned squares of side 0.05 at uniform positions in [-1.4, 1.4]^2,
//               each intersected with a smooth 10,000-vertex star (one call per square; the
//               time is for all 1,000);
//   tiles       the same star cut into a 32 x 32 grid of tiles over its bounding box (1,024
//               boxes, one call each; contain's `tile` does the grid in one call).
// contain: polygon_boolean (every scene); on the box scenes also clip_polygon(region, Box2) (the
// one-pass box cut), clip_polygon by the box's four half-planes and by the box as a convex ring,
// BoxClipper (prepared once inside the timed loop, then one clip per box) and tile (tiles only;
// one thread, and all cores by wall time).
// Peers: Clipper2 2.0.1 when built (CONTAIN_CLIPPER2_DIR; -O3 by its build.sh): Intersect on
// Paths64 (coordinates scaled by 2^29 and rounded) and on PathsD (precision 8, the finest it
// takes), RectClip on Paths64 and PathsD on the box scenes; Clipper 1 (libpolyclipping 6.4,
// the same 2^29 grid); Boost.Geometry 1.74 bg::intersection (double, counter-clockwise closed
// polygons); GEOS 3.11 C API GEOSIntersection_r (geometries built outside the timed loop).
// Checked outside the timed loops: every contain result is valid for GEOS (GEOSisValid_r);
// polygon_boolean's areas obey |A n B| + |A u B| = |A| + |B| (relative residual reported); every
// other result's area is reported relative to polygon_boolean's (area_rel_vs_contain). Times:
// CPU ms per case (thread CPU time; the 2-core machine is shared), wall time for the threaded
// tile. A ratio table (contain / peer) is printed at the end.
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

#include "contain/clip/box_clipper.h"
#include "contain/clip/clip_polygon.h"
#include "contain/clip/polygon_boolean.h"
#include "scenes/scenes.h"

#ifdef CONTAIN_HAVE_CLIPPER2
#include "clipper2/clipper.h"
#endif

namespace {

namespace bg = boost::geometry;
using contain::Box2;
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
  std::vector<Box2> boxes;           // the box scenes: the same regions as boxes
  clip::TileGrid grid;               // tiles: the grid
};

enum CaseId : int { smooth1k = 0, smooth100k = 1, spiky1k = 2, squares = 3, tiles = 4 };
const char* const kNames[] = {"smooth1k", "smooth100k", "spiky1k", "squares", "tiles"};

Ring box_ring(const Box2& b) {
  return {b.min, {b.max.x, b.min.y}, b.max, {b.min.x, b.max.y}};
}

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
    case squares: {
      c.a = {blob_ring(10000, 3, {0, 0})};
      std::mt19937_64 rng(5);
      std::uniform_real_distribution<double> u(-1.4, 1.4);
      for (int i = 0; i < 1000; ++i) {
        const double x = u(rng), y = u(rng), s = 0.05;
        c.boxes.push_back({{x, y}, {x + s, y + s}});
      }
      break;
    }
    default: {
      c.a = {blob_ring(10000, 3, {0, 0})};
      c.grid = {.bounds = contain::bounding_box(c.a), .columns = 32, .rows = 32};
      for (int row = 0; row < 32; ++row) {
        for (int column = 0; column < 32; ++column)
          c.boxes.push_back(c.grid.tile(column, row));
      }
    }
  }
  for (const Box2& b : c.boxes)
    c.b.push_back({box_ring(b)});
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

// GEOS's validity of a contain result.
bool valid_for_geos(GEOSContextHandle_t geos, const MultiPolygon& m) {
  std::string wkt;
  for (const auto& p : m.polygons) {
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
  const bool valid = g != nullptr && GEOSisValid_r(geos, g) == 1;
  if (g != nullptr) GEOSGeom_destroy_r(geos, g);
  GEOSWKTReader_destroy_r(geos, reader);
  return valid;
}

// polygon_boolean's reference per case: total area.
std::map<int, double>& references() {
  static std::map<int, double> r;
  return r;
}

double reference_area(int id) {
  auto it = references().find(id);
  if (it != references().end()) return it->second;
  const Case& c = scene(id);
  double total = 0;
  for (const auto& b : c.b)
    total += area(clip::polygon_boolean(c.a, b, {.op = clip::Op::intersection}));
  references()[id] = total;
  return total;
}

void report_vs_contain(benchmark::State& state, int id, double peer_area, std::size_t pieces) {
  const double ref = reference_area(id);
  state.counters["pieces"] = static_cast<double>(pieces);
  state.counters["area_rel_vs_contain"] = ref != 0 ? std::abs(peer_area - ref) / std::abs(ref) : 0;
  state.SetLabel(kNames[id]);
}

// --- contain --------------------------------------------------------------------------------

void BM_contain(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  MultiPolygon last;
  std::size_t pieces = 0;
  for (auto _ : state) {
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
  double residual = 0, scale = 0, total = 0;
  for (const auto& b : c.b) {
    const MultiPolygon i = clip::polygon_boolean(c.a, b, {.op = clip::Op::intersection});
    const MultiPolygon u = clip::polygon_boolean(c.a, b, {.op = clip::Op::union_});
    const std::vector<Ring> none;
    const double aa = area(clip::polygon_boolean(c.a, none, {.op = clip::Op::union_}));
    const double ab = area(clip::polygon_boolean(b, none, {.op = clip::Op::union_}));
    residual = std::max(residual, std::abs(area(i) + area(u) - aa - ab));
    scale = std::max(scale, aa + ab);
    total += area(i);
    valid = valid && valid_for_geos(geos, i);
  }
  GEOS_finish_r(geos);
  references()[id] = total;
  state.counters["pieces"] = static_cast<double>(pieces);
  state.counters["valid_geos"] = valid ? 1 : 0;
  state.counters["area_identity_rel"] = residual / scale;
  state.SetLabel(kNames[id]);
}

// Area and GEOS validity of contain's box results, untimed.
void check_boxes(benchmark::State& state, int id, const std::vector<MultiPolygon>& results) {
  GEOSContextHandle_t geos = GEOS_init_r();
  bool valid = true;
  double total = 0;
  std::size_t pieces = 0;
  for (const MultiPolygon& m : results) {
    valid = valid && valid_for_geos(geos, m);
    total += area(m);
    pieces += m.polygons.size();
  }
  GEOS_finish_r(geos);
  state.counters["valid_geos"] = valid ? 1 : 0;
  report_vs_contain(state, id, total, pieces);
}

void BM_contain_clip_box(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  const MultiPolygon region{{contain::Polygon{c.a}}};
  std::vector<MultiPolygon> results(c.boxes.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < c.boxes.size(); ++i)
      results[i] = clip::clip_polygon(region, c.boxes[i]);
    benchmark::DoNotOptimize(results);
  }
  check_boxes(state, id, results);
}

// The same boxes as four half-planes, and as convex rings (clip_polygon's other forms).
void BM_contain_clip_halfplanes(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  const MultiPolygon region{{contain::Polygon{c.a}}};
  std::vector<std::vector<contain::HalfPlane>> planes;
  for (const Box2& b : c.boxes) {
    planes.push_back({{1, 0, -b.min.x}, {-1, 0, b.max.x}, {0, 1, -b.min.y}, {0, -1, b.max.y}});
  }
  std::vector<MultiPolygon> results(c.boxes.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < c.boxes.size(); ++i)
      results[i] = clip::clip_polygon(region, planes[i]);
    benchmark::DoNotOptimize(results);
  }
  check_boxes(state, id, results);
}

void BM_contain_clip_convex(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  const MultiPolygon region{{contain::Polygon{c.a}}};
  std::vector<MultiPolygon> results(c.boxes.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < c.boxes.size(); ++i)
      results[i] = clip::clip_polygon(region, c.b[i][0]);
    benchmark::DoNotOptimize(results);
  }
  check_boxes(state, id, results);
}

void BM_contain_box_clipper(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  const MultiPolygon region{{contain::Polygon{c.a}}};
  std::vector<MultiPolygon> results(c.boxes.size());
  for (auto _ : state) {
    const clip::BoxClipper prepared(region);  // preparation included
    for (std::size_t i = 0; i < c.boxes.size(); ++i)
      results[i] = prepared.clip(c.boxes[i]);
    benchmark::DoNotOptimize(results);
  }
  check_boxes(state, id, results);
}

void BM_contain_tile(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(1));
  const Case& c = scene(tiles);
  const MultiPolygon region{{contain::Polygon{c.a}}};
  std::vector<MultiPolygon> results;
  for (auto _ : state) {
    results = clip::tile(region, c.grid, {.threads = threads});
    benchmark::DoNotOptimize(results);
  }
  check_boxes(state, tiles, results);
}

// --- Clipper2 -------------------------------------------------------------------------------

constexpr double kClipperScale = 536870912.0;  // 2^29

// A and every B of a case in a peer's path type.
template <class Paths, class Convert>
std::vector<Paths> convert_all(const Case& c, Paths& a, Convert convert) {
  for (const Ring& r : c.a)
    a.push_back(convert(r));
  std::vector<Paths> bs;
  for (const auto& b : c.b) {
    Paths p;
    for (const Ring& r : b)
      p.push_back(convert(r));
    bs.push_back(std::move(p));
  }
  return bs;
}

#ifdef CONTAIN_HAVE_CLIPPER2
namespace c2 = Clipper2Lib;
constexpr int kPrecisionD = 8;  // PathsD: the finest decimal precision Clipper2 accepts

c2::Path64 to_path64(const Ring& ring) {
  c2::Path64 path;
  for (const Vec2 v : ring) {
    path.push_back({static_cast<int64_t>(std::llround(v.x * kClipperScale)),
                    static_cast<int64_t>(std::llround(v.y * kClipperScale))});
  }
  return path;
}

c2::PathD to_pathd(const Ring& ring) {
  c2::PathD path;
  for (const Vec2 v : ring)
    path.push_back({v.x, v.y});
  return path;
}

c2::Rect64 to_rect64(const Box2& b) {
  return c2::Rect64(std::llround(b.min.x * kClipperScale), std::llround(b.min.y * kClipperScale),
                    std::llround(b.max.x * kClipperScale), std::llround(b.max.y * kClipperScale));
}

void BM_clipper2_intersect64(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  c2::Paths64 a;
  const std::vector<c2::Paths64> bs = convert_all(c, a, to_path64);
  double total = 0;
  std::size_t pieces = 0;
  for (auto _ : state) {
    total = 0;
    pieces = 0;
    for (const auto& b : bs) {
      const c2::Paths64 out = c2::Intersect(a, b, c2::FillRule::EvenOdd);
      for (const auto& p : out) {
        total += c2::Area(p) / (kClipperScale * kClipperScale);
        pieces += c2::Area(p) > 0 ? 1 : 0;
      }
    }
  }
  report_vs_contain(state, id, total, pieces);
}

void BM_clipper2_intersectD(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  c2::PathsD a;
  const std::vector<c2::PathsD> bs = convert_all(c, a, to_pathd);
  double total = 0;
  std::size_t pieces = 0;
  for (auto _ : state) {
    total = 0;
    pieces = 0;
    for (const auto& b : bs) {
      const c2::PathsD out = c2::Intersect(a, b, c2::FillRule::EvenOdd, kPrecisionD);
      for (const auto& p : out) {
        total += c2::Area(p);
        pieces += c2::Area(p) > 0 ? 1 : 0;
      }
    }
  }
  report_vs_contain(state, id, total, pieces);
}

void BM_clipper2_rect64(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  c2::Paths64 a;
  for (const Ring& r : c.a)
    a.push_back(to_path64(r));
  std::vector<c2::Rect64> rects;
  for (const Box2& b : c.boxes)
    rects.push_back(to_rect64(b));
  double total = 0;
  std::size_t pieces = 0;
  for (auto _ : state) {
    total = 0;
    pieces = 0;
    for (const c2::Rect64& r : rects) {
      const c2::Paths64 out = c2::RectClip(r, a);
      for (const auto& p : out) {
        total += c2::Area(p) / (kClipperScale * kClipperScale);
        pieces += c2::Area(p) > 0 ? 1 : 0;
      }
    }
  }
  report_vs_contain(state, id, total, pieces);
}

void BM_clipper2_rectD(benchmark::State& state) {
  const int id = static_cast<int>(state.range(0));
  const Case& c = scene(id);
  c2::PathsD a;
  for (const Ring& r : c.a)
    a.push_back(to_pathd(r));
  double total = 0;
  std::size_t pieces = 0;
  for (auto _ : state) {
    total = 0;
    pieces = 0;
    for (const Box2& b : c.boxes) {
      const c2::PathsD out =
          c2::RectClip(c2::RectD(b.min.x, b.min.y, b.max.x, b.max.y), a, kPrecisionD);
      for (const auto& p : out) {
        total += c2::Area(p);
        pieces += c2::Area(p) > 0 ? 1 : 0;
      }
    }
  }
  report_vs_contain(state, id, total, pieces);
}
#endif

// --- Clipper 1 ------------------------------------------------------------------------------

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
  const std::vector<ClipperLib::Paths> bs = convert_all(c, a, to_clipper);
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
}

void all_cases(benchmark::internal::Benchmark* b) {
  for (int id : {smooth1k, smooth100k, spiky1k, squares, tiles})
    b->Arg(id);
  b->Unit(benchmark::kMillisecond);
}

void box_cases(benchmark::internal::Benchmark* b) {
  for (int id : {squares, tiles})
    b->Arg(id);
  b->Unit(benchmark::kMillisecond);
}

// Collects CPU (or, for the threaded tile, real) time per benchmark and scene for the ratios.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.error_occurred || run.run_type != Run::RT_Iteration) continue;
      const std::string name = run.benchmark_name();
      const double ms = (name.find("threads:0") != std::string::npos ? run.GetAdjustedRealTime()
                                                                     : run.GetAdjustedCPUTime());
      times_[name] = ms;
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf("\nRatios contain / peer (CPU time; < 1: contain is faster)\n");
    const char* contains[] = {"BM_contain", "BM_contain_clip_box", "BM_contain_clip_halfplanes",
                              "BM_contain_clip_convex", "BM_contain_box_clipper"};
    const char* peers[] = {"BM_clipper2_intersect64",
                           "BM_clipper2_intersectD",
                           "BM_clipper2_rect64",
                           "BM_clipper2_rectD",
                           "BM_clipper",
                           "BM_boost",
                           "BM_geos"};
    for (int id = 0; id < 5; ++id) {
      for (const char* mine : contains) {
        const auto m = times_.find(std::string(mine) + "/" + std::to_string(id));
        if (m == times_.end()) continue;
        std::printf("  %-10s %-23s %9.3f ms", kNames[id], mine, m->second);
        for (const char* peer : peers) {
          const auto p = times_.find(std::string(peer) + "/" + std::to_string(id));
          if (p == times_.end()) continue;
          std::printf("  %s %.3gx", peer + 3, m->second / p->second);
        }
        std::printf("\n");
      }
    }
    for (const auto& [name, ms] : times_) {
      if (name.rfind("BM_contain_tile", 0) == 0)
        std::printf("  tiles      %-34s %9.3f ms\n", name.c_str(), ms);
    }
  }

 private:
  std::map<std::string, double> times_;
};

}  // namespace

BENCHMARK(BM_contain)->Apply(all_cases);
BENCHMARK(BM_contain_clip_box)->Apply(box_cases);
BENCHMARK(BM_contain_clip_halfplanes)->Apply(box_cases);
BENCHMARK(BM_contain_clip_convex)->Apply(box_cases);
BENCHMARK(BM_contain_box_clipper)->Apply(box_cases);
BENCHMARK(BM_contain_tile)
    ->ArgNames({"scene", "threads"})
    ->Args({tiles, 1})
    ->Args({tiles, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
#ifdef CONTAIN_HAVE_CLIPPER2
BENCHMARK(BM_clipper2_intersect64)->Apply(all_cases);
BENCHMARK(BM_clipper2_intersectD)->Apply(all_cases);
BENCHMARK(BM_clipper2_rect64)->Apply(box_cases);
BENCHMARK(BM_clipper2_rectD)->Apply(box_cases);
#endif
BENCHMARK(BM_clipper)->Apply(all_cases);
BENCHMARK(BM_boost)->Apply(all_cases);
BENCHMARK(BM_geos)->Apply(all_cases);

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
