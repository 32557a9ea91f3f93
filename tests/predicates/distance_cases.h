#pragma once
/// \file
/// Point-triangle cases for the distance oracle tests: uniform, on vertices, edges and faces
/// (exactly, on lattices), 1e-9 off the surface, on the perpendicular planes that separate a
/// triangle's vertex, edge and face regions, degenerate triangles (collinear, coincident corners),
/// far points, and every kind scaled by a power of two from 2^-1000 to 2^900.

#include <cmath>

#include "contain/values/triangle.h"
#include "contain/values/vec.h"
#include "predicates/cases.h"

namespace contain::test {

struct PointTriangleCase {
  Vec3 p;
  Triangle3 t;
};

[[nodiscard]] inline Vec3 uniform_vec(CaseRng& rng, double scale) {
  return {rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale, rng.uniform(-1, 1) * scale};
}
[[nodiscard]] inline Vec3 lattice_vec(CaseRng& rng, int bits) {
  return {rng.small_integer(bits), rng.small_integer(bits), rng.small_integer(bits)};
}
[[nodiscard]] inline Vec3 scaled_vec(Vec3 v, double s) {
  return {v.x * s, v.y * s, v.z * s};
}

/// One case of kind `kind` (0..11).
[[nodiscard]] inline PointTriangleCase point_triangle_case(CaseRng& rng, int kind) {
  const Vec3 a = lattice_vec(rng, 10), u = lattice_vec(rng, 5), v = lattice_vec(rng, 5);
  Triangle3 lattice_tri{a, a + u, a + v};
  switch (kind) {
    case 0:  // uniform
      return {uniform_vec(rng, 1), {uniform_vec(rng, 1), uniform_vec(rng, 1), uniform_vec(rng, 1)}};
    case 1: {  // exactly on a vertex
      const Triangle3 t{uniform_vec(rng, 1), uniform_vec(rng, 1), uniform_vec(rng, 1)};
      const Vec3 corners[3] = {t.a, t.b, t.c};
      return {corners[rng.integer(0, 2)], t};
    }
    case 2: {  // exactly on an edge (lattice, dyadic parameter)
      const double s = static_cast<double>(rng.integer(0, 16)) / 16.0;
      return {a + s * u, lattice_tri};
    }
    case 3: {  // exactly on the face
      const double s = static_cast<double>(rng.integer(0, 8)) / 16.0;
      const double r = static_cast<double>(rng.integer(0, 8)) / 16.0;
      return {a + s * u + r * v, lattice_tri};
    }
    case 4: {  // 1e-9 off the surface, near a random point of the triangle
      const Triangle3 t{uniform_vec(rng, 1), uniform_vec(rng, 1), uniform_vec(rng, 1)};
      double s = rng.uniform(0, 1), r = rng.uniform(0, 1);
      if (s + r > 1) {
        s = 1 - s;
        r = 1 - r;
      }
      if (rng.integer(0, 2) == 0) r = 0;  // on an edge
      const Vec3 on = t.a + s * (t.b - t.a) + r * (t.c - t.a);
      return {on + scaled_vec(uniform_vec(rng, 1), 1e-9), t};
    }
    case 5: {  // on the planes separating the vertex, edge and face regions (exact zeros)
      const Vec3 w = cross(u, lattice_vec(rng, 3));
      const Vec3 n = cross(u, v);
      const double k = rng.small_integer(3);
      switch (rng.integer(0, 2)) {
        case 0:  // perpendicular to edge a b through a
          return {a + w, lattice_tri};
        case 1:  // perpendicular to edge a b through b
          return {a + u + w, lattice_tri};
        default:  // above the edge a b, along the normal (the edge-face boundary)
          return {a + 0.5 * u + k * n, lattice_tri};
      }
    }
    case 6: {  // collinear corners
      const double k = rng.small_integer(3);
      return {lattice_vec(rng, 11), {a, a + u, a + k * u}};
    }
    case 7: {  // coincident corners
      const Vec3 p = lattice_vec(rng, 11);
      switch (rng.integer(0, 2)) {
        case 0:
          return {p, {a, a, a + v}};
        case 1:
          return {p, {a, a + v, a}};
        default:
          return {p, {a, a, a}};
      }
    }
    case 8:  // far away
      return {uniform_vec(rng, 1e8),
              {uniform_vec(rng, 1), uniform_vec(rng, 1), uniform_vec(rng, 1)}};
    case 9:  // lattice points near a lattice triangle (many exact ties between regions)
      return {lattice_vec(rng, 6) + a, lattice_tri};
    case 10: {  // a sliver: one corner a few ulps off the line of the other two
      const Vec3 b = uniform_vec(rng, 1), c = uniform_vec(rng, 1);
      const Vec3 mid = 0.5 * (b + c);
      return {uniform_vec(rng, 1), {b, c, {rng.nudge(mid.x, 4), rng.nudge(mid.y, 4), mid.z}}};
    }
    default: {  // mixed magnitudes
      return {{rng.scaled(300), rng.scaled(300), rng.scaled(300)},
              {{rng.scaled(300), rng.scaled(300), rng.scaled(300)},
               {rng.scaled(300), rng.scaled(300), rng.scaled(300)},
               {rng.scaled(300), rng.scaled(300), rng.scaled(300)}}};
    }
  }
}

/// The case scaled by 2^k (exact unless it underflows): the answers scale with it.
[[nodiscard]] inline PointTriangleCase scaled_case(const PointTriangleCase& c, int k) {
  const double s = std::ldexp(1.0, k);
  return {scaled_vec(c.p, s), {scaled_vec(c.t.a, s), scaled_vec(c.t.b, s), scaled_vec(c.t.c, s)}};
}

}  // namespace contain::test
