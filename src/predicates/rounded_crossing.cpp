#include "contain/predicates/rounded_crossing.h"

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
