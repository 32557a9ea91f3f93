#include "contain/inside/point_in_triangle.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "contain/predicates/cross_dot.h"
#include "contain/predicates/orient2d.h"

namespace contain::inside {
namespace {

// Projection dropping coordinate `axis` (0: x, 1: y, 2: z), keeping a right-handed pair so that
// orientation along +axis is preserved: (y, z), (z, x), (x, y).
Vec2 drop(Vec3 p, int axis) {
  switch (axis) {
    case 0:
      return {p.y, p.z};
    case 1:
      return {p.z, p.x};
    default:
      return {p.x, p.y};
  }
}

double coord(Vec3 p, int axis) {
  return axis == 0 ? p.x : (axis == 1 ? p.y : p.z);
}

// Three points in space are collinear iff all three coordinate projections are collinear.
bool collinear(Vec3 a, Vec3 b, Vec3 c) {
  for (int axis = 0; axis < 3; ++axis) {
    if (predicates::orient2d(drop(a, axis), drop(b, axis), drop(c, axis)) != Sign::zero) {
      return false;
    }
  }
  return true;
}

// p on the closed segment ab (possibly a == b): collinear and inside the bounding box.
bool on_segment(Vec3 a, Vec3 b, Vec3 p) {
  if (!collinear(a, b, p)) return false;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = std::min(coord(a, axis), coord(b, axis));
    const double hi = std::max(coord(a, axis), coord(b, axis));
    if (coord(p, axis) < lo || coord(p, axis) > hi) return false;
  }
  return true;
}

// A degenerate triangle is the segment between its two farthest vertices, i.e. the union of its
// three edges (one of which contains the others).
Location in_degenerate(const Triangle3& t, Vec3 p) {
  const bool on = on_segment(t.a, t.b, p) || on_segment(t.b, t.c, p) || on_segment(t.c, t.a, p);
  return on ? Location::boundary : Location::outside;
}

// Combines three edge signs, each positive when p is on the inner side of the edge.
Location combine(Sign s0, Sign s1, Sign s2) {
  if (s0 == Sign::negative || s1 == Sign::negative || s2 == Sign::negative) {
    return Location::outside;
  }
  if (s0 == Sign::zero || s1 == Sign::zero || s2 == Sign::zero) return Location::boundary;
  return Location::inside;
}

Location same_side(const Triangle3& t, Vec3 p) {
  return combine(predicates::cross_dot(t.a, t.b, p, t.c), predicates::cross_dot(t.b, t.c, p, t.a),
                 predicates::cross_dot(t.c, t.a, p, t.b));
}

Location projected(const Triangle3& t, Vec3 p) {
  // Axes by decreasing |normal component| (floating point: only a preference, see the header).
  const Vec3 n = t.normal();
  std::array<int, 3> order{2, 0, 1};
  const std::array<double, 3> size{std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)};
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) {
    return size[static_cast<std::size_t>(i)] > size[static_cast<std::size_t>(j)];
  });
  for (int axis : order) {
    Vec2 a = drop(t.a, axis), b = drop(t.b, axis), c = drop(t.c, axis);
    const Sign turn = predicates::orient2d(a, b, c);
    if (turn == Sign::zero) continue;  // degenerate along this axis: try the next one
    // The book's exchange of two vertices (§ 22.4) so that the third is left of the first edge.
    if (turn == Sign::negative) std::swap(b, c);
    const Vec2 q = drop(p, axis);
    return combine(predicates::orient2d(a, b, q), predicates::orient2d(b, c, q),
                   predicates::orient2d(c, a, q));
  }
  return in_degenerate(t, p);  // not reached: a proper triangle has a proper projection
}

}  // namespace

Location point_in_triangle(const Triangle3& triangle, Vec3 p,
                           const PointInTriangleOptions& options) {
  if (collinear(triangle.a, triangle.b, triangle.c)) return in_degenerate(triangle, p);
  switch (options.method) {
    case TriangleMethod::same_side:
      return same_side(triangle, p);
    case TriangleMethod::projected:
      break;
  }
  return projected(triangle, p);
}

}  // namespace contain::inside
