#include "inside/polygon_oracle.h"

#include <gmpxx.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "support/exact.h"

namespace contain::test {

namespace {

struct QEdge {
  QVec2 a, b;
};

std::vector<QEdge> exact_edges(std::span<const Ring> rings) {
  std::vector<QEdge> edges;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      edges.push_back({exact(ring[i]), exact(ring[(i + 1) % ring.size()])});
    }
  }
  return edges;
}

mpq_class cross(const QVec2& u, const QVec2& v) {
  return u.x * v.y - u.y * v.x;
}
mpq_class dot(const QVec2& u, const QVec2& v) {
  return u.x * v.x + u.y * v.y;
}
QVec2 sub(const QVec2& u, const QVec2& v) {
  return {u.x - v.x, u.y - v.y};
}

bool on_segment(const QEdge& e, const QVec2& q) {
  if (cross(sub(e.b, e.a), sub(q, e.a)) != 0) return false;
  return std::min(e.a.x, e.b.x) <= q.x && q.x <= std::max(e.a.x, e.b.x) &&
         std::min(e.a.y, e.b.y) <= q.y && q.y <= std::max(e.a.y, e.b.y);
}

// Winding number at q on no edge: crossings of the ray to +x, at exact rational abscissae.
int winding_at(const std::vector<QEdge>& edges, const QVec2& q) {
  int w = 0;
  for (const QEdge& e : edges) {
    if ((e.a.y <= q.y) == (e.b.y <= q.y)) continue;
    const mpq_class x = e.a.x + (q.y - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y);
    if (x > q.x) w += e.b.y > e.a.y ? 1 : -1;
  }
  return w;
}

mpq_class l1(const QVec2& u) {
  return abs(u.x) + abs(u.y);
}

}  // namespace

bool oracle_on_edge(std::span<const Ring> rings, Vec2 p) {
  const QVec2 q = exact(p);
  for (const QEdge& e : exact_edges(rings)) {
    if (on_segment(e, q)) return true;
  }
  return false;
}

int oracle_winding_number(std::span<const Ring> rings, Vec2 p) {
  return winding_at(exact_edges(rings), exact(p));
}

Location oracle_point_in_polygon(std::span<const Ring> rings, Vec2 p, Fill fill) {
  const std::vector<QEdge> edges = exact_edges(rings);
  const QVec2 q = exact(p);
  std::vector<QVec2> dirs;  // directions of the edges leaving p
  std::vector<const QEdge*> others;
  for (const QEdge& e : edges) {
    if (!on_segment(e, q)) {
      others.push_back(&e);
      continue;
    }
    if (e.a.x == e.b.x && e.a.y == e.b.y) continue;
    for (const QVec2* end : {&e.a, &e.b}) {
      if (end->x != q.x || end->y != q.y) dirs.push_back(sub(*end, q));
    }
  }
  if (dirs.empty()) {
    return is_filled(fill, winding_at(edges, q)) ? Location::inside : Location::outside;
  }
  // Distinct directions in angular order.
  auto upper = [](const QVec2& d) { return d.y > 0 || (d.y == 0 && d.x > 0); };
  std::sort(dirs.begin(), dirs.end(), [&](const QVec2& u, const QVec2& v) {
    if (upper(u) != upper(v)) return upper(u);
    return cross(u, v) > 0;
  });
  std::vector<QVec2> distinct;
  for (const QVec2& d : dirs) {
    if (!distinct.empty() && upper(distinct.back()) == upper(d) && cross(distinct.back(), d) == 0) {
      continue;
    }
    distinct.push_back(d);
  }
  bool any_filled = false, any_empty = false;
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    const QVec2& d1 = distinct[i];
    const QVec2& d2 = distinct[(i + 1) % distinct.size()];
    const mpq_class c = cross(d1, d2);
    const QVec2 n1{d1.x / l1(d1), d1.y / l1(d1)}, n2{d2.x / l1(d2), d2.y / l1(d2)};
    QVec2 u;
    if (c > 0) {
      u = {n1.x + n2.x, n1.y + n2.y};
    } else if (c < 0) {
      u = {-(n1.x + n2.x), -(n1.y + n2.y)};
    } else {
      u = {-d1.y, d1.x};  // opposite directions, or a single one: a quarter turn from d1
    }
    // Step along u less than the distance to the first other edge.
    std::optional<mpq_class> first;
    for (const QEdge* e : others) {
      const QVec2 ab = sub(e->b, e->a), ap = sub(e->a, q);
      const mpq_class den = cross(u, ab);
      if (den == 0) {
        if (cross(ap, u) != 0) continue;
        for (const QVec2* end : {&e->a, &e->b}) {
          const mpq_class s = dot(sub(*end, q), u) / dot(u, u);
          if (s > 0 && (!first || s < *first)) first = s;
        }
        continue;
      }
      const mpq_class s = cross(ap, ab) / den;
      const mpq_class r = cross(ap, u) / den;
      if (r >= 0 && r <= 1 && s > 0 && (!first || s < *first)) first = s;
    }
    const mpq_class t = first ? mpq_class(*first / 2) : mpq_class(1);
    const QVec2 sample{q.x + t * u.x, q.y + t * u.y};
    if (is_filled(fill, winding_at(edges, sample))) {
      any_filled = true;
    } else {
      any_empty = true;
    }
  }
  if (any_filled && any_empty) return Location::boundary;
  return any_filled ? Location::inside : Location::outside;
}

}  // namespace contain::test
