// 10^7 random 3D segments against a box: segments per second for Cohen-Sutherland,
// Liang-Barsky, Cyrus-Beck (six half-spaces) and the branch-free batch kernel, beside a plain
// pass that copies the same data (the memory limit). Answers are checked outside the timed
// loops (every clipper keeps the same segments). Best of several runs: the machine is shared.
//
//   segment_clip_bench [count=10000000] [repeats=5]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "contain/clip/box_halfspaces.h"
#include "contain/clip/clip_segments.h"
#include "contain/clip/cohen_sutherland.h"
#include "contain/clip/cyrus_beck.h"
#include "contain/clip/liang_barsky.h"
#include "contain/core/parallel.h"

namespace {

using namespace contain;

template <class F>
double best_seconds(int repeats, F run) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    run();
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    best = std::min(best, took.count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t count = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 10'000'000;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<Segment3> in(count);
  for (auto& s : in)
    s = {{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
  const Box3 box{{-1, -1, -1}, {1, 1, 1}};
  const auto planes = clip::box_halfspaces(box);
  std::vector<Segment3> out(count);
  std::vector<std::uint8_t> kept(count), reference(count);

  struct Row {
    std::string name;
    double seconds;
  };
  std::vector<Row> rows;
  auto scalar = [&](const char* name, auto clipper) {
    const double s = best_seconds(repeats, [&] {
      for (std::size_t i = 0; i < count; ++i) {
        const auto r = clipper(in[i]);
        kept[i] = r.kept ? 1 : 0;
        if (r.kept) out[i] = r.segment;
      }
    });
    rows.push_back({name, s});
    if (!std::equal(kept.begin(), kept.end(), reference.begin())) {
      std::printf("MISMATCH: %s keeps other segments than Liang-Barsky\n", name);
      std::exit(1);
    }
  };
  for (std::size_t i = 0; i < count; ++i)
    reference[i] = clip::liang_barsky(in[i], box).kept;

  const double copy1 = best_seconds(repeats, [&] {
    std::memcpy(out.data(), in.data(), count * sizeof(Segment3));
    std::memset(kept.data(), 1, count);
  });
  rows.push_back({"copy (memcpy, 1 thread)", copy1});
  const double copy2 = best_seconds(repeats, [&] {
    parallel_for(count, {.threads = 2}, [&](std::size_t b, std::size_t e) {
      std::memcpy(out.data() + b, in.data() + b, (e - b) * sizeof(Segment3));
      std::memset(kept.data() + b, 1, e - b);
    });
  });
  rows.push_back({"copy (memcpy, 2 threads)", copy2});
  scalar("Cohen-Sutherland (exact, scalar)",
         [&](const Segment3& s) { return clip::cohen_sutherland(s, box); });
  scalar("Liang-Barsky (exact, scalar)",
         [&](const Segment3& s) { return clip::liang_barsky(s, box); });
  scalar("Cyrus-Beck, 6 half-spaces (exact, scalar)",
         [&](const Segment3& s) { return clip::cyrus_beck(s, planes); });
  for (int threads : {1, 2}) {
    const double s = best_seconds(
        repeats, [&] { clip::clip_segments(in, box, out, kept, {.threads = threads}); });
    rows.push_back(
        {threads == 1 ? "clip_segments kernel (1 thread)" : "clip_segments kernel (2 threads)", s});
    if (!std::equal(kept.begin(), kept.end(), reference.begin())) {
      std::printf("MISMATCH: batch kernel\n");
      return 1;
    }
  }
  std::size_t kept_count = 0;
  for (auto k : reference)
    kept_count += k;
  std::printf("%zu random segments in [-2,2]^3 against [-1,1]^3 (%zu kept), best of %d\n", count,
              kept_count, repeats);
  std::printf("traffic per segment: 48 B read + 48 B written + 1 B flag\n\n");
  std::printf("%-44s %10s %12s %10s %14s\n", "pass", "ms", "M seg/s", "GB/s in", "vs copy (2t)");
  for (const Row& r : rows) {
    const double rate = static_cast<double>(count) / r.seconds;
    std::printf("%-44s %10.1f %12.1f %10.2f %13.1f%%\n", r.name.c_str(), r.seconds * 1e3,
                rate * 1e-6, rate * 48e-9, 100.0 * copy2 / r.seconds);
  }
  return 0;
}
