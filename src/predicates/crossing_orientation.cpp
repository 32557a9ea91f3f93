// Orientations of constructed points by their defining doubles: expansions on exact differences
// (the common case of inputs on a grid, where these predicates are asked), big numbers otherwise.

#include "contain/predicates/crossing_orientation.h"

#include <array>
#include <cmath>

#include "contain/predicates/big_float.h"
#include "predicates/expansion.h"

namespace contain::predicates {
namespace {

using detail::Expansion;

double coordinate(Vec3 p, int i) {
  return i == 0 ? p.x : (i == 1 ? p.y : p.z);
}

// Magnitudes for which products of up to five differences of the inputs, and sums of a few dozen
// of them, neither overflow nor underflow inside expansion arithmetic: a difference is below
// 2^191, a product of five below 2^955 (Dekker's split needs its operands below 2^996); every
// nonzero input is a multiple of 2^-212, so a product of five is a multiple of 2^-1060 and its
// tail is representable.
bool in_range(double x) {
  const double m = std::fabs(x);
  return m == 0.0 || (m >= 0x1p-160 && m < 0x1p190);
}

// x - y as one double, or false when it is not exact (or out of range).
bool exact_difference(double x, double y, double& d) {
  if (!in_range(x) || !in_range(y)) return false;
  double tail = 0.0;
  detail::two_diff(x, y, d, tail);
  return tail == 0.0;
}

// orient2d(a, b, c) = (b - a) x (c - a) on exact differences.
bool orient2d_expansion(Vec2 a, Vec2 b, Vec2 c, Expansion<4>& out) {
  double d[4];
  if (!exact_difference(b.x, a.x, d[0]) || !exact_difference(b.y, a.y, d[1]) ||
      !exact_difference(c.x, a.x, d[2]) || !exact_difference(c.y, a.y, d[3])) {
    return false;
  }
  out = Expansion<1>(d[0]) * Expansion<1>(d[3]) - Expansion<1>(d[1]) * Expansion<1>(d[2]);
  return true;
}

// orient3d(t0, t1, t2, p) = ((t1 - t0) x (t2 - t0)) . (p - t0) on exact differences.
bool orient3d_expansion(Vec3 t0, Vec3 t1, Vec3 t2, Vec3 p, Expansion<24>& out) {
  double e[9];
  const Vec3 rows[3] = {t1, t2, p};
  for (int r = 0; r < 3; ++r) {
    for (int i = 0; i < 3; ++i) {
      if (!exact_difference(coordinate(rows[r], i), coordinate(t0, i), e[3 * r + i])) return false;
    }
  }
  const auto x = [&](int i) { return Expansion<1>(e[i]); };
  const Expansion<4> nx = x(1) * x(5) - x(2) * x(4);
  const Expansion<4> ny = x(2) * x(3) - x(0) * x(5);
  const Expansion<4> nz = x(0) * x(4) - x(1) * x(3);
  out = nx * x(6) + ny * x(7) + nz * x(8);
  return true;
}

BigFloat orient2d_big(Vec2 a, Vec2 b, Vec2 c) {
  const BigFloat ax(a.x), ay(a.y);
  return (BigFloat(b.x) - ax) * (BigFloat(c.y) - ay) - (BigFloat(b.y) - ay) * (BigFloat(c.x) - ax);
}

BigFloat orient3d_big(Vec3 t0, Vec3 t1, Vec3 t2, Vec3 p) {
  const BigVec3 o = to_big(t0);
  return dot(cross(to_big(t1) - o, to_big(t2) - o), to_big(p) - o);
}

Vec2 project(Vec3 p, int u, int v) {
  return {coordinate(p, u), coordinate(p, v)};
}

}  // namespace

Sign orient2d_of_crossing(Vec2 a, Vec2 b, Vec3 p, Vec3 q, Vec3 t0, Vec3 t1, Vec3 t2, int u, int v) {
  const Vec2 pp = project(p, u, v), pq = project(q, u, v);
  // The side of p decides the direction of dq - dp. dp is orient3d(t0, t1, t2, p) itself, the
  // same determinant ((t1 - t0) x (t2 - t0)) . (p - t0) exactly (an expansion on exact
  // differences, or big numbers), so its sign is orient3d's: no third evaluation.
  Expansion<4> fp, fq;
  Expansion<24> dp, dq;
  if (orient2d_expansion(a, b, pp, fp) && orient2d_expansion(a, b, pq, fq) &&
      orient3d_expansion(t0, t1, t2, p, dp) && orient3d_expansion(t0, t1, t2, q, dq)) {
    const Sign s = (dp * fq - dq * fp).sign();
    return dp.sign() == Sign::negative ? -s : s;
  }
  const BigFloat big_dp = orient3d_big(t0, t1, t2, p);
  const Sign s =
      (big_dp * orient2d_big(a, b, pq) - orient3d_big(t0, t1, t2, q) * orient2d_big(a, b, pp))
          .sign();
  return big_dp.sign() == Sign::negative ? -s : s;
}

Sign orient2d_of_centroid(Vec2 a, Vec2 b, Vec2 c0, Vec2 c1, Vec2 c2) {
  Expansion<4> o[3];
  if (orient2d_expansion(a, b, c0, o[0]) && orient2d_expansion(a, b, c1, o[1]) &&
      orient2d_expansion(a, b, c2, o[2])) {
    return (o[0] + o[1] + o[2]).sign();
  }
  return (orient2d_big(a, b, c0) + orient2d_big(a, b, c1) + orient2d_big(a, b, c2)).sign();
}

Sign orient3d_of_centroid(Vec3 a, Vec3 b, Vec3 c, Vec3 d0, Vec3 d1, Vec3 d2) {
  Expansion<24> o[3];
  if (orient3d_expansion(a, b, c, d0, o[0]) && orient3d_expansion(a, b, c, d1, o[1]) &&
      orient3d_expansion(a, b, c, d2, o[2])) {
    return (o[0] + o[1] + o[2]).sign();
  }
  return (orient3d_big(a, b, c, d0) + orient3d_big(a, b, c, d1) + orient3d_big(a, b, c, d2)).sign();
}

}  // namespace contain::predicates
