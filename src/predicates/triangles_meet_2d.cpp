#include "contain/predicates/triangles_meet_2d.h"

#include <algorithm>

#include "contain/predicates/orient2d.h"
#include "predicates/simplex.h"

namespace contain::predicates {
namespace {

using Simplex2 = detail::Simplex<Vec2>;

bool point_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  if (orient2d(a, b, p) != Sign::zero) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// p in the closed counter-clockwise triangle t.
bool point_in_ccw(Vec2 p, const std::array<Vec2, 3>& t) {
  return orient2d(t[0], t[1], p) != Sign::negative && orient2d(t[1], t[2], p) != Sign::negative &&
         orient2d(t[2], t[0], p) != Sign::negative;
}

// Some edge line of the counter-clockwise triangle t has all of `others` strictly on its right.
bool separated_by_edge(const std::array<Vec2, 3>& t, const Vec2* others, int count) {
  for (int e = 0; e < 3; ++e) {
    const Vec2 u = t[static_cast<std::size_t>(e)];
    const Vec2 v = t[static_cast<std::size_t>((e + 1) % 3)];
    bool all_right = true;
    for (int k = 0; k < count && all_right; ++k) {
      all_right = orient2d(u, v, others[k]) == Sign::negative;
    }
    if (all_right) return true;
  }
  return false;
}

Simplex2 simplex_of(const Triangle2& t) {
  const Sign o = orient2d(t.a, t.b, t.c);
  if (o == Sign::positive) return {2, {t.a, t.b, t.c}};
  if (o == Sign::negative) return {2, {t.a, t.c, t.b}};
  return detail::collinear_simplex(t.a, t.b, t.c);
}

bool simplices_intersect(const Simplex2& s, const Simplex2& t) {
  if (s.dim < t.dim) return simplices_intersect(t, s);
  switch (s.dim * 3 + t.dim) {
    case 8:  // triangle, triangle
      return !separated_by_edge(s.p, t.p.data(), 3) && !separated_by_edge(t.p, s.p.data(), 3);
    case 7:  // triangle, segment
      if (point_in_ccw(t.p[0], s.p) || point_in_ccw(t.p[1], s.p)) return true;
      for (int e = 0; e < 3; ++e) {
        if (segments_meet(
                {s.p[static_cast<std::size_t>(e)], s.p[static_cast<std::size_t>((e + 1) % 3)]},
                {t.p[0], t.p[1]})) {
          return true;
        }
      }
      return false;
    case 6:  // triangle, point
      return point_in_ccw(t.p[0], s.p);
    case 4:  // segment, segment
      return segments_meet({s.p[0], s.p[1]}, {t.p[0], t.p[1]});
    case 3:  // segment, point
      return point_on_segment(t.p[0], s.p[0], s.p[1]);
    default:  // point, point
      return s.p[0] == t.p[0];
  }
}

}  // namespace

bool segments_meet(const Segment2& a, const Segment2& b) {
  if (a.a == a.b) return point_on_segment(a.a, b.a, b.b);
  if (b.a == b.b) return point_on_segment(b.a, a.a, a.b);
  const Sign o1 = orient2d(a.a, a.b, b.a), o2 = orient2d(a.a, a.b, b.b);
  if (o1 != Sign::zero && o1 == o2) return false;
  const Sign o3 = orient2d(b.a, b.b, a.a), o4 = orient2d(b.a, b.b, a.b);
  if (o3 != Sign::zero && o3 == o4) return false;
  if (o1 == Sign::zero && o2 == Sign::zero) {
    // Collinear: on a common line the closed boxes overlap iff the segments do.
    return std::max(std::min(a.a.x, a.b.x), std::min(b.a.x, b.b.x)) <=
               std::min(std::max(a.a.x, a.b.x), std::max(b.a.x, b.b.x)) &&
           std::max(std::min(a.a.y, a.b.y), std::min(b.a.y, b.b.y)) <=
               std::min(std::max(a.a.y, a.b.y), std::max(b.a.y, b.b.y));
  }
  // Not collinear, and each segment has its endpoints on both sides of (or on) the other's line:
  // the lines meet in one point, which lies on both segments.
  return true;
}

bool triangles_meet(const Triangle2& a, const Triangle2& b) {
  return simplices_intersect(simplex_of(a), simplex_of(b));
}

}  // namespace contain::predicates
