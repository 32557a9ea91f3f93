#include "support/tri_tri_oracle.h"

#include <array>

#include "support/exact.h"

namespace contain::test {
namespace {

using Q = mpq_class;

bool eq(const QVec3& a, const QVec3& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

bool point_on_segment(const QVec3& p, const QVec3& s0, const QVec3& s1) {
  const QVec3 u = qsub(s1, s0), w = qsub(p, s0);
  if (qzero(u)) return eq(p, s0);
  if (!qzero(qcross(w, u))) return false;
  const Q t = qdot(w, u);
  return t >= 0 && t <= qdot(u, u);
}

bool seg_seg(const QVec3& s0, const QVec3& s1, const QVec3& t0, const QVec3& t1) {
  const QVec3 u = qsub(s1, s0), v = qsub(t1, t0), w = qsub(t0, s0);
  if (qzero(u)) return point_on_segment(s0, t0, t1);
  if (qzero(v)) return point_on_segment(t0, s0, s1);
  const QVec3 n = qcross(u, v);
  if (qdot(n, w) != 0) return false;  // skew
  if (qzero(n)) {                     // parallel
    if (!qzero(qcross(w, u))) return false;
    return point_on_segment(t0, s0, s1) || point_on_segment(t1, s0, s1) ||
           point_on_segment(s0, t0, t1) || point_on_segment(s1, t0, t1);
  }
  const Q nn = qdot(n, n);
  const Q lambda = qdot(qcross(w, v), n) / nn, mu = qdot(qcross(w, u), n) / nn;
  return lambda >= 0 && lambda <= 1 && mu >= 0 && mu <= 1;
}

// p in the plane of the proper triangle (a, b, c) with normal n: inside the closed triangle?
bool in_triangle(const QVec3& p, const QVec3& a, const QVec3& b, const QVec3& c, const QVec3& n) {
  return qdot(n, qcross(qsub(b, a), qsub(p, a))) >= 0 &&
         qdot(n, qcross(qsub(c, b), qsub(p, b))) >= 0 &&
         qdot(n, qcross(qsub(a, c), qsub(p, c))) >= 0;
}

bool seg_tri(const QVec3& s0, const QVec3& s1, const std::array<QVec3, 3>& t) {
  const QVec3 n = qcross(qsub(t[1], t[0]), qsub(t[2], t[0]));
  if (qzero(n)) {
    return seg_seg(s0, s1, t[0], t[1]) || seg_seg(s0, s1, t[1], t[2]) ||
           seg_seg(s0, s1, t[2], t[0]);
  }
  const Q d0 = qdot(n, qsub(s0, t[0])), d1 = qdot(n, qsub(s1, t[0]));
  if ((d0 > 0 && d1 > 0) || (d0 < 0 && d1 < 0)) return false;
  if (d0 == 0 && d1 == 0) {
    return in_triangle(s0, t[0], t[1], t[2], n) || in_triangle(s1, t[0], t[1], t[2], n) ||
           seg_seg(s0, s1, t[0], t[1]) || seg_seg(s0, s1, t[1], t[2]) ||
           seg_seg(s0, s1, t[2], t[0]);
  }
  const Q lambda = d0 / (d0 - d1);
  const QVec3 u = qsub(s1, s0);
  const QVec3 x{s0.x + lambda * u.x, s0.y + lambda * u.y, s0.z + lambda * u.z};
  return in_triangle(x, t[0], t[1], t[2], n);
}

std::array<QVec3, 3> exact3(const Triangle3& t) {
  return {exact(t.a), exact(t.b), exact(t.c)};
}

QVec3 lift(Vec2 p) {
  return exact(Vec3{p.x, p.y, 0.0});
}

}  // namespace

bool exact_tri_tri_3d(const Triangle3& a, const Triangle3& b) {
  const auto ta = exact3(a), tb = exact3(b);
  for (int e = 0; e < 3; ++e) {
    if (seg_tri(ta[e], ta[(e + 1) % 3], tb)) return true;
    if (seg_tri(tb[e], tb[(e + 1) % 3], ta)) return true;
  }
  return false;
}

bool exact_tri_tri_2d(const Triangle2& a, const Triangle2& b) {
  // The plane z = 0 in space: the same oracle (coplanar branch).
  const std::array<QVec3, 3> ta{lift(a.a), lift(a.b), lift(a.c)};
  const std::array<QVec3, 3> tb{lift(b.a), lift(b.b), lift(b.c)};
  for (int e = 0; e < 3; ++e) {
    if (seg_tri(ta[e], ta[(e + 1) % 3], tb)) return true;
    if (seg_tri(tb[e], tb[(e + 1) % 3], ta)) return true;
  }
  return false;
}

}  // namespace contain::test
