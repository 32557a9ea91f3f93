#include "support/exact.h"

namespace contain::test {

QVec2 exact(Vec2 p) {
  return {mpq_class(p.x), mpq_class(p.y)};
}
QVec3 exact(Vec3 p) {
  return {mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)};
}

Sign sign_of(const mpq_class& v) {
  const int s = sgn(v);
  return s > 0 ? Sign::positive : (s < 0 ? Sign::negative : Sign::zero);
}

QVec3 qsub(const QVec3& a, const QVec3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
QVec3 qcross(const QVec3& a, const QVec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
std::optional<QVec3> exact_segment_plane_crossing(Vec3 p, Vec3 q, Vec3 t0, Vec3 t1, Vec3 t2) {
  const QVec3 n = qcross(qsub(exact(t1), exact(t0)), qsub(exact(t2), exact(t0)));
  const mpq_class dp = qdot(n, qsub(exact(p), exact(t0))), dq = qdot(n, qsub(exact(q), exact(t0)));
  if (sgn(dp) * sgn(dq) >= 0) return std::nullopt;
  const mpq_class t = dp / (dp - dq);
  const QVec3 a = exact(p), b = exact(q);
  return QVec3{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
}

mpq_class qdot(const QVec3& a, const QVec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
bool qzero(const QVec3& a) {
  return a.x == 0 && a.y == 0 && a.z == 0;
}

Sign exact_orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const QVec2 qa = exact(a), qb = exact(b), qc = exact(c);
  return sign_of((qb.x - qa.x) * (qc.y - qa.y) - (qb.y - qa.y) * (qc.x - qa.x));
}

Sign exact_orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const QVec3 qa = exact(a);
  return sign_of(qdot(qcross(qsub(exact(b), qa), qsub(exact(c), qa)), qsub(exact(d), qa)));
}

Sign exact_side_of_plane(const Plane& plane, Vec3 p) {
  return sign_of(mpq_class(plane.a) * p.x + mpq_class(plane.b) * p.y + mpq_class(plane.c) * p.z +
                 mpq_class(plane.d));
}

Sign exact_side_of_line(const HalfPlane& half_plane, Vec2 p) {
  return sign_of(mpq_class(half_plane.a) * p.x + mpq_class(half_plane.b) * p.y +
                 mpq_class(half_plane.c));
}

Sign exact_side_of_sphere(const Sphere& sphere, Vec3 p) {
  const QVec3 d = qsub(exact(p), exact(sphere.center));
  const mpq_class r(sphere.radius);
  return sign_of(r * r - qdot(d, d));
}

Sign exact_side_of_circle(const Circle& circle, Vec2 p) {
  const mpq_class dx = mpq_class(p.x) - circle.center.x, dy = mpq_class(p.y) - circle.center.y;
  const mpq_class r(circle.radius);
  return sign_of(r * r - dx * dx - dy * dy);
}

Sign exact_cross_dot(Vec3 a, Vec3 b, Vec3 p, Vec3 c) {
  const QVec3 qa = exact(a), ab = qsub(exact(b), qa);
  return sign_of(qdot(qcross(ab, qsub(exact(p), qa)), qcross(ab, qsub(exact(c), qa))));
}

mpq_class exact_volume(const Mesh& mesh) {
  mpq_class six = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle3 tri = mesh.triangle(t);
    six += qdot(exact(tri.a), qcross(exact(tri.b), exact(tri.c)));
  }
  return six / 6;
}

}  // namespace contain::test
