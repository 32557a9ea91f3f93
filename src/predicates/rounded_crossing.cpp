#include "contain/predicates/rounded_crossing.h"

#include <array>
#include <cmath>
#include <utility>

#include "contain/predicates/big_float.h"
#include "predicates/nearest_double.h"

namespace contain::predicates {

namespace {

double coord(Vec3 p, int k) {
  return k == 0 ? p.x : (k == 1 ? p.y : p.z);
}
void set_coord(Vec3& p, int k, double x) {
  (k == 0 ? p.x : (k == 1 ? p.y : p.z)) = x;
}

// x_j = p_j + (q_j - p_j)(c - p_k) / (q_k - p_k): the base p_j plus an offset whose numerator
// and denominator are products of differences of doubles (degree 2 over degree 1), signs taken
// so that the denominator is positive. The base is the endpoint nearer to the plane, so the
// offset, and its rounding error, is the smaller part.
double crossing_coordinate(Vec3 p, Vec3 q, int k, int j, double c) {
  using detail::Mag;
  const bool up = coord(q, k) > coord(p, k);
  const double lo = up ? coord(p, k) : c;
  const double hi = up ? c : coord(p, k);
  const Mag off = (Mag(coord(q, j)) - Mag(coord(p, j))) * (Mag(hi) - Mag(lo));
  const Mag den = up ? Mag(coord(q, k)) - Mag(coord(p, k)) : Mag(coord(p, k)) - Mag(coord(q, k));
  double out = 0.0;
  if (detail::offset_stage_a(coord(p, j), 1.0, detail::bounded(off), detail::bounded(den), out)) {
    return out;
  }
  const BigFloat pj(coord(p, j));
  const BigFloat d = up ? BigFloat(coord(q, k)) - BigFloat(coord(p, k))
                        : BigFloat(coord(p, k)) - BigFloat(coord(q, k));
  const BigFloat n = pj * d + (BigFloat(coord(q, j)) - pj) * (BigFloat(hi) - BigFloat(lo));
  return detail::quotient_stage_b(n, d);
}

}  // namespace

Vec3 rounded_axis_crossing(Vec3 a, Vec3 b, int axis, double c) {
  if (coord(a, axis) == c) return a;
  if (coord(b, axis) == c) return b;
  if (coord(a, axis) > coord(b, axis)) std::swap(a, b);
  // The nearer endpoint as base; which one does not change the exactly rounded answer.
  const bool from_b = coord(b, axis) - c < c - coord(a, axis);
  Vec3 out = a;
  set_coord(out, axis, c);
  for (int j = 0; j < 3; ++j) {
    if (j == axis) continue;
    if (coord(a, j) == coord(b, j)) {
      set_coord(out, j, coord(a, j));
      continue;
    }
    set_coord(
        out, j,
        from_b ? crossing_coordinate(b, a, axis, j, c) : crossing_coordinate(a, b, axis, j, c));
  }
  return out;
}

}  // namespace contain::predicates

namespace contain::predicates {

namespace {

using detail::Mag;

std::array<Mag, 3> diff(Vec3 x, Vec3 y) {
  return {Mag(x.x) - Mag(y.x), Mag(x.y) - Mag(y.y), Mag(x.z) - Mag(y.z)};
}

Mag dot(const std::array<Mag, 3>& u, const std::array<Mag, 3>& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

// Coordinate j of the crossing, exactly: (p_j d_q - q_j d_p) / (d_q - d_p), nearest double.
double exact_plane_crossing(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c, int j) {
  const BigVec3 ba = to_big(a);
  const BigVec3 n = cross(to_big(b) - ba, to_big(c) - ba);
  const BigFloat dp = predicates::dot(n, to_big(p) - ba), dq = predicates::dot(n, to_big(q) - ba);
  BigFloat num = BigFloat(coord(p, j)) * dq - BigFloat(coord(q, j)) * dp;
  BigFloat den = dq - dp;
  if (den.sign() == Sign::negative) {
    num = -num;
    den = -den;
  }
  return detail::quotient_stage_b(num, den);
}

}  // namespace

Vec3 rounded_plane_crossing(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  const std::array<Mag, 3> ab = diff(b, a), ac = diff(c, a);
  const std::array<Mag, 3> n = {ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
                                ab[0] * ac[1] - ab[1] * ac[0]};
  Mag dp = dot(n, diff(p, a)), dq = dot(n, diff(q, a));
  // The nearer endpoint as base (its offset, and the offset's error, is the smaller part);
  // which one does not change the exactly rounded answer.
  if (std::fabs(dp.v) > std::fabs(dq.v)) {
    std::swap(p, q);
    std::swap(dp, dq);
  }
  // x_j = p_j + (q_j - p_j) d_p / D with D = d_p - d_q = n . (p - q), taken positive.
  const Mag den = dot(n, diff(p, q));
  const double sign = den.v < 0 ? -1.0 : 1.0;
  detail::ErrLD d = detail::bounded(den);
  d.value = std::fabs(d.value);
  Vec3 out = p;
  for (int j = 0; j < 3; ++j) {
    if (coord(p, j) == coord(q, j)) continue;  // the exact coordinate is p_j
    const Mag off = (Mag(coord(q, j)) - Mag(coord(p, j))) * dp;
    double x = 0.0;
    if (!detail::offset_stage_a(coord(p, j), sign, detail::bounded(off), d, x)) {
      x = exact_plane_crossing(p, q, a, b, c, j);
    }
    set_coord(out, j, x);
  }
  return out;
}

}  // namespace contain::predicates
