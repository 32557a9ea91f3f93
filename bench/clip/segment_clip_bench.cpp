// 10^7 random 3D segments against a box: segments per second for Cohen-Sutherland,
// Liang-Barsky, Cyrus-Beck (six half-spaces) and the branch-free batch kernel (each version:
// portable SSE2 pairs, AVX2 quadruples), beside a plain pass that copies the same data (the
// memory limit). Answers are checked outside the timed loops (every clipper keeps the same
// segments; every kernel version gives the same points bit for bit). Best of several runs, in
// wall-clock time and in CPU time of the process (all its threads): the machine is shared, and
// CPU time does not count the time other jobs held the core.
//
//   segment_clip_bench [count=10000000] [repeats=5] [only rows whose name contains this]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "clip/box_kernel.h"
#include "contain/clip/box_halfspaces.h"
#include "contain/clip/clip_segments.h"
#include "contain/clip/cohen_sutherland.h"
#include "contain/clip/cyrus_beck.h"
#include "contain/clip/liang_barsky.h"
#include "contain/core/parallel.h"

namespace {

using namespace contain;

struct Timing {
  double wall = 1e300;
  double cpu = 1e300;
};

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <class F>
Timing best_of(int repeats, F run) {
  Timing best;
  for (int r = 0; r < repeats; ++r) {
    const double cpu0 = cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    run();
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    best.wall = std::min(best.wall, took.count());
    best.cpu = std::min(best.cpu, cpu_seconds() - cpu0);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t count = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 10'000'000;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
  const std::string only = argc > 3 ? argv[3] : "";
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<Segment3> in(count);
  for (auto& s : in)
    s = {{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
  const Box3 box{{-1, -1, -1}, {1, 1, 1}};
  const auto planes = clip::box_halfspaces(box);
  std::vector<Segment3> out(count), first_out;
  std::vector<std::uint8_t> kept(count), reference(count);
  for (std::size_t i = 0; i < count; ++i)
    reference[i] = clip::liang_barsky(in[i], box).kept;

  struct Row {
    std::string name;
    int threads;
    Timing time;
  };
  std::vector<Row> rows;
  const auto wanted = [&](const std::string& name) {
    return only.empty() || name.find(only) != std::string::npos;
  };
  const auto check = [&](const std::string& name) {
    if (!std::equal(kept.begin(), kept.end(), reference.begin())) {
      std::printf("MISMATCH: %s keeps other segments than Liang-Barsky\n", name.c_str());
      std::exit(1);
    }
  };
  const auto scalar = [&](const std::string& name, auto clipper) {
    if (!wanted(name)) return;
    rows.push_back({name, 1, best_of(repeats, [&] {
                      for (std::size_t i = 0; i < count; ++i) {
                        const auto r = clipper(in[i]);
                        kept[i] = r.kept ? 1 : 0;
                        if (r.kept) out[i] = r.segment;
                      }
                    })});
    check(name);
  };
  const auto batch = [&](const std::string& name, int threads, clip::detail::KernelIsa isa) {
    if (!wanted(name)) return;
    rows.push_back({name, threads, best_of(repeats, [&] {
                      clip::detail::clip_segments_with(in, box, out, kept, {.threads = threads},
                                                       isa);
                    })});
    check(name);
    for (std::size_t i = 0; i < count; ++i)
      if (!kept[i]) out[i] = {};
    if (first_out.empty()) {
      first_out = out;
    } else if (std::memcmp(first_out.data(), out.data(), count * sizeof(Segment3)) != 0) {
      std::printf("MISMATCH: %s gives other points than the first kernel row\n", name.c_str());
      std::exit(1);
    }
  };

  const Timing copy1 = best_of(repeats, [&] {
    std::memcpy(out.data(), in.data(), count * sizeof(Segment3));
    std::memset(kept.data(), 1, count);
  });
  const Timing copy2 = best_of(repeats, [&] {
    parallel_for(count, {.threads = 2}, [&](std::size_t b, std::size_t e) {
      std::memcpy(out.data() + b, in.data() + b, (e - b) * sizeof(Segment3));
      std::memset(kept.data() + b, 1, e - b);
    });
  });
  rows.push_back({"copy (memcpy, 1 thread)", 1, copy1});
  rows.push_back({"copy (memcpy, 2 threads)", 2, copy2});
  scalar("Cohen-Sutherland (exact, scalar)",
         [&](const Segment3& s) { return clip::cohen_sutherland(s, box); });
  scalar("Liang-Barsky (exact, scalar)",
         [&](const Segment3& s) { return clip::liang_barsky(s, box); });
  scalar("Cyrus-Beck, 6 half-spaces (exact, scalar)",
         [&](const Segment3& s) { return clip::cyrus_beck(s, planes); });
  using clip::detail::KernelIsa;
  const bool avx2 = clip::detail::kernel_isa_available(KernelIsa::avx2);
  batch("clip_segments, SSE2 kernel (1 thread)", 1, KernelIsa::portable);
  if (avx2) batch("clip_segments, AVX2 kernel (1 thread)", 1, KernelIsa::avx2);
  batch("clip_segments, SSE2 kernel (2 threads)", 2, KernelIsa::portable);
  if (avx2) batch("clip_segments, AVX2 kernel (2 threads)", 2, KernelIsa::avx2);

  std::size_t kept_count = 0;
  for (auto k : reference)
    kept_count += k;
  std::printf("%zu random segments in [-2,2]^3 against [-1,1]^3 (%zu kept), best of %d\n", count,
              kept_count, repeats);
  std::printf("traffic per segment: 48 B read + 48 B written + 1 B flag\n");
  std::printf("ratios: to the copy pass with the same thread count (wall / CPU time)\n\n");
  std::printf("%-42s %9s %9s %9s %8s %9s %9s\n", "pass", "wall ms", "CPU ms", "M seg/s", "GB/s in",
              "vs copy", "(CPU)");
  for (const Row& r : rows) {
    const double rate = static_cast<double>(count) / r.time.wall;
    const Timing& copy = r.threads == 1 ? copy1 : copy2;
    std::printf("%-42s %9.1f %9.1f %9.1f %8.2f %8.1f%% %8.1f%%\n", r.name.c_str(),
                r.time.wall * 1e3, r.time.cpu * 1e3, rate * 1e-6, rate * 48e-9,
                100.0 * copy.wall / r.time.wall, 100.0 * copy.cpu / r.time.cpu);
  }
  return 0;
}
