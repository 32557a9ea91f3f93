#pragma once
// Sutherland-Hodgman on one ring and one half-space function (exact_value.h), and the crossing
// points it adds; shared by the polygon and mesh clippers.

#include <algorithm>
#include <vector>

#include "contain/predicates/halfspace_function.h"

namespace contain::clip::detail {

/// An axis-parallel boundary with a unit coefficient puts its crossings on it exactly.
inline void snap(const predicates::LineFunction& f, Vec2& x) {
  if (f.line.b == 0.0 && (f.line.a == 1.0 || f.line.a == -1.0)) x.x = -f.line.c * f.line.a;
  if (f.line.a == 0.0 && (f.line.b == 1.0 || f.line.b == -1.0)) x.y = -f.line.c * f.line.b;
}
inline void snap(const predicates::EdgeFunction& f, Vec2& x) {
  if (f.p.x == f.q.x) x.x = f.p.x;
  if (f.p.y == f.q.y) x.y = f.p.y;
}
inline void snap(const predicates::PlaneFunction& f, Vec3& x) {
  const Plane& h = f.plane;
  auto unit = [](double v) { return v == 1.0 || v == -1.0; };
  if (h.b == 0.0 && h.c == 0.0 && unit(h.a)) x.x = -h.d * h.a;
  if (h.a == 0.0 && h.c == 0.0 && unit(h.b)) x.y = -h.d * h.b;
  if (h.a == 0.0 && h.b == 0.0 && unit(h.c)) x.z = -h.d * h.c;
}

inline void snap(const predicates::FaceFunction& f, Vec3& x) {
  const Triangle3& t = f.face;
  if (t.a.x == t.b.x && t.a.x == t.c.x) x.x = t.a.x;
  if (t.a.y == t.b.y && t.a.y == t.c.y) x.y = t.a.y;
  if (t.a.z == t.b.z && t.a.z == t.c.z) x.z = t.a.z;
}

/// The crossing of the edge p->q (one endpoint strictly in, one strictly out) with the boundary.
template <class V, class F>
[[nodiscard]] V crossing_point(const V& p, const V& q, const F& f) {
  const double sp = f.approx(p).value, sq = f.approx(q).value;
  double t = sp / (sp - sq);
  t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.5;
  V x = p + t * (q - p);
  snap(f, x);
  return x;
}

/// The section's algorithm: keep inside vertices, add crossings of edges that change side.
template <class V, class F>
[[nodiscard]] std::vector<V> sutherland_hodgman_ring(const std::vector<V>& ring, const F& f) {
  std::vector<V> out;
  const std::size_t n = ring.size();
  if (n == 0) return out;
  out.reserve(n + 2);
  Sign sp = f.side(ring[n - 1]);
  for (std::size_t i = 0; i < n; ++i) {
    const V& p = ring[(i + n - 1) % n];
    const V& q = ring[i];
    const Sign sq = f.side(q);
    if ((sp == Sign::positive && sq == Sign::negative) ||
        (sp == Sign::negative && sq == Sign::positive)) {
      out.push_back(crossing_point(p, q, f));
    }
    if (sq != Sign::negative) out.push_back(q);
    sp = sq;
  }
  if (out.size() < 3) out.clear();
  return out;
}

}  // namespace contain::clip::detail
