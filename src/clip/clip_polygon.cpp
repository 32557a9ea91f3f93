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
#include <deque>
#include <limits>
#include <numeric>
#include <optional>

#include "clip/box_cut.h"
#include "clip/convex_functions.h"
#include "clip/ring_clip.h"
#include "contain/clip/box_halfspaces.h"
#include "contain/inside/point_in_polygon.h"
#include "contain/predicates/ring_orientation.h"

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

// The sign of the exact area; for a simple ring, the turn at its lowest vertex. Rings of zero
// area count as clockwise.
bool counter_clockwise(const Ring& ring) {
  return predicates::ring_orientation(ring) == Sign::positive;
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

// Whether the region left of the edge p -> q, which lies on f's line, is outside the half-plane:
// the edge runs against the line's direction (inside on the left). Exact: the edge is parallel
// to the line, so the sign of one coordinate difference decides.
bool faces_out(const predicates::LineFunction& f, Vec2 p, Vec2 q) {
  // The line's direction with the inside on its left is (b, -a).
  const double b = f.line.b, a = f.line.a;
  if (b != 0.0) return (q.x > p.x) != (b > 0.0);
  return (q.y > p.y) != (-a > 0.0);
}
bool faces_out(const predicates::EdgeFunction& f, Vec2 p, Vec2 q) {
  if (f.q.x != f.p.x) return (q.x > p.x) != (f.q.x > f.p.x);
  return (q.y > p.y) != (f.q.y > f.p.y);
}

// A ring read in place: its points forward, or backward when it must be reversed to be
// oriented (shell counter-clockwise, hole clockwise).
struct RingView {
  std::span<const Vec2> points;
  bool reversed = false;
  [[nodiscard]] std::size_t size() const { return points.size(); }
  [[nodiscard]] Vec2 operator[](std::size_t i) const {
    return points[reversed ? points.size() - 1 - i : i];
  }
  [[nodiscard]] Ring materialised() const {
    Ring out(points.begin(), points.end());
    if (reversed) std::reverse(out.begin(), out.end());
    return out;
  }
};

// The ring's points with their exact sides, every run of consecutive points strictly outside
// reduced to its first and last point: the chord between them lies strictly outside too (the
// outside of a half-plane is convex), so the cut drops it whole like the run, and its chains,
// their ends and the pieces are the same. Inside a run only the floating-point filter runs (one
// evaluation a point), so a large region against a small clip region costs one light pass and
// leaves a short ring.
template <class F>
void reduce(const RingView& ring, const F& f, Ring& out, std::vector<Sign>& side) {
  out.clear();
  side.clear();
  const std::size_t n = ring.size();
  auto clearly_outside = [&](Vec2 v) {
    const predicates::Bounded a = f.approx(v);
    return a.value < -a.error;
  };
  for (std::size_t i = 0; i < n;) {
    const Vec2 v = ring[i++];
    const Sign s = clearly_outside(v) ? Sign::negative : f.side(v);
    out.push_back(v);
    side.push_back(s);
    if (s != Sign::negative) continue;
    std::size_t j = i;
    while (j < n && clearly_outside(ring[j]))
      ++j;
    if (j > i) {
      out.push_back(ring[j - 1]);
      side.push_back(Sign::negative);
    }
    i = j;
  }
}

// One half-plane's cut of a polygon whose rings are oriented (shell counter-clockwise, holes
// clockwise) and free of repeated points; an empty ring is a shell that had no area.
template <class F>
std::vector<Polygon> split(std::span<const RingView> polygon, const F& f) {
  std::vector<Chain> chains;
  std::vector<Ring> shells, holes;
  Ring ring;
  std::vector<Sign> side;
  for (std::size_t r = 0; r < polygon.size(); ++r) {
    if (polygon[r].size() < 3) continue;
    reduce(polygon[r], f, ring, side);
    bool any_in = false, any_out = false;
    for (const Sign s : side) {
      any_in |= s == Sign::positive;
      any_out |= s == Sign::negative;
    }
    // An edge on the line with the region outside the half-plane beside it bounds nothing that
    // is kept: a point strictly outside is put between its ends, so the ring is cut there and a
    // hole whose edge lies on the line becomes a notch of the shell (never a hole touching it
    // along the edge). The point is never used for a crossing: its neighbours lie on the line.
    bool along_out = false;
    for (std::size_t i = 0; i < ring.size() && !along_out; ++i) {
      const std::size_t j = (i + 1) % ring.size();
      along_out = side[i] == Sign::zero && side[j] == Sign::zero && faces_out(f, ring[i], ring[j]);
    }
    if (along_out) {
      Ring cut;
      std::vector<Sign> cut_side;
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const std::size_t j = (i + 1) % ring.size();
        cut.push_back(ring[i]);
        cut_side.push_back(side[i]);
        if (side[i] == Sign::zero && side[j] == Sign::zero && faces_out(f, ring[i], ring[j])) {
          cut.push_back(ring[i]);
          cut_side.push_back(Sign::negative);
        }
      }
      ring = std::move(cut);
      side = std::move(cut_side);
      any_out = true;
    }
    if (!any_in) continue;
    if (!any_out) {  // nothing reduced: the ring as it is
      (r == 0 ? shells : holes).push_back(polygon[r].materialised());
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
    Ring joined;
    for (std::size_t k = c; !used[k]; k = next[k]) {
      used[k] = true;
      joined.insert(joined.end(), chains[k].points.begin(), chains[k].points.end());
    }
    joined = without_repeats(joined);
    if (joined.size() < 3 || !has_area(joined)) continue;
    (counter_clockwise(joined) ? shells : holes).push_back(std::move(joined));
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

// The region's polygons as oriented views (shells counter-clockwise, holes clockwise) without
// repeated points and without rings of no area (a shell of no area stays as an empty view: its
// holes still count as holes). Rings are read in place; one with repeated points is copied
// without them into `storage`.
std::vector<std::vector<RingView>> oriented(const MultiPolygon& region, std::deque<Ring>& storage) {
  std::vector<std::vector<RingView>> out;
  out.reserve(region.polygons.size());
  for (const Polygon& polygon : region.polygons) {
    if (polygon.rings.empty()) continue;
    std::vector<RingView> p;
    for (std::size_t r = 0; r < polygon.rings.size(); ++r) {
      const Ring* ring = &polygon.rings[r];
      const std::size_t n = ring->size();
      bool repeats = n > 0 && (*ring)[0] == (*ring)[n - 1];
      for (std::size_t i = 1; i < n && !repeats; ++i)
        repeats = (*ring)[i] == (*ring)[i - 1];
      if (repeats) ring = &storage.emplace_back(without_repeats(*ring));
      if (ring->size() < 3 || !has_area(*ring)) {
        if (r == 0) p.emplace_back();
        continue;
      }
      p.push_back({*ring, counter_clockwise(*ring) != (r == 0)});
    }
    out.push_back(std::move(p));
  }
  return out;
}

template <class F>
MultiPolygon clip_pieces(const MultiPolygon& region, std::span<const F> functions) {
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
  // The first cut reads the input in place; later ones their oriented pieces.
  std::deque<Ring> storage;
  MultiPolygon current;
  for (const std::vector<RingView>& polygon : oriented(region, storage)) {
    for (Polygon& piece : split(std::span<const RingView>(polygon), functions[0]))
      current.polygons.push_back(std::move(piece));
  }
  std::vector<RingView> views;
  for (std::size_t k = 1; k < functions.size(); ++k) {
    MultiPolygon next;
    for (const Polygon& polygon : current.polygons) {
      views.clear();
      for (const Ring& ring : polygon.rings)
        views.push_back({ring, false});
      for (Polygon& piece : split(std::span<const RingView>(views), functions[k]))
        next.polygons.push_back(std::move(piece));
    }
    current = std::move(next);
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
  if (options.output == PolygonClipOutput::pieces) {
    // Half-planes x >= k, x <= k, y >= k, y <= k (unit coefficients: the bound k is exact) form
    // a box: the one-pass box cut takes them all at once, and the others cut its result.
    constexpr double inf = std::numeric_limits<double>::infinity();
    Box2 box{{-inf, -inf}, {inf, inf}};
    std::vector<HalfPlane> others;
    bool any_box = false;
    for (const HalfPlane& h : half_planes) {
      if (h.b == 0.0 && (h.a == 1.0 || h.a == -1.0)) {
        if (h.a > 0)
          box.min.x = std::max(box.min.x, -h.c);
        else
          box.max.x = std::min(box.max.x, h.c);
        any_box = true;
      } else if (h.a == 0.0 && (h.b == 1.0 || h.b == -1.0)) {
        if (h.b > 0)
          box.min.y = std::max(box.min.y, -h.c);
        else
          box.max.y = std::min(box.max.y, h.c);
        any_box = true;
      } else {
        others.push_back(h);
      }
    }
    if (any_box) {
      // A box without interior (or NaN bounds) leaves no area.
      if (!(box.min.x < box.max.x && box.min.y < box.max.y)) return {};
      const MultiPolygon cut = detail::clip_by_box(region, box);
      if (others.empty()) return cut;
      const auto functions = detail::line_functions(others);
      return clip_with(cut, std::span<const predicates::LineFunction>(functions), options);
    }
  }
  const auto functions = detail::line_functions(half_planes);
  return clip_with(region, std::span<const predicates::LineFunction>(functions), options);
}

MultiPolygon clip_polygon(const MultiPolygon& region, const Box2& box,
                          const PolygonClipOptions& options) {
  if (box.empty()) return {};
  if (options.output == PolygonClipOutput::pieces) return detail::clip_by_box(region, box);
  const auto planes = box_halfspaces(box);
  return clip_polygon(region, planes, options);
}

MultiPolygon clip_polygon(const MultiPolygon& region, const Ring& convex_ring,
                          const PolygonClipOptions& options) {
  const auto edges = detail::edge_functions(convex_ring);
  if (!edges) return {};
  if (options.output == PolygonClipOutput::pieces) {
    // The ring lies in its box: the one-pass box cut leaves the part of the region near it,
    // valid, and the ring's edges cut that.
    const MultiPolygon near =
        detail::clip_by_box(region, bounding_box(std::span<const Ring>(&convex_ring, 1)));
    return clip_with(near, std::span<const predicates::EdgeFunction>(*edges), options);
  }
  return clip_with(region, std::span<const predicates::EdgeFunction>(*edges), options);
}

}  // namespace contain::clip
