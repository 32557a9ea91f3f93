// The arrangement behind the polygon booleans.
//
// Stages, one function each (extraction in extract.cpp):
// 1. Noding (noding.cpp): every input edge becomes a chain of pieces that meet other
//    pieces only at shared endpoints.
// 2. Graph: the points that something else meets (Noded::event), split points and path ends
//    are vertices; equal ones merge (sorted by (x, y)). Every run of pieces from a vertex along
//    its path through the other points to the next vertex is one edge carrying its inner points
//    (rule clip-events); runs of one piece that are equal merge into one edge whose
//    multiplicities in A and B add up (opposite directions cancel); an edge that no operand
//    counts is dropped unless it is part of an open path. Around every vertex the outgoing
//    half-edges are sorted counter-clockwise by their first piece, exactly: the half-plane of the
//    direction (signs of coordinate differences, exact for doubles), then orient2d.
// 3. Faces: the face left of h = u -> v continues with the half-edge of v that is the next
//    clockwise from v -> u. A face left of h has winding numbers w(left) = w(right) + m(h) for
//    the multiplicities m(h) of h. Per connected component, the face around it is found at its
//    lowest (x, y) point o, a vertex (all its edges leave o into x >= o.x) or a point inside a
//    run (the face left of the run when it turns counter-clockwise there), and its winding
//    numbers are those of o with respect to the other components: a ray from o towards -x
//    counted with the half-open rule and exact orient2d (no piece of the component meets the
//    open ray, and no piece of another component passes through o). The rest follows by the
//    relation above, breadth first over the faces.
// 4. Extraction: a half-edge is a boundary of the result when the face on its left is kept and
//    the one on its right is not. Boundary chains take at each vertex the first boundary
//    half-edge clockwise from the reverse of the arriving one (the tightest turn, which keeps
//    two kept sectors meeting at a vertex apart); a chain that revisits a vertex is split there,
//    so every ring is simple; rings copy the inner points of their runs. Counter-clockwise rings
//    are shells, clockwise ones holes, and a hole joins the shell whose kept faces are connected
//    to its own across non-boundary edges.

#include "clip/boolean/arrangement.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "clip/boolean/graph_helpers.h"
#include "contain/core/union_find.h"
#include "contain/predicates/orient2d.h"

namespace contain::clip::detail {
namespace {

using graph::half_of;
using graph::kNone;
using graph::lex_less;
using predicates::orient2d;

// Both pieces cross the line y = c (lo.y <= c < hi.y) and meet at most in endpoints: true when
// t crosses it right of s. The higher of the two lower endpoints lies within the other's y span,
// and the pieces cannot change sides between there and the line.
bool crosses_right_of(Vec2 s_lo, Vec2 s_hi, Vec2 t_lo, Vec2 t_hi) {
  if (t_lo.y >= s_lo.y) {
    Sign o = orient2d(s_lo, s_hi, t_lo);
    if (o == Sign::zero) o = orient2d(s_lo, s_hi, t_hi);  // shared lower endpoint
    return o == Sign::negative;
  }
  Sign o = orient2d(t_lo, t_hi, s_lo);
  if (o == Sign::zero) o = orient2d(t_lo, t_hi, s_hi);
  return o == Sign::positive;  // s left of t
}

// Consecutive segments of one path: the first ends where the next starts, with the same label.
std::vector<char> links_by_labels(const ArrangementInput& input) {
  const std::size_t n = input.segments.size();
  std::vector<char> links(n, 0);
  for (std::size_t c = 0; c + 1 < n; ++c) {
    const SegmentLabel l = input.labels[c], r = input.labels[c + 1];
    links[c] = (input.segments[c].b == input.segments[c + 1].a && l.a == r.a && l.b == r.b &&
                l.open == r.open)
                   ? 1
                   : 0;
  }
  return links;
}

}  // namespace

struct Arrangement::Piece {
  std::uint64_t key;
  std::uint32_t piece;
  std::int32_t a, b;  // multiplicity along key's u -> v
  bool open;
  bool flipped;
};

struct Arrangement::Lowest {
  Vec2 p;
  std::uint32_t vertex = kNone;
  std::uint32_t edge = kNone;
  std::uint32_t k = 0;
};

void ArrangementInput::add_rings(std::span<const Ring> rings, SegmentLabel label) {
  for (const Ring& ring : rings) {
    const std::size_t n = ring.size();
    bool continues = false;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = ring[i], b = i + 1 < n ? ring[i + 1] : ring[0];
      if (a == b) continue;
      push(a, b, label, continues);
      continues = true;
    }
  }
}

