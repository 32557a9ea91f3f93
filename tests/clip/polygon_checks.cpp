#include "clip/polygon_checks.h"

#include <algorithm>
#include <vector>

#include "contain/predicates/orient2d.h"

namespace contain::test {
namespace {

using predicates::orient2d;

bool on_segment(Vec2 p, Vec2 a, Vec2 b) {
  return orient2d(a, b, p) == Sign::zero && std::min(a.x, b.x) <= p.x &&
         p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

bool meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const Sign s1 = orient2d(a, b, c), s2 = orient2d(a, b, d);
  const Sign s3 = orient2d(c, d, a), s4 = orient2d(c, d, b);
  if (s1 != s2 && s3 != s4 && s1 != Sign::zero && s2 != Sign::zero && s3 != Sign::zero &&
      s4 != Sign::zero) {
    return true;
  }
  return on_segment(c, a, b) || on_segment(d, a, b) || on_segment(a, c, d) || on_segment(b, c, d);
}

}  // namespace

std::string ogc_problem(const MultiPolygon& region) {
  struct Edge {
    Vec2 a, b;
    std::size_t ring, index, size;
  };
  std::vector<Edge> edges;
  std::size_t ring_id = 0;
  for (const Polygon& p : region.polygons) {
    for (std::size_t r = 0; r < p.rings.size(); ++r, ++ring_id) {
      const Ring& ring = p.rings[r];
      if (ring.size() < 3) return "ring of fewer than 3 points";
      const double a = signed_area2(ring);
      if ((r == 0) != (a > 0)) return r == 0 ? "shell not counter-clockwise" : "hole not clockwise";
      for (std::size_t i = 0; i < ring.size(); ++i) {
        if (ring[i] == ring[(i + 1) % ring.size()]) return "repeated point";
        edges.push_back({ring[i], ring[(i + 1) % ring.size()], ring_id, i, ring.size()});
      }
    }
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge& e = edges[i];
      const Edge& f = edges[j];
      const bool adjacent = e.ring == f.ring && ((e.index + 1) % e.size == f.index ||
                                                 (f.index + 1) % f.size == e.index);
      if (adjacent) {
        // Consecutive edges share one vertex; they must not overlap beyond it.
        const Vec2 shared = (e.index + 1) % e.size == f.index ? e.b : e.a;
        const Vec2 other_e = shared == e.a ? e.b : e.a;
        const Vec2 other_f = shared == f.a ? f.b : f.a;
        if (orient2d(shared, other_e, other_f) == Sign::zero &&
            (on_segment(other_f, shared, other_e) || on_segment(other_e, shared, other_f))) {
          return "consecutive edges overlap";
        }
        continue;
      }
      if (meet(e.a, e.b, f.a, f.b)) return "edges meet";
    }
  }
  return {};
}

double area(const MultiPolygon& region) {
  double total = 0.0;
  for (const Polygon& p : region.polygons) {
    for (const Ring& r : p.rings)
      total += 0.5 * signed_area2(r);
  }
  return total;
}

}  // namespace contain::test
