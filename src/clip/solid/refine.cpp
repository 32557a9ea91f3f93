// Stage 3 of the mesh boolean: each triangle split by its constraints into a triangulation whose
// edges include every piece of every constraint (rule solid-refinement in docs/robustness.md).
//
// In a triangle T (worked in the projection that drops the largest component of T's normal,
// orientations multiplied by that component's sign so that T turns positively), the segments
// are T's three edges and its constraints. Each pair that crosses properly gives a point (two
// lines in T's plane, `line_line`); a point on a segment (an end of another, a crossing, a
// point given by a neighbour) splits it; a coplanar partner's edge is cut to T (the points
// outside T dropped, the pieces between the points inside kept). So that the refined surface
// is conforming, every point found on an input edge (T's own or a coplanar partner's) is
// gathered per edge in a first pass over all triangles and given to every triangle that has
// that edge as a segment in the second: triangles sharing an edge split it at the same points.
// A triangle is arranged once: the first pass keeps its points (and which of its edges each
// lies on, known from the test that kept it in T), the second adds the points given to it.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"
#include "contain/core/next_double.h"
#include "contain/predicates/orient3d.h"

namespace contain::clip::solid {
namespace {

// The points found on each input edge, as flat sorted arrays (not a map of vectors: a node and
// a vector per edge): `keys` every edge some triangle with constraints has as a segment (even
// when no point was found on it, so that its triangles are not taken as plain), `points` the
// (edge, point) pairs, sorted and unique.
struct EdgePoints {
  std::vector<std::uint64_t> keys;
  std::vector<std::pair<std::uint64_t, std::int32_t>> points;

  [[nodiscard]] bool contains(std::uint64_t key) const {
    return std::binary_search(keys.begin(), keys.end(), key);
  }
  // The points on edge `key`, ascending.
  void append(std::uint64_t key, std::vector<std::int32_t>& out) const {
    auto it = std::lower_bound(points.begin(), points.end(),
                               std::pair{key, std::numeric_limits<std::int32_t>::min()});
    for (; it != points.end() && it->first == key; ++it)
      out.push_back(it->second);
  }
};

struct Local {
  std::array<std::int32_t, 3> corners{};
  Vec3 a{};
  const Soup* soup = nullptr;  // T's exact normal made only for `line_line` (few triangles)
  std::size_t triangle = 0;
  int axis = 2;
  Sign sense = Sign::positive;
  const PointStore* store = nullptr;

  [[nodiscard]] int orient(std::int32_t p, std::int32_t q, std::int32_t r) const {
    return to_int(sense) *
           to_int(orient2d_dropped(store->point(p), store->point(q), store->point(r), axis));
  }
  // Whether p lies in T (closed) and, when it does, on which of T's edges: bit i for the edge
  // from corner i to corner i + 1 (p on its line, hence, being in T, on the edge).
  [[nodiscard]] bool inside(std::int32_t p, std::uint8_t& on_edges) const {
    on_edges = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      const int o = orient(corners[i], corners[(i + 1) % 3], p);
      if (o < 0) return false;
      on_edges |= static_cast<std::uint8_t>(o == 0 ? 1U << i : 0U);
    }
    return true;
  }
};

struct Segment {
  std::int32_t a, b;
  std::uint64_t edge;
  bool own;  // one of T's edges
};

// The points of a triangle's arrangement (inside T, corners included), ascending, each with its
// bits of T's edges it lies on.
struct Arranged {
  std::vector<std::int32_t> points;
  std::vector<std::uint8_t> on_edges;

