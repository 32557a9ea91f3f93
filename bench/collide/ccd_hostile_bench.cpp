// Continuous collision on the hostile queries of issue 24: coordinates of 1e300 next to 1e-300,
// which overflow the double filters and leave the exact polynomial stage big numbers of
// thousands of bits. Two deterministic sets (seed 24): every coordinate one of 1e300, -1e300,
// 3e300, 1e-300, -1e-300, 2e-300, 0, 1, -1 (exact coincidences), and random mantissas near
// 1e300, near 1e-300, in [0, 1) or zero (the generator of the test
// CcdOracle.HostileMixedMagnitudesEqualTheOracle, which checks the answers against GMP). Each
// query runs as vertex-face and as edge-edge, one thread; printed: the time per query (mean,
// median, 99th percentile, worst) in wall time and the worst query.
//
// Usage: ccd_hostile_bench [QUERIES]   (default 300 of each set)

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "contain/collide/ccd.h"

namespace {

using contain::Vec3;
using contain::collide::CcdQuery;

class Hostile {
 public:
  explicit Hostile(bool coincident) : coincident_(coincident) {}

  CcdQuery next() {
    CcdQuery q;
    for (Vec3& p : q)
      p = {coordinate(), coordinate(), coordinate()};
    return q;
  }

 private:
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  double coordinate() {
    static constexpr double kValues[] = {1e300,  -1e300, 3e300, 1e-300, -1e-300,
                                         2e-300, 0.0,    1.0,   -1.0};
    if (coincident_) return kValues[integer(0, 8)];
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

  std::mt19937_64 rng_{24};
  bool coincident_;
};

void run(const char* name, bool coincident, int count) {
  Hostile gen(coincident);
  std::vector<double> ms;
  double worst = -1.0;
  CcdQuery worst_query{};
  int hits = 0;
  for (int i = 0; i < count; ++i) {
    const CcdQuery q = gen.next();
    for (const bool vf : {true, false}) {
      const auto t0 = std::chrono::steady_clock::now();
      const contain::collide::Impact r =
          vf ? contain::collide::vertex_face_ccd(q) : contain::collide::edge_edge_ccd(q);
      const double t =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      hits += r.hit ? 1 : 0;
      ms.push_back(t);
      if (t > worst) {
        worst = t;
        worst_query = q;
      }
    }
  }
  std::sort(ms.begin(), ms.end());
  double sum = 0.0;
  for (const double t : ms)
    sum += t;
  std::printf(
      "%-12s %zu queries, %d hits: mean %.3f ms, median %.3f ms, p99 %.3f ms, worst %.3f ms\n",
      name, ms.size(), hits, sum / static_cast<double>(ms.size()), ms[ms.size() / 2],
      ms[ms.size() * 99 / 100], worst);
  std::printf("  worst query:");
  for (const Vec3& p : worst_query)
    std::printf(" %.17g %.17g %.17g", p.x, p.y, p.z);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::max(1, std::atoi(argv[1])) : 300;
  run("coincident", true, count);
  run("mixed", false, count);
  return 0;
}
