#include "contain/collide/region_region.h"

#include <algorithm>
#include <vector>

#include "contain/bvh/bvh.h"
#include "contain/collide/tri_tri_2d.h"
#include "contain/inside/polygon_index.h"

namespace contain::collide {
namespace {

struct Edges {
  std::vector<Segment2> segments;
  std::vector<std::int32_t> ring_first;  // index of each ring's first vertex (= first edge)
};

Edges edges_of(const MultiPolygon& region) {
  Edges e;
  for (const Polygon& p : region.polygons) {
    for (const Ring& r : p.rings) {
      if (r.empty()) continue;
      e.ring_first.push_back(static_cast<std::int32_t>(e.segments.size()));
      for (std::size_t i = 0; i < r.size(); ++i)
        e.segments.push_back({r[i], r[(i + 1) % r.size()]});
    }
  }
  return e;
}

bvh::Bvh hierarchy(const Edges& e) {
  std::vector<Box3> boxes;
  boxes.reserve(e.segments.size());
  for (const Segment2& s : e.segments) {
    boxes.push_back(Box3{{std::min(s.a.x, s.b.x), std::min(s.a.y, s.b.y), 0.0},
                         {std::max(s.a.x, s.b.x), std::max(s.a.y, s.b.y), 0.0}});
  }
  return bvh::Bvh(boxes);
}

bool box_overlap(const Segment2& s, const Segment2& t) {
  return std::max(std::min(s.a.x, s.b.x), std::min(t.a.x, t.b.x)) <=
             std::min(std::max(s.a.x, s.b.x), std::max(t.a.x, t.b.x)) &&
         std::max(std::min(s.a.y, s.b.y), std::min(t.a.y, t.b.y)) <=
             std::min(std::max(s.a.y, s.b.y), std::max(t.a.y, t.b.y));
}

}  // namespace

Contact region_region(const MultiPolygon& a, const MultiPolygon& b,
                      const RegionRegionOptions& options) {
  Contact contact;
  const Edges ea = edges_of(a), eb = edges_of(b);
  if (ea.segments.empty() || eb.segments.empty()) return contact;
  const bvh::Bvh ha = hierarchy(ea), hb = hierarchy(eb);
  const bvh::TraversalStats stats = bvh::traverse_pairs(
      ha, hb, [](const bvh::Node& p, const bvh::Node& q) { return p.box.overlaps(q.box); },
      [&](std::int32_t i, std::int32_t j) {
        const Segment2& s = ea.segments[static_cast<std::size_t>(i)];
        const Segment2& t = eb.segments[static_cast<std::size_t>(j)];
        if (!box_overlap(s, t)) return bvh::Visit::proceed;
        ++contact.exact_tests;
        if (!segment_segment(s, t)) return bvh::Visit::proceed;
        contact.intersect = true;
        contact.witness = inside::PairWitness::edges;
        contact.triangle_a = i;
        contact.triangle_b = j;
        return bvh::Visit::stop;
      });
  contact.node_pairs = stats.nodes;
  if (contact.intersect) return contact;
  // Boundaries disjoint: each ring lies wholly on one side of the other region's boundary.
  auto nested = [&](const Edges& e, const MultiPolygon& other, inside::PairWitness kind) {
    // One point a ring: the index's cost model skips the grid for few rings.
    const inside::PolygonIndex index(other, {.fill = options.fill, .queries = e.ring_first.size()});
    for (const std::int32_t v : e.ring_first) {
      ++contact.exact_tests;
      if (index.locate(e.segments[static_cast<std::size_t>(v)].a) != Location::outside) {
        contact.intersect = true;
        contact.witness = kind;
        contact.vertex = v;
        return true;
      }
    }
    return false;
  };
  if (!nested(ea, b, inside::PairWitness::vertex_of_a_in_b))
    nested(eb, a, inside::PairWitness::vertex_of_b_in_a);
  return contact;
}

}  // namespace contain::collide
