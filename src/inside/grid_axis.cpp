#include "contain/inside/grid_axis.h"

#include <cmath>

namespace contain::inside {

GridAxis::GridAxis(double lo, double hi, int cells)
    : lines_(static_cast<std::size_t>(cells) + 1), origin_(lo), cells_(cells) {
  lines_.front() = lo;
  for (int i = 1; i < cells; ++i) {
    const double t = static_cast<double>(i) / cells;
    const double v = lo * (1.0 - t) + hi * t;
    lines_[static_cast<std::size_t>(i)] =
        std::clamp(v, lines_[static_cast<std::size_t>(i) - 1], hi);
  }
  lines_.back() = hi;
  // Half units: the extent of any finite box is finite.
  const double half = 0.5 * hi - 0.5 * lo;
  scale_ = half > 0.0 ? cells / half : 0.0;
  if (!std::isfinite(scale_)) scale_ = 0.0;
}

int GridAxis::first_meeting_searched(double lo) const {
  const auto first = std::lower_bound(lines_.begin() + 1, lines_.end(), lo) - (lines_.begin() + 1);
  return static_cast<int>(std::min<std::ptrdiff_t>(first, cells_ - 1));
}

int GridAxis::last_meeting_searched(double hi) const {
  const auto last = (std::upper_bound(lines_.begin(), lines_.end() - 1, hi) - lines_.begin()) - 1;
  return static_cast<int>(std::max<std::ptrdiff_t>(last, 0));
}

}  // namespace contain::inside
