#include "contain/io/points_io.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <memory>
#include <type_traits>
#include <utility>

#include "contain/core/huge_pages.h"
#include "contain/core/parallel.h"
#include "contain/io/number_table.h"
#include "io/masked_lines.h"
#include "io/point_lines.h"
#include "io/text_scan.h"

namespace contain::io {
namespace {

// The lines of `text` as one pass over it counts them: a last line without its newline counts.
std::int64_t count_lines(std::string_view text) {
  return std::count(text.begin(), text.end(), '\n') + (text.empty() || text.back() == '\n' ? 0 : 1);
}

// The coordinates a point file's item holds: 2 or 3.
template <class Item>
constexpr int kColumnsOf =
    std::is_same_v<Item, Vec2> || std::is_same_v<Item, BoundedPoint2> ? 2 : 3;

// A row of a table of 2 or 3 columns as an item, appended: a point, or a bounded point whose
// box is the point (read in full).
void append_row(const double* v, std::vector<Vec2>& points) {
  points.push_back({v[0], v[1]});
}
void append_row(const double* v, std::vector<Vec3>& points) {
  points.push_back({v[0], v[1], v[2]});
}
void append_row(const double* v, std::vector<BoundedPoint2>& points) {
  const Vec2 p{v[0], v[1]};
  points.push_back({.box = {p, p}});
}
void append_row(const double* v, std::vector<BoundedPoint3>& points) {
  const Vec3 p{v[0], v[1], v[2]};
  points.push_back({.box = {p, p}});
}

// The rows of a table of 2 or 3 columns as items, appended.
template <class Item>
void append_rows(const NumberTable& table, std::vector<Item>& points) {
  constexpr std::size_t columns = kColumnsOf<Item>;
  points.reserve(points.size() + table.rows());
  for (std::size_t i = 0; i < table.rows(); ++i)
    append_row(table.values.data() + columns * i, points);
}

// The one-pass scan of a slice into items: points, or bounded points.
template <class Item>
detail::PointLinesScan scan_items(std::string_view text, std::vector<Item>& items) {
  if constexpr (std::is_same_v<Item, Vec2> || std::is_same_v<Item, Vec3>) {
    return detail::scan_point_lines(text, items);
  } else {
    // By masks where the CPU makes it pay (the same results either way).
    static const bool masked = detail::masked_scan_pays();
    return masked ? detail::scan_bounded_masked(text, items)
                  : detail::scan_bounded_lines(text, items);
  }
}

template <class Points>
Result<Points> to_points(Result<NumberTable> table) {
  if (!table) return table.error();
  Points out;
  append_rows(*table, out.points);
  out.lines = std::move(table->lines);
  return out;
}

const NumberTableOptions kTwo{.columns = {2}};
const NumberTableOptions kThree{.columns = {3}};

// A whole text of points with their lines: the scanner, and at a line it cannot take the table
// parser over the whole text, for the error (and its line) worded as ever.
template <class Points>
Result<Points> scan_points(std::string_view text, const std::string& source,
                           const NumberTableOptions& options) {
  Points out;
  const std::string_view lines = detail::skip_bom(text);
  // Room for every line: counting them is a pass at memory speed, and capacity that a comment or
  // a blank line leaves unused is never touched.
  const auto most = static_cast<std::size_t>(count_lines(lines));
  out.points.reserve(most);
  out.lines.reserve(most);
  if (detail::scan_point_lines(lines, out.points, &out.lines).complete) return out;
  return to_points<Points>(parse_number_table(text, source, options));
}

// One slice of a block, parsed on its own thread: its items (its points, or their answers), lines
// and the line of its first point (from 1 within the slice; 0: none), or `failed` when the scanner
// stopped at a line it cannot take, which the table parser then reads again in file order, with
// the lines before it known, for the error of one pass over the file.
// `scratch`: what the slicer keeps with the slice from block to block (cleared, not freed).
struct NoScratch {};
template <class Item, class Scratch = NoScratch>
struct Slice {
  std::vector<Item> items;
  std::int64_t lines = 0;
  std::int64_t first_row = 0;
  bool failed = false;
  Scratch scratch;
};

// Room for a point every 32 bytes at once (a coordinate file's lines are 30 to 60 bytes): the
// vector grown by doubling copied itself into fresh pages several times, each page a fault (dear
// in a virtual machine); capacity never used is never touched. Shorter lines grow it.
template <class Item, class Scratch>
void begin_slice(std::string_view text, Slice<Item, Scratch>& slice) {
  slice.items.clear();
  slice.items.reserve(text.size() / 32 + 64);
}
template <class Item, class Scratch>
void end_slice(const detail::PointLinesScan& scan, Slice<Item, Scratch>& slice) {
  slice.failed = !scan.complete;
  slice.lines = scan.lines;
  slice.first_row = scan.first_row;
}

// The slices of the chunked readers: the points themselves (Vec2, Vec3, or boxes).
template <class Point>
struct PointSlices {
  using Item = Point;
  using Part = Slice<Point>;
  static constexpr int kColumns = kColumnsOf<Point>;
  void parse(std::string_view text, Part& slice) const {
    begin_slice(text, slice);
    end_slice(scan_items(text, slice.items), slice);
  }
  void from_table(const NumberTable& table, Part& slice) const {
    slice.items.clear();
    append_rows(table, slice.items);
  }
};

// The slices of the locating readers: each point's answer, given as the scan hands over a run of
// points (detail::BoundedSink), while their boxes are in the cache, so that no array of points is
// written and read again; the points whose box has no one answer are read in full, kept with
// their places, and located together at the slice's end (the index's batch pipeline).
template <class Bounded, class Point>
struct LocatingSlices {
  using Item = Location;
  static constexpr int kColumns = kColumnsOf<Bounded>;
  const BoxLocator<Bounded, Point>& locator;

