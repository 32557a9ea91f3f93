#include "contain/distance/region_pair_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/bvh/nearest_pairs.h"
#include "contain/inside/polygon_index.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/rounded_distance.h"
#include "contain/predicates/squared_distance.h"
#include "contain/predicates/unit_roundoff.h"
#include "contain/values/max_abs.h"
#include "distance/bound_constants.h"
#include "distance/least_contender.h"
#include "distance/triangle_pair_bounds.h"
#include "distance/triangle_search.h"

namespace contain::distance {

namespace {

struct Edges {
  std::vector<Segment2> segments;
  std::vector<std::int32_t> ring;   // per edge
  std::vector<std::int32_t> start;  // first edge of each ring
  std::vector<Ring> rings;
  bvh::Bvh tree;
  double max_abs = 0.0;
};

Edges edges_of(const MultiPolygon& region) {
  Edges e;
  e.rings = region.all_rings();
  std::vector<Box3> boxes;
  for (std::size_t r = 0; r < e.rings.size(); ++r) {
    e.start.push_back(static_cast<std::int32_t>(e.segments.size()));
    const Ring& ring = e.rings[r];
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Segment2 s{ring[k], ring[(k + 1) % ring.size()]};
      e.segments.push_back(s);
      e.ring.push_back(static_cast<std::int32_t>(r));
      Box3 b;
      b.expand(Vec3{s.a.x, s.a.y, 0});
      b.expand(Vec3{s.b.x, s.b.y, 0});
      boxes.push_back(b);
      e.max_abs = std::max(e.max_abs, max_abs(s.a));
    }
  }
  e.tree = bvh::Bvh(boxes);
  return e;
}

double box_gap(const Box3& a, const Box3& b) {
  const double dx = std::max({a.min.x - b.max.x, b.min.x - a.max.x, 0.0});
  const double dy = std::max({a.min.y - b.max.y, b.min.y - a.max.y, 0.0});
  return (dx * dx + dy * dy) * (1 - 8 * kEps);
}

struct Found {
  bool empty = true;
  predicates::FlatPair2 pair{};
  std::int32_t ea = -1, eb = -1;
};

// The exact closest pair of edges: the descent with proven bounds, then exact comparisons.
Found closest_edges(const Edges& a, const Edges& b) {
  Found f;
  if (a.tree.empty() || b.tree.empty()) return f;
  // The descent: node pairs bounded by their boxes' gap, leaf pairs by the edges' own bounds.
  struct Descent {
    const Edges& a;
    const Edges& b;
    double slack;
    double best = kInf;
    std::vector<detail::PairContender> candidates;

    double lower(std::int32_t x, std::int32_t y) const {
      return box_gap(a.tree.nodes()[static_cast<std::size_t>(x)].box,
                     b.tree.nodes()[static_cast<std::size_t>(y)].box);
    }
    bool worth(const bvh::NodePair& e) const { return !(e.lower > best); }
    bool split_a(std::int32_t x, std::int32_t y) const {
      return bvh::surface_area(a.tree.nodes()[static_cast<std::size_t>(x)].box) >=
             bvh::surface_area(b.tree.nodes()[static_cast<std::size_t>(y)].box);
    }
    bvh::Visit leaves(std::int32_t x, std::int32_t y) {
      const bvh::Node& p = a.tree.nodes()[static_cast<std::size_t>(x)];
      const bvh::Node& q = b.tree.nodes()[static_cast<std::size_t>(y)];
      for (std::int32_t s = p.first; s < p.first + p.count; ++s) {
        for (std::int32_t t = q.first; t < q.first + q.count; ++t) {
          const std::int32_t ea = a.tree.items()[static_cast<std::size_t>(s)];
          const std::int32_t eb = b.tree.items()[static_cast<std::size_t>(t)];
          double lo = 0, hi = 0;
          detail::segment_pair_bounds(a.segments[static_cast<std::size_t>(ea)],
                                      b.segments[static_cast<std::size_t>(eb)], slack, lo, hi);
          if (lo > best) continue;
          candidates.push_back({ea, eb, lo, hi});
          best = std::min(best, hi);
        }
      }
      return bvh::Visit::proceed;
    }
  };
  Descent descent{a, b, detail::triangle_slack(std::max(a.max_abs, b.max_abs))};
  (void)bvh::nearest_pairs(a.tree, b.tree, descent);
  const auto winner = detail::least_contender(
      descent.candidates, descent.best, [&](std::int32_t x, std::int32_t y) {
        return predicates::closest_flats(a.segments[static_cast<std::size_t>(x)],
                                         b.segments[static_cast<std::size_t>(y)]);
      });
  if (winner.found) f = {false, winner.pair, winner.a, winner.b};
  return f;
}

// A vertex of each ring of `inner` inside `outer`: the first found, as a global vertex number.
std::int32_t nested_vertex(const Edges& inner, const Edges& outer, Fill fill) {
  if (outer.rings.empty()) return -1;
  // One point a ring: the index's cost model skips the grid for few rings.
  const inside::PolygonIndex index(std::span<const Ring>(outer.rings),
                                   {.fill = fill, .queries = inner.rings.size()});
  std::int32_t base = 0;
  for (const Ring& ring : inner.rings) {
    if (!ring.empty() && index.locate(ring.front()) == Location::inside) return base;
    base += static_cast<std::int32_t>(ring.size());
  }
  return -1;
}

Vec2 vertex_at(const Edges& e, std::int32_t v) {
  for (const Ring& ring : e.rings) {
    if (v < static_cast<std::int32_t>(ring.size())) return ring[static_cast<std::size_t>(v)];
    v -= static_cast<std::int32_t>(ring.size());
  }
  return {};
}

}  // namespace

