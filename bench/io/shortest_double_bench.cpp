// Shortest round-trip text of one double, single-threaded, on 4,096 precomputed inputs:
//   random       uniform random bit patterns, NaN and infinity left out: every exponent;
//   unit         uniform in [-1, 1], as the slicer's crossing coordinates on a unit sphere;
//   short        decimals of 1 to 6 digits (0.5, 12.25, 3e-05): the digits found one step early;
// through
//   to_chars     std::to_chars(first, last, double) (libstdc++: Ryu, then its layout);
//   writer       contain::io::detail::write_shortest_double (Schubfach, the same bytes).
// Counter: doubles/s (items_per_second); ns per double = 1e9 / items_per_second.
#include <benchmark/benchmark.h>

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "io/shortest_double.h"

namespace {

constexpr std::size_t kInputs = 1 << 12;

enum class Kind { random, unit, short_decimal };

std::vector<double> inputs(Kind kind) {
  std::mt19937_64 rng(26);
  std::vector<double> values;
  while (values.size() < kInputs) {
    double value = 0;
    switch (kind) {
      case Kind::random:
        value = std::bit_cast<double>(rng());
        if (!std::isfinite(value)) continue;
        break;
      case Kind::unit:
        value = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
        break;
      case Kind::short_decimal: {
        const std::string text = std::to_string(rng() % 1000000) + "e-" + std::to_string(rng() % 8);
        std::from_chars(text.data(), text.data() + text.size(), value);
        break;
      }
    }
    values.push_back(value);
  }
  return values;
}

template <typename Write>
void run(benchmark::State& state, Kind kind, Write write) {
  const std::vector<double> values = inputs(kind);
  std::array<char, 64> buffer{};
  for (auto _ : state) {
    for (const double value : values) {
      char* end = write(buffer.data(), value);
      benchmark::DoNotOptimize(end);
      benchmark::ClobberMemory();
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * values.size()));
}

char* standard(char* at, double value) {
  return std::to_chars(at, at + 64, value).ptr;
}

char* writer(char* at, double value) {
  return contain::io::detail::write_shortest_double(at, value);
}

void BM_to_chars_random(benchmark::State& s) {
  run(s, Kind::random, standard);
}
void BM_writer_random(benchmark::State& s) {
  run(s, Kind::random, writer);
}
void BM_to_chars_unit(benchmark::State& s) {
  run(s, Kind::unit, standard);
}
void BM_writer_unit(benchmark::State& s) {
  run(s, Kind::unit, writer);
}
void BM_to_chars_short(benchmark::State& s) {
  run(s, Kind::short_decimal, standard);
}
void BM_writer_short(benchmark::State& s) {
  run(s, Kind::short_decimal, writer);
}

BENCHMARK(BM_to_chars_random);
BENCHMARK(BM_writer_random);
BENCHMARK(BM_to_chars_unit);
BENCHMARK(BM_writer_unit);
BENCHMARK(BM_to_chars_short);
BENCHMARK(BM_writer_short);

}  // namespace

BENCHMARK_MAIN();
