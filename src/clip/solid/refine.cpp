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

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"

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
  [[nodiscard]] bool inside(std::int32_t p) const {
    return orient(corners[0], corners[1], p) >= 0 && orient(corners[1], corners[2], p) >= 0 &&
           orient(corners[2], corners[0], p) >= 0;
  }
};

struct Arranged {
  std::vector<std::int32_t> points;                     // inside T, corners included
  std::vector<std::array<std::int32_t, 2>> pieces;      // constraint pieces (not T's edges)
  std::vector<std::array<std::int32_t, 2>> all_pieces;  // T's edge pieces too
};

// Points of `candidates` on segment a b (ends included), sorted from a to b.
std::vector<std::int32_t> on_segment(const Local& l, std::int32_t a, std::int32_t b,
                                     const std::vector<std::int32_t>& candidates) {
  const PointStore& store = *l.store;
  int k = (l.axis + 1) % 3;
  if (compare_coordinate(store.point(a), store.point(b), k) == Sign::zero) k = (l.axis + 2) % 3;
  const Sign dir = compare_coordinate(store.point(b), store.point(a), k);
  std::vector<std::int32_t> out;
  for (const std::int32_t p : candidates) {
    if (p == a || p == b) {
      out.push_back(p);
    } else if (l.orient(a, b, p) == 0 &&
               compare_coordinate(store.point(p), store.point(a), k) == dir &&
               compare_coordinate(store.point(b), store.point(p), k) == dir) {
      out.push_back(p);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  std::sort(out.begin(), out.end(), [&](std::int32_t p, std::int32_t q) {
    return compare_coordinate(store.point(p), store.point(q), k) == dir;
  });
  return out;
}

struct Segment {
  std::int32_t a, b;
  std::uint64_t edge;
  bool own;  // one of T's edges
};

Arranged arrange(const Local& l, const TriangleWork& work, const EdgePoints& given,
                 PointStore& store) {
  std::vector<Segment> segments;
  std::vector<std::int32_t> points(l.corners.begin(), l.corners.end());
  for (int i = 0; i < 3; ++i) {
    const std::int32_t a = l.corners[static_cast<std::size_t>(i)],
                       b = l.corners[static_cast<std::size_t>((i + 1) % 3)];
    segments.push_back({a, b, edge_key(a, b), true});
  }
  for (const Constraint& c : work.constraints) {
    points.push_back(c.a);
    points.push_back(c.b);
    if (c.a == c.b) continue;
    const bool seen = std::any_of(segments.begin(), segments.end(), [&](const Segment& s) {
      return (s.a == c.a && s.b == c.b) || (s.a == c.b && s.b == c.a);
    });
    if (!seen) segments.push_back({c.a, c.b, c.edge, false});
  }
  for (const Segment& s : segments) {
    if (s.edge == no_edge) continue;
    given.append(s.edge, points);
  }
  for (std::size_t i = 0; i < segments.size(); ++i) {
    for (std::size_t j = i + 1; j < segments.size(); ++j) {
      const Segment& s = segments[i];
      const Segment& t = segments[j];
      if (s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b) continue;
      if (l.orient(s.a, s.b, t.a) * l.orient(s.a, s.b, t.b) < 0 &&
          l.orient(t.a, t.b, s.a) * l.orient(t.a, t.b, s.b) < 0) {
        points.push_back(
            store.add(line_line(store.point(s.a), store.point(s.b), store.point(t.a),
                                store.point(t.b), l.a, l.soup->normal(l.triangle), l.axis)));
      }
    }
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  Arranged out;
  for (const std::int32_t p : points) {
    if (l.inside(p)) out.points.push_back(p);
  }
  for (const Segment& s : segments) {
    const std::vector<std::int32_t> run = on_segment(l, s.a, s.b, out.points);
    for (std::size_t i = 1; i < run.size(); ++i) {
      out.all_pieces.push_back({run[i - 1], run[i]});
      if (!s.own) out.pieces.push_back({run[i - 1], run[i]});
    }
  }
  return out;
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

// The points each input edge holds, from every triangle that has it as a segment.
EdgePoints gather_edge_points(const Soup& soup, const std::vector<TriangleWork>& work,
                              PointStore& store) {
  EdgePoints found;
  const EdgePoints none;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    if (soup.degenerate[t] || work[t].constraints.empty()) continue;
    const Local l = local_of(soup, t, store);
    const Arranged arranged = arrange(l, work[t], none, store);
    std::vector<std::uint64_t> keys;
    for (int i = 0; i < 3; ++i) {
      keys.push_back(edge_key(l.corners[static_cast<std::size_t>(i)],
                              l.corners[static_cast<std::size_t>((i + 1) % 3)]));
    }
    for (const Constraint& c : work[t].constraints) {
      if (c.edge != no_edge) keys.push_back(c.edge);
    }
    for (const std::uint64_t key : keys) {
      const auto a = static_cast<std::int32_t>(key >> 32U);
      const auto b = static_cast<std::int32_t>(key & 0xffffffffU);
      found.keys.push_back(key);
      for (const std::int32_t p : on_segment(l, a, b, arranged.points))
        found.points.emplace_back(key, p);
    }
  }
  std::sort(found.keys.begin(), found.keys.end());
  found.keys.erase(std::unique(found.keys.begin(), found.keys.end()), found.keys.end());
  std::sort(found.points.begin(), found.points.end());
  found.points.erase(std::unique(found.points.begin(), found.points.end()), found.points.end());
  return found;
}

}  // namespace

Refinement refine(const Soup& soup, const std::vector<TriangleWork>& work, PointStore& store) {
  const EdgePoints given = gather_edge_points(soup, work, store);
  Refinement out;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    if (soup.degenerate[t]) continue;
    const TriangleIndices& v = soup.triangles[t];
    const bool plain = work[t].constraints.empty() && !given.contains(edge_key(v[0], v[1])) &&
                       !given.contains(edge_key(v[1], v[2])) &&
                       !given.contains(edge_key(v[2], v[0]));
    if (plain) {
      out.faces.push_back({{v[0], v[1], v[2]}, static_cast<std::int32_t>(t)});
      continue;
    }
    const Local l = local_of(soup, t, store);
    const Arranged arranged = arrange(l, work[t], given, store);
    if (arranged.points.size() == 3) {
      out.faces.push_back({l.corners, static_cast<std::int32_t>(t)});
      continue;
    }
    for (const auto& piece : arranged.pieces)
      out.curve_edges.push_back(edge_key(piece[0], piece[1]));
    for (const auto& f :
         triangulate(l.corners, arranged.points, arranged.all_pieces, store, l.axis, l.sense)) {
      out.faces.push_back({f, static_cast<std::int32_t>(t)});
    }
  }
  std::sort(out.curve_edges.begin(), out.curve_edges.end());
  out.curve_edges.erase(std::unique(out.curve_edges.begin(), out.curve_edges.end()),
                        out.curve_edges.end());
  return out;
}

}  // namespace contain::clip::solid
