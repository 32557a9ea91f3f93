// orient2d and orient3d, single-threaded, on 4,096 precomputed inputs per scene:
//   random      coordinates uniform in [-1, 1]: the filter answers;
//   near        a rounded point of the line (plane) through the others, moved by <= 2 ulps:
//               the filter fails and the exact stage sees non-zero difference tails;
//   degenerate  exactly collinear (coplanar) small-integer lattice points: the answer is 0, so
//               the filter fails and the exact stage runs on exact differences;
// through
//   contain     contain::predicates::orient2d / orient3d (exact);
//   call        the same through a non-inlined wrapper: what an out-of-line filter would cost;
//   naive       the sign of the double expression (not exact: mismatches are counted);
//   cgal        CGAL::orientation with Exact_predicates_inexact_constructions_kernel (exact).
// Every callee is wrapped in a lambda so that the compiler may inline it, as in user code.
// Counters: calls/s (items_per_second), mismatches against contain (outside the timed loop).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"

#ifdef CONTAIN_BENCH_HAS_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

using contain::Sign;
using contain::Vec2;
using contain::Vec3;
namespace pr = contain::predicates;

constexpr std::size_t kInputs = 1 << 12;  // 200-300 KB: cache-resident, measures compute

enum class Kind { random, near, degenerate };

double nudge(std::mt19937_64& rng, double x) {
  const int k = static_cast<int>(rng() % 5) - 2;
  for (int i = 0; i < k; ++i)
    x = std::nextafter(x, 2.0 * x + 1.0);
  for (int i = 0; i > k; --i)
    x = std::nextafter(x, 2.0 * x - 1.0);
  return x;
}

struct Triple {
  Vec2 a, b, c;
};
struct Quad {
  Vec3 a, b, c, d;
};

const std::vector<Triple>& triples(Kind kind) {
  static std::vector<Triple> cache[3];
  auto& out = cache[static_cast<int>(kind)];
  if (!out.empty()) return out;
  std::mt19937_64 rng(2024 + static_cast<int>(kind));
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> small(-1000, 1000);
  for (std::size_t i = 0; i < kInputs; ++i) {
    if (kind == Kind::random) {
      out.push_back({{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}});
    } else if (kind == Kind::near) {
      const Vec2 a{u(rng), u(rng)}, b{u(rng), u(rng)};
      const double t = u(rng) * 2;
      out.push_back({a, b, {nudge(rng, a.x + t * (b.x - a.x)), nudge(rng, a.y + t * (b.y - a.y))}});
    } else {
      const Vec2 a{double(small(rng)), double(small(rng))},
          d{double(small(rng)), double(small(rng))};
      const double k = small(rng) % 8, m = small(rng) % 8;
      out.push_back({a, a + k * d, a + m * d});
    }
  }
  return out;
}

const std::vector<Quad>& quads(Kind kind) {
  static std::vector<Quad> cache[3];
  auto& out = cache[static_cast<int>(kind)];
  if (!out.empty()) return out;
  std::mt19937_64 rng(4048 + static_cast<int>(kind));
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> small(-1000, 1000);
  const auto point = [&] { return Vec3{u(rng), u(rng), u(rng)}; };
  const auto lattice = [&] {
    return Vec3{double(small(rng)), double(small(rng)), double(small(rng))};
  };
  for (std::size_t i = 0; i < kInputs; ++i) {
    if (kind == Kind::random) {
      out.push_back({point(), point(), point(), point()});
    } else if (kind == Kind::near) {
      const Vec3 a = point(), b = point(), c = point();
      const double s = u(rng), t = u(rng);
      const Vec3 d = a + s * (b - a) + t * (c - a);
      out.push_back({a, b, c, {nudge(rng, d.x), nudge(rng, d.y), nudge(rng, d.z)}});
    } else {
      const Vec3 a = lattice(), e = lattice(), f = lattice();
      const double s = small(rng) % 8, t = small(rng) % 8;
      out.push_back({a, a + e, a + f, a + s * e + t * f});
    }
  }
  return out;
}