  // The points of a slice left to `locate`, their places (size_t: a slice is as large as the
  // caller's `block` makes it) and their answers: kept with the slice, so the ~160 blocks of 10^6
  // points on one thread allocate them once, not once a block.
  struct Scratch {
    std::vector<Point> exact;
    std::vector<std::size_t> where;
    std::vector<Location> located;
  };
  using Part = Slice<Location, Scratch>;

  struct Open {  // a slice being parsed: its answers and the points left to `locate`
    const BoxLocator<Bounded, Point>& locator;
    std::vector<Location>& answers;
    std::vector<Point>& exact;
    std::vector<std::size_t>& where;
    std::vector<Location>& located;

    static Open of(const BoxLocator<Bounded, Point>& locator, Part& slice) {
      Scratch& scratch = slice.scratch;
      scratch.exact.clear();
      scratch.where.clear();
      return {.locator = locator,
              .answers = slice.items,
              .exact = scratch.exact,
              .where = scratch.where,
              .located = scratch.located};
    }
    void take(std::span<const Bounded> run) {
      const std::size_t at = answers.size();
      answers.resize(at + run.size());
      std::uint64_t left = locator.settle(run, std::span<Location>(answers).subspan(at));
      // A caller's settle may set bits past its run: they name no point of it.
      if (run.size() < 64) left &= (std::uint64_t{1} << run.size()) - 1;
      for (; left != 0; left &= left - 1) {
        const auto k = static_cast<std::size_t>(std::countr_zero(left));
        exact.push_back(exact_point(run[k]));
        where.push_back(at + k);
      }
    }
    void finish() {
      if (exact.empty()) return;
      located.resize(exact.size());
      locator.locate(exact, located);
      for (std::size_t i = 0; i < where.size(); ++i)
        answers[where[i]] = located[i];
    }
  };

