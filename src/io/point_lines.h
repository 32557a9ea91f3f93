#pragma once
/// \file
/// Private: the one-pass scanner of point files, the fast way of the point readers. It accepts
/// exactly the rows parse_number_table accepts with a fixed count (2 or 3), and gives the same
/// doubles, but splits the lines and scans the numbers in one walk over the bytes (no line-end
/// search before each line, no row array) and writes each point straight into its destination.
/// It does not word errors: at the first line it cannot take (a bad number, NaN, a wrong count,
/// a stray character) it stops, and the caller reads the text again with parse_number_table for
/// the error and its line. Errors are rare, so their second pass costs nothing in the common case.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <vector>

#include "contain/io/points_io.h"
#include "io/number_bound.h"
#include "io/text_scan.h"

namespace contain::io::detail {

/// Parses the number at `p` as parse_double does (an optional '+' before a digit or a point,
/// then std::from_chars' general format; underflow through parse_double's correctly rounded
/// path), advancing `p` past it; false, with `p` anywhere, when it is not a finite number.
/// Inline because it runs once a number: the call and the '+' test cost a tenth of the reading.
inline bool scan_finite_number(const char*& p, const char* end, double& out) {
  const char* start = p;
  if (start != end && *start == '+') {
    ++start;
    if (start == end || !((*start >= '0' && *start <= '9') || *start == '.')) return false;
  }
  const auto [ptr, ec] = std::from_chars(start, end, out, std::chars_format::general);
  if (ec == std::errc{}) {
    p = ptr;
    return std::isfinite(out);
  }
  if (ec != std::errc::result_out_of_range) return false;
  // Underflow (a subnormal or zero) or overflow: parse_double decides, as the table parser does.
  return parse_double(p, end, out) == NumberStatus::ok;
}

/// Advances `p` past the next newline (or to `end`).
inline void skip_past_line(const char*& p, const char* end) {
  const void* newline = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
  p = newline == nullptr ? end : static_cast<const char*>(newline) + 1;
}

/// What scan_point_lines read.
struct PointLinesScan {
  bool complete = false;       ///< every line was taken; false: stopped at a line it cannot take
  std::int64_t lines = 0;      ///< the lines walked (the text's lines when complete)
  std::int64_t first_row = 0;  ///< the line of the first point, from 1 (0: none)
};

/// Walks `text` (whole lines; the last may lack its newline) by the grammar of
/// parse_number_table for rows of `kColumns` numbers: numbers apart by blanks or by one comma
/// with optional blanks around it, blank lines, `#` comments (a whole line, or after the
/// numbers), CR LF. `read(p, end, k)` reads the k-th number of a row at `p` (advancing `p`
/// past it; false: not a number, the walk stops); `row(first, last, line)` takes a row whose
/// numbers span [first, last), on the text's 1-based line `line`. The text's byte order mark,
/// if any, is the caller's.
template <int kColumns, class Read, class Row>
PointLinesScan walk_point_lines(std::string_view text, Read&& read, Row&& row) {
  PointLinesScan scan;
  const char* p = text.data();
  const char* const end = p + text.size();
  while (p != end) {
    ++scan.lines;
    skip_blanks(p, end);
    if (p == end) break;
    if (*p == '\n') {
      ++p;
      continue;
    }
    if (*p == '#') {
      skip_past_line(p, end);
      continue;
    }
    const char* first = p;
    if (!read(p, end, 0)) return scan;
    for (int k = 1; k < kColumns; ++k) {
      const char* after = p;
      skip_blanks(p, end);
      if (p != end && *p == ',') {
        ++p;
        skip_blanks(p, end);
      } else if (p == after) {
        return scan;  // a character glued to the number
      }
      if (!read(p, end, k)) return scan;
    }
    const char* last = p;
    skip_blanks(p, end);
    if (p != end) {
      if (*p == '\n') {
        ++p;
      } else if (*p == '#') {
        skip_past_line(p, end);
      } else {
        return scan;  // another number, a comma, other text
      }
    }
    row(first, last, scan.lines);
    if (scan.first_row == 0) scan.first_row = scan.lines;
  }
  scan.complete = true;
  return scan;
}

/// Scans `text` (whole lines, as walk_point_lines) for points of `Point` (Vec2: 2 numbers a
/// line, Vec3: 3), appending them to `points` and, when `lines` is given, each one's line
/// (`lines_before` + its line in the text).
template <class Point>
PointLinesScan scan_point_lines(std::string_view text, std::vector<Point>& points,
                                std::vector<std::int64_t>* lines = nullptr,
                                std::int64_t lines_before = 0) {
  constexpr int kColumns = sizeof(Point) / sizeof(double);
  static_assert(kColumns == 2 || kColumns == 3);
  double v[kColumns];
  return walk_point_lines<kColumns>(
      text,
      [&](const char*& p, const char* end, int k) { return scan_finite_number(p, end, v[k]); },
      [&](const char*, const char*, std::int64_t line) {
        if constexpr (kColumns == 2) {
          points.push_back({v[0], v[1]});
        } else {
          points.push_back({v[0], v[1], v[2]});
        }
        if (lines != nullptr) lines->push_back(lines_before + line);
      });
}

/// The one point of [first, last), text that scan_point_lines takes as one row (as a bounded
/// point's numbers): the doubles it gives for them.
template <class Point>
Point scan_one_point(const char* first, const char* last) {
  constexpr int kColumns = sizeof(Point) / sizeof(double);
  double v[kColumns] = {};
  walk_point_lines<kColumns>(
      std::string_view(first, static_cast<std::size_t>(last - first)),
      [&](const char*& p, const char* end, int k) { return scan_finite_number(p, end, v[k]); },
      [](const char*, const char*, std::int64_t) {});
  if constexpr (kColumns == 2) {
    return {v[0], v[1]};
  } else {
    return {v[0], v[1], v[2]};
  }
}

/// The walk of scan_bounded_lines, each point given to `emit(point)` as its line is taken.
template <class Bounded, class Emit>
PointLinesScan walk_bounded_lines(std::string_view text, Emit&& emit) {
  constexpr int kColumns = std::is_same_v<Bounded, BoundedPoint2> ? 2 : 3;
  NumberBound v[kColumns];
  int read_in_full = 0;
  return walk_point_lines<kColumns>(
      text,
      // Inlined into the walk: a call a number cost a tenth of the scan.
      [&](const char*& p, const char* end, int k) __attribute__((always_inline)) {
        if (bound_plain_number(p, end, v[k])) return true;
        read_in_full += 1;
        if (!scan_finite_number(p, end, v[k].lo)) return false;
        v[k].hi = v[k].lo;
        return true;
      },
      [&](const char* first, const char* last, std::int64_t) __attribute__((always_inline)) {
        Bounded point;
        if constexpr (kColumns == 2) {
          point.box = {{v[0].lo, v[1].lo}, {v[0].hi, v[1].hi}};
        } else {
          point.box = {{v[0].lo, v[1].lo, v[2].lo}, {v[0].hi, v[1].hi, v[2].hi}};
        }
        if (read_in_full < kColumns) {
          point.first = first;
          point.last = last;
        }
        read_in_full = 0;
        emit(point);
      });
}

/// Scans `text` as scan_point_lines does (the same lines taken, the same lines refused), each
/// point as a box from its numbers' first digits (bound_plain_number; a number of another shape
/// read in full), appended to `points` (BoundedPoint2 or BoundedPoint3).
template <class Bounded>
PointLinesScan scan_bounded_lines(std::string_view text, std::vector<Bounded>& points) {
  return walk_bounded_lines<Bounded>(
      text, [&](const Bounded& point) __attribute__((always_inline)) { points.push_back(point); });
}

/// scan_bounded_lines(text, points), the points handed to `take(run)` in text order, runs of at
/// most 64 staged in a small array: no vector of a whole slice's points to write and read again
/// (the locating readers' walk, where the masks do not pay or leave a line).
template <class Bounded, class Take>
PointLinesScan scan_bounded_runs(std::string_view text, Take&& take) {
  constexpr std::size_t kRun = 64;
  Bounded run[kRun];
  std::size_t held = 0;
  const PointLinesScan scan = walk_bounded_lines<Bounded>(
      text, [&](const Bounded& point) __attribute__((always_inline)) {
        run[held++] = point;
        if (held == kRun) {
          take(std::span<const Bounded>(run, held));
          held = 0;
        }
      });
  if (held > 0) take(std::span<const Bounded>(run, held));
  return scan;
}

}  // namespace contain::io::detail
