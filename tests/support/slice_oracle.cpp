#include "support/slice_oracle.h"

#include <algorithm>

#include "support/exact.h"

namespace contain::test {

namespace {

double coord(Vec3 p, int i) {
  return i == 0 ? p.x : (i == 1 ? p.y : p.z);
}

const mpq_class& perturbation() {
  static const mpq_class e = [] {
    mpz_class den = 1;
    den <<= 300;
    return mpq_class(mpz_class(1), den);
  }();
  return e;
}

mpq_class orient(const mpq_class& ax, const mpq_class& ay, const mpq_class& bx, const mpq_class& by,
                 const mpq_class& cx, const mpq_class& cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

// Where the ray along +axis from the moved point crosses triangle t: nothing when it misses or
// the triangle is vertical; else the crossing height and the sign of the normal's axis part.
struct Hit {
  bool hit = false;
  mpq_class height;
  int sign = 0;
};
Hit vertical_hit(const Triangle3& t, int axis, Vec2 p) {
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  const Vec3 corners[3] = {t.a, t.b, t.c};
  double lo_u = coord(t.a, u), hi_u = lo_u, lo_v = coord(t.a, v), hi_v = lo_v;
  for (const Vec3& q : corners) {
    lo_u = std::min(lo_u, coord(q, u));
    hi_u = std::max(hi_u, coord(q, u));
    lo_v = std::min(lo_v, coord(q, v));
    hi_v = std::max(hi_v, coord(q, v));
  }
  Hit out;
  if (p.x < lo_u || p.x > hi_u || p.y < lo_v || p.y > hi_v) return out;
  const mpq_class& e = perturbation();
  const mpq_class pu = mpq_class(p.x) + e;
  const mpq_class pv = mpq_class(p.y) + e * e;
  mpq_class cu[3], cv[3];
  for (int i = 0; i < 3; ++i) {
    cu[i] = coord(corners[i], u);
    cv[i] = coord(corners[i], v);
  }
  const mpq_class area = orient(cu[0], cv[0], cu[1], cv[1], cu[2], cv[2]);
  if (area == 0) return out;
  mpq_class w[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int k = (i + 2) % 3;
    w[i] = orient(cu[j], cv[j], cu[k], cv[k], pu, pv);  // the sub-area opposite corner i
    if (sgn(w[i]) != 0 && sgn(w[i]) != sgn(area)) return out;
  }
  out.hit = true;
  out.sign = sgn(area);
  out.height = (w[0] * coord(corners[0], axis) + w[1] * coord(corners[1], axis) +
                w[2] * coord(corners[2], axis)) /
               area;
  return out;
}

}  // namespace

SideWindings oracle_side_windings(const Mesh& mesh, int axis, Vec2 p, double c) {
  // The winding number at a point is the signed count of the surface crossings of a ray from it
  // to infinity, +1 where the ray leaves through a face whose normal points along the ray.
  SideWindings out;
  const mpq_class plane(c);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Hit h = vertical_hit(mesh.triangle(t), axis, p);
    if (!h.hit) continue;
    if (h.height > plane) out.above += h.sign;
    if (h.height >= plane) out.below += h.sign;
  }
  return out;
}

bool oracle_in_section(const Mesh& mesh, int axis, Vec2 p, double c) {
  const SideWindings w = oracle_side_windings(mesh, axis, p, c);
  return w.above > 0 && w.below > 0;
}

bool oracle_in_shadow(const Mesh& mesh, int axis, Vec2 p) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (vertical_hit(mesh.triangle(t), axis, p).hit) return true;
  }
  return false;
}

QPoint2 oracle_crossing(Vec3 a, Vec3 b, int axis, double c) {
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  const mpq_class t =
      (mpq_class(c) - coord(a, axis)) / (mpq_class(coord(b, axis)) - coord(a, axis));
  return {mpq_class(coord(a, u)) + t * (mpq_class(coord(b, u)) - coord(a, u)),
          mpq_class(coord(a, v)) + t * (mpq_class(coord(b, v)) - coord(a, v))};
}

}  // namespace contain::test