  void parse(std::string_view text, Part& slice) const {
    begin_slice(text, slice);
    Open open = Open::of(locator, slice);
    const detail::BoundedSink<Bounded> sink{
        .context = &open, .take = [](void* context, std::span<const Bounded> run) {
          static_cast<Open*>(context)->take(run);
        }};
    // By masks where the CPU makes it pay (the same points either way).
    static const bool masked = detail::masked_scan_pays();
    detail::PointLinesScan scan;
    if (masked) {
      scan = detail::scan_bounded_masked(text, sink);
    } else {
      scan = detail::scan_bounded_runs<Bounded>(
          text, [&open](std::span<const Bounded> run) { open.take(run); });
    }
    open.finish();
    end_slice(scan, slice);
  }
  void from_table(const NumberTable& table, Part& slice) const {
    slice.items.clear();
    std::vector<Bounded> points;
    append_rows(table, points);
    Open open = Open::of(locator, slice);
    take_runs(points, open);
    open.finish();
  }
  static void take_runs(std::span<const Bounded> points, Open& open) {
    constexpr std::size_t run = detail::BoundedSink<Bounded>::kMaxRun;
    for (std::size_t at = 0; at < points.size(); at += run)
      open.take(points.subspan(at, std::min(run, points.size() - at)));
  }
};

// Where the slices of `text` (whole lines) start: about equal parts, each moved to the next line.
std::vector<std::size_t> slice_starts(std::string_view text, int parts) {
  std::vector<std::size_t> starts{0};
  for (int t = 1; t < parts; ++t) {
    std::size_t at = text.size() / static_cast<std::size_t>(parts) * static_cast<std::size_t>(t);
    at = std::max(at, starts.back());
    const std::size_t newline = text.find('\n', at);
    at = newline == std::string_view::npos ? text.size() : newline + 1;
    if (at > starts.back() && at < text.size()) starts.push_back(at);
  }
  starts.push_back(text.size());
  return starts;
}

// What the file has given so far, to number lines and word errors as one pass over it would.
struct ReadPosition {
  std::int64_t lines = 0;
  std::int64_t first_row = 0;  // the file's first point's line, 0: none yet
  std::size_t bytes = 0;
};

// The least bytes of a slice worth a thread of its own.
constexpr std::size_t kSliceBytes = std::size_t{1} << 20;

// The block of ChunkedReading's `block` 0 (see there): small enough for the cache when one
// thread parses, large enough to share among threads otherwise.
std::size_t block_bytes(const ChunkedReading& reading) {
  if (reading.block != 0) return std::max<std::size_t>(reading.block, 64);
  constexpr std::size_t shared = std::size_t{8} << 20;
  const bool one_thread = thread_count({.threads = reading.threads}, shared, kSliceBytes) == 1;
  return one_thread ? std::size_t{256} << 10 : shared;
}

// Parses the whole lines of `text` (slices on up to `threads` threads, by `slicer`: PointSlices or
// LocatingSlices) and hands their items to `consume` in file order, at most `chunk` at a time; at
// a slice with an error, that slice is parsed again with the lines before it, for the error of
// one pass over the file.
template <class Slicer, class Item = typename Slicer::Item>
Status parse_block(std::string_view text, const ChunkedReading& reading, const std::string& source,
                   ReadPosition& at, std::uintmax_t file_size, const Slicer& slicer,
                   std::vector<typename Slicer::Part>& slices,
                   const std::function<void(std::span<const Item>, double)>& consume) {
  constexpr int kColumns = Slicer::kColumns;
  const BatchOptions options{.threads = reading.threads};
  const std::vector<std::size_t> starts =
      slice_starts(text, thread_count(options, text.size(), kSliceBytes));
  const std::size_t parts = starts.size() - 1;
  if (slices.size() < parts) slices.resize(parts);
  parallel_for(parts, options, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      slicer.parse(text.substr(starts[k], starts[k + 1] - starts[k]), slices[k]);
    }
  });
  const std::size_t chunk = std::max<std::size_t>(reading.chunk, 1);
  for (std::size_t k = 0; k < parts; ++k) {
    typename Slicer::Part& slice = slices[k];
    if (slice.failed) {
      const std::string_view lines = text.substr(starts[k], starts[k + 1] - starts[k]);
      auto table = parse_number_table(lines, source,
                                      {.columns = {kColumns},
                                       .lines_before = at.lines,
                                       .first_row_line = at.first_row,
                                       .first_row_columns = at.first_row == 0 ? 0 : kColumns});
      if (!table) return table.error();
      slicer.from_table(*table, slice);
      slice.first_row = table->rows() == 0 ? 0 : table->lines.front() - at.lines;
      slice.lines = count_lines(lines);
    }
    if (at.first_row == 0 && slice.first_row != 0) at.first_row = at.lines + slice.first_row;
    at.lines += slice.lines;
    const double share = file_size == 0
                             ? 0.0
                             : std::min(1.0, static_cast<double>(at.bytes + starts[k + 1]) /
                                                 static_cast<double>(file_size));
    const std::span<const Item> items(slice.items);
    for (std::size_t begin = 0; begin < items.size(); begin += chunk) {
      consume(items.subspan(begin, std::min(chunk, items.size() - begin)), share);
    }
  }
  at.bytes += text.size();
  return Ok{};
}

