// Noding by "split until no new crossing".
//
// Round r takes the current pieces (consecutive points of every chain) and tests every pair of
// pieces whose boxes overlap and of which at least one is new (made in round r - 1, or an input
// segment in round 1); a pair of old pieces was tested when the younger of the two was new and
// gave nothing then. Candidate pairs come from a uniform grid (each piece listed in the cells it
// passes through, conservatively; later rounds grid only the old pieces whose x interval meets a
// new one's), or, in the first round of input made of long monotone paths, from pairs of
// monotone chains (rule clip-noding-chains). A test is decided by the four exact orient2d signs:
// - disjoint: nothing;
// - collinear overlap: each piece is split at the other's endpoints that lie strictly inside it;
// - an endpoint of one on the other (touching, T junction): the other is split there;
// - a proper crossing: the crossing point is computed in long double, rounded to doubles and
//   clamped to the intersection of both boxes, and both pieces are split there.
// Splits of input doubles are exact. A rounded crossing point lies off both lines by at most an
// ulp, so its pieces can meet a neighbour they did not meet before: those pieces are new and are
// tested again. Rounds stop when one finds nothing; every piece then meets every other at most
// in shared endpoints, or coincides with it exactly. Every endpoint that a test finds met by the
// other piece is marked (Noded::event, rule clip-events), so the arrangement needs to sort only
// those points, the split points and the ends of paths.

#include "clip/boolean_noding.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "clip/boolean_chains.h"
#include "clip/boolean_grid.h"
#include "contain/predicates/orient2d.h"

