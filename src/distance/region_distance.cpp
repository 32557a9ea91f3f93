#include "contain/distance/region_distance.h"

#include <algorithm>
#include <limits>

#include "contain/predicates/closest_feature.h"
#include "contain/predicates/squared_distance.h"
#include "distance/flat_answer.h"
#include "distance/morton_order.h"
#include "distance/segment_search.h"

namespace contain::distance {

namespace {

using predicates::Flat2;
using predicates::FlatPair2;

struct PlanarWinner {
  std::int32_t edge = -1;
  FlatPair2 pair{};
};

// The exact stage, as for meshes: each contender's closest feature exactly, equal features
// without arithmetic, distinct ones compared exactly; ties keep the lowest edge.
PlanarWinner resolve_planar(Vec2 p, const detail::SegmentSearch& search,
                            std::vector<detail::Contender>& contenders) {
  std::sort(contenders.begin(), contenders.end(),
            [](const detail::Contender& a, const detail::Contender& b) { return a.item < b.item; });
  PlanarWinner best;
  for (const detail::Contender& c : contenders) {
    const Segment2& s = search.segment(c.item);
    const FlatPair2 pair{predicates::point_flat(p),
                         predicates::feature_flat(s, predicates::closest_feature(s, p))};
    if (best.edge < 0) {
      best = {c.item, pair};
      continue;
    }
    if (predicates::same_flat(pair.b, best.pair.b)) continue;
    if (predicates::compare_squared_distances(pair, best.pair) == Sign::negative) {
      best = {c.item, pair};
    }
  }
  return best;
}

}  // namespace

RegionDistance::RegionDistance() : search_(std::make_unique<detail::SegmentSearch>()) {}

RegionDistance::RegionDistance(std::span<const Ring> rings, const RegionDistanceOptions& options)
    : signs_(options.signs) {
  std::vector<Segment2> edges;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    ring_start_.push_back(static_cast<std::int32_t>(edges.size()));
    const Ring& ring = rings[r];
    for (std::size_t k = 0; k < ring.size(); ++k) {
      edges.push_back({ring[k], ring[(k + 1) % ring.size()]});
      ring_of_.push_back(static_cast<std::int32_t>(r));
    }
  }
  search_ = std::make_unique<detail::SegmentSearch>(edges, options.bvh);
  if (signs_)
    index_ = inside::PolygonIndex(rings, {.fill = options.fill, .queries = options.queries});
}

RegionDistance::RegionDistance(const Polygon& polygon, const RegionDistanceOptions& options)
    : RegionDistance(std::span<const Ring>(polygon.rings), options) {}

RegionDistance::RegionDistance(const MultiPolygon& region, const RegionDistanceOptions& options)
    : RegionDistance(std::span<const Ring>(region.all_rings()), options) {}

RegionDistance::~RegionDistance() = default;
RegionDistance::RegionDistance(RegionDistance&&) noexcept = default;
RegionDistance& RegionDistance::operator=(RegionDistance&&) noexcept = default;

std::size_t RegionDistance::size() const {
  return search_->size();
}

Closest2 RegionDistance::distance(Vec2 p, const PointQuery& query) const {
  return query_with_hint(p, query, -1);
}

Closest2 RegionDistance::query_with_hint(Vec2 p, const PointQuery& query, std::int32_t hint) const {
  Closest2 out;
  if (!is_finite(p)) {
    out.distance = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  if (search_->empty()) {
    out.distance = std::numeric_limits<double>::infinity();
    return out;
  }
  thread_local std::vector<detail::Contender> contenders;
  search_->contenders(p, contenders, nullptr, hint);
  const PlanarWinner w = resolve_planar(p, *search_, contenders);
  out = detail::answer(w.pair, query.closest_point);
  const std::int32_t ring = ring_of_[static_cast<std::size_t>(w.edge)];
  out.ring = ring;
  out.edge = w.edge - ring_start_[static_cast<std::size_t>(ring)];
  if (query.signed_distance) {
    if (!signs_) {
      out.distance = std::numeric_limits<double>::quiet_NaN();
      return out;
    }
    detail::apply_sign(out, index_.locate(p));
  }
  return out;
}

void RegionDistance::distance(std::span<const Vec2> points, std::span<Closest2> out,
                              const PointQuery& q, const BatchOptions& options) const {
  const std::size_t n = batch_size(points.size(), out.size());
  // Morton order with the previous point's edge as a hint, as MeshDistance does.
  const std::vector<std::uint32_t> order = detail::morton_order(points.first(n));
  parallel_for(n, options, [&](std::size_t begin, std::size_t end) {
    std::int32_t hint = -1;
    for (std::size_t k = begin; k < end; ++k) {
      detail::prefetch_ahead<>(order, k, end, points.data(), out.data());
      const std::size_t i = order[k];
      out[i] = query_with_hint(points[i], q, hint);
      hint =
          out[i].ring < 0 ? -1 : ring_start_[static_cast<std::size_t>(out[i].ring)] + out[i].edge;
    }
  });
}

bool RegionDistance::within(Vec2 p, double d) const {
  if (!(d >= 0) || !is_finite(p) || search_->empty()) return false;
  const detail::SquaredBounds d2 = detail::squared_bounds(d);
  thread_local std::vector<detail::Contender> undecided;
  const int fast = search_->within(p, d2.lo, d2.hi, undecided);
  if (fast != 0) return fast > 0;
  for (const detail::Contender& c : undecided) {
    const Segment2& s = search_->segment(c.item);
    const FlatPair2 pair{predicates::point_flat(p),
                         predicates::feature_flat(s, predicates::closest_feature(s, p))};
    if (predicates::compare_squared_distance(pair, d) != Sign::positive) return true;
  }
  return false;
}

void RegionDistance::within(std::span<const Vec2> points, double d, std::span<std::uint8_t> out,
                            const BatchOptions& options) const {
  batch_map(points, out, options, 4096,
            [&](Vec2 p) -> std::uint8_t { return within(p, d) ? 1 : 0; });
}

Closest2 point_region(const MultiPolygon& region, Vec2 p, const PointQuery& query,
                      const RegionDistanceOptions& options) {
  RegionDistanceOptions o = options;
  o.signs = query.signed_distance;
  return RegionDistance(region, o).distance(p, query);
}

}  // namespace contain::distance