// A mapped file in the blocks read_chunked would read from a stream (the same whole lines, so
// the same pieces and errors), without copying them: each block is the text from the end of the
// last, `block` bytes cut after their last newline unless the rest is shorter; a line longer than
// a block grows the block. The byte order mark counts in the first block, as in the stream's.
template <class Slicer, class Item = typename Slicer::Item>
Status read_mapped(detail::MappedText& mapped, const ChunkedReading& reading,
                   const std::string& source, const Slicer& slicer,
                   const std::function<void(std::span<const Item>, double)>& consume) {
  std::size_t block = block_bytes(reading);
  const std::string_view text = mapped.text();
  const std::size_t mark = text.size() - detail::skip_bom(text).size();
  ReadPosition at{.bytes = mark};
  std::vector<typename Slicer::Part> slices;
  const auto unreadable = [&] {
    return detail::make_error(ErrorKind::io,
                              "the file could not be read to its end (shortened while being "
                              "read, or a read error)",
                              source);
  };
  for (std::size_t from = 0; from < text.size();) {
    std::size_t to = text.size();
    // Present before the search for a line end reads them.
    if (!mapped.reach(std::min(text.size(), from + block))) return unreadable();
    while (text.size() - from >= block) {
      const std::size_t newline = text.rfind('\n', from + block - 1);
      if (newline != std::string_view::npos && newline >= from) {
        to = newline + 1;
        break;
      }
      block *= 2;
    }
    if (!mapped.reach(to)) return unreadable();
    const std::size_t first = std::max(from, mark);
    if (Status parsed = parse_block(text.substr(first, to - first), reading, source, at,
                                    text.size(), slicer, slices, consume);
        !parsed) {
      return parsed;
    }
    from = to;
    mapped.release(from);
  }
  return Ok{};
}

// The file a block at a time: each block's whole lines parsed (parse_block), the partial last
// line carried to the next; a line longer than a block grows the block. A regular file is mapped
// instead (read_mapped) where `reading.map` asks it.
template <class Slicer, class Item = typename Slicer::Item>
Status read_chunked(const std::filesystem::path& path, const ChunkedReading& reading,
                    const Slicer& slicer,
                    const std::function<void(std::span<const Item>, double)>& consume) {
  auto input = detail::BlockInput::open(path);
  if (!input) return input.error();
  if (reading.map) {
    if (auto mapped = detail::MappedText::map(input->file(), input->size())) {
      return read_mapped(*mapped, reading, input->source(), slicer, consume);
    }
  }
  std::size_t block = block_bytes(reading);
  // The block in huge pages (HugePageVector: one 2 MB page for the one thread's 256 KB, four for
  // the 8 MB of several threads), written once and reused: where a fault is dear (a virtual
  // machine, docs/benchmarks.md) one fault a 2 MB page instead of 512. Elements not zeroed (the
  // allocator's construct): only the bytes read into it are scanned.
  HugePageVector<char> buffer(block);
  std::size_t held = 0;  // bytes in the buffer
  ReadPosition at;
  std::vector<typename Slicer::Part> slices;
  bool first = true;
  while (true) {
    auto got = input->read(buffer.data() + held, block - held);
    if (!got) return got.error();
    held += *got;
    const bool last = *got == 0 || held < block;
    std::string_view text(buffer.data(), held);
    std::size_t whole = text.size();
    if (!last) {
      const std::size_t newline = text.rfind('\n');
      if (newline == std::string_view::npos) {
        // One line fills the block: a larger block holds it.
        buffer.resize(2 * block);
        block *= 2;
        continue;
      }
      whole = newline + 1;
    }
    std::string_view lines = text.substr(0, whole);
    if (first) {
      const std::string_view skipped = detail::skip_bom(lines);
      at.bytes = lines.size() - skipped.size();
      lines = skipped;
      first = false;
    }
    if (Status parsed = parse_block(lines, reading, input->source(), at, input->size(), slicer,
                                    slices, consume);
        !parsed) {
      return parsed;
    }
    std::memmove(buffer.data(), buffer.data() + whole, held - whole);
    held -= whole;
    if (last && held == 0) return Ok{};
  }
}

}  // namespace

