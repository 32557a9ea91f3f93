// Stage 4b of slicing: a plane through no vertex whose chained rings are simple and pairwise
// disjoint, nested in any way, needs no 2D boolean either.
//
// Sections of non-convex solids (several rings per plane, holes, rings that are not
// star-shaped) are where simple_section declines and the 2D engine ran. When no two edges of
// the rings meet, except consecutive ones at their joint (exact orient2d on the pairs of
// segments whose boxes overlap, found through monotone chains as the engine's noding finds
// them), the engine's noding finds nothing and its arrangement is the rings themselves: ring r
// bounds the faces with winding numbers W_r (outside, the sum of the orientations of the rings
// around it) and W_r + o_r (inside). With the fill rule `positive` a ring is on the result's
// boundary when exactly one side is filled: a counter-clockwise ring with W = 0 (a shell) or a
// clockwise one with W = 1 (a hole), each kept as given, from its first point (its earliest
// input segment starts there). The polygons are then the engine's: shells in input order, each
// with the holes whose nearest boundary ring outside is that shell, in input order; and every
// edge's triangle is its own segment's (no other segment has an end on it).

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "clip/boolean/chains.h"
#include "clip/slice/stages.h"
#include "contain/inside/winding_number.h"
#include "contain/predicates/orient2d.h"

namespace contain::clip::slice {

namespace {

// The rings' edges as the engine reads them: ring after ring, point k to k + 1, the last
// closing the ring; consecutive edges of a ring linked.
struct RingEdges {
  std::vector<detail::NodingInput> segments;
  std::vector<char> links;
  std::vector<std::uint32_t> ring_first;  // per ring its first edge, and the total at the end
  std::vector<std::uint32_t> ring_of;     // per edge its ring
};

// False when a ring has two equal consecutive points (an edge the engine would drop).
bool ring_edges(const std::vector<Ring>& rings, RingEdges& out) {
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = rings[r];
    out.ring_first.push_back(static_cast<std::uint32_t>(out.segments.size()));
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 a = ring[i];
      const Vec2 b = ring[i + 1 < ring.size() ? i + 1 : 0];
      if (a == b) return false;
      out.segments.push_back({a, b});
      out.links.push_back(i + 1 < ring.size() ? 1 : 0);
      out.ring_of.push_back(static_cast<std::uint32_t>(r));
    }
  }
  out.ring_first.push_back(static_cast<std::uint32_t>(out.segments.size()));
  return true;
}

int sign_of_difference(double a, double b) {
  return (a > b) - (a < b);
}

// Edges p -> q and q -> r of one ring meet only at q: not collinear, or collinear with r
// beyond q (exact: on one line, the directions compare by coordinates).
bool joint_only(Vec2 p, Vec2 q, Vec2 r) {
  if (predicates::orient2d(p, q, r) != Sign::zero) return true;
  return sign_of_difference(p.x, q.x) != sign_of_difference(r.x, q.x) ||
         sign_of_difference(p.y, q.y) != sign_of_difference(r.y, q.y);
}

// Segments a-b and c-d share no point: the ends of one strictly on one side of the other's line.
bool segments_apart(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const Sign o1 = predicates::orient2d(a, b, c);
  if (o1 != Sign::zero && o1 == predicates::orient2d(a, b, d)) return true;
  const Sign o3 = predicates::orient2d(c, d, a);
  return o3 != Sign::zero && o3 == predicates::orient2d(c, d, b);
}

// No two edges meet but consecutive edges of a ring at their joint.
bool edges_apart(const RingEdges& e) {
  const std::vector<detail::Chain> chains = detail::monotone_chains(e.segments, e.links);
  bool apart = true;
  detail::chain_pairs(e.segments, chains, [&](std::uint32_t i, std::uint32_t j) {
    if (!apart) return;
    if (j < i) std::swap(i, j);
    const detail::NodingInput& s = e.segments[i];
    const detail::NodingInput& t = e.segments[j];
    const std::uint32_t r = e.ring_of[i];
    if (r == e.ring_of[j]) {
      if (j == i + 1) {
        apart = joint_only(s.a, s.b, t.b);
        return;
      }
      if (i == e.ring_first[r] && j + 1 == e.ring_first[r + 1]) {  // the closing joint
        apart = joint_only(t.a, t.b, s.b);
        return;
      }
    }
    apart = segments_apart(s.a, s.b, t.a, t.b);
  });
  return apart;
}

