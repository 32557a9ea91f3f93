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

#include "clip/boolean/noding.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "clip/boolean/chains.h"
#include "clip/boolean/grid.h"
#include "clip/boolean/piece_tests.h"
#include "contain/values/max_abs.h"

namespace contain::clip::detail {
namespace {

using pieces::Marks;
using pieces::Split;

// The state of one noding: the chains of pieces and what the rounds keep between them. Each
// stage is one member function; run() is the loop of rounds.
class Noder {
 public:
  Noder(std::span<const NodingInput> segments, std::span<const char> links, double magnitude)
      : segments_(segments),
        links_(links),
        n_(static_cast<std::uint32_t>(segments.size())),
        linked_paths_(links.size() == segments.size()) {
    prepare(magnitude);
  }

  Noded run() && {
    // First round by monotone chains when they are long (smooth input); short chains (spiky
    // input, many small rings) go to the grid.
    const bool chains_done = chain_round();
    constexpr int kMaxRounds = 256;
    for (int round = 0; round < kMaxRounds; ++round) {
      if (chains_done && round == 0) {
        hot_fresh_from_ = 0;  // every crossing of the chain round is new
      } else if (round == 1 && near_ok_) {
        near_round();
      } else {
        grid_round(round, chains_done);
      }
      if (splits_.empty()) return std::move(out_);
      insert_splits();
    }
    out_.converged = false;
    return std::move(out_);
  }

 private:
  // Every segment as a chain of one piece; the hot-pixel radius; the joints of linked paths.
  void prepare(double magnitude) {
    const std::uint32_t n = n_;
    // Room for some splits: the rounds insert them in place.
    const std::size_t room = 2 * std::size_t{n} + n / 8 + 64;
    out_.points.reserve(room);
    out_.points.resize(2 * std::size_t{n});
    out_.first.resize(std::size_t{n} + 1);
    for (std::uint32_t c = 0; c < n; ++c) {
      out_.first[c] = 2 * c;
      out_.points[2 * c] = segments_[c].a;
      out_.points[2 * c + 1] = segments_[c].b;
    }
    out_.first[n] = 2 * n;
    if (magnitude <= 0.0) {
      for (const NodingInput& s : segments_) {
        magnitude = std::max(magnitude, max_abs(s.a));
        magnitude = std::max(magnitude, max_abs(s.b));
      }
    }
    out_.event.reserve(room);
    out_.event.assign(out_.points.size(), 0);
    // joint[k]: points[k] ends a segment linked to the next one (the piece at k + 1 continues it).
    joint_.reserve(room);
    joint_.assign(out_.points.size(), 0);
    if (linked_paths_) {
      for (std::uint32_t c = 0; c < n; ++c)
        joint_[out_.first[c + 1] - 1] = links_[c];
    }
    // Hot pixels: half-side of two ulps of the largest coordinate (rule clip-noding); for
    // subnormal coordinates two ulps are 2^-1073, not 2^(ilogb - 51), which underflows to zero.
    radius_ = magnitude > 0 ? std::ldexp(1.0, std::max(std::ilogb(magnitude) - 51, -1073))
                            : std::numeric_limits<double>::min();
    // fresh[k]: the piece starting at points[k] is new this round.
    fresh_.reserve(room);
    fresh_.assign(out_.points.size(), 1);
  }

  // Tests the pieces starting at points s and t (rule clip-noding), recording splits and events.
  void test(std::uint32_t s, std::uint32_t t) {
    // The lower piece first: the rounded crossing does not depend on the visiting order.
    if (t < s) std::swap(s, t);
    // Consecutive pieces of one chain meet only at their joint, a split point (an event since it
    // was made): every split lies in the box of the piece it splits, so by induction each joint
    // lies between its neighbours on both axes, and the chain never folds back over itself.
    if (t == s + 1) return;
    const Vec2 p0 = out_.points[s], p1 = out_.points[s + 1];
    const Sign o1 = pieces::orient(p0, p1, out_.points[t]);
    const Sign o2 = pieces::orient(p0, p1, out_.points[t + 1]);
    if (o1 == o2 && o1 != Sign::zero) return;
    pieces::test_pair(out_.points, s, t, o1, o2, radius_, splits_, hot_, out_.crossings,
                      Marks{out_.event}, t == s + 2 && joint_[s + 1] != 0);
  }

