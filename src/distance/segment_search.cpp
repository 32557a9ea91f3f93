#include "distance/segment_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contain/predicates/unit_roundoff.h"
#include "contain/values/max_abs.h"
#include "distance/bound_constants.h"

namespace contain::distance::detail {

namespace {

// (p - v) . w minus a bound on its rounding error (one difference, one product, one sum: 3 eps
// of the permanent; 8 eps with room for the bound's own rounding).
inline double separation_lower(Vec2 p, Vec2 v, Vec2 w) {
  const Vec2 d = p - v;
  const double s = d.x * w.x + d.y * w.y;
  const double perm = std::fabs(d.x * w.x) + std::fabs(d.y * w.y);
  return s - 8 * kEps * perm;
}

// A computed a + t (b - a) lies within 3 eps (|a| + |b - a|) <= 9 eps M per coordinate of the
// exact point for the computed t in [0, 1]: delta <= sqrt(2) * 9 eps M < 16 eps M; then as for
// triangles (triangle_search.cpp), (|u| + delta)^2 <= (1 + 2^-20) |u|^2 + (1 + 2^20) delta^2.
double segment_slack(double max_abs) {
  const double delta = 16 * kEps * max_abs;
  return delta * delta * (1 + 0x1p20) * (1 + 0x1p-40) + std::numeric_limits<double>::denorm_min();
}

}  // namespace

void segment_bounds(Vec2 p, const Segment2& s, double slack, double& lo, double& hi) {
  const Vec2 u = s.b - s.a;
  const double uu = dot(u, u);
  double t = uu > 0 ? dot(p - s.a, u) / uu : 0.0;
  if (!(t > 0)) t = 0;  // also NaN
  if (t > 1) t = 1;
  const Vec2 q = s.a + t * u;
  const Vec2 w = p - q;
  const double ww = dot(w, w);
  hi = ww * (1 + 0x1p-19) + slack + 8 * std::numeric_limits<double>::denorm_min();
  if (!std::isfinite(hi)) hi = kInf;
  const double smin = std::min(separation_lower(p, s.a, w), separation_lower(p, s.b, w));
  lo = 0.0;
  if (smin > 0 && ww >= 0x1p-900 && std::isfinite(ww)) {
    const double r = smin / ww;
    if (r >= 0x1p-1000 && std::isfinite(r)) lo = smin * r * (1 - 8 * kEps);
  }
}

SegmentSearch::SegmentSearch(std::span<const Segment2> segments, const bvh::BuildOptions& options)
    : segments_(segments.begin(), segments.end()) {
  std::vector<Vec3> corners;
  corners.reserve(2 * segments_.size());
  double max_abs = 0.0;
  for (const Segment2& s : segments_) {
    corners.push_back({s.a.x, s.a.y, 0});
    corners.push_back({s.b.x, s.b.y, 0});
    max_abs = std::max({max_abs, values::max_abs(s.a), values::max_abs(s.b)});
  }
  tree_ = SearchTree(corners, 2, options);
  ordered_.reserve(segments_.size());
  for (const std::int32_t i : tree_.items())
    ordered_.push_back(segments_[static_cast<std::size_t>(i)]);
  slack_ = segment_slack(max_abs);
}

void SegmentSearch::contenders(Vec2 p, std::vector<Contender>& out, SearchStats* stats,
                               std::int32_t hint) const {
  tree_.contenders(
      {p.x, p.y, 0},
      [&](std::int32_t k, double& lo, double& hi) {
        segment_bounds(p, ordered_[static_cast<std::size_t>(k)], slack_, lo, hi);
      },
      out, stats, hint);
}

int SegmentSearch::within(Vec2 p, double d2_lo, double d2_hi, std::vector<Contender>& out) const {
  return tree_.within(
      {p.x, p.y, 0}, d2_lo, d2_hi,
      [&](std::int32_t k, double& lo, double& hi) {
        segment_bounds(p, ordered_[static_cast<std::size_t>(k)], slack_, lo, hi);
      },
      out);
}

}  // namespace contain::distance::detail
