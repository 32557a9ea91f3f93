#pragma once
// The uniform grids of the prepared indexes (PolygonIndex, MeshIndex, RegionLayer's boxes): grid
// lines as doubles, and cells found by exact comparisons with them (floating point only guesses).
// One copy for the three (issue 16).

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace contain::inside::detail {

// Grid lines from lo to hi (both exact), n cells, monotone; no overflow for huge coordinates.
[[nodiscard]] inline std::vector<double> grid_lines(double lo, double hi, int n) {
  std::vector<double> lines(static_cast<std::size_t>(n) + 1);
  lines.front() = lo;
  for (int i = 1; i < n; ++i) {
    const double t = static_cast<double>(i) / n;
    const double v = lo * (1.0 - t) + hi * t;
    lines[static_cast<std::size_t>(i)] = std::clamp(v, lines[static_cast<std::size_t>(i) - 1], hi);
  }
  lines.back() = hi;
  return lines;
}

// The cell i of `lines` (n cells) holding v: lines[i] <= v < lines[i + 1], the last cell closed;
// v within the lines. `guess` comes from floating point and is usually right.
[[nodiscard]] inline int exact_cell(const std::vector<double>& lines, int n, double v, int guess) {
  const auto i = static_cast<std::size_t>(guess);
  if (lines[i] <= v && (guess + 1 == n || v < lines[i + 1])) return guess;
  const auto it = std::upper_bound(lines.begin() + 1, lines.end() - 1, v);
  return static_cast<int>(it - (lines.begin() + 1));
}

// A guess of the cell of v: origin is the first line, scale the cells per half unit (half units
// keep the span finite near DBL_MAX).
[[nodiscard]] inline int guess_cell(double v, double origin, double scale, int n) {
  const double g = (0.5 * v - 0.5 * origin) * scale;
  if (!(g >= 0.0)) return 0;  // also NaN
  if (g >= static_cast<double>(n)) return n - 1;
  return static_cast<int>(g);
}

// The cells [first, last] of `lines` whose closed spans meet the closed interval [lo, hi].
[[nodiscard]] inline std::pair<int, int> cell_range(const std::vector<double>& lines, int n,
                                                    double lo, double hi) {
  // first: the first cell whose upper line is >= lo; last: the last cell whose lower line <= hi.
  const auto first = std::lower_bound(lines.begin() + 1, lines.end(), lo) - (lines.begin() + 1);
  const auto last = (std::upper_bound(lines.begin(), lines.end() - 1, hi) - lines.begin()) - 1;
  return {static_cast<int>(std::min<std::ptrdiff_t>(first, n - 1)),
          static_cast<int>(std::max<std::ptrdiff_t>(last, 0))};
}

}  // namespace contain::inside::detail