// +1 for a counter-clockwise simple ring, -1 for a clockwise one: the turn at its lowest point
// (convex). Zero cannot occur for a ring whose edges passed edges_apart.
int orientation(const Ring& ring) {
  const std::size_t n = ring.size();
  std::size_t m = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (ring[i].x < ring[m].x || (ring[i].x == ring[m].x && ring[i].y < ring[m].y)) m = i;
  }
  const Sign s = predicates::orient2d(ring[(m + n - 1) % n], ring[m], ring[(m + 1) % n]);
  return s == Sign::positive ? 1 : (s == Sign::negative ? -1 : 0);
}

// Whether p, on no edge of the ring, is inside it: the ring's exact winding number around p
// (a simple ring winds once or not at all).
bool inside_ring(Vec2 p, const Ring& ring) {
  return inside::winding_number(std::span<const Ring>(&ring, 1), p) != 0;
}

bool box_within(const Box2& inner, const Box2& outer) {
  return outer.min.x <= inner.min.x && inner.max.x <= outer.max.x && outer.min.y <= inner.min.y &&
         inner.max.y <= outer.max.y;
}

}  // namespace

bool nested_section(std::vector<Ring>& rings, std::vector<std::vector<std::int32_t>>& triangles,
                    std::size_t segments, Section& out) {
  std::size_t points = 0;
  for (const Ring& ring : rings) {
    if (ring.size() < 3) return false;  // chained rings have 3 points or more
    points += ring.size();
  }
  // Every segment in a ring (as for simple_section), and the rings' boxes compared pairwise.
  constexpr std::size_t kMaxRings = 2048;
  if (points != segments || rings.empty() || rings.size() > kMaxRings) return false;
  RingEdges edges;
  if (!ring_edges(rings, edges) || !edges_apart(edges)) return false;

  const std::size_t n = rings.size();
  std::vector<Box2> boxes(n);
  std::vector<int> turn(n);
  for (std::size_t r = 0; r < n; ++r) {
    for (const Vec2 p : rings[r])
      boxes[r].expand(p);
    turn[r] = orientation(rings[r]);
    if (turn[r] == 0) return false;
  }
  // The rings around each ring (disjoint rings: one point decides), within a budget of edge
  // visits that deeply nested sections would exceed (they go to the engine).
  std::vector<std::vector<std::uint32_t>> around(n);
  std::size_t budget = 8 * points + 4096;
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t s = 0; s < n; ++s) {
      if (s == r || !box_within(boxes[r], boxes[s])) continue;
      if (rings[s].size() > budget) return false;
      budget -= rings[s].size();
      if (inside_ring(rings[r][0], rings[s])) around[r].push_back(static_cast<std::uint32_t>(s));
    }
  }
  // Winding number outside each ring, its parent (the innermost ring around it), and whether it
  // bounds the result.
  std::vector<int> outside(n, 0);
  std::vector<std::int32_t> parent(n, -1);
  std::vector<char> boundary(n, 0);
  for (std::size_t r = 0; r < n; ++r) {
    std::size_t depth = 0;
    for (const std::uint32_t s : around[r]) {
      outside[r] += turn[s];
      if (parent[r] < 0 || around[s].size() > depth) {
        parent[r] = static_cast<std::int32_t>(s);
        depth = around[s].size();
      }
    }
    boundary[r] = (turn[r] > 0 && outside[r] == 0) || (turn[r] < 0 && outside[r] == 1) ? 1 : 0;
  }
  // Shells in input order, then each hole after the shell of its region: the nearest boundary
  // ring around it, whose inside is filled (a shell) as the hole's outside is.
  std::vector<std::int32_t> polygon_of(n, -1);
  std::vector<std::vector<std::size_t>> members;  // per polygon its rings, shell first
  for (std::size_t r = 0; r < n; ++r) {
    if (!boundary[r] || turn[r] < 0) continue;
    polygon_of[r] = static_cast<std::int32_t>(members.size());
    members.push_back({r});
  }
  for (std::size_t r = 0; r < n; ++r) {
    if (!boundary[r] || turn[r] > 0) continue;
    std::int32_t s = parent[r];
    while (s >= 0 && !boundary[static_cast<std::size_t>(s)])
      s = parent[static_cast<std::size_t>(s)];
    if (s < 0 || polygon_of[static_cast<std::size_t>(s)] < 0) return false;  // cannot happen
    members[static_cast<std::size_t>(polygon_of[static_cast<std::size_t>(s)])].push_back(r);
  }
  out.region.polygons.clear();
  out.region.polygons.reserve(members.size());
  out.triangles.clear();
  for (const std::vector<std::size_t>& polygon : members) {
    Polygon& p = out.region.polygons.emplace_back();
    p.rings.reserve(polygon.size());
    for (const std::size_t r : polygon) {
      p.rings.push_back(std::move(rings[r]));
      out.triangles.push_back(std::move(triangles[r]));
    }
  }
  return true;
}

}  // namespace contain::clip::slice
