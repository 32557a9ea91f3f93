// 10^7 random 3D segments against a box: segments per second for Cohen-Sutherland,
// Liang-Barsky, Cyrus-Beck (six half-spaces) and the branch-free batch kernel (each version:
// portable SSE2 pairs, AVX2 quadruples), beside a plain pass that copies the same data (the
// memory limit). Answers are checked outside the timed loops (every clipper keeps the same
// segments; every kernel version gives the same points bit for bit). Best of several rounds
// (each round runs every pass once, in turn), in wall-clock time and in CPU time of the process
// (all its threads): the machine is shared, and CPU time does not count the time other jobs held
// the core.
//
//   segment_clip_bench [count=10000000] [rounds=5] [only rows whose name contains this; the
//                                                   copy passes always run]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
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
Timing timed(F&& run) {
  const double cpu0 = cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  run();
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  return {took.count(), cpu_seconds() - cpu0};
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

  // The passes run in turn, `repeats` rounds, each pass keeping its best time: on a shared
  // machine every pass then meets the same changes of load, and the ratios compare like with like.
  struct Pass {
    std::string name;
    int threads;
    std::function<void()> run;
    std::function<void()> check;
    Timing time;
  };
  std::vector<Pass> passes;
  const auto add = [&](std::string name, int threads, std::function<void()> run,
                       std::function<void()> check) {
    if (only.empty() || name.find(only) != std::string::npos || name.starts_with("copy")) {
      passes.push_back({std::move(name), threads, std::move(run), std::move(check), {}});
    }
  };
  const auto same_decisions = [&](const std::string& name) {
    if (!std::equal(kept.begin(), kept.end(), reference.begin())) {
      std::printf("MISMATCH: %s keeps other segments than Liang-Barsky\n", name.c_str());
      std::exit(1);
    }
  };
  const auto scalar = [&](const std::string& name, auto clipper) {
    add(
        name, 1,
        [&, clipper] {
          for (std::size_t i = 0; i < count; ++i) {
            const auto r = clipper(in[i]);
            kept[i] = r.kept ? 1 : 0;
            if (r.kept) out[i] = r.segment;
          }
        },
        [&, name] { same_decisions(name); });
  };
  const auto batch = [&](const std::string& name, int threads, clip::detail::KernelIsa isa) {
    add(
        name, threads,
        [&, threads, isa] {
          clip::detail::clip_segments_with(in, box, out, kept, {.threads = threads}, isa);
        },
        [&, name] {
          same_decisions(name);
          for (std::size_t i = 0; i < count; ++i)
            if (!kept[i]) out[i] = {};
          if (first_out.empty()) {
            first_out = out;
          } else if (std::memcmp(first_out.data(), out.data(), count * sizeof(Segment3)) != 0) {
            std::printf("MISMATCH: %s gives other points than the first kernel row\n",
                        name.c_str());
            std::exit(1);
          }
        });
  };

  add(
      "copy (memcpy, 1 thread)", 1,
      [&] {
        std::memcpy(out.data(), in.data(), count * sizeof(Segment3));
        std::memset(kept.data(), 1, count);
      },
      [] {});
  add(
      "copy (memcpy, 2 threads)", 2,
      [&] {
        parallel_for(count, {.threads = 2}, [&](std::size_t b, std::size_t e) {
          std::memcpy(out.data() + b, in.data() + b, (e - b) * sizeof(Segment3));
          std::memset(kept.data() + b, 1, e - b);
        });
      },
      [] {});
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

  for (int r = 0; r < repeats; ++r) {
    for (Pass& pass : passes) {
      const Timing t = timed(pass.run);
      pass.time.wall = std::min(pass.time.wall, t.wall);
      pass.time.cpu = std::min(pass.time.cpu, t.cpu);
      pass.check();
    }
  }
  const Timing copy1 = passes[0].time, copy2 = passes[1].time;

  std::size_t kept_count = 0;
  for (auto k : reference)
    kept_count += k;
  std::printf("%zu random segments in [-2,2]^3 against [-1,1]^3 (%zu kept), best of %d rounds\n",
              count, kept_count, repeats);
  std::printf("traffic per segment: 48 B read + 48 B written + 1 B flag\n");
  std::printf("ratios: to the copy pass with the same thread count (wall / CPU time)\n\n");
  std::printf("%-42s %9s %9s %9s %8s %9s %9s\n", "pass", "wall ms", "CPU ms", "M seg/s", "GB/s in",
              "vs copy", "(CPU)");
  for (const Pass& r : passes) {
    const double rate = static_cast<double>(count) / r.time.wall;
    const Timing& copy = r.threads == 1 ? copy1 : copy2;
    std::printf("%-42s %9.1f %9.1f %9.1f %8.2f %8.1f%% %8.1f%%\n", r.name.c_str(),
                r.time.wall * 1e3, r.time.cpu * 1e3, rate * 1e-6, rate * 48e-9,
                100.0 * copy.wall / r.time.wall, 100.0 * copy.cpu / r.time.cpu);
  }
  return 0;
}
