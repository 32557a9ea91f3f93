#pragma once
/// \file
/// Point files: one point a line, 2 (2D) or 3 (3D) numbers separated by white space or commas;
/// blank lines and `#` lines are skipped (the CLI contract, shared/spec/cli.md).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <istream>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "contain/core/location.h"
#include "contain/core/parallel.h"
#include "contain/core/result.h"
#include "contain/values/box.h"
#include "contain/values/vec.h"

namespace contain::io {

/// 2D points in file order, and for each the 1-based line it came from (the CLI prints one output
/// line per point; a caller reporting a per-point problem can name the line).
struct Points2 {
  std::vector<Vec2> points;
  std::vector<std::int64_t> lines;
};

/// 3D points in file order, and for each its 1-based line.
struct Points3 {
  std::vector<Vec3> points;
  std::vector<std::int64_t> lines;
};

/// Parses 2D points: every non-skipped line must hold exactly 2 numbers. The syntax, the number
/// rules and the errors are those of `parse_number_table` (a line with 3 numbers is
/// ErrorKind::invalid_value: "found 3 numbers on the line, expected 2"). No points (empty text,
/// only comments) is not an error. Linear time, from_chars speed.
[[nodiscard]] Result<Points2> parse_points2(std::string_view text, const std::string& source);
/// Parses 3D points: every non-skipped line must hold exactly 3 numbers.
[[nodiscard]] Result<Points3> parse_points3(std::string_view text, const std::string& source);

/// Reads 2D points from a file; the path "-" reads standard input ("<stdin>" in errors).
[[nodiscard]] Result<Points2> read_points2(const std::filesystem::path& path);
/// Reads 3D points from a file; the path "-" reads standard input ("<stdin>" in errors).
[[nodiscard]] Result<Points3> read_points3(const std::filesystem::path& path);

/// How the chunked readers read: pieces of at most `chunk` points, blocks of `block` bytes (the
/// memory a long file costs, with the points of one block; a longer line grows the block), each
/// block parsed on up to `threads` threads (0: every core) in slices split at line ends. The
/// points, their order and the errors are the same whatever the threads and the block. `block`
/// 0: 256 KB when one thread parses (a block the kernel's copy leaves in the cache for the scan:
/// 8 MB blocks read 10^6 points 12-14% slower), else 8 MB shared by the threads (1 MB at least
/// each). `map`: a regular file mapped into memory (detail::MappedText) instead of read() into the
/// block, the same pieces, points and errors for a file not changed while it is read (a file cut
/// short then: read() ends at the cut; a mapping is an io error or SIGBUS). Not the default: where
/// a page's first touch is dear (a virtual machine whose hypervisor fills its page tables: 1.3 us a
/// 4 KB page measured on the project's machine, 12 ms for 40 MB, against 5.5 ms for read() into a
/// reused block and touching every line), the mapping costs more than the kernel's copy it saves;
/// on a machine where the copy is the larger cost (docs/benchmarks.md, "Point files mapped, not
/// copied") it pays.
struct ChunkedReading {
  std::size_t chunk = std::size_t{1} << 20;
  int threads = 1;
  std::size_t block = 0;
  bool map = false;
};

/// Reads 2D points in pieces: `consume(points, share)` sees at most `reading.chunk` points at a
/// time, in file order, `share` the part of the file read so far (0 to 1; 0 when its size is not
/// known, as for standard input), so that a long file costs a block of text and its points, not
/// every point at once. The same syntax and errors as `read_points2` (the line, and the first
/// row named in a wrong count, are the file's own); at the first error the call returns it,
/// after the points before its block's slice were consumed. The path "-" reads standard input.
[[nodiscard]] Status read_points2_chunked(
    const std::filesystem::path& path, const ChunkedReading& reading,
    const std::function<void(std::span<const Vec2>, double)>& consume);

/// Reads 3D points in pieces (see `read_points2_chunked`).
[[nodiscard]] Status read_points3_chunked(
    const std::filesystem::path& path, const ChunkedReading& reading,
    const std::function<void(std::span<const Vec3>, double)>& consume);

/// A 2D point known from its numbers' first digits: the closed box `box` holds the point the
/// full text denotes (the double std::from_chars gives for each number), proven for every
/// token, not estimated. A number of the plain shape `-?D.F` (1 to 7 digits D) is bounded by
/// its first 8 digits after the point, the rest only checked to be digits; any other number is
/// read in full. `first` is null when every number was read in full (the box is then the
/// point); else [first, last) is the text of the point's numbers, valid only in the call that
/// hands the point over, for `exact_point`.
struct BoundedPoint2 {
  Box2 box;
  const char* first = nullptr;
  const char* last = nullptr;
};

/// A 3D point known from its numbers' first digits (see `BoundedPoint2`).
struct BoundedPoint3 {
  Box3 box;
  const char* first = nullptr;
  const char* last = nullptr;
};

/// The point itself: its numbers read in full (std::from_chars), the doubles `read_points2`
/// gives. Only within the call that handed the point over (its text must be alive).
[[nodiscard]] Vec2 exact_point(const BoundedPoint2& point);
/// The point itself (see the 2D overload).
[[nodiscard]] Vec3 exact_point(const BoundedPoint3& point);

/// Reads 2D points in pieces as `read_points2_chunked` does (the same lines, order, errors and
/// chunks), each point as a box from its numbers' first digits, so that a caller whose answer is
/// the same over the whole box needs no more digits (as `locate_points2_bounded` answers them,
/// by the same scan, as it hands the boxes over). Every byte is still checked: a line the chunked
/// reader refuses is the same error here.
[[nodiscard]] Status read_points2_bounded(
    const std::filesystem::path& path, const ChunkedReading& reading,
    const std::function<void(std::span<const BoundedPoint2>, double)>& consume);
/// Reads 3D points in pieces as boxes (see `read_points2_bounded`).
[[nodiscard]] Status read_points3_bounded(
    const std::filesystem::path& path, const ChunkedReading& reading,
    const std::function<void(std::span<const BoundedPoint3>, double)>& consume);

/// How the locating readers (`locate_points2_bounded`) answer points: `settle(run, out)` answers
/// the points of `run` (at most 64) whose box has one answer, `out[i]` for `run[i]`, and returns
/// the bits (bit i) of those it leaves; `locate(points, out)` answers those, read in full
/// (`exact_point`), a slice of the file's at a time. Called from the reading threads at once (on
/// separate points): both must be safe to call concurrently.
template <class Bounded, class Point>
struct BoxLocator {
  std::function<std::uint64_t(std::span<const Bounded>, std::span<Location>)> settle;
  std::function<void(std::span<const Point>, std::span<Location>)> locate;
};
using BoxLocator2 = BoxLocator<BoundedPoint2, Vec2>;
using BoxLocator3 = BoxLocator<BoundedPoint3, Vec3>;

/// The BoxLocator of an index that can answer for a whole box (inside::PolygonIndex,
/// inside::MeshIndex; alive while the locator is used): `settle` is `index.locate_settled`, and
/// `locate` the index's batch locate on the calling thread. So the answers are exactly
/// `index.locate` of each point whenever `locate_settled` is right. No prefetch of the cells a few
/// points ahead: with the boxes handed over 32 at a time it costs a second guess of each cell and
/// paid nothing (docs/benchmarks.md, "Points answered as they are scanned", issue 27).
template <class Bounded, class Index>
[[nodiscard]] auto box_locator(const Index& index) {
  using Point = decltype(exact_point(std::declval<const Bounded&>()));
  return BoxLocator<Bounded, Point>{
      .settle =
          [&index](std::span<const Bounded> run, std::span<Location> out) {
            std::uint64_t left = 0;
            for (std::size_t k = 0; k < run.size(); ++k) {
              const auto settled = index.locate_settled(run[k].box);
              if (settled) {
                out[k] = *settled;
              } else {
                left |= std::uint64_t{1} << k;
              }
            }
            return left;
          },
      .locate = [&index](std::span<const Point> points,
                         std::span<Location> out) { index.locate(points, out, {.threads = 1}); }};
}

/// Reads 2D points as `read_points2_bounded` does (the same lines, order and errors) and answers
/// each by `locator` as it is scanned, while its box is in the cache: `consume(answers, share)`
/// sees the answers in file order, at most `reading.chunk` at a time, and no array of points is
/// kept. The answers are `locator`'s on the points read_points2_bounded gives: with `box_locator`,
/// exactly `index.locate` of each point read in full (whatever the threads, the block and `map`).
/// At the first error the call returns it, after the answers before its block's slice were
/// consumed. A locator without `settle` or `locate` is ErrorKind::usage, before the file is read;
/// bits `settle` sets at or past its run's size are ignored.
[[nodiscard]] Status locate_points2_bounded(
    const std::filesystem::path& path, const ChunkedReading& reading, const BoxLocator2& locator,
    const std::function<void(std::span<const Location>, double)>& consume);
/// Reads 3D points and answers them as they are scanned (see `locate_points2_bounded`).
[[nodiscard]] Status locate_points3_bounded(
    const std::filesystem::path& path, const ChunkedReading& reading, const BoxLocator3& locator,
    const std::function<void(std::span<const Location>, double)>& consume);

/// Reads 2D points from a stream to its end; `source` names it in errors.
[[nodiscard]] Result<Points2> read_points2(std::istream& in, const std::string& source);
/// Reads 3D points from a stream to its end; `source` names it in errors.
[[nodiscard]] Result<Points3> read_points3(std::istream& in, const std::string& source);

}  // namespace contain::io
