#include "distance/oriented_box.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contain/predicates/unit_roundoff.h"
#include "contain/values/max_abs.h"
#include "distance/bound_constants.h"
#include "distance/triangle_pair_bounds.h"

namespace contain::distance::detail {

namespace {

// The frame's orthonormality: |e_i . e_j - delta_ij| <= phi, checked at build.
constexpr double kPhi = 0x1p-40;

// Eigenvectors of a symmetric 3x3 matrix by cyclic Jacobi rotations (Golub and Van Loan 8.5);
// only a guide for the frame, so its accuracy does not matter.
void jacobi_eigenvectors(double a[3][3], double v[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      v[i][j] = i == j ? 1.0 : 0.0;
  // Until the off-diagonal part is negligible against the diagonal (a guide needs no more).
  for (int sweep = 0; sweep < 12; ++sweep) {
    const double off = std::fabs(a[0][1]) + std::fabs(a[0][2]) + std::fabs(a[1][2]);
    const double diag = std::fabs(a[0][0]) + std::fabs(a[1][1]) + std::fabs(a[2][2]);
    if (!(off > 0x1p-40 * diag)) break;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < 3; ++k) {  // A <- A J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // A <- J^T A
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {  // V <- V J
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
    }
  }
}

Vec3 normalized(Vec3 x) {
  const double n = length(x);
  return n > 0 ? (1 / n) * x : Vec3{};
}

// Sums of a node's points about a reference point r (the mesh's first vertex, so that meshes
// far from the origin keep their digits): count, sum of p - r, sum of (p - r)(p - r)^T. A
// parent's are its children's added, so that all nodes cost O(n).
struct Moments {
  double n = 0;
  double s[3] = {0, 0, 0};
  double ss[3][3] = {};
  void add(Vec3 p, Vec3 r) {
    const double d[3] = {p.x - r.x, p.y - r.y, p.z - r.z};
    n += 1;
    for (int i = 0; i < 3; ++i) {
      s[i] += d[i];
      for (int j = 0; j < 3; ++j)
        ss[i][j] += d[i] * d[j];
    }
  }
  void add(const Moments& o) {
    n += o.n;
    for (int i = 0; i < 3; ++i) {
      s[i] += o.s[i];
      for (int j = 0; j < 3; ++j)
        ss[i][j] += o.ss[i][j];
    }
  }
};

// The principal axes of the points summed in `m` (eigenvectors of their covariance), made
// orthonormal (Gram-Schmidt), or the coordinate axes when the result fails the check
// |e_i . e_j - delta_ij| <= 2^-41 as computed (each dot's rounding is below 4u for vectors of
// length <= 1 + 2^-41, so exactly within phi = 2^-40). Only a guide: any frame that passes the
// check gives a valid box.
void principal_frame(const Moments& m, Vec3 e[3]) {
  e[0] = {1, 0, 0};
  e[1] = {0, 1, 0};
  e[2] = {0, 0, 1};
  if (m.n < 2) return;
  double a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      a[i][j] = m.ss[i][j] / m.n - (m.s[i] / m.n) * (m.s[j] / m.n);
  double v[3][3];
  jacobi_eigenvectors(a, v);
  Vec3 f[3];
  f[0] = normalized({v[0][0], v[1][0], v[2][0]});
  const Vec3 g{v[0][1], v[1][1], v[2][1]};
  f[1] = normalized(g - dot(g, f[0]) * f[0]);
  f[2] = normalized(cross(f[0], f[1]));
  for (int i = 0; i < 3; ++i) {
    if (!is_finite(f[i])) return;
    for (int j = i; j < 3; ++j)
      if (!(std::fabs(dot(f[i], f[j]) - (i == j ? 1.0 : 0.0)) <= 0x1p-41)) return;
  }
  for (int i = 0; i < 3; ++i)
    e[i] = f[i];
}

// Coefficient k of p in the frame (c, e), as computed, and a bound on its distance from the
// exact coefficient a_k of E^-1 (p - c) (E = [e0 e1 e2]):
//   d' = fl(p - c) is within u |d| of d = p - c;
//   fl(e_k . d') is within gamma_3 P_k of e_k . d', P_k = sum_i |e_ki d'_i|;
//   e_k . d' is within 1.01 u P_k of e_k . d;
//   E^T d = (I + F) a with |F_ij| <= phi, so |e_k . d - a_k| = |(F a)_k| <= phi |a|_1
//   <= phi sqrt(3) |a| <= phi sqrt(3) |d| / sqrt(1 - 3 phi) <= 2 phi |d'|_1 (1 + u).
// In all below 8 u P_k + 3 phi |d'|_1, with room for the bound's own three roundings.
void coefficients(Vec3 p, Vec3 c, const Vec3 e[3], double coef[3], double err[3]) {
  const Vec3 d = p - c;
  const double d1 = (std::fabs(d.x) + std::fabs(d.y)) + std::fabs(d.z);
  for (int k = 0; k < 3; ++k) {
    coef[k] = dot(e[k], d);
    const double perm =
        (std::fabs(e[k].x * d.x) + std::fabs(e[k].y * d.y)) + std::fabs(e[k].z * d.z);
    err[k] = 8 * kEps * perm + 3 * kPhi * d1 + 4 * std::numeric_limits<double>::denorm_min();
  }
}

// The box of `points` in the frame `e` (orthonormal within phi), in one pass about any point
// c0 (the points' mean is a good one):
//   each exact coefficient a_k of E^-1 (p - c0) lies in [coef_k - err_k, coef_k + err_k]
//   (`coefficients`; the two roundings of those bounds, u (|coef_k| + err_k) <= 1.1 u P_k, are
//   inside err_k's room), so in [lo_k, hi_k] over the points;
//   the centre c = fl(c0 + sum_k mid_k e_k), mid_k = (lo_k + hi_k) / 2 as computed, is within
//   delta_i <= gamma_4 (|c0_i| + sum_k |mid_k e_ki|) per coordinate of the exact sum, so
//   E^-1 (p - c) = a - mid - E^-1 delta with |(E^-1 delta)_k| <= |delta| / sqrt(1 - 3 phi)
//   <= 2 |delta|_inf;
//   h_k = (max(hi_k - mid_k, mid_k - lo_k) + 2 |delta|_inf), each sum and difference rounded
//   up by the final (1 + 8u).
OrientedBox box_of(std::span<const Vec3> points, const Vec3 e[3], Vec3 c0) {
  OrientedBox box;
  for (int k = 0; k < 3; ++k)
    box.e[k] = e[k];
  box.c = c0;
  if (points.empty()) return box;
  double lo[3] = {kInf, kInf, kInf}, hi[3] = {-kInf, -kInf, -kInf};
  for (const Vec3& p : points) {
    double coef[3], err[3];
    coefficients(p, c0, e, coef, err);
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], coef[k] - err[k]);
      hi[k] = std::max(hi[k], coef[k] + err[k]);
    }
  }
  double mid[3];
  for (int k = 0; k < 3; ++k)
    mid[k] = 0.5 * (lo[k] + hi[k]);
  box.c = ((c0 + mid[0] * e[0]) + mid[1] * e[1]) + mid[2] * e[2];
  const double c0_abs[3] = {std::fabs(c0.x), std::fabs(c0.y), std::fabs(c0.z)};
  double delta = 0;
  for (int i = 0; i < 3; ++i) {
    double sum = c0_abs[i];
    for (int k = 0; k < 3; ++k) {
      const double eki = i == 0 ? e[k].x : i == 1 ? e[k].y : e[k].z;
      sum += std::fabs(mid[k] * eki);
    }
    delta = std::max(delta, 5 * kEps * sum + 8 * std::numeric_limits<double>::denorm_min());
  }
  for (int k = 0; k < 3; ++k)
    box.h[k] = (std::max(hi[k] - mid[k], mid[k] - lo[k]) + 2 * delta) * (1 + 8 * kEps);
  if (!std::isfinite(box.h[0] + box.h[1] + box.h[2]) || !is_finite(box.c)) {
    box.h[0] = box.h[1] = box.h[2] = kInf;  // a box that holds everything
  }
  return box;
}

