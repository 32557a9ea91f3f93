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
#include <vector>

#include "contain/core/result.h"
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
/// each).
struct ChunkedReading {
  std::size_t chunk = std::size_t{1} << 20;
  int threads = 1;
  std::size_t block = 0;
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

/// Reads 2D points from a stream to its end; `source` names it in errors.
[[nodiscard]] Result<Points2> read_points2(std::istream& in, const std::string& source);
/// Reads 3D points from a stream to its end; `source` names it in errors.
[[nodiscard]] Result<Points3> read_points3(std::istream& in, const std::string& source);

}  // namespace contain::io