  // The first round from pairs of monotone chains (rule clip-noding-chains), when the paths are
  // long; false when the first round is left to the grid.
  bool chain_round() {
    if (!(linked_paths_ && n_ > 0)) return false;
    chains_ = monotone_chains(segments_, links_);
    if (4 * chains_.size() > n_) return false;
    ++out_.rounds;
    chain_pairs(segments_, chains_,
                [&](std::uint32_t i, std::uint32_t j) { test(out_.first[i], out_.first[j]); });
    return true;
  }

  void piece_item(std::uint32_t k) {
    const Vec2 a = out_.points[k], b = out_.points[k + 1];
    items_.push_back({std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y),
                      std::max(a.y, b.y), k, fresh_[k] != 0, false});
  }
  void pixel_item(std::size_t i) {
    const Vec2 x = hot_[i];
    items_.push_back({pieces::pixel_lo(x.x, radius_), pieces::pixel_hi(x.x, radius_),
                      pieces::pixel_lo(x.y, radius_), pieces::pixel_hi(x.y, radius_),
                      static_cast<std::uint32_t>(i), i >= hot_fresh_from_, true});
  }

  // A round of candidate pairs from the uniform grid: list its items, then test the pairs that
  // share a cell.
  void grid_round(int round, bool chains_done) {
    ++out_.rounds;
    items_.clear();
    keys_.clear();
    const std::size_t hot_before = hot_.size();
    if (round == 0) {
      list_all_items();
    } else {
      list_items_near_fresh(round == 1 && chains_done);
    }
    // The first grid round (whole segments) keeps its pairs for near_round, which needs the
    // grid's widening to exceed the pieces' drift and the pixels by a margin (see there).
    record_ = round == 0;
    visit_grid_pairs();
    near_ok_ = record_ && std::min(grid_.widening_x(), grid_.widening_y()) >= 16.0 * radius_;
    record_ = false;
    hot_fresh_from_ = hot_before;
  }

  // The segments s and t are apart by more than 16 ulps of the largest coordinate (the unit of
  // the hot pixels' radius): one lies strictly on one side of the other's line, farther than
  // that, decided in floating point with the error bound of orient2d's filter (the margin is
  // 8 pixel radii times |dx| + |dy| >= the length).
  [[nodiscard]] bool apart(std::uint32_t s, std::uint32_t t) const {
    const NodingInput& g = segments_[s];
    const NodingInput& h = segments_[t];
    auto beyond = [&](Vec2 p, Vec2 q, Vec2 u, Vec2 v) {
      const double dx = q.x - p.x, dy = q.y - p.y;
      const double lu = dx * (u.y - p.y), ru = dy * (u.x - p.x);
      const double lv = dx * (v.y - p.y), rv = dy * (v.x - p.x);
      const double ou = lu - ru, ov = lv - rv;
      const double eu = 4e-16 * (std::fabs(lu) + std::fabs(ru)) + DBL_MIN;
      const double ev = 4e-16 * (std::fabs(lv) + std::fabs(rv)) + DBL_MIN;
      const double margin = 8.0 * radius_ * (std::fabs(dx) + std::fabs(dy)) * (1.0 + 1e-12);
      if (ou > 0 && ov > 0) return ou - eu > margin && ov - ev > margin;
      if (ou < 0 && ov < 0) return -ou - eu > margin && -ov - ev > margin;
      return false;
    };
    return beyond(g.a, g.b, h.a, h.b) || beyond(h.a, h.b, g.a, g.b);
  }

