#include "distance/triangle_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contain/predicates/unit_roundoff.h"
#include "contain/values/max_abs.h"
#include "distance/bound_constants.h"

namespace contain::distance::detail {

namespace {

// Ericson's closest point on a triangle (Real-Time Collision Detection, 5.1.5), in doubles: only
// a guess, bounded afterwards. Its parameters along the edges lie in [0, 1] as computed (each is
// d / (d - d') with d >= 0 >= d'), and inside the face they are nonnegative with a sum within a
// few ulps of 1.
inline Vec3 approximate_closest(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return a + v * ab;
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return a + w * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return b + w * (c - b);
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  // triangle_slack counts on v + w passing 1 by a few ulps at most; a sliver's noise (va
  // computed negative beside the edge tests) could give more, and a point off the triangle
  // would make the upper bound too small. A corner is on the triangle: always a valid guess.
  if (!(v >= 0 && w >= 0 && v + w <= 1 + 4 * kEps)) return a;
  return a + ab * v + ac * w;
}

// (p - v) . w minus a bound on its rounding error: a lower bound of the exact value with w
// taken as exact doubles. Each monomial passes one difference, one product and two sums:
// gamma_4 < 5 eps of the permanent; 8 eps leaves room for the rounding of the bound.
inline double separation_lower(Vec3 p, Vec3 v, Vec3 w) {
  const Vec3 d = p - v;
  const double s = (d.x * w.x + d.y * w.y) + d.z * w.z;
  const double perm = (std::fabs(d.x * w.x) + std::fabs(d.y * w.y)) + std::fabs(d.z * w.z);
  return s - 8 * kEps * perm;
}

// The lower bound of the squared distance from p to t given by the separation along w (any
// direction; `ww` is dot(w, w) as rounded): 0 where it proves nothing.
double point_triangle_separation(Vec3 p, const Triangle3& t, Vec3 w, double ww) {
  const double smin = std::min(
      {separation_lower(p, t.a, w), separation_lower(p, t.b, w), separation_lower(p, t.c, w)});
  if (smin > 0 && ww >= 0x1p-900 && std::isfinite(ww)) {
    const double r = smin / ww;
    if (r >= 0x1p-1000 && std::isfinite(r)) {
      // smin^2 / |w|^2 (smin > 0 is below the exact separation, so its square is too), with
      // ww = |w|^2 rounded (three squares and two sums: at most 3 eps low) and three more
      // roundings (quotient, product, the factor): (1 + eps)^3 (1 - 8 eps) / (1 - 3 eps) < 1.
      return smin * r * (1 - 8 * kEps);
    }
  }
  return 0.0;
}

}  // namespace

Vec3 approximate_closest_point(Vec3 p, const Triangle3& t) {
  return approximate_closest(p, t.a, t.b, t.c);
}

double triangle_slack(double max_abs) {
  // A computed point a + ab v + ac w (or a vertex, or on an edge) lies within
  // 4 eps (|a| + |ab| + |ac|) <= 20 eps M per coordinate of the exact a + v (b - a) + w (c - a)
  // for the computed v, w, and that point lies within 4 eps (|ab| + |ac|) <= 16 eps M of the
  // triangle (v + w may pass 1 by a few ulps): delta <= sqrt(3) * 36 eps M < 64 eps M. Then
  // (|u| + delta)^2 <= (1 + t) |u|^2 + (1 + 1 / t) delta^2 with t = 2^-20. The square may
  // underflow: plus one subnormal unit.
  const double delta = 64 * kEps * max_abs;
  return delta * delta * (1 + 0x1p20) * (1 + 0x1p-40) + std::numeric_limits<double>::denorm_min();
}

Vec3 triangle_bounds(Vec3 p, const Triangle3& t, double slack, double& lo, double& hi) {
  const Vec3 q = approximate_closest(p, t.a, t.b, t.c);
  const Vec3 w = p - q;
  const double ww = dot(w, w);
  // hi: |p - q| with |w| rounded per coordinate (relative eps each, 3 eps for the sum of
  // squares), times (1 + 2^-20) for the cross term, plus the slack.
  // Squares that underflow lose up to 2^-1075 each: 8 subnormal units cover them.
  hi = ww * (1 + 0x1p-19) + slack + 8 * std::numeric_limits<double>::denorm_min();
  if (!std::isfinite(hi)) hi = kInf;
  lo = point_triangle_separation(p, t, w, ww);
  return w;
}

TriangleSearch::TriangleSearch(std::span<const Triangle3> triangles,
                               const bvh::BuildOptions& options)
    : triangles_(triangles.begin(), triangles.end()) {
  std::vector<Vec3> corners;
  corners.reserve(3 * triangles_.size());
  for (const Triangle3& t : triangles_)
    for (int k = 0; k < 3; ++k)
      corners.push_back(t.corner(k));
  const double scale = values::max_abs(std::span<const Vec3>(corners));
  tree_ = SearchTree(corners, 3, options);
  ordered_.reserve(triangles_.size());
  planes_.reserve(triangles_.size());
  for (const std::int32_t i : tree_.items()) {
    ordered_.push_back(triangles_[static_cast<std::size_t>(i)]);
    planes_.emplace_back(ordered_.back());
  }
  slack_ = triangle_slack(scale);
  max_abs_ = scale;
}

PlaneBound::PlaneBound(const Triangle3& t) {
  const Vec3 n = cross(t.b - t.a, t.c - t.a);
  const double nn = dot(n, n);
  if (!(nn >= 0x1p-900) || !std::isfinite(nn)) return;  // k_ = 0: no bound
  const Vec3 u = n * (1.0 / std::sqrt(nn));
  const double uu = dot(u, u);
  const double d = dot(u, t.a);
  // e: max over the corners v of |u . v - d| (the exact value, u and d as stored): the computed
  // dot product is within 3.01 eps of the sum of |u_i v_i| (perm); 8 eps and the final factor
  // cover that and the roundings of this bound; 2^-1000 covers products that underflow.
  double e = 0.0;
  for (const Vec3 v : {t.a, t.b, t.c}) {
    const double perm = (std::fabs(u.x * v.x) + std::fabs(u.y * v.y)) + std::fabs(u.z * v.z);
    e = std::max(e, std::fabs(dot(u, v) - d) + 8 * kEps * perm);
  }
  e = e * (1 + 16 * kEps) + 0x1p-1000;
  // k <= 1 / |u|: uu is within 3.01 eps of |u|^2; the root, the quotient and the factor round
  // once each.
  const double k = 1.0 / std::sqrt(uu) * (1 - 8 * kEps);
  if (!std::isfinite(e) || !std::isfinite(d) || !(k > 0) || !std::isfinite(k)) return;
  n_ = u;
  d_ = d;
  e_ = e;
  k_ = k;
}

HalfSpaceTest::HalfSpaceTest(Vec3 p, Vec3 w, double best, double max_abs) {
  const double ww = dot(w, w);
  if (!(ww >= 0x1p-900) || !std::isfinite(ww) || !(best >= 0)) return;  // c_ = -inf: no test
  w_ = w;
  const double a = dot(p, w);
  const double pw = (std::fabs(p.x * w.x) + std::fabs(p.y * w.y)) + std::fabs(p.z * w.z);
  const double mw = max_abs * ((std::fabs(w.x) + std::fabs(w.y)) + std::fabs(w.z));
  // b >= sqrt(best) |w|: ww is at most 3 eps low (its root 1.5 eps), the two roots, the product
  // and the factor round once each. Not sqrt(best * ww): that product underflows for tiny
  // coordinates (2^-300: best * ww ~ 2^-1200), and b = 0 would let the test put out the closest
  // triangle. This product may underflow only below 2^-1022, by less than the 2^-1000 in m.
  const double b = std::sqrt(best) * std::sqrt(ww) * (1 + 8 * kEps);
  const double m = 16 * kEps * (((pw + mw) + b) + std::fabs(a)) + 0x1p-1000;
  const double c = (a - b) - m;
  if (std::isfinite(c)) c_ = c;
}

void TriangleSearch::contenders(Vec3 p, std::vector<Contender>& out, SearchStats* stats,
                                std::int32_t hint) const {
  // A first, cheap test for each triangle (HalfSpaceTest): does it lie beyond the plane
  // normal to w at the best distance so far, w the direction from the best triangle's
  // approximate closest point to p? `best` is the least upper bound returned so far, i.e. the
  // search's own best: a triangle beyond the plane is farther than sqrt(best) and out (lo >
  // best), exactly as if the full bounds had put it out.
  double best = kInf;
  HalfSpaceTest beyond;
  std::size_t cheap = 0;
  tree_.contenders(
      p,
      [&](std::int32_t k, double& lo, double& hi) {
        const Triangle3& t = ordered_[static_cast<std::size_t>(k)];
        if (beyond(t)) {
          ++cheap;
          lo = kInf;
          hi = kInf;
          return;
        }
        // Then the triangle's own plane, before its closest point (a triangle farther than the
        // best is out whatever its upper bound).
        const double plane = planes_[static_cast<std::size_t>(k)].lower(p);
        if (plane > best) {
          ++cheap;
          lo = plane;
          hi = kInf;
          return;
        }
        const Vec3 w = triangle_bounds(p, t, slack_, lo, hi);
        if (hi < best) {
          best = hi;
          beyond = HalfSpaceTest(p, w, best, max_abs_);
        }
      },
      out, stats, hint);
  if (stats) stats->cheap += cheap;
}

int TriangleSearch::within(Vec3 p, double d2_lo, double d2_hi, std::vector<Contender>& out) const {
  return tree_.within(
      p, d2_lo, d2_hi,
      [&](std::int32_t k, double& lo, double& hi) {
        const double plane = planes_[static_cast<std::size_t>(k)].lower(p);
        if (plane > d2_hi) {  // beyond the distance asked: out, as the full bounds would say
          lo = plane;
          hi = kInf;
          return;
        }
        triangle_bounds(p, ordered_[static_cast<std::size_t>(k)], slack_, lo, hi);
      },
      out);
}

}  // namespace contain::distance::detail
