#include "support/perturbed_ray_oracle.h"

#include <gmpxx.h>

#include <algorithm>

#include "support/exact.h"

namespace contain::test {
namespace {

const mpq_class& epsilon() {
  static const mpq_class e = [] {
    mpz_class den = 1;
    den <<= 300;
    return mpq_class(mpz_class(1), den);
  }();
  return e;
}

// 2D orientation in (y, z) of a, b, p.
mpq_class orient_yz(const QVec3& a, const QVec3& b, const mpq_class& py, const mpq_class& pz) {
  return (b.y - a.y) * (pz - a.z) - (b.z - a.z) * (py - a.y);
}

// q on the closed segment [a, b] (exact).
bool on_segment(const QVec3& a, const QVec3& b, const QVec3& q) {
  if (!qzero(qcross(qsub(b, a), qsub(q, a)))) return false;
  const mpq_class t = qdot(qsub(q, a), qsub(b, a));
  return t >= 0 && t <= qdot(qsub(b, a), qsub(b, a));
}

}  // namespace

bool oracle_ray_crosses(const Triangle3& t, Vec3 q) {
  // Speed only: the perturbed line has y in (q.y, q.y + e] and z likewise; a triangle whose
  // (y, z) box it misses is missed (plain comparisons, exact).
  if (q.y < std::min({t.a.y, t.b.y, t.c.y}) || q.y > std::max({t.a.y, t.b.y, t.c.y}) ||
      q.z < std::min({t.a.z, t.b.z, t.c.z}) || q.z > std::max({t.a.z, t.b.z, t.c.z})) {
    return false;
  }
  const QVec3 a = exact(t.a), b = exact(t.b), c = exact(t.c), p = exact(q);
  const mpq_class& e = epsilon();
  const mpq_class py = p.y + e, pz = p.z + e * e;
  const mpq_class s = orient_yz(a, b, c.y, c.z);
  if (s == 0) return false;
  const mpq_class o1 = orient_yz(a, b, py, pz), o2 = orient_yz(b, c, py, pz),
                  o3 = orient_yz(c, a, py, pz);
  const bool inside = s > 0 ? (o1 > 0 && o2 > 0 && o3 > 0) : (o1 < 0 && o2 < 0 && o3 < 0);
  if (!inside) return false;
  // n . (r - a) = 0 on the line r = (x, py, pz): x = a.x - (n.y (py - a.y) + n.z (pz - a.z)) / n.x
  const QVec3 n = qcross(qsub(b, a), qsub(c, a));
  const mpq_class x = a.x - (n.y * (py - a.y) + n.z * (pz - a.z)) / n.x;
  return x > p.x;
}

bool oracle_on_triangle(const Triangle3& t, Vec3 q) {
  if (q.x < std::min({t.a.x, t.b.x, t.c.x}) || q.x > std::max({t.a.x, t.b.x, t.c.x}) ||
      q.y < std::min({t.a.y, t.b.y, t.c.y}) || q.y > std::max({t.a.y, t.b.y, t.c.y}) ||
      q.z < std::min({t.a.z, t.b.z, t.c.z}) || q.z > std::max({t.a.z, t.b.z, t.c.z})) {
    return false;
  }
  const QVec3 a = exact(t.a), b = exact(t.b), c = exact(t.c), p = exact(q);
  const QVec3 n = qcross(qsub(b, a), qsub(c, a));
  if (qzero(n)) return on_segment(a, b, p) || on_segment(b, c, p) || on_segment(c, a, p);
  if (qdot(n, qsub(p, a)) != 0) return false;
  return qdot(qcross(qsub(b, a), qsub(p, a)), n) >= 0 &&
         qdot(qcross(qsub(c, b), qsub(p, b)), n) >= 0 &&
         qdot(qcross(qsub(a, c), qsub(p, c)), n) >= 0;
}

Location oracle_locate(const Mesh& mesh, Vec3 q) {
  bool odd = false;
  for (const TriangleIndices& tri : mesh.triangles) {
    const Triangle3 t{mesh.vertices[static_cast<std::size_t>(tri[0])],
                      mesh.vertices[static_cast<std::size_t>(tri[1])],
                      mesh.vertices[static_cast<std::size_t>(tri[2])]};
    if (oracle_on_triangle(t, q)) return Location::boundary;
    if (oracle_ray_crosses(t, q)) odd = !odd;
  }
  return odd ? Location::inside : Location::outside;
}

int oracle_winding(const Mesh& mesh, Vec3 q) {
  int w = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle3 tri = mesh.triangle(t);
    if (!oracle_ray_crosses(tri, q)) continue;
    const mpq_class nx = (mpq_class(tri.b.y) - tri.a.y) * (mpq_class(tri.c.z) - tri.a.z) -
                         (mpq_class(tri.b.z) - tri.a.z) * (mpq_class(tri.c.y) - tri.a.y);
    w += sgn(nx);
  }
  return w;
}

}  // namespace contain::test
