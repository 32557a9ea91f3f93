#pragma once
// Pieces every verb of the CLI shares: exit codes, error reporting, option values, output.

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "contain/core/location.h"
#include "contain/core/parallel.h"
#include "contain/core/result.h"
#include "contain/shapes/mesh.h"
#include "contain/shapes/polygon.h"
#include "contain/values/transform.h"

namespace contain::cli {

inline constexpr int exit_ok = 0;
inline constexpr int exit_usage = 2;      // the contract: unknown option, missing argument
inline constexpr int exit_bad_input = 3;  // the contract: unreadable or malformed input

/// A subcommand: its CLI11 node and what runs once it has been parsed.
struct Verb {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

/// Prints "contain: <file>:<line>: <message>" on stderr and returns the contract's exit code
/// (2 for usage errors, 3 for bad input).
int report(const Error& error);

/// Prints a warning on stderr (never on stdout, which holds only results).
void warn(std::string_view message);

/// Warns "NAME: mesh ..." with `contain inside`'s words (io::mesh_warning) for a closed mesh read
/// as a solid by a pair or scene query (the same solid as `inside`: the winding number, ray
/// parity for inconsistent orientation), when there is something to say (a mesh turned inside
/// out, inconsistent orientation, pinch vertices, degenerate or duplicated triangles).
void warn_of_solid(std::string_view name, const Mesh& mesh);

/// The numbers of a list-valued option ("1,0,0,2.5" or "1 0 0 2.5"), all finite; `option` names
/// the option in the error.
[[nodiscard]] Result<std::vector<double>> parse_numbers(std::string_view text,
                                                        std::string_view option);

/// A rigid transform from a 12-number option (r00 r01 r02 t0 ... t2); a usage error naming
/// `option` otherwise.
[[nodiscard]] Result<Transform> parse_transform(std::string_view text, std::string_view option);

/// Where two shapes stand: A's transform (--transform-a) and B's poses, either the one
/// --transform-b (identity when absent) or one a line of the --poses file (12 numbers a line;
/// an error names its line). --poses and --transform-b exclude each other.
struct Placements {
  Transform a;
  std::vector<Transform> b;
};
[[nodiscard]] Result<Placements> read_placements(const std::string& transform_a,
                                                 const std::string& transform_b,
                                                 const std::string& poses_file);

/// Where the answers go: the file `path`, or stdout when `path` is empty or "-"; written in
/// pieces, so that long results need not be held whole. Opening it starts the write phase
/// (--timings).
class Output {
 public:
  [[nodiscard]] static Result<Output> open(const std::string& path);
  [[nodiscard]] Status write(std::string_view text);
  /// Flushes; an error when some write failed.
  [[nodiscard]] Status close();

 private:
  std::unique_ptr<std::ofstream> file_;  // null: stdout
  std::string path_;
};

/// Formats `count` items in parts on up to `options.threads` threads (at least `min_per_thread`
/// items a thread) and writes the parts to `output` in order: `format(at, size)` returns the text
/// of items [at, at + size). The parts of one call are held at once; callers bound `count`.
template <typename Format>
[[nodiscard]] Status write_in_parallel_parts(Output& output, std::size_t count,
                                             const BatchOptions& options,
                                             std::size_t min_per_thread, Format&& format) {
  const auto threads = static_cast<std::size_t>(thread_count(options, count, min_per_thread));
  const std::size_t step = (count + threads - 1) / threads;
  std::vector<std::string> parts(threads);
  parallel_for(threads, options, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      const std::size_t at = std::min(count, k * step);
      parts[k] = format(at, std::min(step, count - at));
    }
  });
  for (const std::string& part : parts) {
    if (Status written = output.write(part); !written) return written;
  }
  return Ok{};
}

/// Writes `text` to `path`, or to stdout when `path` is empty or "-".
[[nodiscard]] Status write_output(std::string_view text, const std::string& path);

/// Writes the results (see `write_output`) and returns the exit code: 0, or 3 when writing failed.
[[nodiscard]] int emit(std::string_view text, const std::string& path);

/// Writes one line per location (format_locations) to `path` as `emit` does, formatted in
/// blocks on up to `threads` threads (0: every core), in order.
[[nodiscard]] int emit_locations(std::span<const Location> locations, BoundaryPolicy policy,
                                 const std::string& path, int threads);

/// io::read_region, with a warning on stderr for each WKT ring that is not closed (read as
/// closed: "FILE:LINE: warning: ring not closed ...").
[[nodiscard]] Result<MultiPolygon> read_region_warned(const std::string& path);

/// True when the path names a 2D region file (.wkt, .geojson, .json, any case) rather than a mesh.
[[nodiscard]] bool is_region_path(const std::string& path);

/// True when stderr is a terminal (progress is shown only then).
[[nodiscard]] bool stderr_is_terminal();

/// `--boundary report|inside|outside` and `--fill evenodd|nonzero|positive|negative` as CLI11
/// transforms onto the library's enums.
void add_boundary_option(CLI::App& app, BoundaryPolicy& policy);
void add_fill_option(CLI::App& app, Fill& fill);
/// `--threads N` (0 or absent: all cores).
void add_threads_option(CLI::App& app, int& threads);

/// `--quiet`: no progress on stderr (warnings and errors still go there).
void add_quiet_option(CLI::App& app, bool& quiet);

/// One line per location ("in", "on", "out") after applying `policy`.
[[nodiscard]] std::string format_locations(std::span<const Location> locations,
                                           BoundaryPolicy policy);

/// The bytes format_locations_into may write for each location (a line and the slack of its
/// fixed-size copy).
inline constexpr std::size_t kLocationSlot = 8;
/// The text of format_locations written at `out`, which has room for kLocationSlot bytes a
/// location (past the returned size the bytes are unspecified); returns the text's size.
std::size_t format_locations_into(std::span<const Location> locations, BoundaryPolicy policy,
                                  char* out);

}  // namespace contain::cli
