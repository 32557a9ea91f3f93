// Polygons clipped by half-planes, split into pieces. Outline per half-plane and polygon:
//  1. orient rings (shell counter-clockwise, holes clockwise) so the inside is on the left;
//  2. classify vertices exactly; rings with no vertex strictly outside stay, rings with no
//     vertex strictly inside go;
//  3. walk each cut ring from an outside vertex into chains: entry point, inside vertices, exit
//     point (crossings of edges, or vertices on the line chosen by the next vertex off it);
//  4. sort chain ends along the line's direction d (inside on the left of d) exactly, and join
//     each exit to the next entry: the piece's boundary follows the line forward from an exit;
//  5. the cycles are the pieces' shells; uncut holes go to the shell that contains them.

#include "contain/clip/clip_polygon.h"

#include <algorithm>
#include <numeric>
#include <optional>

#include "clip/convex_functions.h"
#include "clip/ring_clip.h"
#include "contain/clip/box_halfspaces.h"
#include "contain/inside/point_in_polygon.h"

namespace contain::clip {
namespace {

using predicates::BigFloat;

// Position along the boundary's direction d, exactly: pi(v) = d . v.
BigFloat position(const predicates::LineFunction& f, Vec2 v) {
  return BigFloat(f.line.b) * BigFloat(v.x) - BigFloat(f.line.a) * BigFloat(v.y);  // d = (b, -a)
}
BigFloat position(const predicates::EdgeFunction& f, Vec2 v) {
  return (BigFloat(f.q.x) - BigFloat(f.p.x)) * BigFloat(v.x) +
         (BigFloat(f.q.y) - BigFloat(f.p.y)) * BigFloat(v.y);
}

// A chain end on the line at position num / den (den > 0), exactly.
struct LinePoint {
  BigFloat num;
  BigFloat den;
};

template <class F>
LinePoint on_vertex(const F& f, Vec2 v) {
  return {position(f, v), BigFloat(1.0)};
}

// The crossing of p->q: pi = (s_p pi(q) - s_q pi(p)) / (s_p - s_q), sign-normalised.
template <class F>
LinePoint on_edge(const F& f, Vec2 p, Vec2 q) {
  const BigFloat sp = f.exact(p), sq = f.exact(q);
  BigFloat num = sp * position(f, q) - sq * position(f, p);
  BigFloat den = sp - sq;
  if (den.sign() == Sign::negative) {
    num = BigFloat() - num;
    den = BigFloat() - den;
  }
  return {num, den};
}

int compare(const LinePoint& x, const LinePoint& y) {
  return to_int((x.num * y.den - y.num * x.den).sign());
}

struct Chain {
  std::vector<Vec2> points;
  LinePoint entry;
  LinePoint exit;
};

// Exact orientation of a ring: at its lowest (then leftmost) vertex, which is convex; the float
// area where that vertex is a spike.
bool counter_clockwise(const Ring& ring) {
  const std::size_t n = ring.size();
  std::size_t m = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (ring[i].y < ring[m].y || (ring[i].y == ring[m].y && ring[i].x < ring[m].x)) m = i;
  }
  std::size_t prev = (m + n - 1) % n, next = (m + 1) % n;
  while (prev != m && ring[prev] == ring[m])
    prev = (prev + n - 1) % n;
  while (next != m && ring[next] == ring[m])
    next = (next + 1) % n;
  const Sign s = predicates::orient2d(ring[prev], ring[m], ring[next]);
  if (s != Sign::zero) return s == Sign::positive;
  return signed_area2(ring) > 0.0;
}

bool has_area(const Ring& ring) {
  for (std::size_t i = 2; i < ring.size(); ++i) {
    if (predicates::orient2d(ring[0], ring[1], ring[i]) != Sign::zero) return true;
  }
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
    if (predicates::orient2d(ring[i], ring[i + 1], ring[0]) != Sign::zero) return true;
  }
  return false;
}

Ring without_repeats(const Ring& ring) {
  Ring out;
  for (const Vec2& p : ring) {
    if (out.empty() || !(out.back() == p)) out.push_back(p);
  }
  while (out.size() > 1 && out.front() == out.back())
    out.pop_back();
  return out;
}

