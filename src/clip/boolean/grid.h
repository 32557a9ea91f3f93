#pragma once
// The uniform grid of candidate pairs of a noding round (noding.cpp). Private to the
// polygon booleans.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "contain/inside/grid_axis.h"
#include "contain/values/vec.h"

namespace contain::clip::detail {

struct Item {
  double xmin, xmax, ymin, ymax;
  std::uint32_t piece;  // or the index of a hot pixel
  bool fresh;
  bool pixel;
};

// An item of the round and its position in the grid's per-item cell lists.
struct Key {
  std::uint32_t item;
  std::uint32_t rank;
};

// A uniform grid over the items of a round, about four cells per item, on the library's grid
// axes (GridAxis: the lines and the floating-point cell guess of the prepared indexes). Every
// item is listed in every cell its piece (or pixel square) passes through, conservatively: the
// rows and, per row, the x range of the piece are widened by a millionth of a cell, far above the
// rounding of their computation and of the guess, so two pieces that meet share a listed cell
// (the one of a common point). The indexes look cells up exactly instead (a query needs its one
// cell); here the widening is kept because the noding's near round relies on it (noding.cpp).
class CellGrid {
 public:
  void build(const std::vector<Item>& items, std::vector<Key>& keys) {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
    double x1 = -x0, y1 = -y0;
    for (const Key& k : keys) {
      const Item& it = items[k.item];
      x0 = std::min(x0, it.xmin);
      y0 = std::min(y0, it.ymin);
      x1 = std::max(x1, it.xmax);
      y1 = std::max(y1, it.ymax);
    }
    const double w = x1 - x0, h = y1 - y0;
    const double side = std::ceil(std::sqrt(4.0 * static_cast<double>(keys.size())));
    // An extent that overflows (coordinates of both signs near DBL_MAX): one column or row.
    constexpr double kInf = std::numeric_limits<double>::infinity();
    nx_ = w > 0 && w < kInf ? static_cast<int>(std::clamp(side, 1.0, 4096.0)) : 1;
    ny_ = h > 0 && h < kInf ? static_cast<int>(std::clamp(side, 1.0, 4096.0)) : 1;
    x_ = inside::GridAxis(x0, x1, nx_);
    y_ = inside::GridAxis(y0, y1, ny_);
    const double cw = nx_ > 1 ? w / nx_ : 1.0;
    const double ch = ny_ > 1 ? h / ny_ : 1.0;
    // The widening must exceed the rounding of the cell computations, a few ulps of the largest
    // coordinate: cells can be far narrower than that (later rounds grid only the pieces near new
    // ones, which may crowd within ulps of a point), and below 2^-1000 a millionth of a cell
    // underflows.
    ex_ = std::max(1e-6 * cw, 16 * ulp(std::max(std::fabs(x0), std::fabs(x1))));
    ey_ = std::max(1e-6 * ch, 16 * ulp(std::max(std::fabs(y0), std::fabs(y1))));
    entries_.clear();
    // Room for a dozen cells per item saves most regrowth of the array (long pieces list more).
    entries_.reserve(12 * keys.size());
    item_first_.clear();
    for (Key& k : keys) {
      k.rank = static_cast<std::uint32_t>(item_first_.size());
      item_first_.push_back(static_cast<std::uint32_t>(entries_.size()));
      const Item& it = items[k.item];
      add(it, k.item);
    }
    item_first_.push_back(static_cast<std::uint32_t>(entries_.size()));
    // Counting sort of (cell, item) into per-cell lists.
    const std::size_t ncell = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
    cell_first_.assign(ncell + 1, 0);
    for (const auto& e : entries_)
      ++cell_first_[e.first + 1];
    for (std::size_t c = 0; c < ncell; ++c)
      cell_first_[c + 1] += cell_first_[c];
    cell_items_.resize(entries_.size());
    fill_.assign(cell_first_.begin(), cell_first_.end() - 1);
    for (const auto& e : entries_)
      cell_items_[fill_[e.first]++] = e.second;
  }
  /// How far beyond its line (and box) each item is listed, in x and in y.
  [[nodiscard]] double widening_x() const { return ex_; }
  [[nodiscard]] double widening_y() const { return ey_; }
  [[nodiscard]] std::span<const std::uint32_t> items_in(std::uint32_t cell) const {
    return {cell_items_.data() + cell_first_[cell], cell_first_[cell + 1] - cell_first_[cell]};
  }
  // The cells of the item of rank r (its position in the keys).
  [[nodiscard]] auto cells_of(std::uint32_t r) const {
    struct Range {
      const std::pair<std::uint32_t, std::uint32_t>* b;
      const std::pair<std::uint32_t, std::uint32_t>* e;
      struct It {
        const std::pair<std::uint32_t, std::uint32_t>* p;
        std::uint32_t operator*() const { return p->first; }
        It& operator++() {
          ++p;
          return *this;
        }
        bool operator!=(const It& o) const { return p != o.p; }
      };
      [[nodiscard]] It begin() const { return {b}; }
      [[nodiscard]] It end() const { return {e}; }
    };
    return Range{entries_.data() + item_first_[r], entries_.data() + item_first_[r + 1]};
  }