Arrangement::Arrangement(const ArrangementInput& input) {
  std::vector<char> computed;
  if (input.links.size() != input.segments.size()) computed = links_by_labels(input);
  const std::span<const char> links =
      input.links.size() == input.segments.size() ? std::span<const char>(input.links) : computed;
  noded_ = node_segments(input.segments, links, input.magnitude);
  crossings = noded_.crossings;
  rounds = noded_.rounds;
  converged = noded_.converged;
  // The graph.
  const std::vector<std::uint32_t> vid = number_vertices(input, links);
  std::vector<Piece> pieces = collect_runs(input, links, vid);
  merge_single_pieces(pieces, input.open_paths);
  edges = static_cast<std::int64_t>(edge_.size());
  sort_half_edges();
  // Its faces and their winding numbers, component by component.
  const std::vector<std::int32_t> face_start = trace_faces();
  const std::size_t nf = face_start.size();
  face_a_.assign(nf, 0);
  face_b_.assign(nf, 0);
  std::vector<std::uint32_t> edge_root;
  std::vector<char> has;
  const std::vector<Lowest> lowest = lowest_points(edge_root, has);
  std::vector<char> done(nf, 0);
  std::vector<std::int32_t> queue;
  for (std::size_t root = 0; root < lowest.size(); ++root) {
    if (!has[root]) continue;
    const std::int32_t f0 = outer_face(lowest[root]);
    label_outer_face(static_cast<std::uint32_t>(root), lowest[root], f0, edge_root);
    done[f0] = 1;
    spread_labels(f0, face_start, done, queue);
  }
}

std::vector<std::uint32_t> Arrangement::number_vertices(const ArrangementInput& input,
                                                        std::span<const char> links) {
  const std::vector<Vec2>& pts = noded_.points;
  const std::vector<std::uint32_t>& first = noded_.first;
  const std::size_t nchains = input.segments.size();
  // Which points are vertices: the noding's events, the ends of paths, every point of an open
  // path (clip_polylines reads its pieces one by one). The end of a linked segment is the start
  // of the next one (alias): it takes that start's vertex, and is a vertex when either is.
  std::vector<char>& is_vertex = noded_.event;
  struct Keyed {
    Vec2 p;
    std::uint32_t i;
  };
  std::vector<Keyed> order;
  const bool any_open = input.open_paths;
  for (std::size_t c = 0; c < nchains; ++c) {
    const std::uint32_t s = first[c], e = first[c + 1] - 1;
    if (any_open && input.labels[c].open) {
      std::fill(is_vertex.begin() + s, is_vertex.begin() + e + 1, 1);
    }
    if (c == 0 || links[c - 1] == 0) is_vertex[s] = 1;
    if (links[c] != 0) {
      is_vertex[e + 1] = static_cast<char>(is_vertex[e + 1] | is_vertex[e]);
      is_vertex[e] = 0;
    } else {
      is_vertex[e] = 1;
    }
    for (std::uint32_t k = s; k <= e; ++k) {
      if (is_vertex[k]) order.push_back({pts[k], k});
    }
  }
  std::sort(order.begin(), order.end(), [](const Keyed& l, const Keyed& r) {
    return lex_less(l.p, r.p) || (l.p == r.p && l.i < r.i);
  });
  // vid: the vertex of a point, kNone for the others and for aliases (see collect_runs).
  std::vector<std::uint32_t> vid(pts.size(), kNone);
  vertex_.clear();
  vertex_.reserve(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || order[i].p != order[i - 1].p) vertex_.push_back(order[i].p);
    vid[order[i].i] = static_cast<std::uint32_t>(vertex_.size() - 1);
  }
  origin_.assign(vertex_.size(), kNone);
  for (std::size_t c = nchains; c-- > 0;) {
    const std::uint32_t v = vid[first[c]];
    if (v != kNone) origin_[v] = static_cast<std::uint32_t>(c);
  }
  return vid;
}