  void clear() {
    points.clear();
    on_edges.clear();
  }
  void push_back(std::int32_t p, std::uint8_t edges) {
    points.push_back(p);
    on_edges.push_back(edges);
  }
};

// Buffers kept from one triangle to the next (the refinement of most triangles allocated a
// dozen small vectors, each call).
struct Scratch {
  std::vector<Segment> segments;
  std::vector<std::int32_t> candidates;
  std::vector<std::int32_t> run;
  Arranged arranged;
  Arranged merged;
  std::vector<std::array<std::int32_t, 2>> all_pieces;  // T's edge pieces too
};

// The coordinate along which segment a b is ordered (one in which a and b differ) and the
// direction from a to b in it.
std::pair<int, Sign> order_of(const Local& l, std::int32_t a, std::int32_t b) {
  const PointStore& store = *l.store;
  int k = (l.axis + 1) % 3;
  if (compare_coordinate(store.point(a), store.point(b), k) == Sign::zero) k = (l.axis + 2) % 3;
  return {k, compare_coordinate(store.point(b), store.point(a), k)};
}

// `run` (distinct points of segment a b) sorted from a to b.
void sort_along(const Local& l, std::int32_t a, std::int32_t b, std::vector<std::int32_t>& run) {
  const PointStore& store = *l.store;
  const auto [k, dir] = order_of(l, a, b);
  std::sort(run.begin(), run.end(), [&, k = k, dir = dir](std::int32_t p, std::int32_t q) {
    return compare_coordinate(store.point(p), store.point(q), k) == dir;
  });
}

// Points of `candidates` (distinct, in T) on segment a b (ends included), sorted from a to b.
void on_segment(const Local& l, std::int32_t a, std::int32_t b,
                const std::vector<std::int32_t>& candidates, std::vector<std::int32_t>& out) {
  const PointStore& store = *l.store;
  const auto [k, dir] = order_of(l, a, b);
  out.clear();
  for (const std::int32_t p : candidates) {
    if (p == a || p == b) {
      out.push_back(p);
    } else if (l.orient(a, b, p) == 0 &&
               compare_coordinate(store.point(p), store.point(a), k) == dir &&
               compare_coordinate(store.point(b), store.point(p), k) == dir) {
      out.push_back(p);
    }
  }
  sort_along(l, a, b, out);
}

// The points of `arranged` on T's edge i (its ends included), sorted from its start.
void on_own_edge(const Local& l, const Arranged& arranged, std::size_t i,
                 std::vector<std::int32_t>& out) {
  out.clear();
  for (std::size_t j = 0; j < arranged.points.size(); ++j) {
    if ((arranged.on_edges[j] >> i) & 1U) out.push_back(arranged.points[j]);
  }
  sort_along(l, l.corners[i], l.corners[(i + 1) % 3], out);
}

// T's edges, then its constraints' segments not among them.
void segments_of(const Local& l, const TriangleWork& work, std::vector<Segment>& segments) {
  segments.clear();
  for (std::size_t i = 0; i < 3; ++i) {
    const std::int32_t a = l.corners[i], b = l.corners[(i + 1) % 3];
    segments.push_back({a, b, edge_key(a, b), true});
  }
  for (const Constraint& c : work.constraints) {
    if (c.a == c.b) continue;
    const bool seen = std::any_of(segments.begin(), segments.end(), [&](const Segment& s) {
      return (s.a == c.a && s.b == c.b) || (s.a == c.b && s.b == c.a);
    });
    if (!seen) segments.push_back({c.a, c.b, c.edge, false});
  }
}

// `candidates` sorted, unique, and those in T kept in `out` (ascending).
void keep_inside(const Local& l, std::vector<std::int32_t>& candidates, Arranged& out) {
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  out.clear();
  for (const std::int32_t p : candidates) {
    std::uint8_t edges = 0;
    if (l.inside(p, edges)) out.push_back(p, edges);
  }
}

// Whether point p lies in T's plane, by doubles that define it: every point of its hull on the
// plane, or for a crossing the three corners of its plane (a sufficient test only: false where
// neither shows it).
bool in_plane(const Local& l, const ExactPoint& p) {
  const Soup& soup = *l.soup;
  const Vec3 a = soup.vertices[static_cast<std::size_t>(l.corners[0])],
             b = soup.vertices[static_cast<std::size_t>(l.corners[1])],
             c = soup.vertices[static_cast<std::size_t>(l.corners[2])];
  const auto on = [&](Vec3 v) { return predicates::orient3d(a, b, c, v) == Sign::zero; };
  if (p.crossing && on(p.crossing->a) && on(p.crossing->b) && on(p.crossing->c)) return true;
  const Hull h = hull_of(p);
  if (h.size == 0) return false;
  for (std::size_t i = 0; i < h.size; ++i) {
    if (!on(h.points[i])) return false;
  }
  return true;
}

// The number of the point where segments s and t of T cross properly (strictly inside both).
// On inputs in common planes most such crossings are points already stored (a vertex, an edge's
// crossing with a plane, another triangle's crossing of the same lines), and their construction
// in big numbers, rounding and exact comparison with the stored point were a third of the
// refinement. So first, for each of the 27 triples of doubles within one step of the
// crossing's estimate in doubles, the first stored point with those nearest doubles is asked
// (only the first: later points of the same doubles are not walked, the store's exact lookup
// below finds them): one in T's plane (`in_plane`) on both lines is the crossing (the lines meet
// once, and the projection is one to one on T's plane), the number the store would give it.
// Otherwise it is constructed and stored as before.
std::int32_t crossing_of(const Local& l, const Segment& s, const Segment& t, PointStore& store) {
  const Vec3 sa = store.rounded(s.a), sb = store.rounded(s.b), ta = store.rounded(t.a),
             tb = store.rounded(t.b);
  const Vec2 ps = drop_axis(sa, l.axis), qs = drop_axis(sb, l.axis), pt = drop_axis(ta, l.axis),
             qt = drop_axis(tb, l.axis);
  const Vec2 ds = qs - ps, dt = qt - pt, w = pt - ps;
  const double den = ds.x * dt.y - ds.y * dt.x;
  const double lambda = (w.x * dt.y - w.y * dt.x) / den;
  if (std::isfinite(lambda)) {
    const Vec3 x = sa + (sb - sa) * lambda;
    const auto near = [](double v, int k) {
      return k < 0 ? next_down(v) : (k > 0 ? next_up(v) : v);
    };
    for (int i = 0; i < 27; ++i) {
      const Vec3 r{near(x.x, i % 3 - 1), near(x.y, (i / 3) % 3 - 1), near(x.z, i / 9 - 1)};
      const std::int32_t p = store.first_rounded_to(r);
      if (p >= 0 && p != s.a && p != s.b && p != t.a && p != t.b && in_plane(l, store.point(p)) &&
          l.orient(s.a, s.b, p) == 0 && l.orient(t.a, t.b, p) == 0) {
        return p;
      }
    }
  }
  return store.add(line_line(store.point(s.a), store.point(s.b), store.point(t.a), store.point(t.b),
                             l.a, l.soup->normal(l.triangle), l.axis, true));
}

// The points of T's own arrangement (before its neighbours' points are given): its corners, its
// constraints' ends, and the crossings of its segments (made and stored here, once per triangle
// and in the order of before: the store numbers them).
void arrange(const Local& l, const TriangleWork& work, PointStore& store, Scratch& scratch) {
  segments_of(l, work, scratch.segments);
  std::vector<std::int32_t>& points = scratch.candidates;
  points.assign(l.corners.begin(), l.corners.end());
  for (const Constraint& c : work.constraints) {
    points.push_back(c.a);
    points.push_back(c.b);
  }
  const std::vector<Segment>& segments = scratch.segments;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    for (std::size_t j = i + 1; j < segments.size(); ++j) {
      const Segment& s = segments[i];
      const Segment& t = segments[j];
      if (s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b) continue;
      if (l.orient(s.a, s.b, t.a) * l.orient(s.a, s.b, t.b) < 0 &&
          l.orient(t.a, t.b, s.a) * l.orient(t.a, t.b, s.b) < 0) {
        points.push_back(crossing_of(l, s, t, store));
      }
    }
  }
  keep_inside(l, points, scratch.arranged);
}

