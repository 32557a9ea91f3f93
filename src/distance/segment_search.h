#pragma once
// Private to contain::distance: the closest segments of a point in the plane, found in floating
// point with proven bounds (search_tree.h, with the plane as z = 0), as triangle_search.h does
// for triangles: the approximate closest point q = a + t (b - a), t clamped to [0, 1], gives
//   hi: |p - q|^2 plus a bound on q's distance from the segment and on its rounding;
//   lo: the separation along w = p - q, min over the two ends v of (p - v) . w / |w|.

#include <cstdint>
#include <span>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/values/segment.h"
#include "contain/values/vec.h"
#include "distance/search_tree.h"

namespace contain::distance::detail {

class SegmentSearch {
 public:
  SegmentSearch() = default;
  /// Segments numbered 0..n-1 in the order given.
  SegmentSearch(std::span<const Segment2> segments, const bvh::BuildOptions& options);

  [[nodiscard]] bool empty() const { return tree_.empty(); }
  [[nodiscard]] const Segment2& segment(std::int32_t i) const {
    return segments_[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] std::size_t size() const { return segments_.size(); }

  void contenders(Vec2 p, std::vector<Contender>& out, SearchStats* stats = nullptr,
                  std::int32_t hint = -1) const;
  [[nodiscard]] int within(Vec2 p, double d2_lo, double d2_hi, std::vector<Contender>& out) const;

 private:
  std::vector<Segment2> segments_;  // in the order given
  std::vector<Segment2> ordered_;   // in the tree's leaf order
  SearchTree tree_;
  double slack_ = 0.0;
};

/// The bounds of one segment (exposed for the tests).
void segment_bounds(Vec2 p, const Segment2& s, double slack, double& lo, double& hi);

}  // namespace contain::distance::detail
