#include "contain/predicates/rounded_crossing.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>

#include "contain/predicates/big_float.h"
#include "predicates/expansion.h"
#include "predicates/nearest_double.h"
#include "predicates/stages.h"

namespace contain::predicates {

namespace detail {

namespace {

constexpr double kUd = 0x1p-53;  // unit roundoff of double (kU is long double's)

// Differences in this range keep the filter's products exact by two_product: rho0 lies in
// [2^-401, 1 + 2^-51], h1 rho0 and rho0 h3 in [2^-602, 2^201] with tails above 2^-710, normal.
bool in_filter_range(double x) {
  const double a = std::fabs(x);
  return a >= 0x1p-200 && a <= 0x1p200;
}

// True when every value cand + z + d with |d| <= bound rounds to cand: strictly inside the
// interval between the midpoints to cand's neighbours (half an ulp away from zero; a quarter of
// the next ulp toward zero when |cand| is a power of two). A normal cand only, so that those
// half gaps are exact powers of two. The comparisons are rounded: the slack 2^-50 of the half
// gap covers their error (at most 2^-52 of it where the test is close).
bool rounds_to(double cand, double z, double bound) {
  const double a = std::fabs(cand);
  if (!(a >= 0x1p-1000 && a <= 0x1p1000)) return false;
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(a);
  const double power = std::bit_cast<double>(bits & 0x7FF0000000000000ULL);  // 2^e <= a
  const double away = power * 0x1p-53;
  const double toward = (bits & 0x000FFFFFFFFFFFFFULL) == 0 ? away / 2 : away;
  const double z_away = cand > 0 ? z : -z;
  constexpr double kSlack = 1 - 0x1p-50;
  return z_away + bound < away * kSlack && z_away - bound > -(toward * kSlack);
}

}  // namespace

// X = p + d1 rho with d1 = q - p and rho = d2 / d3, d2 = c - pk, d3 = qk - pk. rho is shared by
// the coordinates of one crossing and costs one division: rho0 = fl(fl(d2) fl(1 / fl(d3))), within
// 4.01 u of rho (u = 2^-53; four roundings).
CrossingRatio crossing_ratio(double pk, double qk, double c) {
  CrossingRatio out;
  out.pk = pk;
  out.qk = qk;
  out.c = c;
  const double h2 = c - pk;
  const double h3 = qk - pk;
  if (!in_filter_range(h2) || !in_filter_range(h3)) return out;
  out.inverse = 1 / h3;
  out.rho0 = h2 * out.inverse;
  out.valid = true;
  return out;
}

// The quick stage: t = fl(fl(q - p) rho0) is within 6.02 u |T| of T = d1 rho (six roundings) and
// p + t = s + e exactly (two_sum), so X = s + e + d with |d| <= 6.03 u |t| < 7 u |t| (the bound's
// own rounding included). Certain when X is not within that of a rounding boundary: most
// crossings of a fine mesh, whose offsets |X - p| are small beside |X|.
bool rounded_offset_quick(double p, double q, const CrossingRatio& rho, double& out) {
  if (!rho.valid) return false;
  const double h1 = q - p;
  if (!in_filter_range(h1) || !(std::fabs(p) <= 0x1p200)) return false;
  const double t = h1 * rho.rho0;
  double s, e;
  two_sum(p, t, s, e);
  if (!rounds_to(s, e, 7 * kUd * std::fabs(t))) return false;
  out = s;
  return true;
}

// The double-double ratio: each difference d = h + l exactly (two_diff), the residual
// R = d2 - rho0 d3 = (h2 - qh) - ql + l2 - rho0 l3 from the exact product rho0 h3 = qh + ql, and
// rho1 = fl(r i) with i = fl(1 / h3), within 2.01 u of r / h3; so rho = rho0 + rho1 + e with
// (S the sum of the residual terms' absolute values) |R - r| <= 4.1 u S (four terms, one
// rounded product) and |e| <= 3.03 u |rho1| + 4.2 u S / |h3| (d3 = h3 (1 + t), |t| <= u).
// Products that underflow add at most 2^-1075 each: after the division by |h3| >= 2^-200,
// under the 2^-860 term.
void refine_ratio(CrossingRatio& rho) {
  if (!rho.valid || rho.refined) return;
  double h2, l2, h3, l3;
  two_diff(rho.c, rho.pk, h2, l2);
  two_diff(rho.qk, rho.pk, h3, l3);
  double qh, ql;
  two_product(rho.rho0, h3, qh, ql);
  const double terms[] = {h2 - qh, -ql, l2, -(rho.rho0 * l3)};
  double r = 0.0;
  double size = 0.0;
  for (const double x : terms) {
    r += x;
    size += std::fabs(x);
  }
  rho.rho1 = r * rho.inverse;
  rho.error = 4 * kUd * std::fabs(rho.rho1) + 5 * kUd * (size * std::fabs(rho.inverse)) + 0x1p-860;
  rho.refined = true;
}

// Then d1 rho = ph + pl + h1 rho1 + l1 rho0 + l1 rho1 + d1 e with h1 rho0 = ph + pl exactly:
// the small terms summed into r2 lose at most 4.1 u S2, and |d1 e| <= 1.01 |h1| |e|. p + ph =
// s + f exactly (two_sum), w = fl(f + r2) adds 1.01 u |w|, and s + w = cand + z exactly: X =
// cand + z + d with |d| under the bound below, whose constants (5, 1.1, 2) exceed the derived
// ones by margins covering the rounding of the bound; 2^-800 covers underflowed products. The
// bound is about 20 u^2 |X - p|: only values that close to a rounding boundary go on.
bool rounded_offset(double p, double q, const CrossingRatio& rho, double& out) {
  if (!rho.valid || !rho.refined) return false;
  double h1, l1;
  two_diff(q, p, h1, l1);
  if (!in_filter_range(h1) || !(std::fabs(p) <= 0x1p200)) return false;
  double ph, pl;
  two_product(h1, rho.rho0, ph, pl);
  const double terms[] = {pl, h1 * rho.rho1, l1 * rho.rho0, l1 * rho.rho1};
  double r = 0.0;
  double size = 0.0;
  for (const double x : terms) {
    r += x;
    size += std::fabs(x);
  }
  double s, f;
  two_sum(p, ph, s, f);
  const double w = f + r;
  double cand, z;
  two_sum(s, w, cand, z);
  const double bound =
      5 * kUd * size + 1.1 * std::fabs(h1) * rho.error + 2 * kUd * std::fabs(w) + 0x1p-800;
  if (!rounds_to(cand, z, bound)) return false;
  out = cand;
  return true;
}

bool rounded_crossing_filter(double p, double q, double pk, double qk, double c, double& out) {
  CrossingRatio rho = crossing_ratio(pk, qk, c);
  if (rounded_offset_quick(p, q, rho, out)) return true;
  refine_ratio(rho);
  return rounded_offset(p, q, rho, out);
}

// x = p + (q - p)(c - pk) / (qk - pk): the base p plus an offset whose numerator and
// denominator are products of differences of doubles (degree 2 over degree 1), signs taken
// so that the denominator is positive.
double rounded_crossing_exact(double p, double q, double pk, double qk, double c) {
  const bool up = qk > pk;
  const double lo = up ? pk : c;
  const double hi = up ? c : pk;
  const Mag off = (Mag(q) - Mag(p)) * (Mag(hi) - Mag(lo));
  const Mag den = up ? Mag(qk) - Mag(pk) : Mag(pk) - Mag(qk);
  double out = 0.0;
  if (offset_stage_a(p, 1.0, bounded(off), bounded(den), out)) return out;
  const BigFloat bp(p);
  const BigFloat d = up ? BigFloat(qk) - BigFloat(pk) : BigFloat(pk) - BigFloat(qk);
  const BigFloat n = bp * d + (BigFloat(q) - bp) * (BigFloat(hi) - BigFloat(lo));
  return quotient_stage_b(n, d);
}

}  // namespace detail

namespace {

// The base p is the endpoint nearer to the plane, so the offset, and its rounding error, is
// the smaller part.
double crossing_coordinate(Vec3 p, Vec3 q, int k, int j, double c, detail::CrossingRatio& rho) {
  double out = 0.0;
  if (detail::rounded_offset_quick(component(p, j), component(q, j), rho, out)) return out;
  detail::refine_ratio(rho);
  if (detail::rounded_offset(component(p, j), component(q, j), rho, out)) return out;
  return detail::rounded_crossing_exact(component(p, j), component(q, j), component(p, k),
                                        component(q, k), c);
}

}  // namespace

Vec3 rounded_axis_crossing(Vec3 a, Vec3 b, int axis, double c) {
  if (component(a, axis) == c) return a;
  if (component(b, axis) == c) return b;
  if (component(a, axis) > component(b, axis)) std::swap(a, b);
  // The nearer endpoint as base; which one does not change the exactly rounded answer.
  const bool from_b = component(b, axis) - c < c - component(a, axis);
  const Vec3 base = from_b ? b : a;
  const Vec3 other = from_b ? a : b;
  // The ratio (c - base) / (other - base) in double-double, shared by both coordinates.
  detail::CrossingRatio rho =
      detail::crossing_ratio(component(base, axis), component(other, axis), c);
  Vec3 out = a;
  component_ref(out, axis) = c;
  for (int j = 0; j < 3; ++j) {
    if (j == axis) continue;
    if (component(a, j) == component(b, j)) {
      component_ref(out, j) = component(a, j);
      continue;
    }
    component_ref(out, j) = crossing_coordinate(base, other, axis, j, c, rho);
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
  BigFloat num = BigFloat(component(p, j)) * dq - BigFloat(component(q, j)) * dp;
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
    if (component(p, j) == component(q, j)) continue;  // the exact coordinate is p_j
    const Mag off = (Mag(component(q, j)) - Mag(component(p, j))) * dp;
    double x = 0.0;
    if (!detail::offset_stage_a(component(p, j), sign, detail::bounded(off), d, x)) {
      x = exact_plane_crossing(p, q, a, b, c, j);
    }
    component_ref(out, j) = x;
  }
  return out;
}

}  // namespace contain::predicates
