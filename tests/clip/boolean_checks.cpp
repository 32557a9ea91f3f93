#include "clip/boolean_checks.h"

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "contain/inside/point_in_polygon.h"
#include "contain/predicates/orient2d.h"
#include "support/exact.h"

namespace contain::test {
namespace {

using predicates::orient2d;

mpq_class ring_area2(const Ring& ring) {
  mpq_class sum = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const QVec2 a = exact(ring[i]), b = exact(ring[(i + 1) % ring.size()]);
    sum += a.x * b.y - a.y * b.x;
  }
  return sum;
}

bool lex_less(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

struct Edge {
  Vec2 a, b;
};

// Where the midpoint of a -> b lies with respect to the ring `of`, in rationals: a rounded
// midpoint lands on the wrong side of thin rings whose coordinates span 2^+-500 (a vertex at
// 1e163 beside vertices of size 10: fuzz_polygon_boolean).
Location midpoint_side(Vec2 a, Vec2 b, const Ring& of) {
  const QVec2 qa = exact(a), qb = exact(b);
  const mpq_class mx = (qa.x + qb.x) / 2, my = (qa.y + qb.y) / 2;
  bool in = false;
  for (std::size_t i = 0; i < of.size(); ++i) {
    const QVec2 u = exact(of[i]), v = exact(of[(i + 1) % of.size()]);
    const mpq_class cross = (v.x - u.x) * (my - u.y) - (v.y - u.y) * (mx - u.x);
    if (cross == 0 && std::min(u.x, v.x) <= mx && mx <= std::max(u.x, v.x) &&
        std::min(u.y, v.y) <= my && my <= std::max(u.y, v.y)) {
      return Location::boundary;
    }
    // Half-open crossing rule on the ray towards +x: u -> v upwards crosses it right of the
    // midpoint when the midpoint is left of u -> v.
    if ((u.y > my) != (v.y > my) && (cross > 0) == (v.y > u.y)) in = !in;
  }
  return in ? Location::inside : Location::outside;
}

// Segments that meet anywhere other than one shared endpoint.
bool bad_pair(const Edge& p, const Edge& q) {
  if (std::max(p.a.x, p.b.x) < std::min(q.a.x, q.b.x) ||
      std::max(q.a.x, q.b.x) < std::min(p.a.x, p.b.x) ||
      std::max(p.a.y, p.b.y) < std::min(q.a.y, q.b.y) ||
      std::max(q.a.y, q.b.y) < std::min(p.a.y, p.b.y)) {
    return false;
  }
  const Sign o1 = orient2d(p.a, p.b, q.a), o2 = orient2d(p.a, p.b, q.b);
  const Sign o3 = orient2d(q.a, q.b, p.a), o4 = orient2d(q.a, q.b, p.b);
  if ((o1 == o2 && o1 != Sign::zero) || (o3 == o4 && o3 != Sign::zero)) return false;
  const int shared = (p.a == q.a || p.a == q.b ? 1 : 0) + (p.b == q.a || p.b == q.b ? 1 : 0);
  if (o1 == Sign::zero && o2 == Sign::zero) {
    // Collinear with overlapping boxes: fine only when they share exactly one endpoint and
    // lie on opposite sides of it.
    if (shared != 1) return true;
    const Vec2 s = (p.a == q.a || p.a == q.b) ? p.a : p.b;
    const Vec2 po = s == p.a ? p.b : p.a, qo = s == q.a ? q.b : q.a;
    return lex_less(s, po) == lex_less(s, qo);
  }
  // Not parallel: they meet in one point; fine if it is a shared endpoint.
  return shared == 0;
}

}  // namespace

mpq_class exact_signed_area(const MultiPolygon& region) {
  mpq_class sum = 0;
  for (const Polygon& p : region.polygons) {
    for (const Ring& r : p.rings)
      sum += ring_area2(r);
  }
  return sum / 2;
}

::testing::AssertionResult is_valid_ogc(const MultiPolygon& region) {
  std::vector<Edge> edges;
  for (std::size_t pi = 0; pi < region.polygons.size(); ++pi) {
    const Polygon& polygon = region.polygons[pi];
    if (polygon.rings.empty()) return ::testing::AssertionFailure() << "polygon without rings";
    for (std::size_t ri = 0; ri < polygon.rings.size(); ++ri) {
      const Ring& ring = polygon.rings[ri];
      const std::string where = "polygon " + std::to_string(pi) + " ring " + std::to_string(ri);
      if (ring.size() < 3) return ::testing::AssertionFailure() << where << ": < 3 vertices";
      std::set<std::pair<double, double>> seen;
      for (const Vec2 v : ring) {
        if (!seen.insert({v.x, v.y}).second) {
          return ::testing::AssertionFailure()
                 << where << ": repeated vertex " << v.x << " " << v.y;
        }
      }
      const int s = sgn(ring_area2(ring));
      if (ri == 0 && s <= 0) return ::testing::AssertionFailure() << where << ": shell not CCW";
      if (ri > 0 && s >= 0) return ::testing::AssertionFailure() << where << ": hole not CW";
      for (std::size_t i = 0; i < ring.size(); ++i) {
        edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
      }
    }
  }
  std::vector<std::size_t> order(edges.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t l, std::size_t r) {
    return std::min(edges[l].a.x, edges[l].b.x) < std::min(edges[r].a.x, edges[r].b.x);
  });
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Edge& p = edges[order[i]];
    const double xmax = std::max(p.a.x, p.b.x);
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      const Edge& q = edges[order[j]];
      if (std::min(q.a.x, q.b.x) > xmax) break;
      if (bad_pair(p, q)) {
        return ::testing::AssertionFailure()
               << "edges meet improperly: (" << p.a.x << " " << p.a.y << ")-(" << p.b.x << " "
               << p.b.y << ") and (" << q.a.x << " " << q.a.y << ")-(" << q.b.x << " " << q.b.y
               << ")";
      }
    }
  }
  // Holes inside their shell; shells outside every other polygon. Rings meet at most in
  // vertices, so one vertex off the other ring decides.
  auto side = [](const Ring& ring, const Ring& of) {
    for (const Vec2 v : ring) {
      const Location l = inside::point_in_polygon(std::span<const Ring>(&of, 1), v);
      if (l != Location::boundary) return l;
    }
    // Every vertex on the other ring: an edge's midpoint, exactly.
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Location l = midpoint_side(ring[i], ring[(i + 1) % ring.size()], of);
      if (l != Location::boundary) return l;
    }
    return Location::boundary;
  };
  std::vector<Box2> boxes;
  for (const Polygon& p : region.polygons) {
    boxes.push_back(bounding_box(std::span<const Ring>(p.rings.data(), 1)));
  }
  for (std::size_t pi = 0; pi < region.polygons.size(); ++pi) {
    const Polygon& polygon = region.polygons[pi];
    for (std::size_t ri = 1; ri < polygon.rings.size(); ++ri) {
      if (side(polygon.rings[ri], polygon.rings[0]) == Location::outside) {
        return ::testing::AssertionFailure()
               << "hole " << ri << " of polygon " << pi << " outside its shell";
      }
    }
    const Box2& box = boxes[pi];
    for (std::size_t pj = 0; pj < region.polygons.size(); ++pj) {
      if (pj == pi) continue;
      const Box2& other = boxes[pj];
      if (box.min.x < other.min.x || box.min.y < other.min.y || box.max.x > other.max.x ||
          box.max.y > other.max.y) {
        continue;  // not within the other's box, so not inside it
      }
      const Location l = side(polygon.rings[0], region.polygons[pj].rings[0]);
      if (l != Location::inside) continue;
      // Inside the other shell: must be inside one of its holes.
      bool in_hole = false;
      for (std::size_t h = 1; h < region.polygons[pj].rings.size(); ++h) {
        if (side(polygon.rings[0], region.polygons[pj].rings[h]) == Location::inside) {
          in_hole = true;
        }
      }
      if (!in_hole) {
        return ::testing::AssertionFailure() << "polygon " << pi << " lies inside polygon " << pj;
      }
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace contain::test
