// The parse rate of point files against its limit, one thread, on a real file of points
// (CONTAIN_POINTS, default /tmp/data/points3.txt, three numbers a line; CONTAIN_POINTS2 for the
// 2D file, default /tmp/data/points2.txt), held in memory once:
//   from_chars_tokens   std::from_chars alone on the numbers, split beforehand (the limit);
//   from_chars_walk     std::from_chars over the bytes, one blank or newline skipped between
//                       numbers (the limit with the least possible scanning; no checks);
//   memchr_lines        the newlines found with memchr alone (what a line split costs);
//   scanner             detail::scan_point_lines on the whole text (the reader's hot loop);
//   mapped              the file memory-mapped in windows (MAP_POPULATE) and scanned;
//   read_copy           the file read with read() into a 256 KB block, nothing parsed (the copy);
//   reader              read_points3_chunked from the file, one thread (the whole read phase);
//   byte_classes        every byte checked to be a digit, '-', '.', blank or newline, 16 at a
//                       time (the floor of checking every byte, with no token logic at all);
//   prefix_walk         each number's first digits bounded (detail::bound_plain_number: the
//                       8-digit prefix read, the rest checked to be digits; from_chars for the
//                       few other shapes), one separator byte skipped between numbers (the
//                       floor of not parsing every digit: no line grammar, no points stored);
//   bounded_scanner     detail::scan_bounded_lines on the whole text (the bounded reader's loop);
//   bounded_reader      read_points3_bounded from the file, one thread (its whole read phase).
//   masked_scanner      detail::scan_bounded_masked on the whole text (the bounded scanner by
//                       byte masks; argument: the masks' version, 0 scalar, 1 SSE2, 2 AVX2,
//                       3 AVX-512BW);
//   masked_classes      detail::classify_blocks alone (the masks' first stage; the same argument).
// Counter: bytes/s of the file's text.
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <charconv>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "contain/io/points_io.h"
#include "io/byte_masks.h"
#include "io/masked_lines.h"
#include "io/number_bound.h"
#include "io/point_lines.h"

namespace {

std::string path_of(const char* variable, const char* fallback) {
  const char* given = std::getenv(variable);
  return given != nullptr ? given : fallback;
}

const std::string& points_path(int columns) {
  static const std::string three = path_of("CONTAIN_POINTS", "/tmp/data/points3.txt");
  static const std::string two = path_of("CONTAIN_POINTS2", "/tmp/data/points2.txt");
  return columns == 3 ? three : two;
}

const std::string& file_text(int columns) {
  static std::string texts[2];
  std::string& text = texts[columns - 2];
  if (text.empty()) {
    std::ifstream in(points_path(columns), std::ios::binary);
    std::ostringstream all;
    all << in.rdbuf();
    text = all.str();
  }
  return text;
}

// The numbers' tokens of the text: (offset, length) pairs.
const std::vector<std::pair<std::uint32_t, std::uint32_t>>& tokens(int columns) {
  static std::vector<std::pair<std::uint32_t, std::uint32_t>> lists[2];
  auto& list = lists[columns - 2];
  if (list.empty()) {
    const std::string& text = file_text(columns);
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && (text[i] == ' ' || text[i] == '\n'))
        ++i;
      const std::size_t start = i;
      while (i < text.size() && text[i] != ' ' && text[i] != '\n')
        ++i;
      if (i > start) list.emplace_back(start, i - start);
    }
  }
  return list;
}

void set_bytes(benchmark::State& state, std::size_t bytes) {
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes));
}

void from_chars_tokens(benchmark::State& state, int columns) {
  const std::string& text = file_text(columns);
  const auto& list = tokens(columns);
  std::vector<double> values(list.size());
  for (auto _ : state) {
    for (std::size_t k = 0; k < list.size(); ++k) {
      const char* first = text.data() + list[k].first;
      std::from_chars(first, first + list[k].second, values[k]);
    }
    benchmark::DoNotOptimize(values.data());
    benchmark::ClobberMemory();
  }
  set_bytes(state, text.size());
}

void from_chars_walk(benchmark::State& state, int columns) {
  const std::string& text = file_text(columns);
  std::vector<double> values(tokens(columns).size() + 1);
  for (auto _ : state) {
    const char* p = text.data();
    const char* const end = p + text.size();
    double* out = values.data();
    while (p < end) {
      p = std::from_chars(p, end, *out++).ptr + 1;
    }
    benchmark::DoNotOptimize(values.data());
    benchmark::ClobberMemory();
  }
  set_bytes(state, text.size());
}

void memchr_lines(benchmark::State& state, int columns) {
  const std::string& text = file_text(columns);
  for (auto _ : state) {
    std::size_t lines = 0;
    const char* p = text.data();
    const char* const end = p + text.size();
    while (const void* newline = std::memchr(p, '\n', static_cast<std::size_t>(end - p))) {
      p = static_cast<const char*>(newline) + 1;
      ++lines;
    }
    benchmark::DoNotOptimize(lines);
  }
  set_bytes(state, text.size());
}