  // The round after the first grid round, without a grid. Round 1's split points lie within
  // 4 ulps (2 pixel radii) of their segment's line, in its box (a rounded or snapped crossing),
  // so every piece lies within that of its segment, and a hot pixel's square within 3 more of
  // the crossing's two segments. Two pieces that meet, or a piece through a pixel, therefore
  // belong to segments that pass within 11 ulps of each other at a point of both boxes: the
  // grid listed both in that point's cell (its widening is at least 32 ulps, checked), the
  // round recorded them as a pair, and they are not `apart` (16 ulps). So the pieces of the
  // recorded pairs that are not apart, and each pixel against the pieces of its two segments and
  // of their common close partners, are every test of a grid round that can find anything; the
  // others would find nothing (rule clip-noding).
  void near_round() {
    ++out_.rounds;
    const std::size_t hot_before = hot_.size();
    splits_.clear();
    const std::vector<std::uint32_t>& first = out_.first;
    const std::vector<Vec2>& pts = out_.points;
    std::size_t m = 0;
    for (const auto& pair : near_) {
      if (!apart(pair.first, pair.second)) near_[m++] = pair;
    }
    near_.resize(m);
    for (const auto& [s, t] : near_) {
      const std::uint32_t s0 = first[s], s1 = first[s + 1] - 1;
      const std::uint32_t t0 = first[t], t1 = first[t + 1] - 1;
      if (s1 - s0 == 1 && t1 - t0 == 1) continue;  // neither was split: tested already
      for (std::uint32_t i = s0; i < s1; ++i) {
        const Vec2 a = pts[i], b = pts[i + 1];
        const double ax0 = std::min(a.x, b.x), ax1 = std::max(a.x, b.x);
        const double ay0 = std::min(a.y, b.y), ay1 = std::max(a.y, b.y);
        for (std::uint32_t j = t0; j < t1; ++j) {
          if (!fresh_[i] && !fresh_[j]) continue;
          const Vec2 c = pts[j], d = pts[j + 1];
          if (std::max(c.x, d.x) < ax0 || std::min(c.x, d.x) > ax1 || std::max(c.y, d.y) < ay0 ||
              std::min(c.y, d.y) > ay1)
            continue;
          test(i, j);
        }
      }
    }
    // Pixels (all new): the pieces of the crossing's segments and of their common partners.
    std::vector<std::uint32_t> adjacency_first(n_ + 1, 0), adjacency;
    for (const auto& [s, t] : near_) {
      ++adjacency_first[s + 1];
      ++adjacency_first[t + 1];
    }
    for (std::uint32_t c = 0; c < n_; ++c)
      adjacency_first[c + 1] += adjacency_first[c];
    adjacency.resize(adjacency_first[n_]);
    {
      std::vector<std::uint32_t> fill(adjacency_first.begin(), adjacency_first.end() - 1);
      for (const auto& [s, t] : near_) {
        adjacency[fill[s]++] = t;
        adjacency[fill[t]++] = s;
      }
    }
    for (std::uint32_t c = 0; c < n_; ++c) {
      std::sort(adjacency.begin() + adjacency_first[c], adjacency.begin() + adjacency_first[c + 1]);
    }
    for (std::size_t h = 0; h < hot_before; ++h) {
      const Vec2 x = hot_[h];
      auto segment = [&](std::uint32_t u) {
        for (std::uint32_t k = first[u]; k + 1 < first[u + 1]; ++k) {
          // test_pixel splits only pieces whose box holds x.
          const Vec2 a = pts[k], b = pts[k + 1];
          if (x.x < std::min(a.x, b.x) || x.x > std::max(a.x, b.x) || x.y < std::min(a.y, b.y) ||
              x.y > std::max(a.y, b.y))
            continue;
          pieces::test_pixel(pts, k, x, radius_, splits_);
        }
      };
      const auto [s, t] = hot_from_[h];
      segment(s);
      if (t != s) segment(t);
      std::uint32_t i = adjacency_first[s], j = adjacency_first[t];
      const std::uint32_t ie = adjacency_first[s + 1], je = adjacency_first[t + 1];
      while (i < ie && j < je) {
        if (adjacency[i] < adjacency[j]) {
          ++i;
        } else if (adjacency[j] < adjacency[i]) {
          ++j;
        } else {
          if (adjacency[i] != s && adjacency[i] != t) segment(adjacency[i]);
          ++i;
          ++j;
        }
      }
    }
    hot_fresh_from_ = hot_before;
  }

  // The first round on the grid: every piece and pixel.
  void list_all_items() {
    // (Later rounds reserve so only when they list most pieces: a large reserve for a few items
    // would cost fresh pages on every call.)
    items_.reserve(out_.points.size() + hot_.size());
    for (std::uint32_t c = 0; c < n_; ++c) {
      for (std::uint32_t k = out_.first[c]; k + 1 < out_.first[c + 1]; ++k)
        piece_item(k);
    }
    for (std::size_t i = 0; i < hot_.size(); ++i)
      pixel_item(i);
  }

