#pragma once
// Private: the exact kernel shared by point_in_polygon, winding_number, the angle-sum test and
// PolygonIndex (one implementation of every tie-break rule).
//
// Derivation. Let p+ = p + delta*(1, eta) with delta, eta -> 0+ (the right-up perturbation rule).
// The horizontal ray from p+ meets an edge a->b iff, unperturbed,
//   - exactly one of a.y <= p.y, b.y <= p.y holds (a vertex on the ray lies below p+: the
//     half-open ray rule), and
//   - the crossing is right of p: orient2d(a, b, p) has the sign of the edge's direction;
// an edge through p itself (orient2d == 0) is never met: it reaches the height of p+ at a
// distance delta*eta*cot(angle) < delta from p. So the sum of the contributions of the edges not
// through p is the winding number of p+, which is that of p when p is on no edge.
// For p on edges, the incident edge directions cut a small disc around p into sectors; p+ lies in
// the sector just counter-clockwise of +x, and crossing an outgoing (incoming) direction
// counter-clockwise adds +1 (-1). Sorting the directions exactly (half plane by coordinate
// comparison, then orient2d) gives the winding number of every sector.

#include <span>
#include <vector>

#include "contain/core/location.h"
#include "contain/predicates/orient2d.h"
#include "contain/shapes/polygon.h"
#include "contain/values/vec.h"

namespace contain::inside::detail {

struct Edge {
  Vec2 a, b;
};

// Contribution of edge a->b to the winding number of p+ (half-open ray rule); 0 and `incident`
// set when p lies on the closed segment.
inline int ray_crossing(Vec2 a, Vec2 b, Vec2 p, bool& incident) {
  const bool a_below = a.y <= p.y;
  const bool b_below = b.y <= p.y;
  if (a_below != b_below) {
    const int dir = a_below ? 1 : -1;  // upward edges count +1
    if (p.x > a.x && p.x > b.x) return 0;
    if (p.x < a.x && p.x < b.x) return dir;
    const Sign s = predicates::orient2d(a, b, p);
    if (s == Sign::zero) {
      incident = true;
      return 0;
    }
    return (s == Sign::positive) == (dir > 0) ? dir : 0;
  }
  if (a_below && (a.y == p.y || b.y == p.y)) {
    if (a.y == b.y) {
      if ((a.x <= p.x && p.x <= b.x) || (b.x <= p.x && p.x <= a.x)) incident = true;
    } else if (a == p || b == p) {
      incident = true;
    }
  }
  return 0;
}

// True when p lies on the closed segment ab (exact).
inline bool on_segment(Vec2 a, Vec2 b, Vec2 p) {
  if (p.x < a.x && p.x < b.x) return false;
  if (p.x > a.x && p.x > b.x) return false;
  if (p.y < a.y && p.y < b.y) return false;
  if (p.y > a.y && p.y > b.y) return false;
  return predicates::orient2d(a, b, p) == Sign::zero;
}

// Half-open vertical rule: for an edge l->r or r->l with l.x <= x < r.x, true when it passes
// below (x, y)+, i.e. crosses the line x+ below height y+.
inline bool passes_below(Vec2 l, Vec2 r, double x, double y) {
  const Sign s = predicates::orient2d(l, r, Vec2{x, y});
  if (s != Sign::zero) return s == Sign::positive;
  return r.y <= l.y;  // through (x, y): below y+ unless it rises
}

// The filled-sector boundary rule: the location of p, which lies on every edge of `incident`
// (zero-length edges allowed, ignored), given the winding number `winding` of p+.
[[nodiscard]] Location classify_on_edges(Vec2 p, int winding, std::span<const Edge> incident,
                                         Fill fill);

// Walks rings once for a point: the winding number of p+ and the edges through p.
class RayAccumulator {
 public:
  explicit RayAccumulator(Vec2 p) : p_(p) {}
  void add_ring(const Ring& ring);
  [[nodiscard]] int winding() const { return winding_; }
  [[nodiscard]] bool on_edge() const { return !incident_.empty(); }
  [[nodiscard]] Location location(Fill fill) const;

 private:
  Vec2 p_;
  int winding_ = 0;
  std::vector<Edge> incident_;
};

}  // namespace contain::inside::detail
