#include "contain/predicates/closest_feature.h"

#include <array>
#include <cmath>

#include "contain/predicates/big_float.h"
#include "contain/predicates/bounded.h"
#include "contain/predicates/cross_dot.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "predicates/filtered_sign.h"
#include "predicates/flat_formulas.h"
#include "predicates/stages.h"

namespace contain::predicates {

namespace {

template <class T, class V>
T dot_of(V a, V b, V p) {
  return detail::dot(detail::sub<T>(b, a), detail::sub<T>(p, a));
}

// Filter: each monomial of (b - a) . (p - a) passes through at most 5 roundings (two
// differences, the product, two sums), so |error| <= gamma_5 * permanent < 6 eps * computed
// permanent; products that underflow lose at most 2^-1075 each, which DBL_MIN covers. Then the
// running-error stage and big numbers.
inline double dot_terms(Vec3 u, Vec3 v, double& permanent) {
  permanent = (std::fabs(u.x * v.x) + std::fabs(u.y * v.y)) + std::fabs(u.z * v.z);
  return (u.x * v.x + u.y * v.y) + u.z * v.z;
}
inline double dot_terms(Vec2 u, Vec2 v, double& permanent) {
  permanent = std::fabs(u.x * v.x) + std::fabs(u.y * v.y);
  return u.x * v.x + u.y * v.y;
}

template <class V>
Sign dot_sign_of(V a, V b, V p) {
  double permanent = 0.0;
  const double value = dot_terms(b - a, p - a, permanent);
  const double errbound = 6.0 * unit_roundoff<double> * permanent + detail::kUnderflowGuard;
  if (value > errbound) return Sign::positive;
  if (-value > errbound) return Sign::negative;
  const Bounded fast = dot_of<Bounded>(a, b, p);
  if (fast.decided()) return fast.sign();
  return dot_of<BigFloat>(a, b, p).sign();
}

template <class V, class S>
SegmentFeature segment_feature(V p, const S& s) {
  if (s.a == s.b || dot_sign_of(s.a, s.b, p) != Sign::positive) return SegmentFeature::vertex_a;
  if (dot_sign_of(s.b, s.a, p) != Sign::positive) return SegmentFeature::vertex_b;
  return SegmentFeature::interior;
}

}  // namespace

Sign dot_sign(Vec3 a, Vec3 b, Vec3 p) {
  return dot_sign_of(a, b, p);
}
Sign dot_sign(Vec2 a, Vec2 b, Vec2 p) {
  return dot_sign_of(a, b, p);
}

bool collinear(Vec3 a, Vec3 b, Vec3 c) {
  // (b - a) x (c - a) = 0 iff its three components vanish: the orientations of the three
  // coordinate projections.
  return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == Sign::zero &&
         orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == Sign::zero &&
         orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == Sign::zero;
}

SegmentFeature closest_feature(const Segment3& s, Vec3 p) {
  return segment_feature(p, s);
}
SegmentFeature closest_feature(const Segment2& s, Vec2 p) {
  return segment_feature(p, s);
}

namespace {

// Ericson's region of p for t ("Real-Time Collision Detection", 5.1.5) in doubles: only a guess,
// which closest_feature then proves with two or three exact signs.
TriangleFeature guessed_feature(Vec3 p, const Triangle3& t) {
  const Vec3 ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return TriangleFeature::vertex_a;
  const Vec3 bp = p - t.b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return TriangleFeature::vertex_b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return TriangleFeature::edge_ab;
  const Vec3 cp = p - t.c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return TriangleFeature::vertex_c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return TriangleFeature::edge_ca;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return TriangleFeature::edge_bc;
  return TriangleFeature::face;
}

// The vertex feature of corner i: named by the first corner at the same point.
TriangleFeature vertex_named(const Triangle3& t, int i) {
  for (int k = 0; k < i; ++k)
    if (t.corner(k) == t.corner(i)) return static_cast<TriangleFeature>(k);
  return static_cast<TriangleFeature>(i);
}

// Is the guess proven to be closest_feature's answer? (false: undecided, not wrong)
// - vertex v: dot_sign(v, u, p) <= 0 towards both other corners u makes v a closest point of t
//   (t is the hull of its corners); one of them < 0 means p's projection on the plane is not v,
//   so not in the closed triangle: the answer is not `face`, and v, the unique closest point,
//   is the vertex the edges reduce to.
// - edge (v, w) with third corner x: both dot signs > 0 put p's foot q on the line strictly
//   inside the edge, and cross_dot(v, w, p, x) < 0 puts p outside across it (so not `face`, and
//   t not degenerate) with (p - q) . (x - q) < 0 (Binet-Cauchy, as in docs/robustness.md), so q
//   is t's unique closest point, in no other edge.
// - face: all three cross_dots > 0 (none can be, for a degenerate triangle).
bool proven(Vec3 p, const Triangle3& t, TriangleFeature f) {
  if (f <= TriangleFeature::vertex_c) {
    const int i = static_cast<int>(f);
    const Vec3 v = t.corner(i);
    const Sign s1 = dot_sign(v, t.corner((i + 1) % 3), p);
    if (s1 == Sign::positive) return false;
    const Sign s2 = dot_sign(v, t.corner((i + 2) % 3), p);
    return s2 != Sign::positive && (s1 == Sign::negative || s2 == Sign::negative);
  }
  if (f == TriangleFeature::face) {
    return cross_dot(t.a, t.b, p, t.c) == Sign::positive &&
           cross_dot(t.b, t.c, p, t.a) == Sign::positive &&
           cross_dot(t.c, t.a, p, t.b) == Sign::positive;
  }
  const int e = static_cast<int>(f) - static_cast<int>(TriangleFeature::edge_ab);
  const Vec3 v = t.corner(e), w = t.corner((e + 1) % 3), x = t.corner((e + 2) % 3);
  return dot_sign(v, w, p) == Sign::positive && dot_sign(w, v, p) == Sign::positive &&
         cross_dot(v, w, p, x) == Sign::negative;
}

}  // namespace

TriangleFeature closest_feature(const Triangle3& t, Vec3 p) {
  // Most calls: the floating-point region, proven by two or three exact signs.
  const TriangleFeature guess = guessed_feature(p, t);
  if (proven(p, t, guess)) {
    return guess <= TriangleFeature::vertex_c ? vertex_named(t, static_cast<int>(guess)) : guess;
  }
  // The rest (ties, degenerate triangles, points on the boundary planes, wrong guesses): the
  // definition, step by step.
  if (!collinear(t.a, t.b, t.c) && cross_dot(t.a, t.b, p, t.c) != Sign::negative &&
      cross_dot(t.b, t.c, p, t.a) != Sign::negative &&
      cross_dot(t.c, t.a, p, t.b) != Sign::negative) {
    return TriangleFeature::face;
  }
  // The closest point lies on the boundary: the closest of the three closed edges. Each edge's
  // own closest feature, then exact comparisons; a vertex reached from two edges is one feature,
  // and the edges are tried in the order ab, bc, ca so that equal distances keep the first.
  constexpr std::array<TriangleFeature, 3> kEdge{TriangleFeature::edge_ab, TriangleFeature::edge_bc,
                                                 TriangleFeature::edge_ca};
  TriangleFeature best{};
  FlatPair3 best_pair{};
  bool have = false;
  for (int e = 0; e < 3; ++e) {
    const int i = e;
    const int j = (e + 1) % 3;
    const Segment3 s{t.corner(i), t.corner(j)};
    TriangleFeature f{};
    switch (closest_feature(s, p)) {
      case SegmentFeature::vertex_a:
        f = vertex_named(t, i);
        break;
      case SegmentFeature::vertex_b:
        f = vertex_named(t, j);
        break;
      case SegmentFeature::interior:
        f = kEdge[static_cast<std::size_t>(e)];
        break;
    }
    if (have && f == best) continue;
    const FlatPair3 pair{point_flat(p), feature_flat(t, f)};
    if (!have || compare_squared_distances(pair, best_pair) == Sign::negative) {
      best = f;
      best_pair = pair;
      have = true;
    }
  }
  return best;
}

Flat3 feature_flat(const Triangle3& t, TriangleFeature f) {
  switch (f) {
    case TriangleFeature::vertex_a:
      return point_flat(t.a);
    case TriangleFeature::vertex_b:
      return point_flat(t.b);
    case TriangleFeature::vertex_c:
      return point_flat(t.c);
    case TriangleFeature::edge_ab:
      return line_flat(t.a, t.b);
    case TriangleFeature::edge_bc:
      return line_flat(t.b, t.c);
    case TriangleFeature::edge_ca:
      return line_flat(t.c, t.a);
    case TriangleFeature::face:
      break;
  }
  return plane_flat(t.a, t.b, t.c);
}

Flat3 feature_flat(const Segment3& s, SegmentFeature f) {
  switch (f) {
    case SegmentFeature::vertex_a:
      return point_flat(s.a);
    case SegmentFeature::vertex_b:
      return point_flat(s.b);
    case SegmentFeature::interior:
      break;
  }
  return line_flat(s.a, s.b);
}

Flat2 feature_flat(const Segment2& s, SegmentFeature f) {
  switch (f) {
    case SegmentFeature::vertex_a:
      return point_flat(s.a);
    case SegmentFeature::vertex_b:
      return point_flat(s.b);
    case SegmentFeature::interior:
      break;
  }
  return line_flat(s.a, s.b);
}

}  // namespace contain::predicates