  // A later round: the fresh pieces and pixels, and the old ones whose x interval meets one of
  // theirs (old items meet only fresh ones). `after_chains`: the round after the chain round,
  // whose old pieces are whole input segments in x order along each chain.
  void list_items_near_fresh(bool after_chains) {
    for (const std::uint32_t k : fresh_list_)
      piece_item(k);
    for (std::size_t i = hot_fresh_from_; i < hot_.size(); ++i)
      pixel_item(i);
    merge_fresh_spans();
    if (after_chains) {
      list_old_chain_pieces();
    } else {
      list_old_pieces(0, n_);
    }
    for (std::size_t i = 0; i < hot_fresh_from_; ++i) {
      if (meets_fresh(hot_[i].x - radius_, hot_[i].x + radius_)) pixel_item(i);
    }
  }

  // spans_: the merged x intervals of the fresh items (one infinite span when most pieces are
  // new: every old one is listed).
  void merge_fresh_spans() {
    spans_.clear();
    if (8 * items_.size() < out_.points.size()) {
      for (const Item& it : items_)
        spans_.push_back({it.xmin, it.xmax});
      std::sort(spans_.begin(), spans_.end());
    } else {
      items_.reserve(out_.points.size() + hot_.size());
      const double inf = std::numeric_limits<double>::infinity();
      spans_.push_back({-inf, inf});
    }
    std::size_t m = 0;
    for (const auto& sp : spans_) {
      if (m > 0 && sp.first <= spans_[m - 1].second) {
        spans_[m - 1].second = std::max(spans_[m - 1].second, sp.second);
      } else {
        spans_[m++] = sp;
      }
    }
    spans_.resize(m);
    spans_lo_ = spans_.empty() ? 0.0 : spans_.front().first;
    spans_hi_ = spans_.empty() ? -1.0 : spans_.back().second;
  }

  [[nodiscard]] bool meets_fresh(double xmin, double xmax) const {
    if (xmax < spans_lo_ || xmin > spans_hi_) return false;
    // The first merged span that does not end before the item starts.
    const auto at = std::lower_bound(
        spans_.begin(), spans_.end(), xmin,
        [](const std::pair<double, double>& sp, double x) { return sp.second < x; });
    return at != spans_.end() && at->first <= xmax;
  }

  // The old pieces of segments c0 .. c1 - 1 whose x interval meets a fresh span.
  void list_old_pieces(std::uint32_t c0, std::uint32_t c1) {
    for (std::uint32_t c = c0; c < c1; ++c) {
      const std::uint32_t end = out_.first[c + 1] - 1;
      for (std::uint32_t k = out_.first[c]; k < end; ++k) {
        if (fresh_[k]) continue;
        const double xa = out_.points[k].x, xb = out_.points[k + 1].x;
        if (meets_fresh(std::min(xa, xb), std::max(xa, xb))) piece_item(k);
      }
    }
  }

  // The round after the chain round: its old pieces are whole input segments, and the segments
  // of a chain are in x order, so those that meet a span are a range found by binary search.
  // (Later, a piece may reach a pixel beyond its segment's box: a full scan.)
  void list_old_chain_pieces() {
    for (const Chain& ch : chains_) {
      if (!meets_fresh(ch.xmin, ch.xmax)) continue;
      const bool up = segments_[ch.first].a.x <= segments_[ch.last - 1].b.x;
      // The i-th segment in increasing x order, and its x interval.
      auto seg = [&](std::uint32_t i) { return up ? ch.first + i : ch.last - 1 - i; };
      auto lo_x = [&](std::uint32_t i) {
        const NodingInput& g = segments_[seg(i)];
        return std::min(g.a.x, g.b.x);
      };
      auto hi_x = [&](std::uint32_t i) {
        const NodingInput& g = segments_[seg(i)];
        return std::max(g.a.x, g.b.x);
      };
      const std::uint32_t len = ch.last - ch.first;
      std::uint32_t from = 0;  // segments before this one (in x order) are listed
      for (const auto& sp : spans_) {
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
          list_old_pieces(ch.first + l, ch.first + e);
        } else {
          list_old_pieces(ch.last - e, ch.last - l);
        }
        from = e;
        if (from == len) break;
      }
    }
  }