Local local_of(const Soup& soup, std::size_t t, const PointStore& store) {
  Local l;
  const TriangleIndices& v = soup.triangles[t];
  l.corners = {v[0], v[1], v[2]};
  l.a = soup.vertices[static_cast<std::size_t>(v[0])];
  l.soup = &soup;
  l.triangle = t;
  const Projection p = soup.projection(t);
  l.axis = p.axis;
  l.sense = p.sense;
  l.store = &store;
  return l;
}

// The own arrangements of the triangles with constraints, in triangle order, one after the
// other: made once, by the gathering pass, and completed by the refining pass with the points
// its neighbours give (the same points and pieces as arranging each triangle again).
struct OwnArrangements {
  std::vector<std::int32_t> points;
  std::vector<std::uint8_t> on_edges;
  std::vector<std::size_t> start{0};  // of each constrained triangle's points, and the end
};

// The points each input edge holds, from every triangle that has it as a segment; and each
// constrained triangle's own arrangement.
EdgePoints gather_edge_points(const Soup& soup, const PairWork& work, PointStore& store,
                              Scratch& scratch, OwnArrangements& own) {
  EdgePoints found;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    if (soup.degenerate[t] || work[t].constraints.empty()) continue;
    const Local l = local_of(soup, t, store);
    arrange(l, work[t], store, scratch);
    const Arranged& arranged = scratch.arranged;
    own.points.insert(own.points.end(), arranged.points.begin(), arranged.points.end());
    own.on_edges.insert(own.on_edges.end(), arranged.on_edges.begin(), arranged.on_edges.end());
    own.start.push_back(own.points.size());
    // T's own edges: the points on them are known from the test that kept them in T.
    for (std::size_t i = 0; i < 3; ++i) {
      const std::uint64_t key = edge_key(l.corners[i], l.corners[(i + 1) % 3]);
      found.keys.push_back(key);
      for (std::size_t j = 0; j < arranged.points.size(); ++j) {
        if ((arranged.on_edges[j] >> i) & 1U) found.points.emplace_back(key, arranged.points[j]);
      }
    }
    for (const Constraint& c : work[t].constraints) {
      if (c.edge == no_edge) continue;
      const auto a = static_cast<std::int32_t>(c.edge >> 32U);
      const auto b = static_cast<std::int32_t>(c.edge & 0xffffffffU);
      found.keys.push_back(c.edge);
      on_segment(l, a, b, arranged.points, scratch.run);
      for (const std::int32_t p : scratch.run)
        found.points.emplace_back(c.edge, p);
    }
  }
  std::sort(found.keys.begin(), found.keys.end());
  found.keys.erase(std::unique(found.keys.begin(), found.keys.end()), found.keys.end());
  std::sort(found.points.begin(), found.points.end());
  found.points.erase(std::unique(found.points.begin(), found.points.end()), found.points.end());
  return found;
}

