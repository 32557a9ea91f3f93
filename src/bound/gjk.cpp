#include "contain/bound/gjk.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contain::bound {

namespace {

// A simplex of A - B: its points w = a - b with the support points they came from.
struct Simplex {
  std::array<Vec3, 4> w{}, a{}, b{};
  int n = 0;
};

// Barycentric coordinates (l[0..k-1]) of the point of the affine hull of p[0..k-1] closest to
// the origin, by the normal equations G l' = -(p_i - p_0) . p_0 (Cramer's rule). False when the
// points are (numerically) affinely dependent.
bool affine_closest(const Vec3* p, int k, double* l) {
  if (k == 1) {
    l[0] = 1;
    return true;
  }
  Vec3 e[3];
  double rhs[3];
  for (int i = 1; i < k; ++i) {
    e[i - 1] = p[i] - p[0];
    rhs[i - 1] = -dot(e[i - 1], p[0]);
  }
  const int m = k - 1;
  double g[3][3];
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      g[i][j] = dot(e[i], e[j]);
  double sol[3] = {0, 0, 0};
  if (m == 1) {
    if (!(g[0][0] > 0)) return false;
    sol[0] = rhs[0] / g[0][0];
  } else if (m == 2) {
    const double det = g[0][0] * g[1][1] - g[0][1] * g[1][0];
    if (!(det > 1e-24 * g[0][0] * g[1][1])) return false;
    sol[0] = (rhs[0] * g[1][1] - g[0][1] * rhs[1]) / det;
    sol[1] = (g[0][0] * rhs[1] - rhs[0] * g[1][0]) / det;
  } else {
    const auto det3 = [](const double a[3][3]) {
      return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
             a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
             a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double det = det3(g);
    // A nearly flat tetrahedron is left to its faces: its volume says nothing reliable about
    // where the origin is.
    if (!(det > 1e-12 * g[0][0] * g[1][1] * g[2][2])) return false;
    for (int c = 0; c < 3; ++c) {
      double a[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          a[i][j] = j == c ? rhs[i] : g[i][j];
      sol[c] = det3(a) / det;
    }
  }
  double sum = 0;
  for (int i = 0; i < m; ++i) {
    l[i + 1] = sol[i];
    sum += sol[i];
  }
  l[0] = 1 - sum;
  return true;
}

// The point of conv(simplex) closest to the origin, the simplex reduced to the smallest face
// that holds it, and that point's weights on the reduced simplex (Johnson's sub-algorithm, here
// by trying every face: at most 15).
Vec3 closest_to_origin(Simplex& s, double* weights) {
  double best = std::numeric_limits<double>::infinity();
  Vec3 best_v{};
  Simplex best_s;
  for (int mask = 1; mask < (1 << s.n); ++mask) {
    Vec3 p[4];
    int index[4];
    int k = 0;
    for (int i = 0; i < s.n; ++i) {
      if ((mask >> i) & 1) {
        index[k] = i;
        p[k++] = s.w[static_cast<std::size_t>(i)];
      }
    }
    double l[4];
    if (!affine_closest(p, k, l)) continue;
    bool interior = true;
    Vec3 v{0, 0, 0};
    for (int i = 0; i < k; ++i) {
      interior = interior && l[i] > 0;
      v = v + l[i] * p[i];
    }
    if (!interior) continue;
    if (k == 4) v = {0, 0, 0};  // the origin is inside the tetrahedron
    const double d = dot(v, v);
    if (d < best) {
      best = d;
      best_v = v;
      best_s.n = k;
      for (int i = 0; i < k; ++i) {
        const auto from = static_cast<std::size_t>(index[i]);
        best_s.w[static_cast<std::size_t>(i)] = s.w[from];
        best_s.a[static_cast<std::size_t>(i)] = s.a[from];
        best_s.b[static_cast<std::size_t>(i)] = s.b[from];
        weights[i] = l[i];
      }
    }
  }
  s = best_s;
  return best_v;
}

}  // namespace

GjkResult gjk(const Support& support_a, const Support& support_b) {
  GjkResult r;
  Simplex s;
  s.a[0] = support_a({1, 0, 0});
  s.b[0] = support_b({-1, 0, 0});
  s.w[0] = s.a[0] - s.b[0];
  s.n = 1;
  double weights[4] = {1, 0, 0, 0};
  Vec3 v = s.w[0];
  r.size = length(v);
  for (int iter = 0; iter < 64; ++iter) {
    r.iterations = iter + 1;
    const double vv = dot(v, v);
    if (vv == 0) {
      r.origin_inside = true;
      break;
    }
    const Vec3 a = support_a(-1.0 * v), b = support_b(v);
    const Vec3 w = a - b;
    r.size = std::max(r.size, length(w));
    const double vw = dot(v, w);
    r.lower = std::max(r.lower, vw / std::sqrt(vv));
    if (vv - vw <= 1e-12 * vv) break;  // converged: the upper and lower bounds agree
    bool repeated = false;
    for (int i = 0; i < s.n; ++i)
      repeated = repeated || s.w[static_cast<std::size_t>(i)] == w;
    if (repeated) break;
    Simplex next = s;
    next.w[static_cast<std::size_t>(next.n)] = w;
    next.a[static_cast<std::size_t>(next.n)] = a;
    next.b[static_cast<std::size_t>(next.n)] = b;
    ++next.n;
    double next_weights[4] = {0, 0, 0, 0};
    const Vec3 next_v = closest_to_origin(next, next_weights);
    if (dot(next_v, next_v) <= 1e-24 * r.size * r.size) {
      r.origin_inside = true;
      v = {0, 0, 0};
      s = next;
      std::copy(next_weights, next_weights + 4, weights);
      break;
    }
    if (dot(next_v, next_v) >= vv) break;  // no progress: rounding has taken over
    v = next_v;
    s = next;
    std::copy(next_weights, next_weights + 4, weights);
  }
  r.v = v;
  r.simplex_size = s.n;
  for (int i = 0; i < s.n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    r.simplex_a[k] = s.a[k];
    r.simplex_b[k] = s.b[k];
    r.point_a = r.point_a + weights[i] * s.a[k];
    r.point_b = r.point_b + weights[i] * s.b[k];
  }
  return r;
}

}  // namespace contain::bound