namespace contain::predicates {

namespace {

using detail::filtered_sign;

// Keeps the least of candidate pairs, the first of equal ones.
template <class Pair>
struct Least {
  Pair best{};
  bool have = false;
  void offer(const Pair& x) {
    if (!have || compare_squared_distances(x, best) == Sign::negative) {
      best = x;
      have = true;
    }
  }
};

}  // namespace

FlatPair3 closest_flats(const Segment3& s, const Segment3& t) {
  Least<FlatPair3> least;
  least.offer({point_flat(s.a), feature_flat(t, closest_feature(t, s.a))});
  least.offer({point_flat(s.b), feature_flat(t, closest_feature(t, s.b))});
  least.offer({feature_flat(s, closest_feature(s, t.a)), point_flat(t.a)});
  least.offer({feature_flat(s, closest_feature(s, t.b)), point_flat(t.b)});
  if (s.a == s.b || t.a == t.b) return least.best;
  // The feet of the common perpendicular: s.a + x u, t.a + y v with x = (r x v) . m / |m|^2,
  // y = (r x u) . m / |m|^2 (r = t.a - s.a, m = u x v); strictly inside both segments.
  auto foot_inside = [&](bool along_s) {
    const Sign num = filtered_sign([&]<class T>(const T&) {
      const auto u = detail::sub<T>(s.b, s.a), v = detail::sub<T>(t.b, t.a);
      const auto r = detail::sub<T>(t.a, s.a);
      return detail::dot(detail::cross(r, along_s ? v : u), detail::cross(u, v));
    });
    if (num != Sign::positive) return false;
    return filtered_sign([&]<class T>(const T&) {
             const auto u = detail::sub<T>(s.b, s.a), v = detail::sub<T>(t.b, t.a);
             const auto r = detail::sub<T>(t.a, s.a);
             const auto m = detail::cross(u, v);
             return detail::dot(m, m) - detail::dot(detail::cross(r, along_s ? v : u), m);
           }) == Sign::positive;
  };
  // (Parallel lines have m = 0, so the numerators vanish and no foot is strictly inside.)
  if (foot_inside(true) && foot_inside(false)) {
    least.offer({line_flat(s.a, s.b), line_flat(t.a, t.b)});
  }
  return least.best;
}

FlatPair2 closest_flats(const Segment2& s, const Segment2& t) {
  const Sign oc = orient2d(s.a, s.b, t.a), od = orient2d(s.a, s.b, t.b);
  const Sign oa = orient2d(t.a, t.b, s.a), ob = orient2d(t.a, t.b, s.b);
  if (oc != Sign::zero && od == -oc && oa != Sign::zero && ob == -oa) {
    // cross(s.b - s.a, t.b - t.a) = orient2d(s.a, s.b, t.b) - orient2d(s.a, s.b, t.a): orient
    // t so that it is positive.
    return od == Sign::positive ? FlatPair2{line_flat(s.a, s.b), line_flat(t.a, t.b)}
                                : FlatPair2{line_flat(s.a, s.b), line_flat(t.b, t.a)};
  }
  Least<FlatPair2> least;
  least.offer({point_flat(s.a), feature_flat(t, closest_feature(t, s.a))});
  least.offer({point_flat(s.b), feature_flat(t, closest_feature(t, s.b))});
  least.offer({feature_flat(s, closest_feature(s, t.a)), point_flat(t.a)});
  least.offer({feature_flat(s, closest_feature(s, t.b)), point_flat(t.b)});
  return least.best;
}

bool segment_crosses_triangle(const Triangle3& t, Vec3 p, Vec3 q) {
  const Sign op = orient3d(t.a, t.b, t.c, p);
  if (op == Sign::zero) return false;
  if (orient3d(t.a, t.b, t.c, q) != -op) return false;
  const Sign e1 = orient3d(p, q, t.a, t.b);
  if (e1 == Sign::zero) return false;
  return orient3d(p, q, t.b, t.c) == e1 && orient3d(p, q, t.c, t.a) == e1;
}

FlatPair3 closest_flats(const Triangle3& s, const Triangle3& t) {
  const std::array<Vec3, 3> vs{s.a, s.b, s.c}, vt{t.a, t.b, t.c};
  for (int e = 0; e < 3; ++e) {
    const Vec3 p = vs[static_cast<std::size_t>(e)], q = vs[static_cast<std::size_t>((e + 1) % 3)];
    if (segment_crosses_triangle(t, p, q)) {
      // The line from below the plane to above it (orient3d < 0 first).
      const bool p_below = orient3d(t.a, t.b, t.c, p) == Sign::negative;
      return {p_below ? line_flat(p, q) : line_flat(q, p), plane_flat(t.a, t.b, t.c)};
    }
  }
  for (int e = 0; e < 3; ++e) {
    const Vec3 p = vt[static_cast<std::size_t>(e)], q = vt[static_cast<std::size_t>((e + 1) % 3)];
    if (segment_crosses_triangle(s, p, q)) {
      const bool p_below = orient3d(s.a, s.b, s.c, p) == Sign::negative;
      return {plane_flat(s.a, s.b, s.c), p_below ? line_flat(p, q) : line_flat(q, p)};
    }
  }
  Least<FlatPair3> least;
  for (const Vec3& v : vs)
    least.offer({point_flat(v), feature_flat(t, closest_feature(t, v))});
  for (const Vec3& v : vt)
    least.offer({feature_flat(s, closest_feature(s, v)), point_flat(v)});
  for (int i = 0; i < 3; ++i) {
    const Segment3 es{vs[static_cast<std::size_t>(i)], vs[static_cast<std::size_t>((i + 1) % 3)]};
    for (int j = 0; j < 3; ++j) {
      const Segment3 et{vt[static_cast<std::size_t>(j)], vt[static_cast<std::size_t>((j + 1) % 3)]};
      least.offer(closest_flats(es, et));
    }
  }
  return least.best;
}

}  // namespace contain::predicates