  // Grids the listed items and tests every pair sharing a cell with a fresh one, once.
  void visit_grid_pairs() {
    keys_.reserve(items_.size());
    for (std::uint32_t i = 0; i < items_.size(); ++i)
      keys_.push_back({i, 0});
    splits_.clear();
    grid_.points_ = &out_.points;
    grid_.build(items_, keys_);
    // Items are listed fresh first (cell lists are in item order): a fresh item meets the fresh
    // ones before it and every old one; each pair once (stamps).
    std::uint32_t old_from = 0;
    while (old_from < items_.size() && items_[old_from].fresh)
      ++old_from;
    constexpr std::uint32_t kNoStamp = std::numeric_limits<std::uint32_t>::max();
    stamp_.assign(items_.size(), kNoStamp);
    // Local views: the tests write chars (events), which may alias any member.
    std::uint32_t* const stamp = stamp_.data();
    const Item* const items = items_.data();
    const std::size_t count = items_.size();
    auto visit = [&](std::uint32_t i, const Item& it, std::uint32_t j) {
      if (stamp[j] == i) return;
      stamp[j] = i;
      const Item& jt = items[j];
      if (it.pixel && jt.pixel) return;
      if (jt.xmax < it.xmin || it.xmax < jt.xmin || jt.ymax < it.ymin || it.ymax < jt.ymin) return;
      if (it.pixel) {
        pieces::test_pixel(out_.points, jt.piece, hot_[it.piece], radius_, splits_);
      } else if (jt.pixel) {
        pieces::test_pixel(out_.points, it.piece, hot_[jt.piece], radius_, splits_);
      } else if (record_) {
        // Round 1: every piece is a whole segment, starting at point 2 c.
        test(it.piece, jt.piece);
        const std::pair<std::uint32_t, std::uint32_t> segments{it.piece / 2, jt.piece / 2};
        near_.push_back(segments);
        hot_from_.resize(hot_.size(), segments);
      } else {
        test(it.piece, jt.piece);
      }
    };
    for (const Key& key : keys_) {
      const std::uint32_t i = key.item;
      if (i >= old_from) break;
      const Item& it = items[i];
      for (const std::uint32_t cell : grid_.cells_of(key.rank)) {
        const std::span<const std::uint32_t> list = grid_.items_in(cell);
        std::size_t m = 0;
        for (; m < list.size() && list[m] < i; ++m)
          visit(i, it, list[m]);
        if (old_from == count) continue;
        m = static_cast<std::size_t>(
            std::lower_bound(list.begin() + static_cast<std::ptrdiff_t>(m), list.end(), old_from) -
            list.begin());
        for (; m < list.size(); ++m)
          visit(i, it, list[m]);
      }
    }
  }

  // Orders the splits by piece, then along each piece's (short) run by insertion: before_along
  // is the costly part.
  void order_splits() {
    std::sort(splits_.begin(), splits_.end(),
              [](const Split& l, const Split& r) { return l.piece < r.piece; });
    for (std::size_t lo = 0; lo < splits_.size();) {
      const std::uint32_t k = splits_[lo].piece;
      std::size_t hi = lo + 1;
      while (hi < splits_.size() && splits_[hi].piece == k)
        ++hi;
      const Vec2 a = out_.points[k], b = out_.points[k + 1];
      if (hi - lo > 16) {
        std::sort(
            splits_.begin() + static_cast<std::ptrdiff_t>(lo),
            splits_.begin() + static_cast<std::ptrdiff_t>(hi),
            [&](const Split& l, const Split& r) { return pieces::before_along(a, b, l.at, r.at); });
        lo = hi;
        continue;
      }
      for (std::size_t i = lo + 1; i < hi; ++i) {
        const Split v = splits_[i];
        std::size_t j = i;
        for (; j > lo && pieces::before_along(a, b, v.at, splits_[j - 1].at); --j)
          splits_[j] = splits_[j - 1];
        splits_[j] = v;
      }
      lo = hi;
    }
  }