// The coordinate axes around an axis-aligned box that holds the points: c its centre as
// computed, h_k = max(max_k - c_k, min_k - c_k) rounded up (one subtraction, then the factor);
// the axes are exactly orthonormal. O(1), for the few nodes near the root.
OrientedBox box_of(const Box3& aabb) {
  OrientedBox box;
  box.e[0] = {1, 0, 0};
  box.e[1] = {0, 1, 0};
  box.e[2] = {0, 0, 1};
  box.c = 0.5 * (aabb.min + aabb.max);
  const double lo[3] = {aabb.min.x, aabb.min.y, aabb.min.z};
  const double hi[3] = {aabb.max.x, aabb.max.y, aabb.max.z};
  const double c[3] = {box.c.x, box.c.y, box.c.z};
  for (int k = 0; k < 3; ++k)
    box.h[k] = std::max(hi[k] - c[k], c[k] - lo[k]) * (1 + 4 * kEps);
  if (!std::isfinite(box.h[0] + box.h[1] + box.h[2]) || !is_finite(box.c)) {
    box.h[0] = box.h[1] = box.h[2] = std::numeric_limits<double>::infinity();
  }
  return box;
}

// Nodes over more triangles than this get the box of their axis-aligned box: the principal
// frame pays for itself near the leaves, where most pairs are met, and gathering every vertex
// at every level cost as much as building the hierarchy.
constexpr std::int32_t kMaxOriented = 256;

