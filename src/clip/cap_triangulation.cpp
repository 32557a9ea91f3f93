#include "clip/cap_triangulation.h"

#include <algorithm>

#include "contain/inside/point_in_polygon.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/ring_orientation.h"
#include "contain/shapes/polygon.h"

namespace contain::clip::detail {
namespace {

using Loop = std::vector<std::int32_t>;
using predicates::orient2d;

Ring ring_of(const Loop& loop, const std::vector<Vec2>& pts) {
  Ring r;
  for (auto i : loop)
    r.push_back(pts[static_cast<std::size_t>(i)]);
  return r;
}

Sign orientation(const Loop& loop, const std::vector<Vec2>& pts) {
  return predicates::ring_orientation(ring_of(loop, pts));
}

bool ccw(const Loop& loop, const std::vector<Vec2>& pts) {
  return orientation(loop, pts) == Sign::positive;
}

// Segments p1p2 and q1q2 share a point other than a common endpoint position.
bool blocks(Vec2 p1, Vec2 p2, Vec2 q1, Vec2 q2) {
  if (q1 == p1 || q1 == p2 || q2 == p1 || q2 == p2) return false;
  const Sign a = orient2d(p1, p2, q1), b = orient2d(p1, p2, q2);
  const Sign c = orient2d(q1, q2, p1), d = orient2d(q1, q2, p2);
  if (a != Sign::zero && a == b) return false;
  if (c != Sign::zero && c == d) return false;
  if (a == Sign::zero && b == Sign::zero) {  // collinear: overlap of the x (or y) ranges
    auto within = [](Vec2 x, Vec2 s, Vec2 t) {
      return std::min(s.x, t.x) <= x.x && x.x <= std::max(s.x, t.x) && std::min(s.y, t.y) <= x.y &&
             x.y <= std::max(s.y, t.y);
    };
    return within(q1, p1, p2) || within(q2, p1, p2) || within(p1, q1, q2);
  }
  return true;
}

// Inserts `hole` (clockwise) into `outer` (counter-clockwise) through a visible bridge.
void bridge(Loop& outer, const Loop& hole, const std::vector<Loop>& others,
            const std::vector<Vec2>& pts) {
  auto P = [&](std::int32_t i) { return pts[static_cast<std::size_t>(i)]; };
  std::size_t h = 0;
  for (std::size_t i = 1; i < hole.size(); ++i) {
    if (P(hole[i]).x > P(hole[h]).x) h = i;
  }
  const Vec2 ph = P(hole[h]);
  std::vector<std::size_t> order(outer.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return squared_length(P(outer[x]) - ph) < squared_length(P(outer[y]) - ph);
  });
  auto clear = [&](const Loop& loop, Vec2 a, Vec2 b) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      if (blocks(a, b, P(loop[i]), P(loop[(i + 1) % loop.size()]))) return false;
    }
    return true;
  };
  std::size_t m = order.front();
  for (std::size_t cand : order) {
    const Vec2 pm = P(outer[cand]);
    if (!clear(outer, ph, pm) || !clear(hole, ph, pm)) continue;
    bool ok = true;
    for (const Loop& o : others)
      ok = ok && clear(o, ph, pm);
    if (!ok) continue;
    const Ring outer_ring = ring_of(outer, pts);
    const Vec2 mid = 0.5 * (ph + pm);
    if (inside::point_in_polygon(std::span<const Ring>(&outer_ring, 1), mid) == Location::outside) {
      continue;
    }
    m = cand;
    break;
  }
  Loop merged(outer.begin(), outer.begin() + static_cast<std::ptrdiff_t>(m) + 1);
  for (std::size_t k = 0; k <= hole.size(); ++k)
    merged.push_back(hole[(h + k) % hole.size()]);
  merged.push_back(outer[m]);
  merged.insert(merged.end(), outer.begin() + static_cast<std::ptrdiff_t>(m) + 1, outer.end());
  outer = std::move(merged);
}