template <class F>
void cut_ring(const Ring& ring, const std::vector<Sign>& side, const F& f,
              std::vector<Chain>& chains) {
  const std::size_t n = ring.size();
  std::size_t start = 0;
  while (side[start] != Sign::negative)
    ++start;
  // The sign of the next vertex off the line after index i (walking forward).
  auto next_off = [&](std::size_t i) {
    for (std::size_t k = 1; k <= n; ++k) {
      const Sign s = side[(i + k) % n];
      if (s != Sign::zero) return s;
    }
    return Sign::zero;
  };
  bool in_chain = false;
  Chain chain;
  for (std::size_t k = 1; k <= n; ++k) {
    const std::size_t iq = (start + k) % n, ip = (start + k - 1) % n;
    const Vec2 p = ring[ip], q = ring[iq];
    const Sign sp = side[ip], sq = side[iq];
    if (sq == Sign::positive) {
      if (!in_chain) {
        chain = Chain{};
        if (sp == Sign::negative) {
          chain.points.push_back(detail::crossing_point(p, q, f));
          chain.entry = on_edge(f, p, q);
        } else {  // p on the line, after an outside vertex: the entry
          chain.points.push_back(p);
          chain.entry = on_vertex(f, p);
        }
        in_chain = true;
      }
      chain.points.push_back(q);
    } else if (sq == Sign::zero) {
      if (!in_chain) continue;
      chain.points.push_back(q);
      if (next_off(iq) == Sign::negative) {
        chain.exit = on_vertex(f, q);
        chains.push_back(std::move(chain));
        in_chain = false;
      }
    } else if (in_chain) {  // sp is positive here: a zero would have ended the chain
      chain.points.push_back(detail::crossing_point(p, q, f));
      chain.exit = on_edge(f, p, q);
      chains.push_back(std::move(chain));
      in_chain = false;
    }
  }
}

template <class F>
std::vector<Polygon> split(const Polygon& polygon, const F& f) {
  std::vector<Chain> chains;
  std::vector<Ring> shells, holes;
  for (std::size_t r = 0; r < polygon.rings.size(); ++r) {
    Ring ring = without_repeats(polygon.rings[r]);
    if (ring.size() < 3 || !has_area(ring)) continue;
    if (counter_clockwise(ring) != (r == 0)) std::reverse(ring.begin(), ring.end());
    std::vector<Sign> side(ring.size());
    bool any_in = false, any_out = false;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      side[i] = f.side(ring[i]);
      any_in |= side[i] == Sign::positive;
      any_out |= side[i] == Sign::negative;
    }
    if (!any_in) continue;
    if (!any_out) {
      (r == 0 ? shells : holes).push_back(std::move(ring));
      continue;
    }
    cut_ring(ring, side, f, chains);
  }
  // Join each exit to the next entry along the line (exits first at equal positions).
  struct End {
    std::size_t chain;
    bool exit;
  };
  std::vector<End> ends;
  for (std::size_t c = 0; c < chains.size(); ++c) {
    ends.push_back({c, true});
    ends.push_back({c, false});
  }
  std::stable_sort(ends.begin(), ends.end(), [&](const End& x, const End& y) {
    const LinePoint& px = x.exit ? chains[x.chain].exit : chains[x.chain].entry;
    const LinePoint& py = y.exit ? chains[y.chain].exit : chains[y.chain].entry;
    const int c = compare(px, py);
    if (c != 0) return c < 0;
    return x.exit && !y.exit;
  });
  std::vector<std::size_t> next(chains.size());
  std::iota(next.begin(), next.end(), std::size_t{0});  // unmatched: closes on itself
  std::vector<std::size_t> pending;
  for (const End& e : ends) {
    if (e.exit) {
      pending.push_back(e.chain);
    } else if (!pending.empty()) {
      next[pending.back()] = e.chain;
      pending.pop_back();
    }
  }
  std::vector<bool> used(chains.size(), false);
  for (std::size_t c = 0; c < chains.size(); ++c) {
    if (used[c]) continue;
    Ring ring;
    for (std::size_t k = c; !used[k]; k = next[k]) {
      used[k] = true;
      ring.insert(ring.end(), chains[k].points.begin(), chains[k].points.end());
    }
    ring = without_repeats(ring);
    if (ring.size() < 3 || !has_area(ring)) continue;
    (counter_clockwise(ring) ? shells : holes).push_back(std::move(ring));
  }
  std::vector<Polygon> out;
  for (Ring& s : shells)
    out.push_back(Polygon{{std::move(s)}});
  for (Ring& h : holes) {
    for (Polygon& piece : out) {
      const Ring* shell = &piece.rings.front();
      bool inside = false, decided = false;
      for (const Vec2& v : h) {
        const Location at = inside::point_in_polygon(std::span<const Ring>(shell, 1), v);
        if (at == Location::boundary) continue;
        inside = at == Location::inside;
        decided = true;
        break;
      }
      if (inside || !decided) {
        piece.rings.push_back(std::move(h));
        break;
      }
    }
  }
  return out;
}

