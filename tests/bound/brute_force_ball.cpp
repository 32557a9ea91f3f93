#include "bound/brute_force_ball.h"

#include <optional>

namespace contain::test {
namespace {

using QPoint = std::vector<mpq_class>;

mpq_class squared_distance(const QPoint& a, const QPoint& b) {
  mpq_class s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    mpq_class d = a[i] - b[i];
    s += d * d;
  }
  return s;
}

// The circumcenter of `support` in its affine hull: c = q0 + sum_i l_i (q_i - q0) with
// 2 (q_j - q0).(c - q0) = |q_j - q0|^2 for every j; nothing when the points are dependent.
std::optional<ExactBall> circumball(const std::vector<const QPoint*>& support) {
  const QPoint& q0 = *support[0];
  const std::size_t k = support.size() - 1;
  const std::size_t dim = q0.size();
  std::vector<QPoint> v(k, QPoint(dim));
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t c = 0; c < dim; ++c)
      v[i][c] = (*support[i + 1])[c] - q0[c];
  }
  // Augmented Gram system, Gaussian elimination with exact pivots.
  std::vector<std::vector<mpq_class>> m(k, std::vector<mpq_class>(k + 1));
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) {
      mpq_class s = 0;
      for (std::size_t c = 0; c < dim; ++c)
        s += v[i][c] * v[j][c];
      m[i][j] = 2 * s;
    }
    mpq_class s = 0;
    for (std::size_t c = 0; c < dim; ++c)
      s += v[i][c] * v[i][c];
    m[i][k] = s;
  }
  for (std::size_t col = 0; col < k; ++col) {
    std::size_t pivot = col;
    while (pivot < k && sgn(m[pivot][col]) == 0)
      ++pivot;
    if (pivot == k) return std::nullopt;
    std::swap(m[col], m[pivot]);
    for (std::size_t r = 0; r < k; ++r) {
      if (r == col || sgn(m[r][col]) == 0) continue;
      mpq_class f = m[r][col] / m[col][col];
      for (std::size_t c = col; c <= k; ++c)
        m[r][c] -= f * m[col][c];
    }
  }
  ExactBall ball{q0, 0};
  for (std::size_t i = 0; i < k; ++i) {
    mpq_class l = m[i][k] / m[i][i];
    for (std::size_t c = 0; c < dim; ++c)
      ball.center[c] += l * v[i][c];
  }
  ball.squared_radius = squared_distance(ball.center, q0);
  return ball;
}

ExactBall brute_force(const std::vector<QPoint>& points) {
  const std::size_t n = points.size();
  const std::size_t max_size = points[0].size() + 1;
  std::optional<ExactBall> best;
  std::vector<std::size_t> pick;
  std::vector<const QPoint*> support;
  // Subsets in lexicographic order, sizes 1 .. d + 1.
  for (std::size_t size = 1; size <= std::min(max_size, n); ++size) {
    pick.assign(size, 0);
    for (std::size_t i = 0; i < size; ++i)
      pick[i] = i;
    while (true) {
      support.clear();
      for (std::size_t i : pick)
        support.push_back(&points[i]);
      if (auto ball = circumball(support)) {
        if (!best || ball->squared_radius < best->squared_radius) {
          bool holds = true;
          for (const QPoint& p : points) {
            if (squared_distance(p, ball->center) > ball->squared_radius) {
              holds = false;
              break;
            }
          }
          if (holds) best = std::move(ball);
        }
      }
      std::size_t i = size;
      while (i > 0 && pick[i - 1] == n - size + i - 1)
        --i;
      if (i == 0) break;
      ++pick[i - 1];
      for (std::size_t j = i; j < size; ++j)
        pick[j] = pick[j - 1] + 1;
    }
  }
  return *best;
}

}  // namespace

ExactBall brute_force_min_ball(std::span<const Vec3> points) {
  std::vector<QPoint> q;
  for (const Vec3& p : points)
    q.push_back({p.x, p.y, p.z});
  return brute_force(q);
}

ExactBall brute_force_min_ball(std::span<const Vec2> points) {
  std::vector<QPoint> q;
  for (const Vec2& p : points)
    q.push_back({p.x, p.y});
  return brute_force(q);
}

mpq_class exact_square(double r) {
  mpq_class q(r);
  return q * q;
}

}  // namespace contain::test