template <class Point>
void scanner(benchmark::State& state) {
  constexpr int kColumns = sizeof(Point) / sizeof(double);
  const std::string& text = file_text(kColumns);
  std::vector<Point> points;
  points.reserve(tokens(kColumns).size() / kColumns + 1);
  for (auto _ : state) {
    points.clear();
    const auto scan = contain::io::detail::scan_point_lines(text, points);
    benchmark::DoNotOptimize(scan);
    benchmark::DoNotOptimize(points.data());
  }
  set_bytes(state, text.size());
}

// The file mapped in windows of `state.range(0)` MB (MAP_POPULATE), each window's whole lines
// scanned (the window overlaps the next by the partial line).
template <class Point>
void mapped(benchmark::State& state) {
  constexpr int kColumns = sizeof(Point) / sizeof(double);
  const std::size_t window = static_cast<std::size_t>(state.range(0)) << 20;
  std::vector<Point> points;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const int fd = ::open(points_path(kColumns).c_str(), O_RDONLY);
    struct stat info {};
    ::fstat(fd, &info);
    bytes = static_cast<std::size_t>(info.st_size);
    std::size_t at = 0;
    while (at < bytes) {
      const std::size_t page = at & ~std::size_t{4095};
      const std::size_t length = std::min(window, bytes - page);
      void* map = ::mmap(nullptr, length, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd,
                         static_cast<off_t>(page));
      std::string_view text(static_cast<const char*>(map) + (at - page), length - (at - page));
      if (page + length < bytes) text = text.substr(0, text.rfind('\n') + 1);
      points.clear();
      const auto scan = contain::io::detail::scan_point_lines(text, points);
      benchmark::DoNotOptimize(scan);
      at += text.size();
      ::munmap(map, length);
    }
    ::close(fd);
  }
  set_bytes(state, bytes);
}

void read_copy(benchmark::State& state, int columns) {
  const std::size_t block = std::size_t{256} << 10;
  std::vector<char> buffer(block);
  std::size_t total = 0;
  for (auto _ : state) {
    const int fd = ::open(points_path(columns).c_str(), O_RDONLY);
    total = 0;
    while (true) {
      const ssize_t got = ::read(fd, buffer.data(), block);
      if (got <= 0) break;
      total += static_cast<std::size_t>(got);
    }
    ::close(fd);
    benchmark::DoNotOptimize(buffer.data());
  }
  set_bytes(state, total);
}

template <class Point>
void reader(benchmark::State& state) {
  constexpr int kColumns = sizeof(Point) / sizeof(double);
  const std::size_t bytes = file_text(kColumns).size();
  // The block of the reading: 0 is the reader's own choice, else the argument in KB.
  const contain::io::ChunkedReading reading{
      .threads = 1, .block = static_cast<std::size_t>(state.range(0)) << 10};
  for (auto _ : state) {
    std::size_t count = 0;
    const auto consume = [&](std::span<const Point> points, double) { count += points.size(); };
    contain::Status status = contain::Ok{};
    if constexpr (kColumns == 3) {
      status = contain::io::read_points3_chunked(points_path(3), reading, consume);
    } else {
      status = contain::io::read_points2_chunked(points_path(2), reading, consume);
    }
    if (!status) state.SkipWithError("the file does not read");
    benchmark::DoNotOptimize(count);
  }
  set_bytes(state, bytes);
}

void byte_classes(benchmark::State& state, int columns) {
  const std::string& text = file_text(columns);
  // 16 bytes at a time in GCC's portable vectors (SSE2 on x86-64): a byte is allowed iff it is a
  // digit or one of "-. \n"; the flags are or-ed together, nothing else is done.
  using Bytes = unsigned char __attribute__((vector_size(16)));
  for (auto _ : state) {
    Bytes bad{};
    const char* p = text.data();
    const char* const end = p + text.size();
    for (; end - p >= 16; p += 16) {
      Bytes x;
      std::memcpy(&x, p, 16);
      const Bytes digit = (x - '0') < 10;
      const Bytes other = (x == '-') | (x == '.') | (x == ' ') | (x == '\n');
      bad |= ~(digit | other);
    }
    benchmark::DoNotOptimize(bad);
  }
  set_bytes(state, text.size());
}

void prefix_walk(benchmark::State& state, int columns) {
  const std::string& text = file_text(columns);
  std::vector<contain::io::detail::NumberBound> bounds(tokens(columns).size() + 1);
  for (auto _ : state) {
    const char* p = text.data();
    const char* const end = p + text.size();
    auto* out = bounds.data();
    while (p < end) {
      if (!contain::io::detail::bound_plain_number(p, end, *out)) {
        p = std::from_chars(p, end, out->lo).ptr;  // another shape (an exponent): in full
      }
      ++out;
      ++p;
    }
    benchmark::DoNotOptimize(bounds.data());
    benchmark::ClobberMemory();
  }
  set_bytes(state, text.size());
}

