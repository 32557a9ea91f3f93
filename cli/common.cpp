#include "common.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <new>
#include <string>

#include "contain/core/huge_pages.h"
#include "contain/core/parallel.h"
#include "contain/io/mesh_warning.h"
#include "contain/io/number_table.h"
#include "contain/io/region_io.h"
#include "contain/shapes/mesh_validation.h"
#include "timings.h"

namespace contain::cli {

int report(const Error& error) {
  std::cerr << "contain: " << error.what() << '\n';
  return error.kind == ErrorKind::usage ? exit_usage : exit_bad_input;
}

void warn(std::string_view message) {
  std::cerr << "contain: warning: " << message << '\n';
}

void warn_of_solid(std::string_view name, const Mesh& mesh) {
  const std::string words = io::mesh_warning(inside::MeshRegime::closed_exact, validate_mesh(mesh));
  if (!words.empty()) warn(std::string(name) + ": " + words);
}

Result<MultiPolygon> read_region_warned(const std::string& path) {
  auto read = io::read_region_with_notes(path);
  if (!read) return read.error();
  for (const std::int64_t line : read->notes.unclosed_rings) {
    warn(path + ":" + std::to_string(line) +
         ": ring not closed (WKT repeats the first point at the end); read as closed");
  }
  return std::move(read->region);
}

Result<std::vector<double>> parse_numbers(std::string_view text, std::string_view option) {
  std::vector<double> out;
  const char* p = text.data();
  const char* end = text.data() + text.size();
  auto is_separator = [](char c) { return c == ',' || c == ' ' || c == '\t' || c == '\n'; };
  while (p < end) {
    while (p < end && is_separator(*p))
      ++p;
    if (p == end) break;
    double value = 0.0;
    const char* start = p;
    if (*p == '+') ++p;  // from_chars does not take a leading '+'
    auto [next, ec] = std::from_chars(p, end, value);
    if (ec != std::errc() || (next < end && !is_separator(*next)) || !std::isfinite(value)) {
      const char* stop = next;
      while (stop < end && !is_separator(*stop))
        ++stop;
      // A number that is NaN, infinite or too large is bad input (exit 3, as NaN coordinates
      // in a file); text that is no number at all is a usage error (exit 2).
      const bool number =
          (ec == std::errc() && next == stop) || ec == std::errc::result_out_of_range;
      return Error{
          number ? ErrorKind::invalid_value : ErrorKind::usage,
          std::string(option) + ": '" + std::string(start, stop) + "' is not a finite number"};
    }
    out.push_back(value);
    p = next;
  }
  return out;
}

Result<Output> Output::open(const std::string& path) {
  enter_phase(Phase::write);
  Output out;
  if (path.empty() || path == "-") return out;
  out.file_ = std::make_unique<std::ofstream>(path, std::ios::binary);
  out.path_ = path;
  if (!*out.file_) return Error{ErrorKind::io, "cannot open for writing", path};
  return out;
}

Status Output::write(std::string_view text) {
  if (!file_) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    return Ok{};
  }
  file_->write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!*file_) return Error{ErrorKind::io, "write failed", path_};
  return Ok{};
}

Status Output::close() {
  if (!file_) {
    std::fflush(stdout);
    return Ok{};
  }
  file_->flush();
  if (!*file_) return Error{ErrorKind::io, "write failed", path_};
  return Ok{};
}

Status write_output(std::string_view text, const std::string& path) {
  auto output = Output::open(path);
  if (!output) return output.error();
  if (Status written = output->write(text); !written) return written;
  return output->close();
}

int emit(std::string_view text, const std::string& path) {
  const Status written = write_output(text, path);
  return written ? exit_ok : report(written.error());
}

int emit_locations(std::span<const Location> locations, BoundaryPolicy policy,
                   const std::string& path, int threads) {
  auto output = Output::open(path);
  if (!output) return report(output.error());
  const BatchOptions options{.threads = threads};
  // Formatting runs at about a nanosecond an answer: one thread formats pieces of 64 K answers
  // into one buffer, written as each is done (512 KB reused, in the cache: no fresh pages of a
  // whole block's text to fault in and clear, 8 MB for 10^6 answers); several threads format
  // blocks of 4 M answers (16 MB of text at most) in parts, written in order.
  constexpr std::size_t kPiece = std::size_t{1} << 16;
  if (thread_count(options, locations.size(), kPiece) == 1) {
    // In a huge page (core/huge_pages.h): its 64-128 pages of 4 kB cost more to fault in.
    HugePageVector<char> buffer(kLocationSlot * kPiece);
    for (std::size_t begin = 0; begin < locations.size(); begin += kPiece) {
      const auto piece = locations.subspan(begin, std::min(kPiece, locations.size() - begin));
      const std::size_t size = format_locations_into(piece, policy, buffer.data());
      if (Status written = output->write({buffer.data(), size}); !written) {
        return report(written.error());
      }
    }
  } else {
    constexpr std::size_t kBlock = std::size_t{1} << 22;
    for (std::size_t begin = 0; begin < locations.size(); begin += kBlock) {
      const auto block = locations.subspan(begin, std::min(kBlock, locations.size() - begin));
      const Status written = write_in_parallel_parts(
          *output, block.size(), options, kPiece, [&](std::size_t at, std::size_t size) {
            return format_locations(block.subspan(at, size), policy);
          });
      if (!written) return report(written.error());
    }
  }
  const Status closed = output->close();
  return closed ? exit_ok : report(closed.error());
}