Result<Points2> parse_points2(std::string_view text, const std::string& source) {
  return scan_points<Points2>(text, source, kTwo);
}
Result<Points3> parse_points3(std::string_view text, const std::string& source) {
  return scan_points<Points3>(text, source, kThree);
}
Result<Points2> read_points2(const std::filesystem::path& path) {
  if (path == "-") return read_points2(std::cin, "<stdin>");
  auto text = detail::read_file(path);
  if (!text) return text.error();
  return parse_points2(*text, detail::source_name(path));
}
Result<Points3> read_points3(const std::filesystem::path& path) {
  if (path == "-") return read_points3(std::cin, "<stdin>");
  auto text = detail::read_file(path);
  if (!text) return text.error();
  return parse_points3(*text, detail::source_name(path));
}
Status read_points2_chunked(const std::filesystem::path& path, const ChunkedReading& reading,
                            const std::function<void(std::span<const Vec2>, double)>& consume) {
  return read_chunked(path, reading, PointSlices<Vec2>{}, consume);
}
Status read_points3_chunked(const std::filesystem::path& path, const ChunkedReading& reading,
                            const std::function<void(std::span<const Vec3>, double)>& consume) {
  return read_chunked(path, reading, PointSlices<Vec3>{}, consume);
}
Status read_points2_bounded(
    const std::filesystem::path& path, const ChunkedReading& reading,
    const std::function<void(std::span<const BoundedPoint2>, double)>& consume) {
  return read_chunked(path, reading, PointSlices<BoundedPoint2>{}, consume);
}
Status read_points3_bounded(
    const std::filesystem::path& path, const ChunkedReading& reading,
    const std::function<void(std::span<const BoundedPoint3>, double)>& consume) {
  return read_chunked(path, reading, PointSlices<BoundedPoint3>{}, consume);
}

namespace {
// An empty settle or locate would throw std::bad_function_call on a reading thread
// (std::terminate): refused before any thread starts.
template <class Locator>
Status check_locator(const Locator& locator, const std::filesystem::path& path) {
  if (locator.settle && locator.locate) return Ok{};
  return detail::make_error(ErrorKind::usage,
                            "the box locator has no settle or no locate function (a "
                            "default-constructed BoxLocator; io::box_locator makes one)",
                            detail::source_name(path));
}
}  // namespace

Status locate_points2_bounded(
    const std::filesystem::path& path, const ChunkedReading& reading, const BoxLocator2& locator,
    const std::function<void(std::span<const Location>, double)>& consume) {
  if (Status checked = check_locator(locator, path); !checked) return checked;
  return read_chunked(path, reading, LocatingSlices<BoundedPoint2, Vec2>{locator}, consume);
}
Status locate_points3_bounded(
    const std::filesystem::path& path, const ChunkedReading& reading, const BoxLocator3& locator,
    const std::function<void(std::span<const Location>, double)>& consume) {
  if (Status checked = check_locator(locator, path); !checked) return checked;
  return read_chunked(path, reading, LocatingSlices<BoundedPoint3, Vec3>{locator}, consume);
}

// The text of a bounded point was taken by the scanner, so the scan of it succeeds.
Vec2 exact_point(const BoundedPoint2& point) {
  if (point.first == nullptr) return point.box.min;
  return detail::scan_one_point<Vec2>(point.first, point.last);
}
Vec3 exact_point(const BoundedPoint3& point) {
  if (point.first == nullptr) return point.box.min;
  return detail::scan_one_point<Vec3>(point.first, point.last);
}

Result<Points2> read_points2(std::istream& in, const std::string& source) {
  auto text = detail::read_stream(in, source);
  if (!text) return text.error();
  return parse_points2(*text, source);
}
Result<Points3> read_points3(std::istream& in, const std::string& source) {
  auto text = detail::read_stream(in, source);
  if (!text) return text.error();
  return parse_points3(*text, source);
}

}  // namespace contain::io
