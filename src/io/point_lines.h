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
#include <string_view>
#include <system_error>
#include <vector>

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

/// Scans `text` (whole lines; the last may lack its newline) for points of `Point` (Vec2: 2
/// numbers a line, Vec3: 3), appending them to `points` and, when `lines` is given, each one's
/// line (`lines_before` + its line in the text). The grammar of parse_number_table: numbers apart
/// by blanks or by one comma with optional blanks around it, blank lines, `#` comments (a whole
/// line, or after the numbers), CR LF. The text's byte order mark, if any, is the caller's.
template <class Point>
PointLinesScan scan_point_lines(std::string_view text, std::vector<Point>& points,
                                std::vector<std::int64_t>* lines = nullptr,
                                std::int64_t lines_before = 0) {
  constexpr int kColumns = sizeof(Point) / sizeof(double);
  static_assert(kColumns == 2 || kColumns == 3);
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
    double v[kColumns];
    if (!scan_finite_number(p, end, v[0])) return scan;
    for (int k = 1; k < kColumns; ++k) {
      const char* after = p;
      skip_blanks(p, end);
      if (p != end && *p == ',') {
        ++p;
        skip_blanks(p, end);
      } else if (p == after) {
        return scan;  // a character glued to the number
      }
      if (!scan_finite_number(p, end, v[k])) return scan;
    }
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
    if constexpr (kColumns == 2) {
      points.push_back({v[0], v[1]});
    } else {
      points.push_back({v[0], v[1], v[2]});
    }
    if (lines != nullptr) lines->push_back(lines_before + scan.lines);
    if (scan.first_row == 0) scan.first_row = scan.lines;
  }
  scan.complete = true;
  return scan;
}

}  // namespace contain::io::detail
