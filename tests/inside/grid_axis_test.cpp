#include "contain/inside/grid_axis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

namespace contain::inside {
namespace {

// The oracle of cell_of: a linear scan of the lines.
int scanned_cell(const GridAxis& axis, double v) {
  const auto lines = axis.lines();
  for (int i = 0; i + 1 < axis.cells(); ++i) {
    if (lines[static_cast<std::size_t>(i)] <= v && v < lines[static_cast<std::size_t>(i) + 1]) {
      return i;
    }
  }
  return axis.cells() - 1;
}

TEST(GridAxis, LinesRunFromLoToHiExactlyAndAreMonotone) {
  for (const auto& [lo, hi, n] : std::vector<std::tuple<double, double, int>>{
           {0.0, 1.0, 7},
           {-3.5, 2.25, 100},
           {-std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), 64},
           {1.0, std::nextafter(1.0, 2.0), 16},
           {5.0, 5.0, 3}}) {
    const GridAxis axis(lo, hi, n);
    ASSERT_EQ(axis.cells(), n);
    ASSERT_EQ(axis.lines().size(), static_cast<std::size_t>(n) + 1);
    EXPECT_EQ(axis.line(0), lo);
    EXPECT_EQ(axis.line(n), hi);
    for (int i = 0; i < n; ++i) {
      EXPECT_LE(axis.line(i), axis.line(i + 1))
          << "line " << i << " of [" << lo << ", " << hi << "]";
      EXPECT_TRUE(std::isfinite(axis.line(i)));
    }
  }
}

TEST(GridAxis, CellOfIsTheExactHalfOpenCellWithTheLastClosed) {
  const GridAxis axis(0.0, 10.0, 10);
  EXPECT_EQ(axis.cell_of(0.0), 0);
  EXPECT_EQ(axis.cell_of(std::nextafter(1.0, 0.0)), 0);
  EXPECT_EQ(axis.cell_of(1.0), 1);  // on a line: the cell above it
  EXPECT_EQ(axis.cell_of(9.5), 9);
  EXPECT_EQ(axis.cell_of(10.0), 9);  // the upper end: the last cell, closed
}

TEST(GridAxis, CellOfMatchesAScanOfTheLinesWhateverTheGuess) {
  std::mt19937_64 rng(7);
  for (const auto& [lo, hi, n] : std::vector<std::tuple<double, double, int>>{
           {0.0, 1.0, 13},
           {-1e300, 1e300, 50},
           {-std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), 31},
           {1e-310, 3e-310, 9},
           {1.0, std::nextafter(1.0, 2.0), 8}}) {
    const GridAxis axis(lo, hi, n);
    std::uniform_real_distribution<double> t(0.0, 1.0);
    std::vector<double> values(axis.lines().begin(), axis.lines().end());
    for (int k = 0; k < 200; ++k) {
      const double u = t(rng);
      values.push_back(std::clamp(lo * (1.0 - u) + hi * u, lo, hi));
    }
    for (double line : axis.lines()) {
      values.push_back(std::max(lo, std::nextafter(line, -INFINITY)));
      values.push_back(std::min(hi, std::nextafter(line, INFINITY)));
    }
    for (double v : values) {
      const int want = scanned_cell(axis, v);
      ASSERT_EQ(axis.cell_of(v), want) << v << " in [" << lo << ", " << hi << "]";
      for (int guess : {0, n / 2, n - 1})
        ASSERT_EQ(axis.cell_of(v, guess), want) << v;
    }
  }
}

// The oracle of cells_meeting: scans for the first cell whose upper line is >= lo and the last
// whose lower line is <= hi, clamped into the grid.
std::pair<int, int> scanned_meeting(const GridAxis& axis, double lo, double hi) {
  const auto lines = axis.lines();
  int first = axis.cells() - 1, last = 0;
  for (int i = axis.cells() - 1; i >= 0; --i)
    if (lines[static_cast<std::size_t>(i) + 1] >= lo) first = i;
  for (int i = 0; i < axis.cells(); ++i)
    if (lines[static_cast<std::size_t>(i)] <= hi) last = i;
  return {first, last};
}

TEST(GridAxis, CellsMeetingMatchesAScanOfTheLinesOnAndBesideEveryLine) {
  // The guessed cells are taken only where exact comparisons prove them: values on the lines,
  // one ulp beside them, beyond the ends, and grids with repeated lines (empty cells).
  for (const auto& [lo, hi, n] :
       std::vector<std::tuple<double, double, int>>{{0.0, 1.0, 13},
                                                    {-3.0, 5.0, 8},
                                                    {-1e300, 1e300, 50},
                                                    {1e-310, 3e-310, 9},
                                                    {1.0, std::nextafter(1.0, 2.0), 8}}) {
    const GridAxis axis(lo, hi, n);
    std::vector<double> values{lo - 1.0, hi + 1.0, -INFINITY, INFINITY};
    for (double line : axis.lines()) {
      values.push_back(line);
      values.push_back(std::nextafter(line, -INFINITY));
      values.push_back(std::nextafter(line, INFINITY));
      values.push_back(0.5 * line + 0.5 * hi);
    }
    for (double a : values) {
      const std::pair<int, int> want = scanned_meeting(axis, a, a);
      ASSERT_EQ(axis.cells_meeting(a, a), want) << a << " in [" << lo << ", " << hi << "]";
    }
  }
}

TEST(GridAxis, GuessIsClampedAndMostlyRight) {
  const GridAxis axis(-2.0, 2.0, 40);
  EXPECT_EQ(axis.guess(-5.0), 0);
  EXPECT_EQ(axis.guess(5.0), 39);
  EXPECT_EQ(axis.guess(std::numeric_limits<double>::quiet_NaN()), 0);
  int right = 0;
  for (int k = 0; k < 400; ++k) {
    const double v = -2.0 + 4.0 * (k + 0.5) / 400;
    right += axis.guess(v) == axis.cell_of(v);
  }
  EXPECT_EQ(right, 400);
}

TEST(GridAxis, ZeroExtentIsOneCellHoldingItsOnlyValue) {
  const GridAxis axis(3.0, 3.0, 1);
  EXPECT_EQ(axis.cell_of(3.0), 0);
  EXPECT_EQ(axis.guess(3.0), 0);
  EXPECT_EQ(axis.cells_meeting(3.0, 3.0), std::make_pair(0, 0));
}

TEST(GridAxis, CellsMeetingAClosedIntervalIncludeNeighboursSharingALine) {
  const GridAxis axis(0.0, 8.0, 8);
  EXPECT_EQ(axis.cells_meeting(2.5, 2.5), std::make_pair(2, 2));
  EXPECT_EQ(axis.cells_meeting(3.0, 3.0), std::make_pair(2, 3));  // on the line between 2 and 3
  EXPECT_EQ(axis.cells_meeting(1.5, 4.0), std::make_pair(1, 4));
  EXPECT_EQ(axis.cells_meeting(0.0, 8.0), std::make_pair(0, 7));
  EXPECT_EQ(axis.cells_meeting(-9.0, -1.0), std::make_pair(0, 0));  // beyond an end: its cell
  EXPECT_EQ(axis.cells_meeting(9.0, 12.0), std::make_pair(7, 7));
}

}  // namespace
}  // namespace contain::inside