template <class F>
MultiPolygon clip_pieces(const MultiPolygon& region, std::span<const F> functions) {
  MultiPolygon current = region;
  for (const F& f : functions) {
    MultiPolygon next;
    for (const Polygon& polygon : current.polygons) {
      if (polygon.rings.empty()) continue;
      for (Polygon& piece : split(polygon, f))
        next.polygons.push_back(std::move(piece));
    }
    current = std::move(next);
  }
  if (functions.empty()) {
    // No half-plane: still return valid pieces (oriented, zero-area rings gone).
    MultiPolygon out;
    for (const Polygon& polygon : region.polygons) {
      Polygon p;
      for (std::size_t r = 0; r < polygon.rings.size(); ++r) {
        Ring ring = without_repeats(polygon.rings[r]);
        if (ring.size() < 3 || !has_area(ring)) continue;
        if (counter_clockwise(ring) != (r == 0)) std::reverse(ring.begin(), ring.end());
        if (r == 0 || !p.rings.empty()) p.rings.push_back(std::move(ring));
      }
      if (!p.rings.empty()) out.polygons.push_back(std::move(p));
    }
    return out;
  }
  return current;
}

template <class F>
MultiPolygon clip_bridged(const MultiPolygon& region, std::span<const F> functions) {
  MultiPolygon out;
  for (const Polygon& polygon : region.polygons) {
    Polygon p;
    for (std::size_t r = 0; r < polygon.rings.size(); ++r) {
      Ring ring = polygon.rings[r];
      for (const F& f : functions) {
        if (ring.empty()) break;
        ring = detail::sutherland_hodgman_ring(ring, f);
      }
      if (ring.empty()) {
        if (r == 0) break;
        continue;
      }
      p.rings.push_back(std::move(ring));
    }
    if (!p.rings.empty()) out.polygons.push_back(std::move(p));
  }
  return out;
}

template <class F>
MultiPolygon clip_with(const MultiPolygon& region, std::span<const F> functions,
                       const PolygonClipOptions& options) {
  if (options.output == PolygonClipOutput::bridged) return clip_bridged(region, functions);
  return clip_pieces(region, functions);
}

}  // namespace

MultiPolygon clip_polygon(const MultiPolygon& region, std::span<const HalfPlane> half_planes,
                          const PolygonClipOptions& options) {
  const auto functions = detail::line_functions(half_planes);
  return clip_with(region, std::span<const predicates::LineFunction>(functions), options);
}

MultiPolygon clip_polygon(const MultiPolygon& region, const Box2& box,
                          const PolygonClipOptions& options) {
  if (box.empty()) return {};
  const auto planes = box_halfspaces(box);
  return clip_polygon(region, planes, options);
}

MultiPolygon clip_polygon(const MultiPolygon& region, const Ring& convex_ring,
                          const PolygonClipOptions& options) {
  const auto edges = detail::edge_functions(convex_ring);
  if (!edges) return {};
  return clip_with(region, std::span<const predicates::EdgeFunction>(*edges), options);
}

}  // namespace contain::clip