std::vector<Arrangement::Piece> Arrangement::collect_runs(const ArrangementInput& input,
                                                          std::span<const char> links,
                                                          const std::vector<std::uint32_t>& vid) {
  const std::vector<Vec2>& pts = noded_.points;
  const std::vector<std::uint32_t>& first = noded_.first;
  const std::size_t np = pts.size();
  const std::size_t nchains = input.segments.size();
  const bool any_open = input.open_paths;
  // The end of a linked segment (an alias) has the vertex of the next segment's start.
  auto alias = [&](std::uint32_t k, std::size_t c) {
    return k + 1 == first[c + 1] && links[c] != 0;
  };
  // Runs: from a vertex along the path through points that are no vertex, to the next vertex.
  // A run of several pieces is an edge of its own (another piece equal to one of its pieces
  // would meet its inner points); single pieces, keyed by their vertex pair, merge into edges.
  // The pieces of a run have consecutive ids (point index - segment index).
  std::vector<Piece> pieces;
  // Pieces to half-edges, for clip_polylines's open paths only.
  piece_half_.assign(any_open ? np - nchains : 0, -1);
  edge_.clear();
  std::size_t c = 0;
  std::uint32_t k = nchains > 0 ? first[0] : 0;
  while (c < nchains) {
    if (k + 1 >= first[c + 1]) {  // the segment's last point: go on with the next segment
      ++c;
      if (c < nchains) k = first[c];
      continue;
    }
    if (vid[k] == kNone) {  // inside a run (not reached: runs are followed to their end)
      ++k;
      continue;
    }
    // Follow the run from k to the next vertex; h steps over the points after k.
    std::size_t cc = c;
    std::uint32_t h = k + 1;
    std::uint32_t v = kNone;
    for (;;) {
      // h is no vertex: a linked segment's end (continue after the alias), or a point inside a
      // segment that no split made (none: splits are events).
      if (alias(h, cc)) {
        v = vid[h + 1];
        if (v != kNone) break;
        h += 2;
        ++cc;
      } else {
        v = vid[h];
        if (v != kNone) break;
        ++h;
      }
    }
    const SegmentLabel label = input.labels[c];
    const std::uint32_t u = vid[k];
    const auto p0 = static_cast<std::uint32_t>(k - c);
    const auto p1 = static_cast<std::uint32_t>(h - 1 - cc);  // the last piece of the run
    if (p0 == p1) {
      std::uint32_t a = u, b = v;
      const bool flip = b < a;
      if (flip) std::swap(a, b);
      const std::int32_t sg = flip ? -1 : 1;
      pieces.push_back(
          {(std::uint64_t{a} << 32) | b, p0, sg * label.a, sg * label.b, label.open, flip});
    } else if (label.a != 0 || label.b != 0 || label.open) {
      const auto e = static_cast<std::int32_t>(edge_.size());
      edge_.push_back({u, v, label.a, label.b, k, h, pts[k + 1], pts[h - 1]});
      if (any_open) std::fill(piece_half_.begin() + p0, piece_half_.begin() + p1 + 1, 2 * e);
    }
    c = cc;
    k = h;
  }
  return pieces;
}

void Arrangement::merge_single_pieces(std::vector<Piece>& pieces, bool any_open) {
  std::sort(pieces.begin(), pieces.end(),
            [](const Piece& l, const Piece& r) { return l.key < r.key; });
  for (std::size_t i = 0; i < pieces.size();) {
    std::size_t j = i;
    std::int32_t a = 0, b = 0;
    bool open = false;
    for (; j < pieces.size() && pieces[j].key == pieces[i].key; ++j) {
      a += pieces[j].a;
      b += pieces[j].b;
      open = open || pieces[j].open;
    }
    if (a != 0 || b != 0 || open) {
      const auto e = static_cast<std::int32_t>(edge_.size());
      const auto u = static_cast<std::uint32_t>(pieces[i].key >> 32);
      const auto v = static_cast<std::uint32_t>(pieces[i].key);
      edge_.push_back({u, v, a, b, kPlain, kPlain, vertex_[v], vertex_[u]});
      for (std::size_t m = i; m < j && any_open; ++m)
        piece_half_[pieces[m].piece] = 2 * e + (pieces[m].flipped ? 1 : 0);
    }
    i = j;
  }
}