void ear_clip(Loop poly, const std::vector<Vec2>& pts,
              std::vector<std::array<std::int32_t, 3>>& out) {
  auto P = [&](std::int32_t i) { return pts[static_cast<std::size_t>(i)]; };
  while (poly.size() > 3) {
    const std::size_t n = poly.size();
    bool clipped = false;
    for (std::size_t i = 0; i < n && !clipped; ++i) {
      const std::int32_t a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
      const Vec2 pa = P(a), pb = P(b), pc = P(c);
      if (orient2d(pa, pb, pc) != Sign::positive) continue;
      bool empty = true;
      for (std::size_t k = 0; k < n && empty; ++k) {
        const Vec2 q = P(poly[k]);
        if (q == pa || q == pb || q == pc) continue;
        empty = !(orient2d(pa, pb, q) != Sign::negative && orient2d(pb, pc, q) != Sign::negative &&
                  orient2d(pc, pa, q) != Sign::negative);
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) {
      // No empty ear (rounded crossings can make a loop touch itself): cut a convex corner
      // anyway, which keeps the cap closed; else drop a flat corner; else give up.
      for (std::size_t i = 0; i < n && !clipped; ++i) {
        const std::int32_t a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
        if (orient2d(P(a), P(b), P(c)) == Sign::positive) {
          out.push_back({a, b, c});
          poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
          clipped = true;
        }
      }
      for (std::size_t i = 0; i < n && !clipped; ++i) {
        if (orient2d(P(poly[(i + n - 1) % n]), P(poly[i]), P(poly[(i + 1) % n])) == Sign::zero) {
          poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
          clipped = true;
        }
      }
      if (!clipped) return;
    }
  }
  if (poly.size() == 3 && orient2d(P(poly[0]), P(poly[1]), P(poly[2])) != Sign::negative) {
    out.push_back({poly[0], poly[1], poly[2]});
  }
}

}  // namespace

std::vector<std::array<std::int32_t, 3>> triangulate_loops(const std::vector<Loop>& input,
                                                           const std::vector<Vec2>& pts,
                                                           bool counter_clockwise) {
  std::vector<Loop> loops;
  for (const Loop& l : input) {
    if (l.size() >= 3 && orientation(l, pts) != Sign::zero) loops.push_back(l);
  }
  std::vector<Ring> rings;
  for (const Loop& l : loops)
    rings.push_back(ring_of(l, pts));
  // Depth: how many other loops contain a vertex of this one (not on their boundary).
  std::vector<int> depth(loops.size(), 0);
  std::vector<int> parent(loops.size(), -1);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    for (std::size_t j = 0; j < loops.size(); ++j) {
      if (i == j) continue;
      for (const Vec2& v : rings[i]) {
        const Location at = inside::point_in_polygon(std::span<const Ring>(&rings[j], 1), v);
        if (at == Location::boundary) continue;
        if (at == Location::inside) {
          ++depth[i];
          if (parent[i] < 0 || depth[static_cast<std::size_t>(parent[i])] < depth[j]) {
            parent[i] = static_cast<int>(j);
          }
        }
        break;
      }
    }
  }
  // Parents by depth: the containing loop of greatest depth (recomputed now depths are known).
  for (std::size_t i = 0; i < loops.size(); ++i) {
    int best = -1;
    for (std::size_t j = 0; j < loops.size(); ++j) {
      if (i == j || depth[j] != depth[i] - 1) continue;
      for (const Vec2& v : rings[i]) {
        const Location at = inside::point_in_polygon(std::span<const Ring>(&rings[j], 1), v);
        if (at == Location::boundary) continue;
        if (at == Location::inside) best = static_cast<int>(j);
        break;
      }
    }
    parent[i] = best;
  }
  std::vector<std::array<std::int32_t, 3>> out;
  for (std::size_t o = 0; o < loops.size(); ++o) {
    if (depth[o] % 2 != 0) continue;
    Loop outer = loops[o];
    if (!ccw(outer, pts)) std::reverse(outer.begin(), outer.end());
    std::vector<Loop> holes;
    for (std::size_t h = 0; h < loops.size(); ++h) {
      if (parent[h] == static_cast<int>(o) && depth[h] == depth[o] + 1) {
        Loop hole = loops[h];
        if (ccw(hole, pts)) std::reverse(hole.begin(), hole.end());
        holes.push_back(std::move(hole));
      }
    }
    std::sort(holes.begin(), holes.end(), [&](const Loop& x, const Loop& y) {
      double mx = -1e308, my = -1e308;
      for (auto i : x)
        mx = std::max(mx, pts[static_cast<std::size_t>(i)].x);
      for (auto i : y)
        my = std::max(my, pts[static_cast<std::size_t>(i)].x);
      return mx > my;
    });
    for (std::size_t h = 0; h < holes.size(); ++h) {
      const std::vector<Loop> rest(holes.begin() + static_cast<std::ptrdiff_t>(h) + 1, holes.end());
      bridge(outer, holes[h], rest, pts);
    }
    ear_clip(outer, pts, out);
  }
  if (!counter_clockwise) {
    for (auto& t : out)
      std::swap(t[1], t[2]);
  }
  return out;
}

}  // namespace contain::clip::detail