// T's points once its neighbours' are given: its own arrangement (`own_begin` .. `own_end`,
// none for a triangle without constraints: then only its corners) and the points given on its
// segments that lie in T, ascending.
void complete(const Local& l, const EdgePoints& given, const OwnArrangements& own,
              std::size_t own_begin, std::size_t own_end, Scratch& scratch) {
  std::vector<std::int32_t>& extra = scratch.candidates;
  extra.clear();
  for (const Segment& s : scratch.segments) {
    if (s.edge != no_edge) given.append(s.edge, extra);
  }
  Arranged& base = scratch.arranged;
  base.clear();
  if (own_begin == own_end) {
    // No constraints: its corners, each on its two edges.
    std::array<std::pair<std::int32_t, std::uint8_t>, 3> corners{
        {{l.corners[0], 0b101}, {l.corners[1], 0b011}, {l.corners[2], 0b110}}};
    std::sort(corners.begin(), corners.end());
    for (const auto& [p, edges] : corners)
      base.push_back(p, edges);
  } else {
    base.points.assign(own.points.begin() + static_cast<std::ptrdiff_t>(own_begin),
                       own.points.begin() + static_cast<std::ptrdiff_t>(own_end));
    base.on_edges.assign(own.on_edges.begin() + static_cast<std::ptrdiff_t>(own_begin),
                         own.on_edges.begin() + static_cast<std::ptrdiff_t>(own_end));
  }
  std::sort(extra.begin(), extra.end());
  extra.erase(std::unique(extra.begin(), extra.end()), extra.end());
  // Merge the given points not already there (tested for T) into the ascending list.
  Arranged& out = scratch.merged;
  out.clear();
  std::size_t i = 0;
  for (const std::int32_t p : extra) {
    while (i < base.points.size() && base.points[i] < p) {
      out.push_back(base.points[i], base.on_edges[i]);
      ++i;
    }
    if (i < base.points.size() && base.points[i] == p) continue;
    std::uint8_t edges = 0;
    if (l.inside(p, edges)) out.push_back(p, edges);
  }
  for (; i < base.points.size(); ++i)
    out.push_back(base.points[i], base.on_edges[i]);
}

}  // namespace