void Arrangement::sort_half_edges() {
  // Outgoing half-edges per vertex, sorted counter-clockwise from +x by the direction of their
  // first piece.
  const std::size_t nv = vertex_.size();
  out_first_.assign(nv + 1, 0);
  for (const Edge& e : edge_) {
    ++out_first_[e.u + 1];
    ++out_first_[e.v + 1];
  }
  for (std::size_t v = 0; v < nv; ++v)
    out_first_[v + 1] += out_first_[v];
  out_.resize(2 * edge_.size());
  {
    std::vector<std::uint32_t> fill(out_first_.begin(), out_first_.end() - 1);
    for (std::size_t e = 0; e < edge_.size(); ++e) {
      out_[fill[edge_[e].u]++] = static_cast<std::int32_t>(2 * e);
      out_[fill[edge_[e].v]++] = static_cast<std::int32_t>(2 * e + 1);
    }
  }
  pos_.resize(2 * edge_.size());
  auto toward = [&](std::int32_t h) { return (h & 1) ? edge_[h >> 1].dv : edge_[h >> 1].du; };
  for (std::size_t v = 0; v < nv; ++v) {
    const auto begin = out_.begin() + out_first_[v], end = out_.begin() + out_first_[v + 1];
    const Vec2 o = vertex_[v];
    if (end - begin > 1) {
      std::sort(begin, end, [&](std::int32_t l, std::int32_t r) {
        const Vec2 pl = toward(l), pr = toward(r);
        const int hl = half_of(o, pl), hr = half_of(o, pr);
        if (hl != hr) return hl < hr;
        return orient2d(o, pl, pr) == Sign::positive;
      });
    }
    for (auto it = begin; it != end; ++it)
      pos_[*it] = static_cast<std::uint32_t>(it - begin);
  }
}

void Arrangement::append_points(std::int32_t h, std::vector<Vec2>& out) const {
  const Edge& e = edge_[h >> 1];
  out.push_back(vertex_[tail(h)]);
  if (e.i0 == kPlain) return;
  const std::vector<Vec2>& pts = noded_.points;
  // A joint's two copies are equal neighbours: the second one is left out.
  if ((h & 1) == 0) {
    for (std::uint32_t k = e.i0 + 1; k < e.i1; ++k) {
      if (pts[k] != pts[k - 1]) out.push_back(pts[k]);
    }
  } else {
    for (std::uint32_t k = e.i1 - 1; k > e.i0; --k) {
      if (pts[k] != pts[k + 1]) out.push_back(pts[k]);
    }
  }
}

std::int32_t Arrangement::next(std::int32_t h) const {
  const std::uint32_t v = head(h);
  const std::uint32_t b = out_first_[v], deg = out_first_[v + 1] - b;
  const std::uint32_t p = pos_[h ^ 1];
  return out_[b + (p == 0 ? deg - 1 : p - 1)];
}

std::vector<std::int32_t> Arrangement::trace_faces() {
  const std::size_t nh = 2 * edge_.size();
  face_.assign(nh, -1);
  std::vector<std::int32_t> face_start;
  for (std::size_t h = 0; h < nh; ++h) {
    if (face_[h] >= 0) continue;
    const auto f = static_cast<std::int32_t>(face_start.size());
    face_start.push_back(static_cast<std::int32_t>(h));
    auto g = static_cast<std::int32_t>(h);
    do {
      face_[g] = f;
      g = next(g);
    } while (g != static_cast<std::int32_t>(h));
  }
  return face_start;
}

std::vector<Arrangement::Lowest> Arrangement::lowest_points(std::vector<std::uint32_t>& edge_root,
                                                            std::vector<char>& has) const {
  const std::vector<Vec2>& pts = noded_.points;
  // Components of the graph, and the lowest (x, y) point of each, a vertex or a point inside a
  // run (ids of the lowest vertex, or kNone and the run's edge and point index).
  const std::size_t nv = vertex_.size();
  UnionFind<std::uint32_t> comp(nv);
  for (const Edge& e : edge_)
    comp.unite(e.u, e.v);
  std::vector<Lowest> lowest(nv);
  has.assign(nv, 0);
  edge_root.resize(edge_.size());
  for (std::uint32_t ei = 0; ei < edge_.size(); ++ei) {
    const Edge& e = edge_[ei];
    const std::uint32_t root = comp.find(e.u);
    edge_root[ei] = root;
    Lowest best{vertex_[std::min(e.u, e.v)], std::min(e.u, e.v), kNone, 0};
    if (e.i0 != kPlain) {
      for (std::uint32_t k = e.i0 + 1; k < e.i1; ++k) {
        // Strictly lower: of a joint's two copies, the first (the end of a segment).
        if (lex_less(pts[k], best.p)) best = {pts[k], kNone, ei, k};
      }
    }
    if (!has[root] || lex_less(best.p, lowest[root].p) ||
        (best.p == lowest[root].p && best.vertex < lowest[root].vertex)) {
      lowest[root] = best;
      has[root] = 1;
    }
  }
  return lowest;
}

