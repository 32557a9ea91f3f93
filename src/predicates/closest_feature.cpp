#include "contain/predicates/closest_feature.h"

#include <array>

#include "contain/predicates/cross_dot.h"
#include "contain/predicates/orient2d.h"
#include "predicates/big_float.h"
#include "predicates/flat_formulas.h"
#include "predicates/running_error.h"

namespace contain::predicates {

namespace {

using detail::BigFloat;
using detail::Err;

template <class T, class V>
T dot_of(V a, V b, V p) {
  return detail::dot(detail::sub<T>(b, a), detail::sub<T>(p, a));
}

template <class V>
Sign dot_sign_of(V a, V b, V p) {
  const Err<double> fast = dot_of<Err<double>>(a, b, p);
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

SegmentFeature closest_feature(Vec3 p, const Segment3& s) {
  return segment_feature(p, s);
}
SegmentFeature closest_feature(Vec2 p, const Segment2& s) {
  return segment_feature(p, s);
}

TriangleFeature closest_feature(Vec3 p, const Triangle3& t) {
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
  const std::array<Vec3, 3> v{t.a, t.b, t.c};
  // Vertex features named by the first vertex of the triangle at that position.
  auto vertex_feature = [&](int i) {
    for (int k = 0; k < i; ++k) {
      if (v[static_cast<std::size_t>(k)] == v[static_cast<std::size_t>(i)]) {
        return static_cast<TriangleFeature>(k);
      }
    }
    return static_cast<TriangleFeature>(i);
  };
  TriangleFeature best{};
  FlatPair3 best_pair{};
  bool have = false;
  for (int e = 0; e < 3; ++e) {
    const int i = e;
    const int j = (e + 1) % 3;
    const Segment3 s{v[static_cast<std::size_t>(i)], v[static_cast<std::size_t>(j)]};
    TriangleFeature f{};
    switch (closest_feature(p, s)) {
      case SegmentFeature::vertex_a:
        f = vertex_feature(i);
        break;
      case SegmentFeature::vertex_b:
        f = vertex_feature(j);
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