template <class Bounded>
void bounded_scanner(benchmark::State& state) {
  constexpr int kColumns = std::is_same_v<Bounded, contain::io::BoundedPoint2> ? 2 : 3;
  const std::string& text = file_text(kColumns);
  std::vector<Bounded> points;
  points.reserve(tokens(kColumns).size() / kColumns + 1);
  for (auto _ : state) {
    points.clear();
    const auto scan = contain::io::detail::scan_bounded_lines(text, points);
    benchmark::DoNotOptimize(scan);
    benchmark::DoNotOptimize(points.data());
  }
  set_bytes(state, text.size());
}

template <class Bounded>
void masked_scanner(benchmark::State& state) {
  constexpr int kColumns = std::is_same_v<Bounded, contain::io::BoundedPoint2> ? 2 : 3;
  const auto isa = static_cast<contain::io::detail::MaskIsa>(state.range(0));
  if (!contain::io::detail::mask_isa_available(isa)) {
    state.SkipWithError("this CPU lacks the version");
    return;
  }
  const std::string& text = file_text(kColumns);
  std::vector<Bounded> points;
  points.reserve(tokens(kColumns).size() / kColumns + 1);
  for (auto _ : state) {
    points.clear();
    const auto scan = contain::io::detail::scan_bounded_masked(text, points, isa);
    benchmark::DoNotOptimize(scan);
    benchmark::DoNotOptimize(points.data());
  }
  set_bytes(state, text.size());
}

void masked_classes(benchmark::State& state, int columns) {
  const auto isa = static_cast<contain::io::detail::MaskIsa>(state.range(0));
  if (!contain::io::detail::mask_isa_available(isa)) {
    state.SkipWithError("this CPU lacks the version");
    return;
  }
  const std::string& text = file_text(columns);
  // 16 KB at a time into masks that stay in the cache, as the scanner classifies.
  std::vector<contain::io::detail::ByteMasks> masks(256);
  for (auto _ : state) {
    for (std::size_t at = 0; at + 64 <= text.size(); at += 64 * masks.size()) {
      const std::size_t blocks = std::min(masks.size(), (text.size() - at) / 64);
      contain::io::detail::classify_blocks(text.data() + at, blocks, masks.data(), isa);
      benchmark::DoNotOptimize(masks.data());
    }
  }
  set_bytes(state, text.size());
}

template <class Bounded>
void bounded_reader(benchmark::State& state) {
  constexpr int kColumns = std::is_same_v<Bounded, contain::io::BoundedPoint2> ? 2 : 3;
  const std::size_t bytes = file_text(kColumns).size();
  const contain::io::ChunkedReading reading{.threads = 1};
  for (auto _ : state) {
    std::size_t count = 0;
    const auto consume = [&](std::span<const Bounded> points, double) { count += points.size(); };
    contain::Status status = contain::Ok{};
    if constexpr (kColumns == 3) {
      status = contain::io::read_points3_bounded(points_path(3), reading, consume);
    } else {
      status = contain::io::read_points2_bounded(points_path(2), reading, consume);
    }
    if (!status) state.SkipWithError("the file does not read");
    benchmark::DoNotOptimize(count);
  }
  set_bytes(state, bytes);
}

}  // namespace

BENCHMARK_CAPTURE(from_chars_tokens, 3d, 3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(from_chars_walk, 3d, 3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(memchr_lines, 3d, 3)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(scanner, contain::Vec3)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(mapped, contain::Vec3)->Unit(benchmark::kMillisecond)->Arg(1)->Arg(8)->Arg(64);
BENCHMARK_CAPTURE(read_copy, 3d, 3)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(reader, contain::Vec3)
    ->Unit(benchmark::kMillisecond)
    ->Arg(0)
    ->Arg(64)
    ->Arg(128)
    ->Arg(512)
    ->Arg(1024);
BENCHMARK_CAPTURE(byte_classes, 3d, 3)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(prefix_walk, 3d, 3)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(bounded_scanner, contain::io::BoundedPoint3)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(bounded_reader, contain::io::BoundedPoint3)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(masked_scanner, contain::io::BoundedPoint3)
    ->Unit(benchmark::kMillisecond)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3);
BENCHMARK_CAPTURE(masked_classes, 3d, 3)
    ->Unit(benchmark::kMillisecond)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3);
BENCHMARK_CAPTURE(from_chars_tokens, 2d, 2)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(from_chars_walk, 2d, 2)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(scanner, contain::Vec2)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(reader, contain::Vec2)->Unit(benchmark::kMillisecond)->Arg(0);
BENCHMARK_CAPTURE(read_copy, 2d, 2)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(byte_classes, 2d, 2)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(prefix_walk, 2d, 2)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(bounded_scanner, contain::io::BoundedPoint2)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(bounded_reader, contain::io::BoundedPoint2)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(masked_scanner, contain::io::BoundedPoint2)
    ->Unit(benchmark::kMillisecond)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3);
BENCHMARK_CAPTURE(masked_classes, 2d, 2)
    ->Unit(benchmark::kMillisecond)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3);

BENCHMARK_MAIN();