PairDistance2 region_region(const MultiPolygon& a, const MultiPolygon& b,
                            const RegionRegionOptions& options) {
  PairDistance2 out;
  const Edges ea = edges_of(a), eb = edges_of(b);
  const Found f = closest_edges(ea, eb);
  if (f.empty) {
    out.distance = kInf;
    return out;
  }
  const bool touching = predicates::flats_meet(f.pair);
  if (!touching) {
    if (const std::int32_t v = nested_vertex(eb, ea, options.fill); v >= 0) {
      out.contact = inside::PairWitness::vertex_of_b_in_a;
      out.vertex = v;
      out.point_a = out.point_b = vertex_at(eb, v);
      return out;
    }
    if (const std::int32_t v = nested_vertex(ea, eb, options.fill); v >= 0) {
      out.contact = inside::PairWitness::vertex_of_a_in_b;
      out.vertex = v;
      out.point_a = out.point_b = vertex_at(ea, v);
      return out;
    }
  }
  out.contact = touching ? inside::PairWitness::edges : inside::PairWitness::none;
  out.distance = predicates::rounded_distance(f.pair);
  const predicates::ClosestPoints2 points = predicates::rounded_closest_points(f.pair);
  out.point_a = points.a;
  out.point_b = points.b;
  out.ring_a = ea.ring[static_cast<std::size_t>(f.ea)];
  out.edge_a = f.ea - ea.start[static_cast<std::size_t>(out.ring_a)];
  out.ring_b = eb.ring[static_cast<std::size_t>(f.eb)];
  out.edge_b = f.eb - eb.start[static_cast<std::size_t>(out.ring_b)];
  return out;
}

bool region_region_within(const MultiPolygon& a, const MultiPolygon& b, double d,
                          const RegionRegionOptions& options) {
  if (!(d >= 0)) return false;
  const Edges ea = edges_of(a), eb = edges_of(b);
  const Found f = closest_edges(ea, eb);
  if (f.empty) return false;
  if (predicates::compare_squared_distance(f.pair, d) != Sign::positive) return true;
  return nested_vertex(eb, ea, options.fill) >= 0 || nested_vertex(ea, eb, options.fill) >= 0;
}

}  // namespace contain::distance
