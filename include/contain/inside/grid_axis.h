#pragma once
/// \file
/// One axis of the library's one uniform grid (exact cell lookups): under `PolygonIndex`,
/// `MeshIndex` and clip's boolean noding grid, one `GridAxis` per dimension.

#include <algorithm>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace contain::inside {

/// The lines L_0 = lo <= L_1 <= ... <= L_n = hi of n cells along one axis, as doubles, and the
/// exact cell of a coordinate: cell i is the half-open span [L_i, L_i+1), the last one closed
/// ([L_n-1, L_n]).
///
/// The inner lines are lo (1 - t) + hi t for t = i / n, clamped to be monotone: evenly spaced up
/// to rounding, finite for every finite lo and hi (no difference hi - lo is formed, so
/// coordinates near DBL_MAX do not overflow). Rounding may make neighbouring lines equal (an
/// empty cell), never out of order. The index of a cell is first guessed in floating point from
/// the spacing (in half units: finite for any finite extent) and then checked against the lines
/// by exact comparisons, so `cell_of` is exact for every double in [lo, hi] whatever the guess.
///
/// Complexity: construction O(n); `guess` O(1); `cell_of` O(1) when the guess is right (almost
/// always), else O(log n); `cells_meeting` O(log n). Thread safety: const member functions may
/// run concurrently.
class GridAxis {
 public:
  /// No cells.
  GridAxis() = default;
  /// `cells` >= 1 cells from `lo` to `hi` (finite, lo <= hi).
  GridAxis(double lo, double hi, int cells);

  /// The number of cells n.
  [[nodiscard]] int cells() const { return cells_; }
  /// The n + 1 lines L_0 .. L_n.
  [[nodiscard]] std::span<const double> lines() const { return lines_; }
  /// The line L_i, 0 <= i <= n.
  [[nodiscard]] double line(int i) const { return lines_[static_cast<std::size_t>(i)]; }

  /// A floating-point guess of the cell of `v`, clamped into [0, n - 1] (NaN gives 0); exact for
  /// almost every v, but only `cell_of` is guaranteed. Precondition: at least one cell.
  [[nodiscard, gnu::always_inline]] int guess(double v) const {
    const double g = (0.5 * v - 0.5 * origin_) * scale_;
    if (!(g >= 0.0)) return 0;  // also NaN
    if (g >= static_cast<double>(cells_)) return cells_ - 1;
    return static_cast<int>(g);
  }

  /// The cell i with L_i <= v < L_i+1 (the last cell closed), decided by exact comparisons.
  /// Precondition: lo <= v <= hi, at least one cell.
  [[nodiscard]] int cell_of(double v) const { return cell_of(v, guess(v)); }

  /// As `cell_of(v)`, starting from a guess already made (`guess(v)` or any cell index).
  [[nodiscard]] int cell_of(double v, int guess) const {
    const auto i = static_cast<std::size_t>(guess);
    if (lines_[i] <= v && (guess + 1 == cells_ || v < lines_[i + 1])) return guess;
    const auto it = std::upper_bound(lines_.begin() + 1, lines_.end() - 1, v);
    return static_cast<int>(it - (lines_.begin() + 1));
  }

  /// The cells [first, last] whose closed spans [L_i, L_i+1] meet the closed interval [lo, hi]
  /// (exact comparisons), clamped into [0, n - 1]: an interval beyond an end gives that end's
  /// cell. Precondition: at least one cell.
  // Always inlined: the build's loops over every triangle call it (GCC kept a call in some).
  [[nodiscard, gnu::always_inline]] std::pair<int, int> cells_meeting(double lo, double hi) const {
    return {first_meeting(lo), last_meeting(hi)};
  }

 private:
  // The first cell whose upper line is >= lo (clamped): the guess where exact comparisons with
  // its two lines prove it (almost always), else a binary search (out of line: the common path
  // stays small enough to inline into the build's loops over every triangle).
  [[nodiscard, gnu::always_inline]] int first_meeting(double lo) const {
    const int g = guess(lo);
    const auto i = static_cast<std::size_t>(g);
    if (lines_[i + 1] >= lo && (g == 0 || lines_[i] < lo)) return g;
    return first_meeting_searched(lo);
  }
  // The last cell whose lower line is <= hi (clamped), the same way.
  [[nodiscard, gnu::always_inline]] int last_meeting(double hi) const {
    const int g = guess(hi);
    const auto i = static_cast<std::size_t>(g);
    if (lines_[i] <= hi && (g + 1 == cells_ || lines_[i + 1] > hi)) return g;
    return last_meeting_searched(hi);
  }
  [[nodiscard]] int first_meeting_searched(double lo) const;
  [[nodiscard]] int last_meeting_searched(double hi) const;

  std::vector<double> lines_;
  double origin_ = 0.0;  // L_0
  double scale_ = 0.0;   // cells per half unit, for the guess (0 for a zero or infinite extent)
  int cells_ = 0;
};

}  // namespace contain::inside
