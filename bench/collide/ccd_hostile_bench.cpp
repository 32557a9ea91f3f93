// Continuous collision on the hostile queries of issue 24: coordinates of 1e300 next to 1e-300,
// which overflow the double filters and leave the exact polynomial stage big numbers of
// thousands of bits. Deterministic sets (seed 24), each query run as vertex-face and as
// edge-edge, one thread:
//   coincident  every coordinate one of 1e300, -1e300, 3e300, 1e-300, -1e-300, 2e-300, 0, 1, -1
//               (exact coincidences);
//   mixed       random mantissas near 1e300, near 1e-300, in [0, 1) or zero (the generator of
//               CcdOracle.HostileMixedMagnitudesEqualTheOracle, checked against GMP);
//   coplanar    the mixed coordinates with one axis shared by the four points at each time
//               (coplanar motion: the exact stage's inclusion polynomials decide);
//   tangent     small-integer configurations whose cubic has a double root in (0, 1) or a root
//               at 0 or 1 (touching, grazing), each axis scaled by its own power of two in
//               2^+-1000 (exact, the answer unchanged) and some coordinates moved by about
//               1e-300 (roots hugging each other or the ends of [0, 1]).
// Printed per set: the thread CPU time per query (the least of REPEAT runs of it; mean, median,
// 99th percentile, worst) and the SHOW slowest queries (time, kind, the 24 numbers, their index).
//
// Usage: ccd_hostile_bench [QUERIES [SET|all [SHOW [REPEAT [INDEX]]]]]   (default 300, all, 1, 1)
//   INDEX: only query INDEX of each set (both kinds), REPEAT times: one query under perf.
//   ccd_hostile_bench answers [QUERIES]: every answer (set, index, kind, hit, time in hex), one a
//   line, to diff the exact stage's answers before and after a change.

#include <time.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include "contain/collide/ccd.h"

namespace {

using contain::Vec3;
using contain::collide::CcdQuery;

double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

enum class Set { coincident, mixed, coplanar, tangent };

class Hostile {
 public:
  explicit Hostile(Set set) : set_(set) {}

  CcdQuery next() {
    CcdQuery q;
    if (set_ == Set::tangent) return tangent();
    for (Vec3& p : q)
      p = {coordinate(), coordinate(), coordinate()};
    if (set_ == Set::coplanar) {
      const int axis = integer(0, 2);
      for (std::size_t i = 0; i < 8; ++i)
        at(q[i], axis) = at(q[i < 4 ? 0 : 4], axis);
    }
    return q;
  }

