// Stage 4a of slicing: a plane through no vertex whose chained rings need no 2D boolean.
//
// A closed mesh's generic section is its chained rings; the 2D engine is needed only where they
// touch, cross (rounded crossings of nearby edges, a self-intersecting mesh), nest or turn
// clockwise. Star-shaped or convex rings with disjoint boxes do none of that, and proving it
// costs one or two filtered orient2d per vertex: such sections (most layers of smooth solids)
// skip the engine and the search for provenance.

#include <algorithm>
#include <cmath>

#include "clip/slice/stages.h"
#include "contain/predicates/orient2d.h"

namespace contain::clip::slice {

namespace {

// Directions (of to - from) in [0, pi) are the upper half: exact, from comparisons of the points.
bool upper(Vec2 from, Vec2 to) {
  return to.y > from.y || (to.y == from.y && to.x > from.x);
}

// Every turn strictly left and the direction passing angle 0 exactly once: a locally convex
// closed path of total turning 2 pi, hence a convex polygon, simple, counter-clockwise. Equal
// consecutive points give a zero orient2d and are refused.
bool strictly_convex_ccw(const Ring& ring) {
  const std::size_t n = ring.size();
  int turns = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i == 0 ? n - 1 : i - 1], b = ring[i], c = ring[i + 1 == n ? 0 : i + 1];
    if (predicates::orient2d(a, b, c) != Sign::positive) return false;
    if (!upper(a, b) && upper(b, c)) ++turns;
  }
  return turns == 1;
}

// Every edge strictly counter-clockwise around the point o and the ring going once around it:
// the angle about o increases along the ring by a total of 2 pi, so each ray from o meets the
// ring once: star-shaped about o, simple, counter-clockwise. Fine meshes round their sections'
// nearly collinear vertices into slightly concave ones, which this still proves.
bool star_ccw_about(const Ring& ring, Vec2 o) {
  const std::size_t n = ring.size();
  int turns = 0;
  // The previous point's angle test carried over: each point's is computed once.
  bool b_upper = upper(o, ring[0]);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 b = ring[i], c = ring[i + 1 == n ? 0 : i + 1];
    if (predicates::orient2d(o, b, c) != Sign::positive) return false;
    const bool c_upper = upper(o, c);
    if (!b_upper && c_upper) ++turns;
    b_upper = c_upper;
  }
  return turns == 1;
}

bool simple_ccw(const Ring& ring, Box2& box) {
  if (ring.size() < 3) return false;  // chained rings have 3 points or more
  // Any finite point o proves it; the mean of the vertices is inside a convex-like ring. Summed
  // as p (1 / n), which cannot overflow (orient2d needs finite input), into locals (the box is
  // written once: through the reference it was stored at every point).
  const double inverse = 1.0 / static_cast<double>(ring.size());
  Vec2 mean{0.0, 0.0};
  Box2 bounds = box;
  for (const Vec2 p : ring) {
    bounds.expand(p);
    mean = mean + Vec2{p.x * inverse, p.y * inverse};
  }
  box = bounds;
  const bool finite = std::isfinite(mean.x) && std::isfinite(mean.y);
  return (finite && star_ccw_about(ring, mean)) || strictly_convex_ccw(ring);
}

bool boxes_apart(const Box2& a, const Box2& b) {
  return a.max.x < b.min.x || b.max.x < a.min.x || a.max.y < b.min.y || b.max.y < a.min.y;
}

}  // namespace

bool simple_section(std::vector<Ring>& rings, std::vector<std::vector<std::int32_t>>& triangles,
                    std::size_t segments, Section& out) {
  // Pairwise boxes: sections with many rings go to the engine rather than pay R^2 here.
  constexpr std::size_t kMaxRings = 32;
  if (rings.size() > kMaxRings) return false;
  std::size_t points = 0;
  for (const Ring& ring : rings)
    points += ring.size();
  // A segment left out (a zero-length piece, a path of two points) is a candidate of the
  // engine's provenance that this path would not weigh.
  if (points != segments) return false;
  std::vector<Box2> boxes(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (!simple_ccw(rings[r], boxes[r])) return false;
    for (std::size_t s = 0; s < r; ++s) {
      if (!boxes_apart(boxes[r], boxes[s])) return false;
    }
  }
  out.region.polygons.clear();
  out.region.polygons.reserve(rings.size());
  for (Ring& ring : rings)
    out.region.polygons.push_back(Polygon{{std::move(ring)}});
  out.triangles = std::move(triangles);
  return true;
}

}  // namespace contain::clip::slice
