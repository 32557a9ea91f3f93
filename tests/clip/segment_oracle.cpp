#include "clip/segment_oracle.h"

#include "support/exact.h"

namespace contain::test {

OracleClip oracle_clip(const std::vector<std::pair<mpq_class, mpq_class>>& values,
                       bool degenerate_segment) {
  OracleClip r;
  for (const auto& [sa, sb] : values) {
    if (sa >= 0 && sb >= 0) continue;
    if (sa < 0 && sb < 0) return {};
    const mpq_class t = sa / (sa - sb);
    if (sa < 0) {
      if (t > r.t0) r.t0 = t;
    } else if (t < r.t1) {
      r.t1 = t;
    }
  }
  r.kept = r.t0 <= r.t1;
  r.touching = r.kept && r.t0 == r.t1 && !degenerate_segment;
  return r;
}

namespace {

template <class S>
bool degenerate(const S& s) {
  return s.a == s.b;
}

mpq_class plane_value(const Plane& p, Vec3 v) {
  const QVec3 q = exact(v);
  return mpq_class(p.a) * q.x + mpq_class(p.b) * q.y + mpq_class(p.c) * q.z + mpq_class(p.d);
}
mpq_class line_value(const HalfPlane& p, Vec2 v) {
  const QVec2 q = exact(v);
  return mpq_class(p.a) * q.x + mpq_class(p.b) * q.y + mpq_class(p.c);
}

}  // namespace

OracleClip oracle_clip(const Segment3& s, std::span<const Plane> planes) {
  std::vector<std::pair<mpq_class, mpq_class>> v;
  for (const Plane& p : planes)
    v.emplace_back(plane_value(p, s.a), plane_value(p, s.b));
  return oracle_clip(v, degenerate(s));
}

OracleClip oracle_clip(const Segment2& s, std::span<const HalfPlane> planes) {
  std::vector<std::pair<mpq_class, mpq_class>> v;
  for (const HalfPlane& p : planes)
    v.emplace_back(line_value(p, s.a), line_value(p, s.b));
  return oracle_clip(v, degenerate(s));
}

OracleClip oracle_clip(const Segment3& s, const Box3& box) {
  if (box.empty()) return {};
  const std::vector<Plane> planes = {{1, 0, 0, -box.min.x}, {-1, 0, 0, box.max.x},
                                     {0, 1, 0, -box.min.y}, {0, -1, 0, box.max.y},
                                     {0, 0, 1, -box.min.z}, {0, 0, -1, box.max.z}};
  return oracle_clip(s, planes);
}

OracleClip oracle_clip(const Segment2& s, const Box2& box) {
  if (box.empty()) return {};
  const std::vector<HalfPlane> planes = {
      {1, 0, -box.min.x}, {-1, 0, box.max.x}, {0, 1, -box.min.y}, {0, -1, box.max.y}};
  return oracle_clip(s, planes);
}

OracleClip oracle_clip(const Segment3& s, std::span<const Triangle3> faces) {
  auto value = [](const Triangle3& f, Vec3 p) {
    const QVec3 a = exact(f.a), b = exact(f.b), c = exact(f.c), q = exact(p);
    // ((c - a) x (b - a)) . (p - a): positive inside for an outward face.
    const mpq_class ux = c.x - a.x, uy = c.y - a.y, uz = c.z - a.z;
    const mpq_class wx = b.x - a.x, wy = b.y - a.y, wz = b.z - a.z;
    return (uy * wz - uz * wy) * (q.x - a.x) + (uz * wx - ux * wz) * (q.y - a.y) +
           (ux * wy - uy * wx) * (q.z - a.z);
  };
  std::vector<std::pair<mpq_class, mpq_class>> v;
  for (const Triangle3& f : faces)
    v.emplace_back(value(f, s.a), value(f, s.b));
  return oracle_clip(v, degenerate(s));
}

OracleClip oracle_clip_ring(const Segment2& s, const Ring& ring) {
  auto value = [](Vec2 p, Vec2 q, Vec2 v) {
    const QVec2 P = exact(p), Q = exact(q), X = exact(v);
    return mpq_class((Q.x - P.x) * (X.y - P.y) - (Q.y - P.y) * (X.x - P.x));
  };
  std::vector<std::pair<mpq_class, mpq_class>> v;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 p = ring[i], q = ring[(i + 1) % ring.size()];
    if (p == q) continue;
    v.emplace_back(value(p, q, s.a), value(p, q, s.b));
  }
  return oracle_clip(v, degenerate(s));
}

double SegmentGenerator::coordinate() {
  std::uniform_int_distribution<int> coin(0, 1);
  if (coin(rng_) == 0) return std::uniform_int_distribution<int>(-3, 3)(rng_) * 0.5;
  return std::uniform_real_distribution<double>(-2.0, 2.0)(rng_);
}

Segment3 SegmentGenerator::segment3() {
  Segment3 s{{coordinate(), coordinate(), coordinate()},
             {coordinate(), coordinate(), coordinate()}};
  if (std::uniform_int_distribution<int>(0, 19)(rng_) == 0) s.b = s.a;
  return s;
}

Segment2 SegmentGenerator::segment2() {
  Segment2 s{{coordinate(), coordinate()}, {coordinate(), coordinate()}};
  if (std::uniform_int_distribution<int>(0, 19)(rng_) == 0) s.b = s.a;
  return s;
}

double to_double(const mpq_class& q) {
  return q.get_d();
}

}  // namespace contain::test
