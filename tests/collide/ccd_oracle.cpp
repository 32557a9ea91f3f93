#include "collide/ccd_oracle.h"

#include <algorithm>
#include <functional>
#include <vector>

#include "support/exact_polynomial.h"

namespace contain::test {
namespace {

using QVecT = std::array<QPoly, 3>;  // a point or vector as polynomials in time

QVecT moving(Vec3 at0, Vec3 at1) {
  return {qlinear(at0.x, at1.x), qlinear(at0.y, at1.y), qlinear(at0.z, at1.z)};
}

QVecT sub(const QVecT& a, const QVecT& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

QVecT cross(const QVecT& u, const QVecT& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

QPoly dot(const QVecT& u, const QVecT& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

// The cyclic projection that drops axis k: (y, z), (z, x), (x, y). Its orient2d of three
// projected points is component k of the cross product, so the sign of the normal's
// component tells the orientation of the projected triangle.
QPoly orient2d(int k, const QVecT& a, const QVecT& b, const QVecT& c) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  return (b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]);
}

// A time at which to decide: a root (exact or isolated).
using Time = QRoot;

Sign at(const QPoly& p, const Time& t) {
  return sign_at(p, t);
}

bool all_zero(const QVecT& v, const Time& t) {
  return at(v[0], t) == Sign::zero && at(v[1], t) == Sign::zero && at(v[2], t) == Sign::zero;
}

// x on the closed segment [a, b] at time t (a point when a = b).
bool on_segment(const QVecT& x, const QVecT& a, const QVecT& b, const Time& t) {
  const QVecT ab = sub(b, a), ax = sub(x, a);
  if (all_zero(ab, t)) return all_zero(ax, t);
  if (!all_zero(cross(ab, ax), t)) return false;
  return at(dot(ax, ab), t) != Sign::negative && at(dot(sub(x, b), sub(a, b)), t) != Sign::negative;
}

// Every polynomial the point-on-segment test reads.
void on_segment_polys(const QVecT& x, const QVecT& a, const QVecT& b, std::vector<QPoly>& out) {
  const QVecT ab = sub(b, a), ax = sub(x, a);
  for (const QVecT& v : {ab, ax, cross(ab, ax)})
    out.insert(out.end(), v.begin(), v.end());
  out.push_back(dot(ax, ab));
  out.push_back(dot(sub(x, b), sub(a, b)));
}

struct VertexFace {
  QVecT p, a, b, c;
  explicit VertexFace(const CcdQuery& q)
      : p(moving(q[0], q[4])),
        a(moving(q[1], q[5])),
        b(moving(q[2], q[6])),
        c(moving(q[3], q[7])) {}

  [[nodiscard]] QPoly coplanarity() const { return dot(cross(sub(b, a), sub(c, a)), sub(p, a)); }

  [[nodiscard]] bool contact(const Time& t) const {
    const QVecT n = cross(sub(b, a), sub(c, a));
    for (int k = 0; k < 3; ++k) {
      const Sign s = at(n[k], t);
      if (s == Sign::zero) continue;
      for (const auto& [u, v] : {std::pair{&a, &b}, std::pair{&b, &c}, std::pair{&c, &a}}) {
        if (to_int(at(orient2d(k, *u, *v, p), t)) * to_int(s) < 0) return false;
      }
      return true;
    }
    return on_segment(p, a, b, t) || on_segment(p, b, c, t) || on_segment(p, c, a, t);
  }

  [[nodiscard]] std::vector<QPoly> decision_polys() const {
    std::vector<QPoly> out;
    const QVecT n = cross(sub(b, a), sub(c, a));
    out.insert(out.end(), n.begin(), n.end());
    for (int k = 0; k < 3; ++k) {
      out.push_back(orient2d(k, a, b, p));
      out.push_back(orient2d(k, b, c, p));
      out.push_back(orient2d(k, c, a, p));
    }
    on_segment_polys(p, a, b, out);
    on_segment_polys(p, b, c, out);
    on_segment_polys(p, c, a, out);
    return out;
  }
};

struct EdgeEdge {
  QVecT p, q, r, s;
  explicit EdgeEdge(const CcdQuery& x)
      : p(moving(x[0], x[4])),
        q(moving(x[1], x[5])),
        r(moving(x[2], x[6])),
        s(moving(x[3], x[7])) {}

  [[nodiscard]] QPoly coplanarity() const { return dot(cross(sub(q, p), sub(r, p)), sub(s, p)); }

  [[nodiscard]] bool contact(const Time& t) const {
    const QVecT n = cross(sub(q, p), sub(s, r));
    for (int k = 0; k < 3; ++k) {
      if (at(n[k], t) == Sign::zero) continue;
      // Not parallel in this projection: the lines cross at one point.
      const int o1 = to_int(at(orient2d(k, p, q, r), t)), o2 = to_int(at(orient2d(k, p, q, s), t));
      const int o3 = to_int(at(orient2d(k, r, s, p), t)), o4 = to_int(at(orient2d(k, r, s, q), t));
      return o1 * o2 <= 0 && o3 * o4 <= 0;
    }
    return on_segment(p, r, s, t) || on_segment(q, r, s, t) || on_segment(r, p, q, t) ||
           on_segment(s, p, q, t);
  }

  [[nodiscard]] std::vector<QPoly> decision_polys() const {
    std::vector<QPoly> out;
    const QVecT n = cross(sub(q, p), sub(s, r));
    out.insert(out.end(), n.begin(), n.end());
    for (int k = 0; k < 3; ++k) {
      out.push_back(orient2d(k, p, q, r));
      out.push_back(orient2d(k, p, q, s));
      out.push_back(orient2d(k, r, s, p));
      out.push_back(orient2d(k, r, s, q));
    }
    on_segment_polys(p, r, s, out);
    on_segment_polys(q, r, s, out);
    on_segment_polys(r, p, q, out);
    on_segment_polys(s, p, q, out);
    return out;
  }
};

template <class Query>
std::optional<double> earliest(const Query& query) {
  const QPoly f = query.coplanarity();
  if (!f.empty()) {
    for (const QRoot& root : isolate_roots(f, 0, 1)) {
      if (query.contact(root)) return floor_to_double(root);
    }
    return std::nullopt;
  }
  // Coplanar all the time: the contact set is closed, so its first point is 0 or a point where
  // some polynomial of the decision changes sign or vanishes.
  const Time zero{{}, 0, 0, true};
  if (query.contact(zero)) return 0.0;
  std::optional<double> best;
  std::vector<ZPoly> seen;  // primitive, so that polynomials equal up to a factor are done once
  for (const QPoly& p : query.decision_polys()) {
    if (degree(p) < 1) continue;
    ZPoly primitive = primitive_part(p);
    if (std::find(seen.begin(), seen.end(), primitive) != seen.end()) continue;
    seen.push_back(std::move(primitive));
    for (const QRoot& root : isolate_roots(p, 0, 1)) {
      if (!query.contact(root)) continue;
      const double t = floor_to_double(root);
      if (!best || t < *best) best = t;
      break;  // later roots of this polynomial round no lower
    }
  }
  return best;
}

}  // namespace

std::optional<double> exact_vertex_face_time(const CcdQuery& q) {
  return earliest(VertexFace(q));
}

std::optional<double> exact_edge_edge_time(const CcdQuery& q) {
  return earliest(EdgeEdge(q));
}

}  // namespace contain::test