  // Inserts the splits into their pieces; the pieces they make are new, and so are their points
  // (events).
  void insert_splits() {
    order_splits();
    // The accepted split points, grouped by piece (none equal to the piece's ends or to the one
    // before), then an in-place insertion from the back: unchanged runs of points move by
    // memmove, so few splits cost no second copy of the arrays.
    struct Group {
      std::uint32_t piece, first, count;  // adds[first .. first + count - 1]
    };
    std::vector<Group> groups;
    std::vector<Vec2> adds;
    for (std::size_t si = 0; si < splits_.size();) {
      const std::uint32_t k = splits_[si].piece;
      const Vec2 a = out_.points[k], b = out_.points[k + 1];
      Group g{k, static_cast<std::uint32_t>(adds.size()), 0};
      Vec2 last = a;
      for (; si < splits_.size() && splits_[si].piece == k; ++si) {
        const Vec2 x = splits_[si].at;
        if (x == a || x == b || x == last) continue;
        adds.push_back(x);
        last = x;
        ++g.count;
      }
      groups.push_back(g);
    }
    const std::size_t old_size = out_.points.size(), new_size = old_size + adds.size();
    out_.points.resize(new_size);
    out_.event.resize(new_size);
    joint_.resize(new_size);
    fresh_.assign(new_size, 0);
    fresh_list_.clear();
    std::size_t src_end = old_size, dst_end = new_size;
    for (std::size_t gi = groups.size(); gi-- > 0;) {
      const Group& g = groups[gi];
      const std::size_t from = g.piece + 1, len = src_end - from;
      if (dst_end != src_end && len > 0) {
        std::memmove(out_.points.data() + dst_end - len, out_.points.data() + from,
                     len * sizeof(Vec2));
        std::memmove(out_.event.data() + dst_end - len, out_.event.data() + from, len);
        std::memmove(joint_.data() + dst_end - len, joint_.data() + from, len);
      }
      dst_end -= len;
      src_end = from;
      for (std::uint32_t m = g.count; m-- > 0;) {
        --dst_end;
        out_.points[dst_end] = adds[g.first + m];
        out_.event[dst_end] = 1;
        joint_[dst_end] = 0;
        fresh_[dst_end] = 1;
        fresh_list_.push_back(static_cast<std::uint32_t>(dst_end));
      }
      // The split piece itself (its start stays the old point) is new.
      fresh_[dst_end - 1] = 1;
      fresh_list_.push_back(static_cast<std::uint32_t>(dst_end - 1));
    }
    std::reverse(fresh_list_.begin(), fresh_list_.end());
    // first[c] moves by the points inserted into pieces before it.
    std::uint32_t shift = 0;
    std::size_t gi = 0;
    for (std::uint32_t c = 0; c <= n_; ++c) {
      while (gi < groups.size() && groups[gi].piece < out_.first[c]) {
        shift += groups[gi].count;
        ++gi;
      }
      out_.first[c] += shift;
    }
  }

  std::span<const NodingInput> segments_;
  std::span<const char> links_;
  std::uint32_t n_;
  bool linked_paths_;
  Noded out_;
  double radius_ = 0.0;
  std::vector<char> joint_;
  std::vector<char> fresh_;
  std::vector<std::uint32_t> fresh_list_;  // pieces made by the last round's splits
  std::vector<Vec2> hot_;                  // crossing points: hot pixels for ever after
  std::size_t hot_fresh_from_ = 0;         // hot[i] for i >= this were made last round
  std::vector<Chain> chains_;
  std::vector<Item> items_;
  std::vector<Key> keys_;
  std::vector<std::pair<double, double>> spans_;  // merged x intervals of the fresh items
  double spans_lo_ = 0.0, spans_hi_ = -1.0;
  CellGrid grid_;
  std::vector<std::uint32_t> stamp_;
  std::vector<Split> splits_;
  // The first grid round's pairs of segments with overlapping boxes, the pair of segments whose
  // crossing made each hot pixel, and whether near_round may use them.
  bool record_ = false;
  bool near_ok_ = false;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> near_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> hot_from_;
};

}  // namespace

Noded node_segments(std::span<const NodingInput> segments, std::span<const char> links,
                    double magnitude) {
  return Noder(segments, links, magnitude).run();
}

}  // namespace contain::clip::detail
