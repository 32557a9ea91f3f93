#include "contain/predicates/triangles_meet.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "contain/predicates/orient3d_set.h"
#include "contain/predicates/triangles_meet_2d.h"
#include "predicates/simplex.h"

namespace contain::predicates {
namespace {

using Simplex3 = detail::Simplex<Vec3>;

// The projection that drops coordinate k (0: x, 1: y, 2: z). On a plane whose normal has a
// non-zero k component it is an affine bijection onto the coordinate plane, so incidences
// (shared points, points on edges) are the same before and after.
Vec2 drop(Vec3 p, int k) {
  if (k == 0) return {p.y, p.z};
  if (k == 1) return {p.z, p.x};
  return {p.x, p.y};
}

// An axis whose projection of the triangle has exactly non-zero area, or -1 (collinear).
int proper_axis(Vec3 a, Vec3 b, Vec3 c) {
  for (int k = 2; k >= 0; --k) {
    if (orient2d(drop(a, k), drop(b, k), drop(c, k)) != Sign::zero) return k;
  }
  return -1;
}

Simplex3 simplex_of(const Triangle3& t, int& axis) {
  axis = proper_axis(t.a, t.b, t.c);
  if (axis >= 0) return {2, {t.a, t.b, t.c}};
  return detail::collinear_simplex(t.a, t.b, t.c);
}

bool collinear3(Vec3 a, Vec3 b, Vec3 c) {
  return proper_axis(a, b, c) < 0;
}

bool point_on_segment3(Vec3 p, Vec3 a, Vec3 b) {
  if (!collinear3(a, b, p)) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y) && std::min(a.z, b.z) <= p.z && p.z <= std::max(a.z, b.z);
}

// Closed segments of non-zero length in space.
bool segments_intersect3(Vec3 s0, Vec3 s1, Vec3 t0, Vec3 t1) {
  if (orient3d(s0, s1, t0, t1) != Sign::zero) return false;
  // Coplanar: find a projection that is injective on their affine hull.
  int k = proper_axis(s0, s1, t0);
  if (k < 0) k = proper_axis(s0, s1, t1);
  if (k < 0) {
    // All four collinear: any axis along which s0 and s1 stay apart.
    for (k = 2; k > 0 && drop(s0, k) == drop(s1, k); --k) {
    }
  }
  return segments_meet({drop(s0, k), drop(s1, k)}, {drop(t0, k), drop(t1, k)});
}

// The segment (s0, s1) in the plane of the triangle (a, b, c), whose projection along `axis` is
// proper: the 2D test there (the projection is one to one on that plane).
bool segment_in_plane_meets(Vec3 s0, Vec3 s1, Vec3 a, Vec3 b, Vec3 c, int axis) {
  const Vec2 p = drop(s0, axis), q = drop(s1, axis);
  return triangles_meet(Triangle2{drop(a, axis), drop(b, axis), drop(c, axis)}, Triangle2{p, q, q});
}

// The segment (s0, s1) with its ends on opposite sides of the plane of (a, b, c), or one end on
// it: the point where it meets the plane is in the closed face iff the tetrahedra (s0, s1, edge)
// have no two opposite signs (the line through s0 and s1 passes on the inner side of, or
// through, every edge).
bool crossing_in_face(Vec3 s0, Vec3 s1, Vec3 a, Vec3 b, Vec3 c) {
  const Sign e0 = orient3d(s0, s1, a, b), e1 = orient3d(s0, s1, b, c), e2 = orient3d(s0, s1, c, a);
  const bool any_pos = e0 == Sign::positive || e1 == Sign::positive || e2 == Sign::positive;
  const bool any_neg = e0 == Sign::negative || e1 == Sign::negative || e2 == Sign::negative;
  return !(any_pos && any_neg);
}

// Segment (s0, s1) against a proper triangle whose projection along `axis` is proper: the
// section's edge-face test.
bool segment_proper_triangle(Vec3 s0, Vec3 s1, Vec3 a, Vec3 b, Vec3 c, int axis) {
  const Sign o0 = orient3d(a, b, c, s0), o1 = orient3d(a, b, c, s1);
  if (o0 != Sign::zero && o0 == o1) return false;
  if (o0 == Sign::zero && o1 == Sign::zero) return segment_in_plane_meets(s0, s1, a, b, c, axis);
  return crossing_in_face(s0, s1, a, b, c);
}

bool point_in_proper_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c, int axis) {
  if (orient3d(a, b, c, p) != Sign::zero) return false;
  const Vec2 q = drop(p, axis);
  return triangles_meet(Triangle2{drop(a, axis), drop(b, axis), drop(c, axis)}, Triangle2{q, q, q});
}