std::int32_t Arrangement::outer_face(const Lowest& low) const {
  const std::vector<Vec2>& pts = noded_.points;
  const Vec2 o = low.p;
  if (low.vertex != kNone) {
    // The outer face is left of the last half-edge of the upper half-plane (or the last one).
    const std::uint32_t v0 = low.vertex;
    const std::uint32_t deg = out_first_[v0 + 1] - out_first_[v0];
    std::uint32_t upper = 0;
    for (std::uint32_t i = 0; i < deg; ++i) {
      const std::int32_t h = out_[out_first_[v0] + i];
      if (half_of(o, (h & 1) ? edge_[h >> 1].dv : edge_[h >> 1].du) == 0) ++upper;
    }
    return face_[out_[out_first_[v0] + (upper > 0 ? upper - 1 : deg - 1)]];
  }
  // A run passes a -> o -> b with a and b above o in (x, y) order: the direction -x from o
  // is left of the run when b turns counter-clockwise from a.
  const Vec2 a = pts[low.k - 1];
  const Vec2 b = pts[low.k + 1] != o ? pts[low.k + 1] : pts[low.k + 2];
  const bool left = orient2d(o, a, b) == Sign::positive;
  return face_[2 * low.edge + (left ? 0 : 1)];
}

void Arrangement::label_outer_face(std::uint32_t root, const Lowest& low, std::int32_t f0,
                                   const std::vector<std::uint32_t>& edge_root) {
  const std::vector<Vec2>& pts = noded_.points;
  const Vec2 o = low.p;
  // Winding numbers of o: pieces of the other components crossing the open ray towards -x
  // (half-open rule: an endpoint on the ray's line counts as below it; none passes through o).
  int wa = 0, wb = 0;
  std::int32_t nearest = -1;  // the edge hit first by the ray: the face around C is beside it
  Vec2 near_lo, near_hi;
  bool near_up = false;
  auto piece = [&](std::int32_t ei, const Edge& e, Vec2 p, Vec2 q) {
    const bool pb = p.y <= o.y, qb = q.y <= o.y;
    if (pb == qb) return;
    if (p.x >= o.x && q.x >= o.x) return;
    // Upward orientation lo -> hi; the crossing is left of o when o is right of lo -> hi.
    const bool up = pb;  // p below: the edge goes up here
    const Vec2 lo = up ? p : q, hi = up ? q : p;
    if (orient2d(lo, hi, o) != Sign::negative) return;
    // Crossing from far left to o over an upward edge goes from its left to its right.
    wa += up ? -e.a : e.a;
    wb += up ? -e.b : e.b;
    if (nearest < 0 || crosses_right_of(near_lo, near_hi, lo, hi)) {
      nearest = ei;
      near_lo = lo;
      near_hi = hi;
      near_up = up;
    }
  };
  for (std::size_t ei = 0; ei < edge_.size(); ++ei) {
    // All points of the component are at or after o in (x, y) order: none meets the ray.
    if (edge_root[ei] == root) continue;
    const Edge& e = edge_[ei];
    const auto id = static_cast<std::int32_t>(ei);
    if (e.i0 == kPlain) {
      piece(id, e, vertex_[e.u], vertex_[e.v]);
    } else {
      for (std::uint32_t k = e.i0; k < e.i1; ++k)
        piece(id, e, pts[k], pts[k + 1]);
    }
  }
  if (nearest >= 0) {
    // East of the upward piece lo -> hi is right of it: the face left of the reverse
    // half-edge when the edge runs upward there.
    face_links_.emplace_back(f0, face_[2 * nearest + (near_up ? 1 : 0)]);
  }
  face_a_[f0] = wa;
  face_b_[f0] = wb;
}

void Arrangement::spread_labels(std::int32_t f0, const std::vector<std::int32_t>& face_start,
                                std::vector<char>& done, std::vector<std::int32_t>& queue) {
  queue.assign(1, f0);
  for (std::size_t qi = 0; qi < queue.size(); ++qi) {
    const std::int32_t f = queue[qi];
    const std::int32_t start = face_start[f];
    std::int32_t g = start;
    do {
      const std::int32_t r = face_[g ^ 1];
      if (!done[r]) {
        const Edge& e = edge_[g >> 1];
        const int s = (g & 1) ? -1 : 1;
        face_a_[r] = face_a_[f] - s * e.a;
        face_b_[r] = face_b_[f] - s * e.b;
        done[r] = 1;
        queue.push_back(r);
      }
      g = next(g);
    } while (g != start);
  }
}

}  // namespace contain::clip::detail
