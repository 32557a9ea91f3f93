#include "clip/box_cut.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "contain/clip/polygon_boolean.h"
#include "contain/inside/point_in_polygon.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/ring_orientation.h"
#include "contain/predicates/unit_roundoff.h"

namespace contain::clip::detail {
namespace {

using predicates::orient2d;

constexpr double kU = predicates::unit_roundoff<double>;

// Along p -> q, which comes first: the crossing of the line x = X (-1), that of y = Y (+1), or
// both at the corner (X, Y) (0). At x = X the line is at y_V with sign(y_V - Y) =
// -sign(orient2d(p, q, (X, Y))) sign(q.x - p.x); the crossing of x = X comes first when y has
// not yet passed Y there, i.e. y_V is on p's side of Y (when p.y == Y the crossing of y = Y is
// at p itself, and comes first).
int v_before_h(Vec2 p, Vec2 q, double x, double y) {
  const Sign o = orient2d(p, q, {x, y});
  if (o == Sign::zero) return 0;
  const int s_yv = -to_int(o) * (q.x > p.x ? 1 : -1);
  const int s_p = (p.y > y) - (p.y < y);
  return s_yv == s_p ? -1 : 1;
}

}  // namespace

namespace {

// w in the closed triangle u v z (any orientation; a degenerate triangle holds the points of its
// line: callers check the box of the points first).
bool in_triangle(Vec2 u, Vec2 v, Vec2 z, Vec2 w) {
  const Sign s1 = orient2d(u, v, w), s2 = orient2d(v, z, w), s3 = orient2d(z, u, w);
  const bool neg = s1 == Sign::negative || s2 == Sign::negative || s3 == Sign::negative;
  const bool pos = s1 == Sign::positive || s2 == Sign::positive || s3 == Sign::positive;
  return !(neg && pos);
}

}  // namespace

BoxCut::BoxCut(const Box2& box) {
  set_box(box);
}

void BoxCut::set_box(const Box2& box) {
  x0_ = box.min.x;
  y0_ = box.min.y;
  x1_ = box.max.x;
  y1_ = box.max.y;
  cx_ = 0.5 * box.min.x + 0.5 * box.max.x;
  cy_ = 0.5 * box.min.y + 0.5 * box.max.y;
  corner_[0] = {x0_, y0_};
  corner_[1] = {x1_, y0_};
  corner_[2] = {x1_, y1_};
  corner_[3] = {x0_, y1_};
  reset();
}

void BoxCut::scan(std::span<const Vec2> ring, std::vector<std::uint32_t>& active,
                  bool& parity) const {
  active.clear();
  const std::size_t n = ring.size();
  const Vec2* v = ring.data();
  unsigned odd = 0;
  // Runs of points strictly beyond one side cost one comparison a point (two right of the box,
  // where the centre's +x ray is counted); the edge that ends a run gets the full outcode test.
  std::size_t i = 0;
  while (i < n) {
    const Vec2 p = v[i];
    std::size_t j = i + 1;
    if (p.x < x0_) {
      while (j < n && v[j].x < x0_)
        ++j;
    } else if (p.x > x1_) {
      unsigned up = p.y > cy_ ? 1u : 0u;
      while (j < n && v[j].x > x1_) {
        const unsigned next = v[j].y > cy_ ? 1u : 0u;
        odd ^= up ^ next;
        up = next;
        ++j;
      }
    } else if (p.y < y0_) {
      while (j < n && v[j].y < y0_)
        ++j;
    } else if (p.y > y1_) {
      while (j < n && v[j].y > y1_)
        ++j;
    }
    const std::size_t e = j - 1;
    const unsigned cp = code(v[e]), cq = code(v[j < n ? j : 0]);
    const unsigned both = cp & cq;
    if ((both & 15u) != 0) {
      // Both strictly right of the box (so of the centre) and on either side of its line.
      odd ^= (both >> 1) & ((cp ^ cq) >> 4) & 1u;
    } else {
      active.push_back(static_cast<std::uint32_t>(e));
    }
    i = j;
  }
  parity = odd != 0;
}

void BoxCut::reset() {
  ok_ = true;
  all_ends_.clear();
  rounded_.clear();
  vertices_.clear();
  out_.polygons.clear();
}

void BoxCut::begin_polygon() {
  points_.clear();
  chains_.clear();
  ends_.clear();
  closed_.clear();
  closed_points_.clear();
  parity_ = false;
  tagged_.clear();
  polygon_pieces_.clear();
  rings_cut_ = 0;
}

Vec2 BoxCut::cross_x(Vec2 p, Vec2 q, double x, double& err) {
  err = 0.0;
  if (p.y == q.y) return {x, p.y};
  const double dx = q.x - p.x, dy = q.y - p.y;
  const double t = (x - p.x) / dx;
  const double prod = t * dy;
  double y = p.y + prod;
  // |y - Y| <= 5.1 u |prod| + 1.01 u |y| for the exact Y; the last term covers an underflowing
  // t or product.
  err = 8.0 * kU * (std::fabs(prod) + std::fabs(y)) + 0x1p-1074 * (2.0 + std::fabs(dy));
  y = std::clamp(y, std::min(p.y, q.y), std::max(p.y, q.y));
  if (!(std::isfinite(y) && std::isfinite(err)) || !(y - err > y0_ && y + err < y1_)) ok_ = false;
  return {x, y};
}

Vec2 BoxCut::cross_y(Vec2 p, Vec2 q, double y, double& err) {
  err = 0.0;
  if (p.x == q.x) return {p.x, y};
  const double dx = q.x - p.x, dy = q.y - p.y;
  const double t = (y - p.y) / dy;
  const double prod = t * dx;
  double x = p.x + prod;
  err = 8.0 * kU * (std::fabs(prod) + std::fabs(x)) + 0x1p-1074 * (2.0 + std::fabs(dx));
  x = std::clamp(x, std::min(p.x, q.x), std::max(p.x, q.x));
  if (!(std::isfinite(x) && std::isfinite(err)) || !(x - err > x0_ && x + err < x1_)) ok_ = false;
  return {x, y};
}

bool BoxCut::cut_edge(Vec2 p, Vec2 q, unsigned cp, unsigned cq, Piece& piece) {
  cp &= 15u;
  cq &= 15u;
  piece.p = p;
  piece.q = q;
  piece.along =
      (p.x == q.x && (p.x == x0_ || p.x == x1_)) || (p.y == q.y && (p.y == y0_ || p.y == y1_));
  if ((cp | cq) == 0) {
    piece.a = p;
    piece.b = q;
    piece.ea = piece.eb = 0.0;
    piece.a_vertex = piece.b_vertex = true;
    return true;
  }
  // The lines an endpoint is strictly beyond: 1 a vertical one, 2 a horizontal one, 3 both.
  auto lines = [&](unsigned c, double& x, double& y) {
    x = (c & kLeft) != 0 ? x0_ : x1_;
    y = (c & kBelow) != 0 ? y0_ : y1_;
    return ((c & (kLeft | kRight)) != 0 ? 1 : 0) | ((c & (kBelow | kTop)) != 0 ? 2 : 0);
  };
  double xe = 0, ye = 0, xx = 0, yx = 0;
  const int le = lines(cp, xe, ye), lx = lines(cq, xx, yx);
  // The entry is the later of p's crossings, the exit the earlier of q's (3: at the corner).
  int ve = le, vx = lx;
  if (le == 3) {
    const int c = v_before_h(p, q, xe, ye);
    ve = c < 0 ? 2 : (c > 0 ? 1 : 3);
  }
  if (lx == 3) {
    const int c = v_before_h(p, q, xx, yx);
    vx = c < 0 ? 1 : (c > 0 ? 2 : 3);
  }
  auto on = [](Vec2 v, int via, double x, double y) {
    return via == 1 ? v.x == x : (via == 2 ? v.y == y : (v.x == x && v.y == y));
  };
  // Positive length: the entry strictly before the exit. Crossings of opposite sides, and a
  // corner entry or exit (its other line is opposite to the other end's), are in order.
  if (le == 0) {
    if (on(p, vx, xx, yx)) return false;
  } else if (lx == 0) {
    if (on(q, ve, xe, ye)) return false;
  } else if (ve == 1 && vx == 2) {
    if (v_before_h(p, q, xe, yx) >= 0) return false;
  } else if (ve == 2 && vx == 1) {
    if (v_before_h(p, q, xx, ye) <= 0) return false;
  }
  piece.a_vertex = le == 0;
  piece.b_vertex = lx == 0;
  piece.ea = piece.eb = 0.0;
  if (le == 0) {
    piece.a = p;
  } else if (ve == 3) {
    piece.a = {xe, ye};
  } else if (ve == 1) {
    piece.a = cross_x(p, q, xe, piece.ea);
  } else {
    piece.a = cross_y(p, q, ye, piece.ea);
  }
  if (lx == 0) {
    piece.b = q;
  } else if (vx == 3) {
    piece.b = {xx, yx};
  } else if (vx == 1) {
    piece.b = cross_x(p, q, xx, piece.eb);
  } else {
    piece.b = cross_y(p, q, yx, piece.eb);
  }
  return ok_;
}

int BoxCut::side_of(Vec2 p) const {
  if (p.y == y0_ && p.x < x1_) return 0;
  if (p.x == x1_ && p.y < y1_) return 1;
  if (p.y == y1_ && p.x > x0_) return 2;
  return 3;
}

double BoxCut::key_of(Vec2 p, int side) const {
  switch (side) {
    case 0:
      return p.x;
    case 1:
      return p.y;
    case 2:
      return -p.x;
    default:
      return -p.y;
  }
}

void BoxCut::add_end(Vec2 p, double err, std::uint32_t chain, bool exit) {
  if (!(p.x == x0_ || p.x == x1_ || p.y == y0_ || p.y == y1_)) {
    ok_ = false;  // not on the boundary: cannot happen for a ring of positive length
    return;
  }
  const int side = side_of(p);
  const End e{side, key_of(p, side), err, chain, exit};
  ends_.push_back(e);
  all_ends_.push_back(e);
}

bool BoxCut::active_parity(std::span<const Vec2> ring,
                           std::span<const std::uint32_t> active) const {
  const std::size_t n = ring.size();
  bool odd = false;
  const Vec2 c{cx_, cy_};
  for (const std::uint32_t e : active) {
    const Vec2 p = ring[e], q = ring[e + 1 < n ? e + 1 : 0];
    if ((p.y > cy_) == (q.y > cy_)) continue;
    const Vec2 lo = p.y < q.y ? p : q, hi = p.y < q.y ? q : p;
    if (orient2d(lo, hi, c) == Sign::positive) odd = !odd;
  }
  return odd;
}

bool BoxCut::add_ring(std::span<const Vec2> ring, std::span<const std::uint32_t> active, bool hole,
                      std::optional<Sign> orientation) {
  const std::size_t n = ring.size();
  if (!ok_ || n < 3) return true;  // fewer than 3 points enclose nothing
  pieces_.clear();
  for (const std::uint32_t e : active) {
    const Vec2 p = ring[e], q = ring[e + 1 < n ? e + 1 : 0];
    if (p == q) continue;
    Piece piece;
    if (!cut_edge(p, q, code(p), code(q), piece)) {
      if (!ok_) return true;
      continue;
    }
    piece.edge = e;
    pieces_.push_back(piece);
  }
  if (!pieces_.empty() && !orientation) orientation = predicates::ring_orientation(ring);
  if (!pieces_.empty() && *orientation == Sign::zero) {  // no area: no side to keep
    ok_ = false;
    return true;
  }
  // Shells counter-clockwise and holes clockwise leave the region on the left of every edge.
  const bool reversed = !pieces_.empty() && (*orientation == Sign::positive) == hole;
  // A piece on a side stays when the region is on the box's side of it: when it runs
  // counter-clockwise along the boundary in the region's orientation.
  std::size_t m = 0;
  for (const Piece& piece : pieces_) {
    if (piece.along) {
      const Vec2 d = piece.b - piece.a;
      const int side = piece.a.y == y0_ && piece.b.y == y0_   ? 0
                       : piece.a.x == x1_ && piece.b.x == x1_ ? 1
                       : piece.a.y == y1_ && piece.b.y == y1_ ? 2
                                                              : 3;
      const bool forward_ccw = side == 0   ? d.x > 0
                               : side == 1 ? d.y > 0
                               : side == 2 ? d.x < 0
                                           : d.y < 0;
      if (forward_ccw == reversed) continue;
    }
    pieces_[m++] = piece;
  }
  pieces_.resize(m);
  if (m == 0) return false;  // the ring counts for the centre's parity only
  // Pieces i and i + 1 are linked when they meet at a vertex of the ring (zero-length edges
  // between them aside).
  auto linked = [&](const Piece& u, const Piece& v) {
    if (!u.b_vertex || !v.a_vertex || u.b != v.a) return false;
    for (std::size_t k = (u.edge + 1) % n; k != v.edge; k = (k + 1) % n) {
      if (ring[k] != u.b || ring[(k + 1) % n] != u.b) return false;
    }
    return true;
  };
  std::vector<char> link(m);
  bool all = true;
  for (std::size_t i = 0; i < m; ++i) {
    const Piece& u = pieces_[i];
    const Piece& v = pieces_[(i + 1) % m];
    link[i] = linked(u, v) ? 1 : 0;
    all = all && link[i];
    if (link[i] && !u.along && !v.along) {
      // A vertex on a side with both pieces inside: the region must be on one side of the
      // touching point only (a convex turn in the region's orientation), else a walk along the
      // side would pass through it.
      const Vec2 t = u.b;
      if (t.x == x0_ || t.x == x1_ || t.y == y0_ || t.y == y1_) {
        const int turn = to_int(orient2d(u.p, t, v.q));
        if ((reversed ? -turn : turn) <= 0) {
          ok_ = false;
          return true;
        }
      }
    }
  }
  for (const Piece& piece : pieces_) {
    if (piece.a_vertex) vertices_.push_back(piece.a);
    if (piece.b_vertex) vertices_.push_back(piece.b);
    if (piece.a_vertex) tagged_.push_back({piece.a, rings_cut_});
    if (piece.b_vertex) tagged_.push_back({piece.b, rings_cut_});
    polygon_pieces_.push_back({piece.a, piece.b, rings_cut_});
    if (piece.ea > 0.0 || piece.eb > 0.0) rounded_.push_back(piece);
  }
  ++rings_cut_;
  if (all) {
    const auto first = static_cast<std::uint32_t>(closed_points_.size());
    for (const Piece& piece : pieces_)
      closed_points_.push_back(piece.a);
    if (reversed) std::reverse(closed_points_.begin() + first, closed_points_.end());
    closed_.push_back({first, static_cast<std::uint32_t>(closed_points_.size()), hole});
    return true;
  }
  std::size_t s = 0;
  while (link[(s + m - 1) % m])
    ++s;
  for (std::size_t done = 0; done < m;) {
    const auto chain = static_cast<std::uint32_t>(chains_.size());
    const auto first = static_cast<std::uint32_t>(points_.size());
    std::size_t i = (s + done) % m;
    points_.push_back(pieces_[i].a);
    const double entry_err = pieces_[i].ea;
    for (;;) {
      points_.push_back(pieces_[i].b);
      ++done;
      if (!link[i]) break;
      i = (i + 1) % m;
    }
    const double exit_err = pieces_[i].eb;
    chains_.push_back({first, static_cast<std::uint32_t>(points_.size())});
    if (reversed) {
      std::reverse(points_.begin() + first, points_.end());
      add_end(points_[first], exit_err, chain, false);
      add_end(points_.back(), entry_err, chain, true);
    } else {
      add_end(points_[first], entry_err, chain, false);
      add_end(points_.back(), exit_err, chain, true);
    }
  }
  return true;
}

Ring BoxCut::box_ring() const {
  return {corner_[0], corner_[1], corner_[2], corner_[3]};
}

void BoxCut::end_polygon() {
  if (!ok_) return;
  if (rings_cut_ > 1 && rings_touch()) {
    ok_ = false;
    return;
  }
  trace_polygon();
}

bool BoxCut::rings_touch() {
  std::sort(tagged_.begin(), tagged_.end(), [](const Tagged& l, const Tagged& r) {
    return l.p.x < r.p.x || (l.p.x == r.p.x && l.p.y < r.p.y);
  });
  for (std::size_t i = 1; i < tagged_.size(); ++i) {
    if (tagged_[i].p == tagged_[i - 1].p && tagged_[i].ring != tagged_[i - 1].ring) return true;
  }
  // A vertex of one ring on a piece of another (a hole touching its shell inside an edge).
  for (const TaggedPiece& e : polygon_pieces_) {
    const double lo = std::min(e.a.x, e.b.x), hi = std::max(e.a.x, e.b.x);
    const double ylo = std::min(e.a.y, e.b.y), yhi = std::max(e.a.y, e.b.y);
    auto it = std::lower_bound(tagged_.begin(), tagged_.end(), lo,
                               [](const Tagged& v, double x) { return v.p.x < x; });
    for (; it != tagged_.end() && it->p.x <= hi; ++it) {
      if (it->ring == e.ring || it->p.y < ylo || it->p.y > yhi) continue;
      if (it->p == e.a || it->p == e.b) continue;  // shared vertices: found above
      if (orient2d(e.a, e.b, it->p) == Sign::zero) return true;
    }
  }
  return false;
}

void BoxCut::trace_polygon() {
  auto closed_ring = [&](const Closed& c) {
    return Ring(closed_points_.begin() + c.first, closed_points_.begin() + c.last);
  };
  std::vector<Polygon> shells;
  if (ends_.empty()) {
    for (const Closed& c : closed_) {
      if (!c.hole) shells.push_back(Polygon{{closed_ring(c)}});
    }
    if (shells.empty() && parity_) {
      if (!(x0_ < cx_ && cx_ < x1_ && y0_ < cy_ && cy_ < y1_)) {
        ok_ = false;
        return;
      }
      shells.push_back(Polygon{{box_ring()}});
    }
    if (shells.size() > 1) {
      ok_ = false;  // two shells wholly inside: not one polygon
      return;
    }
  } else {
    for (const Closed& c : closed_) {
      if (!c.hole) {
        ok_ = false;  // a shell wholly inside beside cut rings: not one OGC polygon
        return;
      }
    }
    std::sort(ends_.begin(), ends_.end(), [](const End& l, const End& r) {
      return l.side < r.side || (l.side == r.side && l.key < r.key);
    });
    const std::size_t m = ends_.size();
    // Each exit joins the entry right after it, counter-clockwise.
    for (std::size_t i = 0; i < m; ++i) {
      if (!ends_[i].exit) continue;
      const End& e = ends_[i];
      const End& n = ends_[(i + 1) % m];
      if (n.exit) {
        ok_ = false;  // ends that do not alternate: input that is not OGC-valid
        return;
      }
      Chain& c = chains_[e.chain];
      c.next = n.chain;
      c.from_side = e.side;
      c.corners = n.side == e.side ? (n.key > e.key ? 0 : 4) : (n.side - e.side + 4) % 4;
    }
    for (std::size_t k = 0; k < chains_.size(); ++k) {
      if (chains_[k].used) continue;
      Ring ring;
      std::size_t c = k;
      while (!chains_[c].used) {
        Chain& ch = chains_[c];
        ch.used = true;
        // An entry or exit at a corner is that corner: once.
        for (std::uint32_t i = ch.first; i < ch.last; ++i) {
          if (ring.empty() || ring.back() != points_[i]) ring.push_back(points_[i]);
        }
        for (int j = 1; j <= ch.corners; ++j) {
          if (ring.back() != corner_[(ch.from_side + j) % 4]) {
            ring.push_back(corner_[(ch.from_side + j) % 4]);
          }
        }
        if (ch.next == kNoChain) {
          ok_ = false;
          return;
        }
        c = ch.next;
      }
      if (c != k) {
        ok_ = false;
        return;
      }
      if (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
      shells.push_back(Polygon{{std::move(ring)}});
    }
  }
  // Holes wholly inside the box go to the shell that holds them.
  for (const Closed& c : closed_) {
    if (!c.hole) continue;
    if (shells.empty()) continue;  // outside the region's part in the box (cannot happen)
    std::size_t at = 0;
    if (shells.size() > 1) {
      at = shells.size();
      for (std::size_t s = 0; s < shells.size() && at == shells.size(); ++s) {
        const std::span<const Ring> shell(&shells[s].rings.front(), 1);
        for (std::uint32_t k = c.first; k < c.last; ++k) {
          const Location where = inside::point_in_polygon(shell, closed_points_[k]);
          if (where == Location::boundary) continue;
          if (where == Location::inside) at = s;
          break;
        }
      }
      if (at == shells.size()) {
        ok_ = false;
        return;
      }
    }
    shells[at].rings.push_back(closed_ring(c));
  }
  for (Polygon& p : shells)
    out_.polygons.push_back(std::move(p));
}

bool BoxCut::vertex_in_hull(const Piece& piece) const {
  // The hull of the piece's rounded ends widened by their bounds along their sides, and its
  // exact ends: it holds both the rounded and the exact piece.
  Vec2 h[4];
  int k = 0;
  auto add = [&](Vec2 v, double err) {
    if (err == 0.0) {
      h[k++] = v;
      return;
    }
    const bool vertical = v.x == x0_ || v.x == x1_;
    const double inf = std::numeric_limits<double>::infinity();
    if (vertical) {
      h[k++] = {v.x, std::nextafter(v.y - err, -inf)};
      h[k++] = {v.x, std::nextafter(v.y + err, inf)};
    } else {
      h[k++] = {std::nextafter(v.x - err, -inf), v.y};
      h[k++] = {std::nextafter(v.x + err, inf), v.y};
    }
  };
  add(piece.a, piece.ea);
  add(piece.b, piece.eb);
  Box2 bounds;
  for (int i = 0; i < k; ++i)
    bounds.expand(h[i]);
  for (const Vec2 w : vertices_) {
    if (!bounds.contains(w)) continue;
    if ((piece.a_vertex && w == piece.a) || (piece.b_vertex && w == piece.b)) continue;
    bool in = false;
    if (k == 3) {
      in = in_triangle(h[0], h[1], h[2], w);
    } else {
      in = in_triangle(h[0], h[1], h[2], w) || in_triangle(h[0], h[1], h[3], w) ||
           in_triangle(h[0], h[2], h[3], w) || in_triangle(h[1], h[2], h[3], w);
    }
    if (in) return true;
  }
  return false;
}

bool BoxCut::check_region() {
  // Boundary points strictly apart by more than their error bounds: the rounded order is the
  // exact one, and no exact point lies between another's exact and rounded position.
  std::sort(all_ends_.begin(), all_ends_.end(), [](const End& l, const End& r) {
    return l.side < r.side || (l.side == r.side && l.key < r.key);
  });
  for (std::size_t i = 1; i < all_ends_.size(); ++i) {
    const End& l = all_ends_[i - 1];
    const End& r = all_ends_[i];
    if (l.side == r.side && !(r.key - l.key > l.err + r.err)) return false;
  }
  // No input vertex in the sliver between a rounded piece and its exact position.
  if (static_cast<double>(rounded_.size()) * static_cast<double>(vertices_.size()) > 0x1p22) {
    return false;  // left to the boolean engine, which is O((n + k) log n)
  }
  for (const Piece& piece : rounded_) {
    if (vertex_in_hull(piece)) return false;
  }
  return true;
}

MultiPolygon BoxCut::take() {
  if (ok_ && !check_region()) ok_ = false;
  return std::move(out_);
}

Box2 finite_box(const Box2& box) {
  if (!(box.min.x < box.max.x && box.min.y < box.max.y)) return {};
  constexpr double big = std::numeric_limits<double>::max();
  Box2 b = box;
  b.min.x = std::max(b.min.x, -big);
  b.min.y = std::max(b.min.y, -big);
  b.max.x = std::min(b.max.x, big);
  b.max.y = std::min(b.max.y, big);
  if (!(b.min.x < b.max.x && b.min.y < b.max.y)) return {};
  return b;
}

MultiPolygon clip_by_box_exactly(const MultiPolygon& region, const Box2& box) {
  const std::vector<Ring> rings = region.all_rings();
  const Ring frame{box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
  return polygon_boolean(rings, std::span<const Ring>(&frame, 1),
                         {.op = Op::intersection, .fill = Fill::even_odd});
}

MultiPolygon clip_by_box(const MultiPolygon& region, const Box2& given) {
  const Box2 box = finite_box(given);
  if (box.empty()) return {};
  BoxCut cut(box);
  std::vector<std::uint32_t> active;
  for (const Polygon& polygon : region.polygons) {
    cut.begin_polygon();
    for (std::size_t r = 0; r < polygon.rings.size() && cut.ok(); ++r) {
      const Ring& ring = polygon.rings[r];
      bool parity = false;
      cut.scan(ring, active, parity);
      if (!cut.add_ring(ring, active, r > 0, std::nullopt)) {
        cut.add_parity(parity != cut.active_parity(ring, active));
      }
    }
    cut.end_polygon();
    if (!cut.ok()) break;
  }
  MultiPolygon out = cut.take();
  if (cut.ok()) return out;
  return clip_by_box_exactly(region, box);
}

}  // namespace contain::clip::detail