bool simplices_intersect(const Simplex3& s, int s_axis, const Simplex3& t, int t_axis) {
  if (s.dim < t.dim) return simplices_intersect(t, t_axis, s, s_axis);
  switch (s.dim * 3 + t.dim) {
    case 8: {  // two proper triangles, known to be coplanar here
      const int k = s_axis;
      return triangles_meet(Triangle2{drop(s.p[0], k), drop(s.p[1], k), drop(s.p[2], k)},
                            Triangle2{drop(t.p[0], k), drop(t.p[1], k), drop(t.p[2], k)});
    }
    case 7:
      return segment_proper_triangle(t.p[0], t.p[1], s.p[0], s.p[1], s.p[2], s_axis);
    case 6:
      return point_in_proper_triangle(t.p[0], s.p[0], s.p[1], s.p[2], s_axis);
    case 4:
      return segments_intersect3(s.p[0], s.p[1], t.p[0], t.p[1]);
    case 3:
      return point_on_segment3(t.p[0], s.p[0], s.p[1]);
    default:
      return s.p[0] == t.p[0];
  }
}

// Coplanar or degenerate pairs: each triangle as the simplex it spans.
bool special_case(const Triangle3& a, const Triangle3& b) {
  int ka = -1, kb = -1;
  const Simplex3 sa = simplex_of(a, ka), sb = simplex_of(b, kb);
  return simplices_intersect(sa, ka, sb, kb);
}

// Cyclic relabelling (and, with flip, reversal of the other triangle) that puts the signs of
// (p, q, r) in the form d(p) > 0, d(q) <= 0, d(r) <= 0 (p strictly off the plane, so that the
// edges pq and pr each meet the plane in one point). Such a form exists for every sign pattern
// that is not all zero, not all one strict sign and not a lone zero beside two equal strict
// signs (those are decided before). Returns the rotation in 0..2 and
// sets `flip` when the signs had to be negated.
constexpr int canonical_rotation(const int d[3], bool& flip) {
  for (int f = 1; f >= -1; f -= 2) {
    for (int k = 0; k < 3; ++k) {
      if (f * d[k] > 0 && f * d[(k + 1) % 3] <= 0 && f * d[(k + 2) % 3] <= 0) {
        flip = f < 0;
        return k;
      }
    }
  }
  flip = false;
  return 0;  // unreachable for the patterns this is called with
}

// The vertex with sign zero when the other two have one strict sign, else -1.
constexpr int lone_vertex_on_plane(const int d[3]) {
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0 && d[(k + 1) % 3] == d[(k + 2) % 3]) return d[(k + 1) % 3] != 0 ? k : -1;
  }
  return -1;
}

// What the three signs of one triangle's vertices against the other's plane decide, for each
// of the 27 patterns, so that the hot path reads a table instead of branching on each sign
// (random input makes those branches unpredictable).
struct SignPattern {
  bool apart = false;    // all strictly on one side
  bool special = false;  // all zero, or a lone zero beside two equal strict signs
  int rotation = 0;      // canonical_rotation's answer for the other patterns
  bool flip = false;
};

constexpr int pattern_code(int d0, int d1, int d2) {
  return (d0 + 1) * 9 + (d1 + 1) * 3 + (d2 + 1);
}

constexpr std::array<SignPattern, 27> make_patterns() {
  std::array<SignPattern, 27> table{};
  for (int c = 0; c < 27; ++c) {
    const int d[3] = {c / 9 - 1, c / 3 % 3 - 1, c % 3 - 1};
    SignPattern& t = table[static_cast<std::size_t>(c)];
    t.apart = d[0] != 0 && d[0] == d[1] && d[0] == d[2];
    t.special = (d[0] == 0 && d[1] == 0 && d[2] == 0) || lone_vertex_on_plane(d) >= 0;
    if (!t.apart && !t.special) t.rotation = canonical_rotation(d, t.flip);
  }
  return table;
}
constexpr std::array<SignPattern, 27> kPatterns = make_patterns();

