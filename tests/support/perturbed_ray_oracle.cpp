#include "support/perturbed_ray_oracle.h"

#include <gmpxx.h>

#include <algorithm>

#include "support/exact.h"

namespace contain::test {
namespace {

struct Q3 {
  mpq_class x, y, z;
};
Q3 q3(Vec3 v) {
  return {mpq_class(v.x), mpq_class(v.y), mpq_class(v.z)};
}
Q3 sub(const Q3& a, const Q3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Q3 cross(const Q3& a, const Q3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
mpq_class dot(const Q3& a, const Q3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
bool is_zero(const Q3& a) {
  return a.x == 0 && a.y == 0 && a.z == 0;
}

const mpq_class& epsilon() {
  static const mpq_class e = [] {
    mpz_class den = 1;
    den <<= 300;
    return mpq_class(mpz_class(1), den);
  }();
  return e;
}

// 2D orientation in (y, z) of a, b, p.
mpq_class orient_yz(const Q3& a, const Q3& b, const mpq_class& py, const mpq_class& pz) {
  return (b.y - a.y) * (pz - a.z) - (b.z - a.z) * (py - a.y);
}

// q on the closed segment [a, b] (exact).
bool on_segment(const Q3& a, const Q3& b, const Q3& q) {
  if (!is_zero(cross(sub(b, a), sub(q, a)))) return false;
  const mpq_class t = dot(sub(q, a), sub(b, a));
  return t >= 0 && t <= dot(sub(b, a), sub(b, a));
}

}  // namespace

bool oracle_ray_crosses(const Triangle3& t, Vec3 q) {
  // Speed only: the perturbed line has y in (q.y, q.y + e] and z likewise; a triangle whose
  // (y, z) box it misses is missed (plain comparisons, exact).
  if (q.y < std::min({t.a.y, t.b.y, t.c.y}) || q.y > std::max({t.a.y, t.b.y, t.c.y}) ||
      q.z < std::min({t.a.z, t.b.z, t.c.z}) || q.z > std::max({t.a.z, t.b.z, t.c.z})) {
    return false;
  }
  const Q3 a = q3(t.a), b = q3(t.b), c = q3(t.c), p = q3(q);
  const mpq_class& e = epsilon();
  const mpq_class py = p.y + e, pz = p.z + e * e;
  const mpq_class s = orient_yz(a, b, c.y, c.z);
  if (s == 0) return false;
  const mpq_class o1 = orient_yz(a, b, py, pz), o2 = orient_yz(b, c, py, pz),
                  o3 = orient_yz(c, a, py, pz);
  const bool inside = s > 0 ? (o1 > 0 && o2 > 0 && o3 > 0) : (o1 < 0 && o2 < 0 && o3 < 0);
  if (!inside) return false;
  // n . (r - a) = 0 on the line r = (x, py, pz): x = a.x - (n.y (py - a.y) + n.z (pz - a.z)) / n.x
  const Q3 n = cross(sub(b, a), sub(c, a));
  const mpq_class x = a.x - (n.y * (py - a.y) + n.z * (pz - a.z)) / n.x;
  return x > p.x;
}

bool oracle_on_triangle(const Triangle3& t, Vec3 q) {
  if (q.x < std::min({t.a.x, t.b.x, t.c.x}) || q.x > std::max({t.a.x, t.b.x, t.c.x}) ||
      q.y < std::min({t.a.y, t.b.y, t.c.y}) || q.y > std::max({t.a.y, t.b.y, t.c.y}) ||
      q.z < std::min({t.a.z, t.b.z, t.c.z}) || q.z > std::max({t.a.z, t.b.z, t.c.z})) {
    return false;
  }
  const Q3 a = q3(t.a), b = q3(t.b), c = q3(t.c), p = q3(q);
  const Q3 n = cross(sub(b, a), sub(c, a));
  if (is_zero(n)) return on_segment(a, b, p) || on_segment(b, c, p) || on_segment(c, a, p);
  if (dot(n, sub(p, a)) != 0) return false;
  return dot(cross(sub(b, a), sub(p, a)), n) >= 0 && dot(cross(sub(c, b), sub(p, b)), n) >= 0 &&
         dot(cross(sub(a, c), sub(p, c)), n) >= 0;
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

}  // namespace contain::test