 private:
  // ulp(m) for m >= 0, subnormals included.
  static double ulp(double m) {
    return m > 0 ? std::ldexp(1.0, std::max(std::ilogb(m) - 52, -1074))
                 : std::numeric_limits<double>::denorm_min();
  }
  // The guessed cell, clamped into the grid (NaN gives 0): monotone in the coordinate, and
  // within a few ulps of the largest coordinate of the exact cell, far below the widening.
  [[nodiscard]] int col(double x) const { return x_.guess(x); }
  [[nodiscard]] int row(double y) const { return y_.guess(y); }
  void add(const Item& it, std::uint32_t item) {
    const int r0 = row(it.ymin - ey_), r1 = row(it.ymax + ey_);
    const int c0 = col(it.xmin - ex_), c1 = col(it.xmax + ex_);
    const bool line = !it.pixel && it.ymin < it.ymax && it.xmin < it.xmax;
    // An item within one row or one column covers its box's cells: no per-row x ranges.
    if (!line || r0 == r1 || c0 == c1) {
      for (int r = r0; r <= r1; ++r)
        emit(r, c0, c1, item);
      return;
    }
    const Vec2 a = points_->at(it.piece), b = points_->at(it.piece + 1);
    // A piece crossing more rows than columns goes column by column (the same bound with the axes
    // swapped): the loop runs over the fewer bands.
    if (r1 - r0 > c1 - c0) {
      bands(
          a.y, a.x, b.y, b.x, it.ymin, it.ymax, it.xmin, it.xmax, c0, c1, x_, ey_, ex_,
          [&](double y) { return row(y); },
          [&](int c, int rl, int rh) {
            for (int r = rl; r <= rh; ++r)
              entries_.emplace_back(
                  static_cast<std::uint32_t>(r) * static_cast<std::uint32_t>(nx_) +
                      static_cast<std::uint32_t>(c),
                  item);
          });
    } else {
      bands(
          a.x, a.y, b.x, b.y, it.xmin, it.xmax, it.ymin, it.ymax, r0, r1, y_, ex_, ey_,
          [&](double x) { return col(x); }, [&](int r, int cl, int ch) { emit(r, cl, ch, item); });
    }
  }
  // The bands k0 .. k1 along axis v (rows: v is y; columns: v is x) that the piece a -> b
  // crosses, each with the cells along the other axis u that the piece passes through within the
  // band (widened by ev), widened by eu, within [umin, umax]: emit_band(k, first, last).
  template <class Cell, class EmitBand>
  static void bands(double au, double av, double bu, double bv, double umin, double umax,
                    double vmin, double vmax, int k0, int k1, const inside::GridAxis& axis,
                    double eu, double ev, Cell cell, EmitBand emit_band) {
    const double du = bu - au, dv = bv - av;
    const double slope = du / dv;
    // The slope overflows for a long piece nearly along u (and inf * 0 is NaN) and underflows for
    // a long one nearly along v (to 0: the u extent is lost), e.g. 1e285 by 1e-117 (fuzz finding
    // invalid_difference_extreme_range, docs/robustness.md): such pieces go through the fraction
    // (v - av) / dv in [0, 1], and a range that is still not finite (du overflowing) takes the
    // piece's whole box.
    const bool by_slope = std::isnormal(slope) || du == 0;
    auto u_at = [&](double v) {
      return by_slope ? au + (v - av) * slope : au + (v - av) / dv * du;
    };
    for (int k = k0; k <= k1; ++k) {
      double ul = umin, ur = umax;
      const double vlo = std::max(vmin, axis.line(k) - ev);
      const double vhi = std::min(vmax, axis.line(k + 1) + ev);
      const double ua = u_at(vlo), ub = u_at(vhi);
      if (std::isfinite(ua) && std::isfinite(ub)) {
        ul = std::max(umin, std::min(ua, ub) - eu);
        ur = std::min(umax, std::max(ua, ub) + eu);
      }
      emit_band(k, cell(ul - eu), cell(ur + eu));
    }
  }
  // Lists the item in cells c0 .. c1 of row r.
  void emit(int r, int c0, int c1, std::uint32_t item) {
    const std::uint32_t base = static_cast<std::uint32_t>(r) * static_cast<std::uint32_t>(nx_);
    for (int c = c0; c <= c1; ++c)
      entries_.emplace_back(base + static_cast<std::uint32_t>(c), item);
  }

 public:
  const std::vector<Vec2>* points_ = nullptr;

 private:
  inside::GridAxis x_, y_;
  double ex_ = 0, ey_ = 0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> entries_;  // (cell, item) per item
  std::vector<std::uint32_t> item_first_;
  std::vector<std::uint32_t> cell_first_, cell_items_, fill_;
};

}  // namespace contain::clip::detail