// The pairs whose sign patterns are special: coplanar triangles, a degenerate triangle, or a
// triangle meeting the other's plane in one vertex only. Out of the hot path.
[[gnu::noinline]] bool special_pair(const Triangle3& a, const Triangle3& b, const int d1[3],
                                    const int d2[3]) {
  // All zero against a plane: coplanar triangles, or that plane's triangle is degenerate.
  if ((d1[0] | d1[1] | d1[2]) == 0 || (d2[0] | d2[1] | d2[2]) == 0) return special_case(a, b);
  // A triangle that meets the other's plane in one vertex only (the other two strictly on one
  // side) meets the other triangle iff that vertex lies in it: the interval test needs
  // intervals of positive length on the line of the planes.
  const Vec3 t1[3] = {a.a, a.b, a.c};
  const Vec3 t2[3] = {b.a, b.b, b.c};
  if (const int v = lone_vertex_on_plane(d1); v >= 0) {
    return point_in_proper_triangle(t1[v], t2[0], t2[1], t2[2], proper_axis(t2[0], t2[1], t2[2]));
  }
  const int v = lone_vertex_on_plane(d2);
  return point_in_proper_triangle(t2[v], t1[0], t1[1], t1[2], proper_axis(t1[0], t1[1], t1[2]));
}

}  // namespace

bool triangles_meet(const Triangle3& a, const Triangle3& b) {
  // The six vertices, T1 as 0, 1, 2 and T2 as 3, 4, 5, share one filter bound; each plane's
  // normal is formed once for its three queries.
  const predicates::Orient3dSet<6> set({a.a, a.b, a.c, b.a, b.b, b.c});
  // Signs of T1's vertices against T2's plane: all strictly on one side -> apart.
  const auto plane2 = set.plane(3, 4, 5);
  const int d1[3] = {to_int(set.sign(plane2, 0)), to_int(set.sign(plane2, 1)),
                     to_int(set.sign(plane2, 2))};
  const SignPattern& pattern1 = kPatterns[pattern_code(d1[0], d1[1], d1[2])];
  if (pattern1.apart) return false;
  const auto plane1 = set.plane(0, 1, 2);
  const int d2[3] = {to_int(set.sign(plane1, 3)), to_int(set.sign(plane1, 4)),
                     to_int(set.sign(plane1, 5))};
  const SignPattern& pattern2 = kPatterns[pattern_code(d2[0], d2[1], d2[2])];
  if (pattern2.apart) return false;
  if (pattern1.special || pattern2.special) return special_pair(a, b, d1, d2);

  // Both proper, not coplanar, each meets the other's plane: relabel T1 so that p1 is alone on
  // the non-negative side of plane 2 (reversing T2 negates those signs) ...
  const int k1 = pattern1.rotation;
  const int f1 = pattern1.flip ? 1 : 0;
  // T2's vertex order after the optional reversal (swap of its vertices 1 and 2).
  const int o1 = 1 + f1, o2 = 2 - f1;
  // ... then T2 likewise against plane 1 (reversing T1 keeps p1 alone on its side).
  const SignPattern& pattern2r = kPatterns[pattern_code(d2[0], d2[o1], d2[o2])];
  const std::size_t order2[3] = {3, static_cast<std::size_t>(3 + o1),
                                 static_cast<std::size_t>(3 + o2)};
  const int k2 = pattern2r.rotation;
  const int f2 = pattern2r.flip ? 1 : 0;
  constexpr std::size_t kNext[5] = {0, 1, 2, 0, 1};  // i mod 3 for i < 5
  const std::size_t p1 = kNext[k1], q1 = kNext[k1 + 1 + f2], r1 = kNext[k1 + 2 - f2];
  const std::size_t p2 = order2[k2], q2 = order2[kNext[k2 + 1]], r2 = order2[kNext[k2 + 2]];
  // T1 meets the line L of the planes in [i, j] (i on p1q1, j on p1r1), T2 in [k, l]; the plane
  // through p1, q1, p2 cuts L at i and orient3d(p1, q1, p2, q2) says on which side of i the
  // point k lies; likewise orient3d(p1, r1, r2, p2) places l against j. In this labelling the
  // intervals overlap iff neither sign is strictly positive (Guigue and Devillers 2003).
  const Sign i_side = set.orient3d(p1, q1, p2, q2);
  const Sign j_side = set.orient3d(p1, r1, r2, p2);
  return (i_side != Sign::positive) & (j_side != Sign::positive);
}