Refinement refine(const Soup& soup, const PairWork& work, PointStore& store) {
  Scratch scratch;
  OwnArrangements own;
  const EdgePoints given = gather_edge_points(soup, work, store, scratch, own);
  // The vertices of the edges given points: a triangle with fewer than two of them as corners
  // has none of those edges (no search of `given` for it).
  std::vector<bool> on_given(soup.vertices.size(), false);
  for (const std::uint64_t key : given.keys) {
    on_given[static_cast<std::size_t>(key >> 32U)] = true;
    on_given[static_cast<std::size_t>(key & 0xffffffffU)] = true;
  }
  const auto given_edge = [&](std::int32_t a, std::int32_t b) {
    return on_given[static_cast<std::size_t>(a)] && on_given[static_cast<std::size_t>(b)] &&
           given.contains(edge_key(a, b));
  };
  Refinement out;
  // Every triangle gives a face, a split one about two more per point it gains (one growth by
  // doubling copied the whole array).
  out.faces.reserve(soup.triangles.size() + 2 * own.points.size() + 64);
  std::size_t constrained = 0;  // constrained triangles before t
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    if (soup.degenerate[t]) continue;
    const TriangleIndices& v = soup.triangles[t];
    const bool has_constraints = !work[t].constraints.empty();
    const bool plain = !has_constraints && !given_edge(v[0], v[1]) && !given_edge(v[1], v[2]) &&
                       !given_edge(v[2], v[0]);
    if (plain) {
      out.faces.push_back({{v[0], v[1], v[2]}, static_cast<std::int32_t>(t)});
      continue;
    }
    const Local l = local_of(soup, t, store);
    segments_of(l, work[t], scratch.segments);
    std::size_t own_begin = 0, own_end = 0;
    if (has_constraints) {
      own_begin = own.start[constrained];
      own_end = own.start[constrained + 1];
      ++constrained;
    }
    complete(l, given, own, own_begin, own_end, scratch);
    const Arranged& arranged = scratch.merged;
    if (arranged.points.size() == 3) {
      out.faces.push_back({l.corners, static_cast<std::int32_t>(t)});
      continue;
    }
    scratch.all_pieces.clear();
    for (std::size_t i = 0; i < scratch.segments.size(); ++i) {
      const Segment& s = scratch.segments[i];
      if (s.own) {
        on_own_edge(l, arranged, i, scratch.run);
      } else {
        on_segment(l, s.a, s.b, arranged.points, scratch.run);
      }
      for (std::size_t j = 1; j < scratch.run.size(); ++j) {
        scratch.all_pieces.push_back({scratch.run[j - 1], scratch.run[j]});
        if (!s.own) out.curve_edges.push_back(edge_key(scratch.run[j - 1], scratch.run[j]));
      }
    }
    for (const auto& f :
         triangulate(l.corners, arranged.points, scratch.all_pieces, store, l.axis, l.sense)) {
      out.faces.push_back({f, static_cast<std::int32_t>(t)});
    }
  }
  std::sort(out.curve_edges.begin(), out.curve_edges.end());
  out.curve_edges.erase(std::unique(out.curve_edges.begin(), out.curve_edges.end()),
                        out.curve_edges.end());
  return out;
}

}  // namespace contain::clip::solid
