#include "contain/collide/pair_search.h"

#include <algorithm>
#include <cstddef>
#include <numeric>

namespace contain::collide {
namespace {

double lo(const Box3& b, int axis) {
  return axis == 0 ? b.min.x : (axis == 1 ? b.min.y : b.min.z);
}
double hi(const Box3& b, int axis) {
  return axis == 0 ? b.max.x : (axis == 1 ? b.max.y : b.max.z);
}

// The axis with the largest spread of box centres: the sweep prunes best there. Any axis is
// correct; this is only a heuristic in floating point.
int sweep_axis(std::span<const Box3> boxes, const std::vector<std::int32_t>& live) {
  double mean[3] = {0, 0, 0}, square[3] = {0, 0, 0};
  for (const std::int32_t i : live) {
    for (int k = 0; k < 3; ++k) {
      const double c = 0.5 * lo(boxes[static_cast<std::size_t>(i)], k) +
                       0.5 * hi(boxes[static_cast<std::size_t>(i)], k);
      mean[k] += c;
      square[k] += c * c;
    }
  }
  int best = 0;
  double best_var = -1;
  const double n = live.empty() ? 1.0 : static_cast<double>(live.size());
  for (int k = 0; k < 3; ++k) {
    const double var = square[k] / n - (mean[k] / n) * (mean[k] / n);
    if (var > best_var) {  // NaN (overflow) never wins: axis 0 stays
      best_var = var;
      best = k;
    }
  }
  return best;
}

}  // namespace

std::vector<std::pair<std::int32_t, std::int32_t>> pair_search(std::span<const Box3> boxes) {
  std::vector<std::int32_t> live;
  live.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Box3& b = boxes[i];
    // Written so that NaN bounds count as empty too.
    if (b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z) {
      live.push_back(static_cast<std::int32_t>(i));
    }
  }
  const int axis = sweep_axis(boxes, live);
  const int other1 = (axis + 1) % 3, other2 = (axis + 2) % 3;
  const auto box = [&](std::int32_t i) -> const Box3& {
    return boxes[static_cast<std::size_t>(i)];
  };
  std::sort(live.begin(), live.end(), [&](std::int32_t a, std::int32_t b) {
    const double la = lo(box(a), axis), lb = lo(box(b), axis);
    return la != lb ? la < lb : a < b;
  });
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
  for (std::size_t s = 0; s < live.size(); ++s) {
    const Box3& a = box(live[s]);
    const double end = hi(a, axis);
    // Boxes later in the order start at or after a's start; they meet a on the sweep axis
    // while they start no later than a's end (closed intervals).
    for (std::size_t t = s + 1; t < live.size() && lo(box(live[t]), axis) <= end; ++t) {
      const Box3& b = box(live[t]);
      if (lo(a, other1) <= hi(b, other1) && lo(b, other1) <= hi(a, other1) &&
          lo(a, other2) <= hi(b, other2) && lo(b, other2) <= hi(a, other2)) {
        pairs.emplace_back(std::min(live[s], live[t]), std::max(live[s], live[t]));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace contain::collide