 private:
  static double& at(Vec3& v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  double coordinate() {
    static constexpr double kValues[] = {1e300,  -1e300, 3e300, 1e-300, -1e-300,
                                         2e-300, 0.0,    1.0,   -1.0};
    if (set_ == Set::coincident) return kValues[integer(0, 8)];
    const double sign = integer(0, 1) == 0 ? 1.0 : -1.0;
    switch (integer(0, 3)) {
      case 0:
        return sign * uniform(1, 10) * 1e299;
      case 1:
        return sign * uniform(1, 10) * 1e-301;
      case 2:
        return sign * uniform(0, 1);
      default:
        return 0.0;
    }
  }

  // A vertex over the plane z = 0 of a triangle whose corner c tilts (c_z = h t): with the
  // vertex at (x, y0 + dy t, z0 + dz t), f(t) = z0 + (dz - h y0) t - h dy t^2 for the triangle
  // (0,0,0), (1,0,0), (0,1,h t); choosing the integers for a zero discriminant gives a double
  // root (the vertex grazes the moving plane), for z0 = 0 a root at 0, for f(1) = 0 one at 1. Then
  // a random edge of it for edge-edge (the same points), axes scaled by powers of two, and nudges
  // of ~1e-300.
  CcdQuery tangent() {
    const int kind = integer(0, 2);
    double h = integer(1, 4), y0 = integer(-3, 3), dy = integer(-3, 3), z0 = 0, dz = integer(-4, 4);
    if (kind == 0) {
      // h (t - 1/2)^2: dy = -1, dz = h (y0 - 1), z0 = h / 4 (a double root at t = 1/2).
      dy = -1;
      dz = h * (y0 - 1);
      z0 = h / 4;
    } else if (kind == 1) {
      z0 = 0;  // a root at t = 0
    } else {
      z0 = -(dz - h * y0 - h * dy);  // f(1) = 0: a root at t = 1
    }
    const double x = uniform(0.0, 0.5);
    CcdQuery q{Vec3{x, y0, z0},           {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
               Vec3{x, y0 + dy, z0 + dz}, {0, 0, 0}, {1, 0, 0}, {0, 1, h}};
    if (integer(0, 1) == 0) std::swap(q[0], q[3]), std::swap(q[4], q[7]);
    const std::array<int, 3> e{integer(-1000, 1000), integer(-1000, 1000), integer(-1000, 1000)};
    for (Vec3& p : q) {
      p = {std::ldexp(p.x, e[0]), std::ldexp(p.y, e[1]), std::ldexp(p.z, e[2])};
      if (integer(0, 3) == 0) at(p, integer(0, 2)) += uniform(-1, 1) * 1e-300;
    }
    return q;
  }

  std::mt19937_64 rng_{24};
  Set set_;
};

void run(const char* name, Set set, int count, std::size_t show, int repeat, int index) {
  Hostile gen(set);
  struct Timed {
    double ms;
    bool vertex_face;
    CcdQuery query;
    int index;
  };
  std::vector<Timed> timed;
  int hits = 0;
  for (int i = 0; i < count; ++i) {
    const CcdQuery q = gen.next();
    if (index >= 0 && i != index) continue;
    for (const bool vf : {true, false}) {
      // The least of `repeat` runs: the query's own cost, without the interference of a
      // loaded machine (cache misses and migrations count in thread CPU time).
      double best = 0.0;
      contain::collide::Impact r;
      for (int k = 0; k < repeat; ++k) {
        const double t0 = cpu_ms();
        r = vf ? contain::collide::vertex_face_ccd(q) : contain::collide::edge_edge_ccd(q);
        const double t = cpu_ms() - t0;
        best = k == 0 ? t : std::min(best, t);
      }
      timed.push_back({best, vf, q, i});
      hits += r.hit ? 1 : 0;
    }
  }
  if (timed.empty()) return;
  std::sort(timed.begin(), timed.end(), [](const Timed& a, const Timed& b) { return a.ms < b.ms; });
  double sum = 0.0;
  for (const Timed& t : timed)
    sum += t.ms;
  const std::size_t n = timed.size();
  std::printf("%-11s %zu queries, %d hits: CPU ms mean %.4f, median %.4f, p99 %.3f, worst %.3f\n",
              name, n, hits, sum / static_cast<double>(n), timed[n / 2].ms, timed[n * 99 / 100].ms,
              timed.back().ms);
  for (std::size_t k = n; k-- > 0 && k + show >= n;) {
    std::printf("  %.3f ms %s:", timed[k].ms, timed[k].vertex_face ? "vf" : "ee");
    for (const Vec3& p : timed[k].query)
      std::printf(" %.17g %.17g %.17g", p.x, p.y, p.z);
    std::printf(" (index %d)\n", timed[k].index);
  }
}

// Every answer of a set, one a line, for diffs.
void answers(const char* name, Set set, int count) {
  Hostile gen(set);
  for (int i = 0; i < count; ++i) {
    const CcdQuery q = gen.next();
    for (const bool vf : {true, false}) {
      const contain::collide::Impact r =
          vf ? contain::collide::vertex_face_ccd(q) : contain::collide::edge_edge_ccd(q);
      std::printf("%s %d %s %d %a\n", name, i, vf ? "vf" : "ee", r.hit ? 1 : 0, r.time);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const struct {
    const char* name;
    Set set;
  } sets[] = {{"coincident", Set::coincident},
              {"mixed", Set::mixed},
              {"coplanar", Set::coplanar},
              {"tangent", Set::tangent}};
  if (argc > 1 && std::strcmp(argv[1], "answers") == 0) {
    const int count = argc > 2 ? std::max(1, std::atoi(argv[2])) : 300;
    for (const auto& s : sets)
      answers(s.name, s.set, count);
    return 0;
  }
  const int count = argc > 1 ? std::max(1, std::atoi(argv[1])) : 300;
  const char* only = argc > 2 && std::strcmp(argv[2], "all") != 0 ? argv[2] : nullptr;
  const std::size_t show = argc > 3 ? static_cast<std::size_t>(std::max(1, std::atoi(argv[3]))) : 1;
  const int repeat = argc > 4 ? std::max(1, std::atoi(argv[4])) : 1;
  const int index = argc > 5 ? std::atoi(argv[5]) : -1;
  for (const auto& s : sets) {
    if (only == nullptr || std::strcmp(only, s.name) == 0) {
      run(s.name, s.set, count, show, repeat, index);
    }
  }
  return 0;
}