// |c|_inf + sum_k h_k of a box.
double box_extent(const OrientedBox& b) {
  return max_abs(b.c) + ((b.h[0] + b.h[1]) + b.h[2]);
}

}  // namespace

std::vector<std::pair<std::int32_t, std::int32_t>> item_ranges(std::span<const bvh::Node> nodes) {
  std::vector<std::pair<std::int32_t, std::int32_t>> out(nodes.size());
  for (std::size_t k = nodes.size(); k-- > 0;) {
    const bvh::Node& n = nodes[k];
    if (n.is_leaf()) {
      out[k] = {n.first, n.first + n.count};
    } else {
      const auto second = static_cast<std::size_t>(n.first);
      out[k] = {std::min(out[k + 1].first, out[second].first),
                std::max(out[k + 1].second, out[second].second)};
    }
  }
  return out;
}

std::vector<OrientedBox> oriented_boxes(const bvh::Bvh& bvh, const Mesh& mesh) {
  const std::span<const bvh::Node> nodes = bvh.nodes();
  const std::span<const std::int32_t> items = bvh.items();
  // A range that holds more than the node's own items still gives a box around them.
  const std::vector<std::pair<std::int32_t, std::int32_t>> range = item_ranges(nodes);
  // Moments: leaves from their vertices, inner nodes from their children.
  const Vec3 r = mesh.vertices.empty() ? Vec3{} : mesh.vertices.front();
  std::vector<Moments> moments(nodes.size());
  for (std::size_t k = nodes.size(); k-- > 0;) {
    const bvh::Node& n = nodes[k];
    if (n.is_leaf()) {
      for (std::int32_t i = n.first; i < n.first + n.count; ++i)
        for (const std::int32_t v :
             mesh.triangles[static_cast<std::size_t>(items[static_cast<std::size_t>(i)])])
          moments[k].add(mesh.vertex(v), r);
    } else {
      moments[k] = moments[k + 1];
      moments[k].add(moments[static_cast<std::size_t>(n.first)]);
    }
  }
  std::vector<OrientedBox> out(nodes.size());
  std::vector<Vec3> points;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const auto [lo, hi] = range[k];
    if (hi - lo > kMaxOriented) {
      out[k] = box_of(nodes[k].box);
      continue;
    }
    points.clear();
    for (std::int32_t i = lo; i < hi; ++i)
      for (const std::int32_t v :
           mesh.triangles[static_cast<std::size_t>(items[static_cast<std::size_t>(i)])])
        points.push_back(mesh.vertex(v));
    const Moments& m = moments[k];
    Vec3 e[3];
    principal_frame(m, e);
    const Vec3 c0 = m.n > 0 ? r + Vec3{m.s[0] / m.n, m.s[1] / m.n, m.s[2] / m.n} : r;
    out[k] = box_of(points, e, is_finite(c0) ? c0 : r);
  }
  return out;
}