bool is_region_path(const std::string& path) {
  return io::region_format(path).has_value();
}

bool stderr_is_terminal() {
  return isatty(STDERR_FILENO) != 0;
}

void add_boundary_option(CLI::App& app, BoundaryPolicy& policy) {
  const std::map<std::string, BoundaryPolicy> names{{"report", BoundaryPolicy::report},
                                                    {"inside", BoundaryPolicy::as_inside},
                                                    {"outside", BoundaryPolicy::as_outside}};
  app.add_option("--boundary", policy,
                 "points exactly on the boundary: 'report' prints 'on' (default), 'inside' / "
                 "'outside' fold them into 'in' / 'out'")
      ->transform(CLI::CheckedTransformer(names, CLI::ignore_case))
      ->option_text("report|inside|outside");
}

void add_fill_option(CLI::App& app, Fill& fill) {
  const std::map<std::string, Fill> names{{"evenodd", Fill::even_odd},
                                          {"nonzero", Fill::nonzero},
                                          {"positive", Fill::positive},
                                          {"negative", Fill::negative}};
  app.add_option("--fill", fill,
                 "how the rings (closed paths, in the direction written) fill the plane; evenodd "
                 "(default) is the OGC meaning for valid polygons")
      ->transform(CLI::CheckedTransformer(names, CLI::ignore_case))
      ->option_text("evenodd|nonzero|positive|negative");
}

void add_threads_option(CLI::App& app, int& threads) {
  // CLI11's NonNegativeNumber would print its range with the largest double written out.
  const CLI::Validator count(
      [](const std::string& text) -> std::string {
        return !text.empty() && text.front() == '-'
                   ? "must be 0 (every core) or a positive count, got " + text
                   : std::string();
      },
      "N");
  app.add_option("--threads", threads, "worker threads for batches (default: all cores)")
      ->check(count)
      ->option_text("N");
}

void add_quiet_option(CLI::App& app, bool& quiet) {
  app.add_flag("--quiet", quiet,
               "no progress on stderr (progress shows only when stderr is a terminal and the run "
               "takes over a second)");
}

std::size_t format_locations_into(std::span<const Location> locations, BoundaryPolicy policy,
                                  char* out) {
  // The three lines once ("in\n", "on\n", "out\n"), each copied as 8 bytes and the end moved by
  // its length: a fixed-size copy a line (the next line overwrites the rest), not a string
  // append.
  std::array<std::array<char, kLocationSlot>, 3> lines{};
  std::array<std::size_t, 3> lengths{};
  for (const Location l : {Location::outside, Location::boundary, Location::inside}) {
    const auto at = static_cast<std::size_t>(static_cast<int>(l) + 1);
    const std::string_view word = to_string(apply(policy, l));
    lengths[at] = std::min(word.size(), kLocationSlot - 1) + 1;
    std::copy_n(word.begin(), lengths[at] - 1, lines[at].begin());
    lines[at][lengths[at] - 1] = '\n';
  }
  char* end = out;
  for (const Location l : locations) {
    const auto at = static_cast<std::size_t>(static_cast<int>(l) + 1);
    std::memcpy(end, lines[at].data(), kLocationSlot);
    end += lengths[at];
  }
  return static_cast<std::size_t>(end - out);
}

std::string format_locations(std::span<const Location> locations, BoundaryPolicy policy) {
  std::string out(locations.size() * kLocationSlot, '\0');
  out.resize(format_locations_into(locations, policy, out.data()));
  return out;
}

Result<Transform> parse_transform(std::string_view text, std::string_view option) {
  auto numbers = parse_numbers(text, option);
  if (!numbers) return numbers.error();
  auto t = Transform::from_row_major(*numbers);
  if (!t) {
    Error e = t.error();
    e.kind = ErrorKind::usage;
    e.message = std::string(option) + ": " + e.message;
    return e;
  }
  return t;
}

Result<Placements> read_placements(const std::string& transform_a, const std::string& transform_b,
                                   const std::string& poses_file) {
  Placements out;
  if (!transform_a.empty()) {
    auto t = parse_transform(transform_a, "--transform-a");
    if (!t) return t.error();
    out.a = *t;
  }
  Transform tb;
  if (!transform_b.empty()) {
    auto t = parse_transform(transform_b, "--transform-b");
    if (!t) return t.error();
    tb = *t;
  }
  if (poses_file.empty()) {
    out.b.push_back(tb);
    return out;
  }
  if (!transform_b.empty()) {
    return Error{ErrorKind::usage, "--poses and --transform-b exclude each other"};
  }
  auto table = io::read_number_table(poses_file, {.columns = {12}});
  if (!table) return table.error();
  for (std::size_t r = 0; r < table->rows(); ++r) {
    auto t = Transform::from_row_major(std::span<const double>(table->values).subspan(r * 12, 12));
    if (!t) {
      Error e = t.error();
      e.source = poses_file;
      e.line = table->lines[r];
      return e;
    }
    out.b.push_back(*t);
  }
  return out;
}

}  // namespace contain::cli