namespace contain::clip::detail {
namespace {

using predicates::orient2d;

struct Split {
  std::uint32_t piece;  // index in points of the piece's first point
  Vec2 at;
};

// orient2d, without its exact fallback when c is an endpoint (pieces sharing an endpoint are the
// most common pair, and their zero determinant is the filter's worst case).
[[gnu::always_inline]] inline Sign orient(Vec2 a, Vec2 b, Vec2 c) {
  if (c == a || c == b) return Sign::zero;
  return orient2d(a, b, c);
}

bool lex_less(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// x strictly between a and b, given that a, b, x are collinear.
bool strictly_inside(Vec2 a, Vec2 b, Vec2 x) {
  if (x == a || x == b) return false;
  return lex_less(a, b) ? (lex_less(a, x) && lex_less(x, b)) : (lex_less(b, x) && lex_less(x, a));
}

// p before q on the way from a to b, for points on (or rounded next to) the piece: compared on
// the axis along which the piece moves most, then on the other one, without products (a dot
// product with the direction underflows to zero for coordinates below 2^-511 and would leave
// the order to lex_less, which zigzags a chain going the other way: fuzz finding
// hang_at_scale_2pow-904, docs/robustness.md).
bool before_along(Vec2 a, Vec2 b, Vec2 p, Vec2 q) {
  const bool by_x = std::fabs(b.x - a.x) >= std::fabs(b.y - a.y);
  const double pu = by_x ? p.x : p.y, qu = by_x ? q.x : q.y;
  const double pv = by_x ? p.y : p.x, qv = by_x ? q.y : q.x;
  const bool u_up = by_x ? a.x < b.x : a.y < b.y;
  const bool v_up = by_x ? a.y < b.y : a.x < b.x;
  if (pu != qu) return u_up ? pu < qu : pu > qu;
  if (pv != qv) return v_up ? pv < qv : pv > qv;
  return false;
}

Vec2 crossing_point(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) {
  // The rounded point depends on the order and direction of the segments: put them in a
  // canonical order, so that equal segments (A and B both holding an edge, a ring edge traversed
  // both ways) are split at equal points and cancel exactly (fuzz finding sliver_in_a_minus_a).
  if (lex_less(p1, p0)) std::swap(p0, p1);
  if (lex_less(q1, q0)) std::swap(q0, q1);
  if (lex_less(q0, p0) || (q0 == p0 && lex_less(q1, p1))) {
    std::swap(p0, q0);
    std::swap(p1, q1);
  }
  using L = long double;
  const L dpx = L(p1.x) - L(p0.x), dpy = L(p1.y) - L(p0.y);
  const L dqx = L(q1.x) - L(q0.x), dqy = L(q1.y) - L(q0.y);
  const L den = dpx * dqy - dpy * dqx;
  const L num = (L(q0.x) - L(p0.x)) * dqy - (L(q0.y) - L(p0.y)) * dqx;
  // The rounded denominator can vanish (or the quotient overflow) for nearly parallel pieces
  // that the exact signs say cross, and NaN would pass the clamps below: then any point of both
  // boxes serves, as the pieces are tested again (fuzz_polygon_boolean, NaN into orient2d).
  L t = num / den;
  if (!std::isfinite(t)) t = 0.5L;
  Vec2 x{static_cast<double>(L(p0.x) + t * dpx), static_cast<double>(L(p0.y) + t * dpy)};
  // The exact crossing lies in both boxes; keep the rounded one there too.
  const double lox = std::max(std::min(p0.x, p1.x), std::min(q0.x, q1.x));
  const double hix = std::min(std::max(p0.x, p1.x), std::max(q0.x, q1.x));
  const double loy = std::max(std::min(p0.y, p1.y), std::min(q0.y, q1.y));
  const double hiy = std::min(std::max(p0.y, p1.y), std::max(q0.y, q1.y));
  x.x = std::clamp(x.x, lox, hix);
  x.y = std::clamp(x.y, loy, hiy);
  return x;
}

// The sides of a hot pixel, clamped to the finite doubles: x +- radius overflows next to
// DBL_MAX, and no piece reaches beyond it, so the clamped square meets the same pieces.
double pixel_lo(double v, double radius) {
  return std::max(v - radius, std::numeric_limits<double>::lowest());
}
double pixel_hi(double v, double radius) {
  return std::min(v + radius, std::numeric_limits<double>::max());
}

bool within(Vec2 a, Vec2 b, double radius) {
  return std::fabs(a.x - b.x) <= radius && std::fabs(a.y - b.y) <= radius;
}

// A piece that passes through the hot pixel of a crossing point x (the square of half-side
// `radius` around it) is split at x, as in snap rounding (Hobby 1999; Hershberger 2013): pieces
// that pass within rounding distance of each other then share the vertex instead of crossing again
// and again near it. The test is exact on the doubles of the square's corners.
void test_pixel(const std::vector<Vec2>& pts, std::uint32_t s, Vec2 x, double radius,
                std::vector<Split>& splits) {
  const Vec2 a = pts[s], b = pts[s + 1];
  // A piece with an endpoint in the pixel already passes through it; its crossings there snap to
  // endpoints (see test_pair).
  if (within(a, x, radius) || within(b, x, radius)) return;
  // Only where x lies in the piece's box, as (unsnapped) crossing points do: a split outside the
  // box turns the chain back, and pixels can then split each other's pieces for ever (a -> b
  // split at x behind a gives x -> b, which passes through the pixel of a and is split there,
  // giving a -> b again; fuzz_polygon_boolean, docs/robustness.md).
  if (x.x < std::min(a.x, b.x) || x.x > std::max(a.x, b.x) || x.y < std::min(a.y, b.y) ||
      x.y > std::max(a.y, b.y))
    return;
  // The line misses the square when all four corners lie strictly on one side. orient2d(a, b, c)
  // is the sign of an affine function of c whose gradient is (-(b.y - a.y), b.x - a.x): over the
  // square it is smallest at the corner that gradient points away from and largest at the
  // opposite one, so those two corners decide exactly what the four would.
  const double x0 = pixel_lo(x.x, radius), x1 = pixel_hi(x.x, radius);
  const double y0 = pixel_lo(x.y, radius), y1 = pixel_hi(x.y, radius);
  const bool rises = b.y > a.y, rightward = b.x > a.x;
  const Vec2 low{rises ? x1 : x0, rightward ? y0 : y1};
  const Vec2 high{rises ? x0 : x1, rightward ? y1 : y0};
  if (orient2d(a, b, low) == Sign::positive || orient2d(a, b, high) == Sign::negative) return;
  splits.push_back({s, x});
}

// Marks point k as a vertex of the arrangement (Noded::event).
struct Marks {
  std::vector<char>& event;
  void operator()(std::uint32_t k) const { event[k] = 1; }
};

// x on the closed piece a b, given that a, b, x are collinear.
bool on_piece(Vec2 a, Vec2 b, Vec2 x) {
  return x == a || x == b || strictly_inside(a, b, x);
}

// `linked`: t is the piece after s on a linked path (t == s + 2, points[s + 1] the joint); their
// common joint is then no event.
// o1, o2: the sides of q0 and q1 of the line p0 p1, not both the same strict side (the caller
// rejects most pairs with them).
[[gnu::noinline]] void test_pair(const std::vector<Vec2>& pts, std::uint32_t s, std::uint32_t t,
                                 Sign o1, Sign o2, double radius, std::vector<Split>& splits,
                                 std::vector<Vec2>& hot, std::int64_t& crossings, const Marks& mark,
                                 bool linked) {
  const Vec2 p0 = pts[s], p1 = pts[s + 1], q0 = pts[t], q1 = pts[t + 1];
  // Pieces sharing an endpoint, the other one off the line: that endpoint is all they share.
  if (o1 == Sign::zero && o2 != Sign::zero && (q0 == p0 || q0 == p1)) {
    if (!(linked && q0 == p1)) {
      mark(t);
      mark(q0 == p0 ? s : s + 1);
    }
    return;
  }
  if (o2 == Sign::zero && o1 != Sign::zero && (q1 == p0 || q1 == p1)) {
    mark(t + 1);
    mark(q1 == p0 ? s : s + 1);
    return;
  }
  const Sign o3 = orient(q0, q1, p0);
  const Sign o4 = orient(q0, q1, p1);
  if (o3 == o4 && o3 != Sign::zero) return;
  if (o1 == Sign::zero && o2 == Sign::zero) {
    // Collinear: boxes overlap (the caller checked), so the pieces overlap or touch. Every
    // endpoint on the other piece is a vertex, but for the joint of a straight linked path.
    const bool q0_on = on_piece(p0, p1, q0), q1_on = on_piece(p0, p1, q1);
    const bool p0_on = on_piece(q0, q1, p0), p1_on = on_piece(q0, q1, p1);
    if (linked && !q1_on && !p0_on) return;
    if (q0_on) mark(t);
    if (q1_on) mark(t + 1);
    if (p0_on) mark(s);
    if (p1_on) mark(s + 1);
    if (strictly_inside(p0, p1, q0)) splits.push_back({s, q0});
    if (strictly_inside(p0, p1, q1)) splits.push_back({s, q1});
    if (strictly_inside(q0, q1, p0)) splits.push_back({t, p0});
    if (strictly_inside(q0, q1, p1)) splits.push_back({t, p1});
    return;
  }
  // Not parallel. A zero sign puts that endpoint on the other piece (the opposite pair of signs
  // is not of one strict sign), and that endpoint is the only common point.
  bool touched = false;
  if (o1 == Sign::zero) {
    touched = true;
    mark(t);
    if (q0 == p0) mark(s);
    if (q0 == p1) mark(s + 1);
    if (q0 != p0 && q0 != p1) splits.push_back({s, q0});
  }
  if (o2 == Sign::zero) {
    touched = true;
    mark(t + 1);
    if (q1 == p0) mark(s);
    if (q1 == p1) mark(s + 1);
    if (q1 != p0 && q1 != p1) splits.push_back({s, q1});
  }
  if (o3 == Sign::zero) {
    touched = true;
    mark(s);
    if (p0 != q0 && p0 != q1) splits.push_back({t, p0});
  }
  if (o4 == Sign::zero) {
    touched = true;
    mark(s + 1);
    if (p1 != q0 && p1 != q1) splits.push_back({t, p1});
  }
  if (touched) return;
  Vec2 x = crossing_point(p0, p1, q0, q1);
  ++crossings;
  // A crossing within a pixel of an endpoint is that endpoint: no sliver pieces. Of several, the
  // lowest in (x, y) order, the same choice whichever pair of pieces meets there. Only endpoints
  // in both pieces' boxes: a piece split outside its box turns back, and where pixels are large
  // against the pieces (a coordinate of 1.4e16 beside pieces a few units long) such splits
  // undid each other round after round (fuzz_polygon_boolean, docs/robustness.md).
  const double lox = std::max(std::min(p0.x, p1.x), std::min(q0.x, q1.x));
  const double hix = std::min(std::max(p0.x, p1.x), std::max(q0.x, q1.x));
  const double loy = std::max(std::min(p0.y, p1.y), std::min(q0.y, q1.y));
  const double hiy = std::min(std::max(p0.y, p1.y), std::max(q0.y, q1.y));
  bool snapped = false;
  Vec2 best{};
  for (const Vec2 e : {p0, p1, q0, q1}) {
    if (e.x < lox || e.x > hix || e.y < loy || e.y > hiy) continue;
    if (within(x, e, radius) && (!snapped || lex_less(e, best))) {
      best = e;
      snapped = true;
    }
  }
  if (snapped) {
    x = best;
    const std::uint32_t ends[4] = {s, s + 1, t, t + 1};
    for (const std::uint32_t k : ends) {
      if (pts[k] == x) mark(k);
    }
  }
  hot.push_back(x);
  if (x != p0 && x != p1) splits.push_back({s, x});
  if (x != q0 && x != q1) splits.push_back({t, x});
}

}  // namespace

Noded node_segments(std::span<const NodingInput> segments, std::span<const char> links,
                    double magnitude) {
  Noded out;
  const auto n = static_cast<std::uint32_t>(segments.size());
  const bool linked_paths = links.size() == segments.size();
  // Room for some splits: the rounds insert them in place.
  const std::size_t room = 2 * std::size_t{n} + n / 8 + 64;
  out.points.reserve(room);
  out.points.resize(2 * std::size_t{n});
  out.first.resize(std::size_t{n} + 1);
  for (std::uint32_t c = 0; c < n; ++c) {
    out.first[c] = 2 * c;
    out.points[2 * c] = segments[c].a;
    out.points[2 * c + 1] = segments[c].b;
  }
  out.first[n] = 2 * n;
  if (magnitude <= 0.0) {
    for (const NodingInput& s : segments) {
      magnitude = std::max(magnitude, std::max(std::fabs(s.a.x), std::fabs(s.a.y)));
      magnitude = std::max(magnitude, std::max(std::fabs(s.b.x), std::fabs(s.b.y)));
    }
  }
  out.event.reserve(room);
  out.event.assign(out.points.size(), 0);
  // joint[k]: points[k] ends a segment linked to the next one (the piece at k + 1 continues it).
  std::vector<char> joint;
  joint.reserve(room);
  joint.assign(out.points.size(), 0);
  if (linked_paths) {
    for (std::uint32_t c = 0; c < n; ++c)
      joint[out.first[c + 1] - 1] = links[c];
  }
  const Marks mark{out.event};
  // Hot pixels: half-side of two ulps of the largest coordinate (rule clip-noding); for
  // subnormal coordinates two ulps are 2^-1073, not 2^(ilogb - 51), which underflows to zero.
  const double radius = magnitude > 0 ? std::ldexp(1.0, std::max(std::ilogb(magnitude) - 51, -1073))
                                      : std::numeric_limits<double>::min();
  // fresh[k]: the piece starting at points[k] is new this round.
  std::vector<char> fresh;
  fresh.reserve(room);
  fresh.assign(out.points.size(), 1);
  std::vector<std::uint32_t> fresh_list;  // pieces made by the last round's splits
  std::vector<Vec2> hot;                  // crossing points: hot pixels for ever after
  std::size_t hot_fresh_from = 0;         // hot[i] for i >= this were made last round
  std::vector<Item> items;
  std::vector<Key> keys;
  std::vector<std::pair<double, double>> spans;  // merged x intervals of the fresh items
  CellGrid grid;
  std::vector<std::uint32_t> stamp;
  constexpr std::uint32_t kNoStamp = std::numeric_limits<std::uint32_t>::max();
  std::vector<Split> splits;
  auto pair = [&](std::uint32_t s, std::uint32_t t) {
    // The lower piece first: the rounded crossing does not depend on the visiting order.
    if (t < s) std::swap(s, t);
    // Consecutive pieces of one chain meet only at their joint, a split point (an event since it
    // was made): every split lies in the box of the piece it splits, so by induction each joint
    // lies between its neighbours on both axes, and the chain never folds back over itself.
    if (t == s + 1) return;
    const Vec2 p0 = out.points[s], p1 = out.points[s + 1];
    const Sign o1 = orient(p0, p1, out.points[t]);
    const Sign o2 = orient(p0, p1, out.points[t + 1]);
    if (o1 == o2 && o1 != Sign::zero) return;
    test_pair(out.points, s, t, o1, o2, radius, splits, hot, out.crossings, mark,
              t == s + 2 && joint[s + 1] != 0);
  };
  // First round by monotone chains when they are long (smooth input); short chains (spiky
  // input, many small rings) go to the grid.
  bool chains_done = false;
  std::vector<Chain> chains;
  if (linked_paths && n > 0) {
    chains = monotone_chains(segments, links);
    if (4 * chains.size() <= n) {
      ++out.rounds;
      chain_pairs(segments, chains,
                  [&](std::uint32_t i, std::uint32_t j) { pair(out.first[i], out.first[j]); });
      chains_done = true;
    }
  }
  constexpr int kMaxRounds = 256;
  for (int round = 0; round < kMaxRounds; ++round) {
    if (!(chains_done && round == 0)) {
      ++out.rounds;
      items.clear();
      keys.clear();
      if (round == 0) {
        // Every piece and pixel (later rounds reserve so only when they list most pieces: a
        // large reserve for a few items would cost fresh pages on every call).
        items.reserve(out.points.size() + hot.size());
      }
      auto piece_item = [&](std::uint32_t k) {
        const Vec2 a = out.points[k], b = out.points[k + 1];
        items.push_back({std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y),
                         std::max(a.y, b.y), k, fresh[k] != 0, false});
      };
      auto pixel_item = [&](std::size_t i) {
        const Vec2 x = hot[i];
        items.push_back({pixel_lo(x.x, radius), pixel_hi(x.x, radius), pixel_lo(x.y, radius),
                         pixel_hi(x.y, radius), static_cast<std::uint32_t>(i), i >= hot_fresh_from,
                         true});
      };
      const std::size_t hot_before = hot.size();
      if (round == 0) {
        for (std::uint32_t c = 0; c < n; ++c) {
          for (std::uint32_t k = out.first[c]; k + 1 < out.first[c + 1]; ++k)
            piece_item(k);
        }
        for (std::size_t i = 0; i < hot.size(); ++i)
          pixel_item(i);
      } else {
        // Old items meet only fresh ones: leave out those whose x interval meets none of theirs.
        for (const std::uint32_t k : fresh_list)
          piece_item(k);
        for (std::size_t i = hot_fresh_from; i < hot.size(); ++i)
          pixel_item(i);
        spans.clear();
        if (8 * items.size() < out.points.size()) {
          for (const Item& it : items)
            spans.push_back({it.xmin, it.xmax});
          std::sort(spans.begin(), spans.end());
        } else {
          // Most pieces are new: every old one is listed.
          items.reserve(out.points.size() + hot.size());
          const double inf = std::numeric_limits<double>::infinity();
          spans.push_back({-inf, inf});
        }
        std::size_t m = 0;
        for (const auto& sp : spans) {
          if (m > 0 && sp.first <= spans[m - 1].second) {
            spans[m - 1].second = std::max(spans[m - 1].second, sp.second);
          } else {
            spans[m++] = sp;
          }
        }
        spans.resize(m);
        const double lo = spans.empty() ? 0.0 : spans.front().first;
        const double hi = spans.empty() ? -1.0 : spans.back().second;
        auto meets = [&](double xmin, double xmax) {
          if (xmax < lo || xmin > hi) return false;
          // The first merged span that does not end before the item starts.
          const auto at = std::lower_bound(
              spans.begin(), spans.end(), xmin,
              [](const std::pair<double, double>& sp, double x) { return sp.second < x; });
          return at != spans.end() && at->first <= xmax;
        };
        auto old_pieces = [&](std::uint32_t c0, std::uint32_t c1) {
          for (std::uint32_t c = c0; c < c1; ++c) {
            const std::uint32_t end = out.first[c + 1] - 1;
            for (std::uint32_t k = out.first[c]; k < end; ++k) {
              if (fresh[k]) continue;
              const double xa = out.points[k].x, xb = out.points[k + 1].x;
              if (meets(std::min(xa, xb), std::max(xa, xb))) piece_item(k);
            }
          }
        };
        if (chains_done && round == 1) {
          // The old pieces of the round after the chain round are whole input segments, and the
          // segments of a chain are in x order: those that meet a span are a range found by
          // binary search. (Later, a piece may reach a pixel beyond its segment's box: a full
          // scan.)
          for (const Chain& ch : chains) {
            if (!meets(ch.xmin, ch.xmax)) continue;
            const bool up = segments[ch.first].a.x <= segments[ch.last - 1].b.x;
            // The i-th segment in increasing x order, and its x interval.
            auto seg = [&](std::uint32_t i) { return up ? ch.first + i : ch.last - 1 - i; };
            auto lo_x = [&](std::uint32_t i) {
              const NodingInput& g = segments[seg(i)];
              return std::min(g.a.x, g.b.x);
            };
            auto hi_x = [&](std::uint32_t i) {
              const NodingInput& g = segments[seg(i)];
              return std::max(g.a.x, g.b.x);
            };
            const std::uint32_t len = ch.last - ch.first;
            std::uint32_t from = 0;  // segments before this one (in x order) are listed
            for (const auto& sp : spans) {
              // The first segment whose x interval reaches the span, and the first one past it.
              std::uint32_t l = from, h = len;
              while (l < h) {
                const std::uint32_t mid = (l + h) / 2;
                if (hi_x(mid) < sp.first) {
                  l = mid + 1;
                } else {
                  h = mid;
                }
              }
              std::uint32_t e = l;
              h = len;
              while (e < h) {
                const std::uint32_t mid = (e + h) / 2;
                if (lo_x(mid) <= sp.second) {
                  e = mid + 1;
                } else {
                  h = mid;
                }
              }
              if (l >= e) continue;
              if (up) {
                old_pieces(ch.first + l, ch.first + e);
              } else {
                old_pieces(ch.last - e, ch.last - l);
              }
              from = e;
              if (from == len) break;
            }
          }
        } else {
          old_pieces(0, n);
        }
        for (std::size_t i = 0; i < hot_fresh_from; ++i) {
          if (meets(hot[i].x - radius, hot[i].x + radius)) pixel_item(i);
        }
      }
      keys.reserve(items.size());
      for (std::uint32_t i = 0; i < items.size(); ++i)
        keys.push_back({i, 0});
      splits.clear();
      grid.points_ = &out.points;
      grid.build(items, keys);
      // A fresh item meets every item sharing a cell with it, an old one only the fresh ones;
      // each pair once (stamps), from its fresh side with the higher index when both are fresh.
      // Items are listed fresh first (cell lists are in item order): a fresh item meets the
      // fresh ones before it and every old one; each pair once (stamps).
      std::uint32_t old_from = 0;
      while (old_from < items.size() && items[old_from].fresh)
        ++old_from;
      stamp.assign(items.size(), kNoStamp);
      auto visit = [&](std::uint32_t i, const Item& it, std::uint32_t j) {
        if (stamp[j] == i) return;
        stamp[j] = i;
        const Item& jt = items[j];
        if (it.pixel && jt.pixel) return;
        if (jt.xmax < it.xmin || it.xmax < jt.xmin || jt.ymax < it.ymin || it.ymax < jt.ymin)
          return;
        if (it.pixel) {
          test_pixel(out.points, jt.piece, hot[it.piece], radius, splits);
        } else if (jt.pixel) {
          test_pixel(out.points, it.piece, hot[jt.piece], radius, splits);
        } else {
          pair(it.piece, jt.piece);
        }
      };
      for (const Key& key : keys) {
        const std::uint32_t i = key.item;
        if (i >= old_from) break;
        const Item& it = items[i];
        for (const std::uint32_t cell : grid.cells_of(key.rank)) {
          const std::span<const std::uint32_t> list = grid.items_in(cell);
          std::size_t m = 0;
          for (; m < list.size() && list[m] < i; ++m)
            visit(i, it, list[m]);
          if (old_from == items.size()) continue;
          m = static_cast<std::size_t>(
              std::lower_bound(list.begin() + static_cast<std::ptrdiff_t>(m), list.end(),
                               old_from) -
              list.begin());
          for (; m < list.size(); ++m)
            visit(i, it, list[m]);
        }
      }
      hot_fresh_from = hot_before;
    } else {
      hot_fresh_from = 0;  // every crossing of the chain round is new
    }
    if (splits.empty()) return out;
    // Insert the splits, ordered along their piece; the pieces they make are new, and so are
    // their points (events).
    // By piece, then along each piece's (short) run by insertion: before_along is the costly part.
    std::sort(splits.begin(), splits.end(),
              [](const Split& l, const Split& r) { return l.piece < r.piece; });
    for (std::size_t lo = 0; lo < splits.size();) {
      const std::uint32_t k = splits[lo].piece;
      std::size_t hi = lo + 1;
      while (hi < splits.size() && splits[hi].piece == k)
        ++hi;
      const Vec2 a = out.points[k], b = out.points[k + 1];
      if (hi - lo > 16) {
        std::sort(splits.begin() + static_cast<std::ptrdiff_t>(lo),
                  splits.begin() + static_cast<std::ptrdiff_t>(hi),
                  [&](const Split& l, const Split& r) { return before_along(a, b, l.at, r.at); });
        lo = hi;
        continue;
      }
      for (std::size_t i = lo + 1; i < hi; ++i) {
        const Split v = splits[i];
        std::size_t j = i;
        for (; j > lo && before_along(a, b, v.at, splits[j - 1].at); --j)
          splits[j] = splits[j - 1];
        splits[j] = v;
      }
      lo = hi;
    }
    // The accepted split points, grouped by piece (none equal to the piece's ends or to the one
    // before), then an in-place insertion from the back: unchanged runs of points move by
    // memmove, so few splits cost no second copy of the arrays.
    struct Group {
      std::uint32_t piece, first, count;  // adds[first .. first + count - 1]
    };
    std::vector<Group> groups;
    std::vector<Vec2> adds;
    for (std::size_t si = 0; si < splits.size();) {
      const std::uint32_t k = splits[si].piece;
      const Vec2 a = out.points[k], b = out.points[k + 1];
      Group g{k, static_cast<std::uint32_t>(adds.size()), 0};
      Vec2 last = a;
      for (; si < splits.size() && splits[si].piece == k; ++si) {
        const Vec2 x = splits[si].at;
        if (x == a || x == b || x == last) continue;
        adds.push_back(x);
        last = x;
        ++g.count;
      }
      groups.push_back(g);
    }
    const std::size_t old_size = out.points.size(), new_size = old_size + adds.size();
    out.points.resize(new_size);
    out.event.resize(new_size);
    joint.resize(new_size);
    fresh.assign(new_size, 0);
    fresh_list.clear();
    std::size_t src_end = old_size, dst_end = new_size;
    for (std::size_t gi = groups.size(); gi-- > 0;) {
      const Group& g = groups[gi];
      const std::size_t from = g.piece + 1, len = src_end - from;
      if (dst_end != src_end && len > 0) {
        std::memmove(out.points.data() + dst_end - len, out.points.data() + from,
                     len * sizeof(Vec2));
        std::memmove(out.event.data() + dst_end - len, out.event.data() + from, len);
        std::memmove(joint.data() + dst_end - len, joint.data() + from, len);
      }
      dst_end -= len;
      src_end = from;
      for (std::uint32_t m = g.count; m-- > 0;) {
        --dst_end;
        out.points[dst_end] = adds[g.first + m];
        out.event[dst_end] = 1;
        joint[dst_end] = 0;
        fresh[dst_end] = 1;
        fresh_list.push_back(static_cast<std::uint32_t>(dst_end));
      }
      // The split piece itself (its start stays the old point) is new.
      fresh[dst_end - 1] = 1;
      fresh_list.push_back(static_cast<std::uint32_t>(dst_end - 1));
    }
    std::reverse(fresh_list.begin(), fresh_list.end());
    // first[c] moves by the points inserted into pieces before it.
    std::uint32_t shift = 0;
    std::size_t gi = 0;
    for (std::uint32_t c = 0; c <= n; ++c) {
      while (gi < groups.size() && groups[gi].piece < out.first[c]) {
        shift += groups[gi].count;
        ++gi;
      }
      out.first[c] += shift;
    }
  }
  out.converged = false;
  return out;
}

}  // namespace contain::clip::detail
