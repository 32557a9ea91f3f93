// Stage 4a of slicing: a plane through no vertex whose chained rings need no 2D boolean.
//
// A closed mesh's generic section is its chained rings; the 2D engine is needed only where they
// touch, cross (rounded crossings of nearby edges, a self-intersecting mesh), nest or turn
// clockwise. Strictly convex rings with disjoint boxes do none of that, and proving it costs
// one filtered orient2d per vertex: sections of convex parts (most layers of smooth solids)
// skip the engine and the search for provenance.

#include <algorithm>

#include "clip/slice/stages.h"
#include "contain/predicates/orient2d.h"

namespace contain::clip::slice {

namespace {

// Directions in [0, pi) are the upper half: exact, from comparisons of the points.
bool upper(Vec2 from, Vec2 to) {
  return to.y > from.y || (to.y == from.y && to.x > from.x);
}

// Every turn strictly left and the direction passing angle 0 exactly once: a locally convex
// closed path of total turning 2 pi, hence a convex polygon, simple, counter-clockwise. Equal
// consecutive points give a zero orient2d and are refused.
bool strictly_convex_ccw(const Ring& ring, Box2& box) {
  const std::size_t n = ring.size();
  int turns = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
    if (predicates::orient2d(a, b, c) != Sign::positive) return false;
    if (!upper(a, b) && upper(b, c)) ++turns;
    box.expand(b);
  }
  return turns == 1;
}

bool boxes_apart(const Box2& a, const Box2& b) {
  return a.max.x < b.min.x || b.max.x < a.min.x || a.max.y < b.min.y || b.max.y < a.min.y;
}

}  // namespace

bool convex_section(std::vector<Ring>& rings, std::vector<std::vector<std::int32_t>>& triangles,
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
    if (!strictly_convex_ccw(rings[r], boxes[r])) return false;
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