[[gnu::noinline]] Sign call2(Vec2 a, Vec2 b, Vec2 c) {
  return pr::orient2d(a, b, c);
}
[[gnu::noinline]] Sign call3(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return pr::orient3d(a, b, c, d);
}

Sign naive2(Vec2 a, Vec2 b, Vec2 c) {
  return contain::sign_of(cross(b - a, c - a));
}
Sign naive3(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return contain::sign_of(dot(cross(b - a, c - a), d - a));
}

template <class F>
void run2(benchmark::State& state, Kind kind, F f) {
  const auto& in = triples(kind);
  long mismatches = 0;
  for (const Triple& t : in)
    mismatches += f(t.a, t.b, t.c) != pr::orient2d(t.a, t.b, t.c);
  for (auto _ : state) {
    int sum = 0;
    for (const Triple& t : in)
      sum += to_int(f(t.a, t.b, t.c));
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * in.size()));
  state.counters["mismatches"] = static_cast<double>(mismatches);
}

template <class F>
void run3(benchmark::State& state, Kind kind, F f) {
  const auto& in = quads(kind);
  long mismatches = 0;
  for (const Quad& q : in)
    mismatches += f(q.a, q.b, q.c, q.d) != pr::orient3d(q.a, q.b, q.c, q.d);
  for (auto _ : state) {
    int sum = 0;
    for (const Quad& q : in)
      sum += to_int(f(q.a, q.b, q.c, q.d));
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * in.size()));
  state.counters["mismatches"] = static_cast<double>(mismatches);
}

#ifdef CONTAIN_BENCH_HAS_CGAL
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
Sign cgal2(Vec2 a, Vec2 b, Vec2 c) {
  return static_cast<Sign>(
      CGAL::orientation(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y), K::Point_2(c.x, c.y)));
}
// CGAL's orientation(p, q, r, s) is positive when s is on the positive side of the plane p q r
// seen as counter-clockwise, the same convention as contain::predicates::orient3d.
Sign cgal3(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return static_cast<Sign>(CGAL::orientation(K::Point_3(a.x, a.y, a.z), K::Point_3(b.x, b.y, b.z),
                                             K::Point_3(c.x, c.y, c.z), K::Point_3(d.x, d.y, d.z)));
}
#endif

// Each callee is a distinct lambda type, so run2/run3 are instantiated per callee and the
// call can be inlined, as in user code.
template <class F>
void add2(const std::string& name, Kind kind, F f) {
  benchmark::RegisterBenchmark(("orient2d/" + name).c_str(),
                               [kind, f](benchmark::State& s) { run2(s, kind, f); });
}
template <class F>
void add3(const std::string& name, Kind kind, F f) {
  benchmark::RegisterBenchmark(("orient3d/" + name).c_str(),
                               [kind, f](benchmark::State& s) { run3(s, kind, f); });
}

void register_all() {
  const struct {
    const char* name;
    Kind kind;
  } kinds[] = {{"random", Kind::random}, {"near", Kind::near}, {"degenerate", Kind::degenerate}};
  for (const auto& k : kinds) {
    const std::string n = k.name;
    add2("contain/" + n, k.kind, [](Vec2 a, Vec2 b, Vec2 c) { return pr::orient2d(a, b, c); });
    add2("call/" + n, k.kind, [](Vec2 a, Vec2 b, Vec2 c) { return call2(a, b, c); });
    add2("naive/" + n, k.kind, [](Vec2 a, Vec2 b, Vec2 c) { return naive2(a, b, c); });
#ifdef CONTAIN_BENCH_HAS_CGAL
    add2("cgal/" + n, k.kind, [](Vec2 a, Vec2 b, Vec2 c) { return cgal2(a, b, c); });
#endif
    add3("contain/" + n, k.kind,
         [](Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return pr::orient3d(a, b, c, d); });
    add3("call/" + n, k.kind, [](Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return call3(a, b, c, d); });
    add3("naive/" + n, k.kind, [](Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return naive3(a, b, c, d); });
#ifdef CONTAIN_BENCH_HAS_CGAL
    add3("cgal/" + n, k.kind, [](Vec3 a, Vec3 b, Vec3 c, Vec3 d) { return cgal3(a, b, c, d); });
#endif
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