bool segment_meets_triangle(const Segment3& s, const Triangle3& t) {
  const Sign o0 = orient3d(t.a, t.b, t.c, s.a), o1 = orient3d(t.a, t.b, t.c, s.b);
  if (o0 != Sign::zero && o0 == o1) return false;
  if (o0 != Sign::zero || o1 != Sign::zero) return crossing_in_face(s.a, s.b, t.a, t.b, t.c);
  // In t's plane, or t degenerate (then every orient3d against it is zero).
  const int axis = proper_axis(t.a, t.b, t.c);
  if (axis < 0) return special_case(Triangle3{s.a, s.b, s.b}, t);
  return segment_in_plane_meets(s.a, s.b, t.a, t.b, t.c, axis);
}

std::array<int, 3> shared_corners(const Triangle3& a, const Triangle3& b) {
  const Vec3 ta[3] = {a.a, a.b, a.c}, tb[3] = {b.a, b.b, b.c};
  std::array<int, 3> b_in_a{-1, -1, -1};
  for (std::size_t m = 0; m < 3; ++m) {
    for (int k = 0; k < 3; ++k) {
      if (tb[m] == ta[k]) b_in_a[m] = k;
    }
  }
  return b_in_a;
}

bool triangles_meet_beyond_shared(const Triangle3& a, const Triangle3& b,
                                  const std::array<int, 3>& b_in_a) {
  std::array<int, 3> a_in_b{-1, -1, -1};
  int shared = 0;
  for (std::size_t m = 0; m < 3; ++m) {
    if (b_in_a[m] >= 0) {
      a_in_b[static_cast<std::size_t>(b_in_a[m])] = static_cast<int>(m);
      ++shared;
    }
  }
  if (shared == 0) return triangles_meet(a, b);
  if (shared == 3) return false;
  const Vec3 ta[3] = {a.a, a.b, a.c}, tb[3] = {b.a, b.b, b.c};
  // The first corner of `in` that is shared (is_shared) or not.
  const auto first = [](const std::array<int, 3>& in, bool is_shared) {
    std::size_t k = 0;
    while ((in[k] >= 0) != is_shared)
      ++k;
    return k;
  };
  if (shared == 1) {
    const std::size_t pa = first(a_in_b, true), pb = first(b_in_a, true);
    return segment_meets_triangle({ta[(pa + 1) % 3], ta[(pa + 2) % 3]}, b) ||
           segment_meets_triangle({tb[(pb + 1) % 3], tb[(pb + 2) % 3]}, a);
  }
  // Edge p q shared, x and y the third corners. Not coplanar (the usual neighbours): the planes
  // meet in the line p q, which holds a and b's common points, and each triangle meets that line
  // in the edge p q only. One orient3d.
  const std::size_t xa = first(a_in_b, false), yb = first(b_in_a, false);
  const Vec3 p = ta[(xa + 1) % 3], q = ta[(xa + 2) % 3], x = ta[xa], y = tb[yb];
  if (orient3d(p, q, x, y) != Sign::zero) return false;
  // In one plane: they meet beyond p q iff x and y are on one side of it, asked in a projection
  // in which x is off the line p q (one exists, a having area; it is one to one on the plane,
  // so y, off the line too as b has area, keeps its side).
  for (int k = 2; k >= 0; --k) {
    const Sign sx = orient2d(drop(p, k), drop(q, k), drop(x, k));
    if (sx != Sign::zero) return orient2d(drop(p, k), drop(q, k), drop(y, k)) == sx;
  }
  return false;  // unreachable: a has area
}

}  // namespace contain::predicates