void principal_axes(std::span<const Vec3> points, Vec3 e[3]) {
  Moments m;
  const Vec3 r = points.empty() ? Vec3{} : points.front();
  for (const Vec3& p : points)
    m.add(p, r);
  principal_frame(m, e);
}

bool oriented_box_surely_holds(const OrientedBox& box, Vec3 p) {
  double coef[3], err[3];
  coefficients(p, box.c, box.e, coef, err);
  for (int k = 0; k < 3; ++k)
    if (!((std::fabs(coef[k]) + err[k]) * (1 + 4 * kEps) <= box.h[k])) return false;
  return true;
}

double oriented_extent(std::span<const OrientedBox> boxes) {
  double m = 0;
  for (const OrientedBox& b : boxes)
    m = std::max(m, box_extent(b));
  return m;
}

OrientedPose oriented_pose(const Transform& tb, double extent_a, double extent_b) {
  // Margin per unit of W = |w|_1 for one evaluation of oriented_box_lower (H_A, H_B: the
  // extents |c|_inf + sum h of every box of A and of B; R1 = max_i sum_j |r_ij|; T = |t|_inf;
  // |e_kj| <= 1 + 2^-41):
  //   min over A, as computed: within gamma_3 |c_A|_inf W + sum_k h_k (gamma_3 (1.01) W) plus
  //     the roundings of three products and four sums: <= 10 u H_A W;
  //   u = R^T w as computed: |u' - u|_1 <= gamma_3 R1 W and |u'|_1 <= 1.01 R1 W; so max over B
  //     with u' instead of u is off by <= 1.01 H_B gamma_3 R1 W <= 3.1 u R1 H_B W, and its
  //     evaluation within 10 u (T + 1.02 R1 H_B) W;
  //   each placed vertex as Transform::apply computes it is within gamma_4 (T + R1 |v|_inf)
  //     of its exact image per coordinate, |v|_inf <= 1.01 H_B: <= 4.1 u (T + 1.02 R1 H_B) W
  //     along w;
  //   the difference min A - max B: u (H_A + T + 1.02 R1 H_B) 1.01 W.
  // Together below 19 u (H_A + T + R1 H_B) W; 32 u leaves room for the margin's own roundings
  // (this product, W's, margin * W) and 256 denorm_min for up to ~60 underflowed products.
  // The last subtraction, gap - margin W, is the one squared_separation_lower rounds down for.
  OrientedPose pose;
  pose.tb = tb;
  double r1 = 0;
  for (const auto& row : tb.r)
    r1 = std::max(r1, (std::fabs(row[0]) + std::fabs(row[1])) + std::fabs(row[2]));
  const double t = max_abs(tb.t);
  pose.margin = 32 * kEps * ((extent_a + t) + r1 * extent_b);
  if (!std::isfinite(pose.margin)) pose.margin = std::numeric_limits<double>::infinity();
  return pose;
}

double oriented_box_lower(const OrientedBox& a, const OrientedBox& b, Vec3 placed_cb,
                          const OrientedPose& pose) {
  const Vec3 w = a.c - placed_cb;
  const auto& r = pose.tb.r;
  const Vec3 u{(r[0][0] * w.x + r[1][0] * w.y) + r[2][0] * w.z,
               (r[0][1] * w.x + r[1][1] * w.y) + r[2][1] * w.z,
               (r[0][2] * w.x + r[1][2] * w.y) + r[2][2] * w.z};
  const double min_a =
      dot(a.c, w) - ((a.h[0] * std::fabs(dot(a.e[0], w)) + a.h[1] * std::fabs(dot(a.e[1], w))) +
                     a.h[2] * std::fabs(dot(a.e[2], w)));
  const double max_b = (dot(pose.tb.t, w) + dot(b.c, u)) +
                       ((b.h[0] * std::fabs(dot(b.e[0], u)) + b.h[1] * std::fabs(dot(b.e[1], u))) +
                        b.h[2] * std::fabs(dot(b.e[2], u)));
  const double w1 = (std::fabs(w.x) + std::fabs(w.y)) + std::fabs(w.z);
  const double gap =
      (min_a - max_b) - (pose.margin * w1 + 256 * std::numeric_limits<double>::denorm_min());
  return squared_separation_lower(gap, dot(w, w));
}

}  // namespace contain::distance::detail
